// ECP5 PLL for the moire ULX3S wrapper: EHXPLLL with feedback from CLKOP, as Project Trellis'
// ecppll writes it. The dividers come from Scala (moire.board.ulx3s.Ecp5Pll): clkSys = CLKOP =
// system clock, clkAdc = CLKOS = AD9226 clock, same divider and phase.
module Ulx3sPll #(
  parameter CLKI_DIV = 1,
  parameter CLKFB_DIV = 2,
  parameter CLKOP_DIV = 12,
  parameter CLKOP_CPHASE = 11
) (
  input  wire clkin,
  output wire clkSys,
  output wire clkAdc,
  output wire locked
);
  (* ICP_CURRENT="12" *) (* LPF_RESISTOR="8" *) (* MFG_ENABLE_FILTEROPAMP="1" *) (* MFG_GMCREF_SEL="2" *)
  EHXPLLL #(
    .PLLRST_ENA("DISABLED"),
    .INTFB_WAKE("DISABLED"),
    .STDBY_ENABLE("DISABLED"),
    .DPHASE_SOURCE("DISABLED"),
    .OUTDIVIDER_MUXA("DIVA"),
    .OUTDIVIDER_MUXB("DIVB"),
    .OUTDIVIDER_MUXC("DIVC"),
    .OUTDIVIDER_MUXD("DIVD"),
    .CLKI_DIV(CLKI_DIV),
    .CLKOP_ENABLE("ENABLED"),
    .CLKOP_DIV(CLKOP_DIV),
    .CLKOP_CPHASE(CLKOP_CPHASE),
    .CLKOP_FPHASE(0),
    .CLKOS_ENABLE("ENABLED"),
    .CLKOS_DIV(CLKOP_DIV),
    .CLKOS_CPHASE(CLKOP_CPHASE),
    .CLKOS_FPHASE(0),
    .FEEDBK_PATH("CLKOP"),
    .CLKFB_DIV(CLKFB_DIV)
  ) pll_i (
    .RST(1'b0),
    .STDBY(1'b0),
    .CLKI(clkin),
    .CLKOP(clkSys),
    .CLKOS(clkAdc),
    .CLKFB(clkSys),
    .CLKINTFB(),
    .PHASESEL0(1'b0),
    .PHASESEL1(1'b0),
    .PHASEDIR(1'b1),
    .PHASESTEP(1'b1),
    .PHASELOADREG(1'b1),
    .PLLWAKESYNC(1'b0),
    .ENCLKOP(1'b0),
    .LOCK(locked)
  );
endmodule
