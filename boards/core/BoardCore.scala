package moire.board

import chisel3._
import chisel3.util._
import moire.chain.CorrectedSubdivider
import moire.io.{QuadratureCounter, QuadratureParams}
import moire.io._
import moire.signal.AdcFormat
import moire.protocol.{BurstLayout, RegReply, Registers, StreamRecord, StreamV1}
import moire.protocol.Registers.{ControlBit, StatusBit}
import moire.subdiv.{AdcPins, SubdivAdc, SubdivOut, SubdivStatus}
import moire.harmonic.{HarmonicCompensator, HarmonicRegPort}

/** Everything of a board on the system clock, shared by the DE2-115 and the ULX3S harnesses:
  * AD9226 capture, datapath, record stream over the UART, register interface, encoder input counter
  * and the status the harness shows on its LEDs.
  *
  * AD9226 capture: the ADC clock rises on the clock edge where the divider phase `ph` becomes 0; the
  * ADC drives its new word tOD = 3.5..7 ns (plus the FPGA clock-to-pin delay) after that edge, and
  * the word is registered on the NEXT rising edge of the system clock, one period later (at 50 MHz
  * 20 ns: 13 ns of setup margin at 7 ns tOD), and the old word is held for tOD(min) after that edge. The word of sample i
  * appears after ADC edge i + 7 (AD9226 pipeline), so record index = captured words - 7.
  */
class BoardCore(val p: BoardParams) extends Module {
  override def desiredName: String = s"BoardCore_${p.design.name}"
  val io = IO(new CoreIO)
  private val sp = p.datapathSubdiv
  private val k = p.adcDivide

  // ---- ADC clock divider (used for k > 1; for k = 1 the top forwards the system clock) ----
  private val ph = RegInit(0.U(log2Ceil(k + 1).W))
  private val phNext = Mux(ph === (k - 1).U, 0.U, ph + 1.U)
  ph := phNext
  private val adcClk = RegInit(false.B)
  adcClk := phNext < ((k + 1) / 2).U
  io.pins.SIN_CLK := adcClk
  io.pins.COS_CLK := adcClk

  // ---- capture: every clock into input registers; valid one clock after the ADC edge ----
  private val sinD = RegNext(io.pins.SIN_D).suggestName("sin_capture")
  private val cosD = RegNext(io.pins.COS_D).suggestName("cos_capture")
  private val otrS = RegNext(io.pins.SIN_OTR).suggestName("otr_sin_capture")
  private val otrC = RegNext(io.pins.COS_OTR).suggestName("otr_cos_capture")
  // The word launched by the ADC edge at clock edge e is valid in the capture registers after edge e + 1.
  private val adcRose = if (k == 1) true.B else adcClk && !RegNext(adcClk, false.B)
  private val capValid = RegNext(adcRose, false.B)
  private val words = RegInit(0.U(32.W))
  private val primed = RegInit(false.B)
  when(capValid) {
    words := words + 1.U
    when(words === (p.adcPipeline - 1).U) { primed := true.B }
  }
  private val sampleValid = capValid && primed
  private val index = words - p.adcPipeline.U

  // ---- datapath ----
  private val clear = Wire(Bool())
  /** Writes to the harmonic window (design compensated), from the register section below. */
  private val harmonicPort = Wire(new HarmonicRegPort(p.harmonicParams))
  private val dpIn = Wire(Valid(new AdcPins(12)))
  dpIn.valid := sampleValid
  dpIn.bits.sin := sinD; dpIn.bits.cos := cosD; dpIn.bits.otrSin := otrS; dpIn.bits.otrCos := otrC
  private val (out, encA, encB, encZ, status, latency, adapt) = p.design match {
    case BoardDesign.Subdiv =>
      val m = Module(new SubdivAdc(p.subdiv, p.adcFormat))
      m.io.in := dpIn; m.io.clearStatus := clear
      (m.io.out, m.io.a, m.io.b, m.io.z, m.io.status, m.latency, None)
    case BoardDesign.Corrected =>
      val m = Module(new CorrectedSubdivider(p.correctedParams, withReadBack = true))
      m.io.in := dpIn; m.io.clearStatus := clear
      (m.io.out, m.io.a, m.io.b, m.io.z, m.io.status, m.latency, m.readBack.zip(m.preset))
    case BoardDesign.Compensated =>
      val m = Module(new SubdivAdc(p.subdiv, p.adcFormat))
      m.io.in := dpIn; m.io.clearStatus := clear
      val hp = p.harmonicParams
      val h = Module(new HarmonicCompensator(hp))
      h.io.reg := harmonicPort
      h.io.in.valid := m.io.out.valid
      h.io.in.bits := m.io.out.bits.position.asUInt(hp.countBits - 1, 0)
      // theta - f(theta), kept multi-turn: the subdivider's position minus f rounded to counts, registered
      // (one clock: the rounding and the subtraction do not share a clock with what reads the position)
      val late = ShiftRegister(m.io.out.bits, hp.latency)
      val fRounded = h.io.out.bits.f +& (BigInt(1) << (hp.outFrac - 1)).S
      moire.emit.Unused("f_fraction", fRounded(hp.outFrac - 1, 0)) // rounded away: whole counts only
      val fCounts = (fRounded >> hp.outFrac).asSInt
      val c = Wire(Valid(new SubdivOut(p.subdiv)))
      c.valid := h.io.out.valid
      c.bits := late
      c.bits.position := (late.position - fCounts)(p.subdiv.positionWidth - 1, 0).asSInt
      val o = Wire(Valid(new SubdivOut(p.subdiv)))
      o.valid := RegNext(c.valid, false.B)
      o.bits := RegNext(c.bits)
      val q = Module(new QuadratureOut(p.subdiv.positionWidth, p.subdiv.countBits, p.subdiv.minEdgeClocks))
      q.io.in.valid := o.valid; q.io.in.bits := o.bits.position
      (o, q.io.a, q.io.b, q.io.z, m.io.status, m.latency + hp.latency + BoardParams.compensatedOutRegs, None)
  }
  require(latency == p.datapathLatency, s"datapath latency $latency, expected ${p.datapathLatency}")

  // The sample each output belongs to: the input side delayed by the datapath latency.
  private val sPins = ShiftRegister(dpIn.bits, latency)
  private val sIndex = ShiftRegister(index, latency)
  private val sideValid = ShiftRegister(sampleValid, latency, false.B, true.B)
  assert(out.valid === sideValid, "datapath output not aligned with its sample")

  // ---- encoder inputs ----
  private val encIn = Seq(io.pins.ENC_A_IN, io.pins.ENC_B_IN, io.pins.ENC_Z_IN).zip(Seq("enc_a", "enc_b", "enc_z"))
    .map { case (x, n) => GlitchFilter(x, p.glitchFilter, init = false, n) }
  private val qc = Module(new QuadratureCounter(QuadratureParams(countBits = 32)))
  qc.io.a := encIn(0); qc.io.b := encIn(1)
  private val zAligned = ShiftRegister(encIn(2), qc.latency)
  private val zRise = zAligned && !RegNext(zAligned, false.B)
  private val zCount = RegInit(0.U(32.W))
  when(zRise) { zCount := qc.io.out.bits }
  // The reference encoder's pins delayed by the counter's latency: count and pins of one clock belong together;
  // both are then aligned with the datapath output like the ADC word (they lag the ADC sample instant by the
  // synchronizer and glitch filter, 2 + glitchFilter clocks, against the ADC's 7 + 1: explain fits the lag).
  private val refPins = ShiftRegister(Cat(encIn(2), encIn(1), encIn(0)), qc.latency + latency)
  private val sRef = ShiftRegister(qc.io.out.bits.asSInt, latency)

  private val livePos = RegInit(0.S(32.W))
  private val present = RegInit(false.B)
  private val dirUp = RegInit(true.B)
  private val pos32 = out.bits.position.pad(32)(31, 0).asSInt
  private val diff = pos32 - livePos
  private val dirNow = Mux(diff > 0.S, true.B, Mux(diff < 0.S, false.B, dirUp))
  when(out.valid) { livePos := pos32; present := out.bits.present; dirUp := dirNow }

  // ---- registers ----
  private val enable = RegInit(true.B)
  private val decimWidth = log2Ceil(Registers.MaxDecimation + 1)
  private val decim = RegInit(p.decimation.U(decimWidth.W))
  private val decCnt = RegInit(0.U(decimWidth.W))
  private val droppedTotal = RegInit(0.U(32.W))
  private val cmdErrors = RegInit(0.U(32.W))
  private def sticky(event: Bool): Bool = {
    val r = RegInit(false.B)
    r := (r && !clear) || event
    r
  }

  // ---- decimation and record FIFO ----
  private val burstBusy = Wire(Bool()) // a burst is being sent: continuous records pause
  private val take = out.valid && decCnt === 0.U && enable && !burstBusy
  when(out.valid) { decCnt := Mux(decCnt === 0.U, decim - 1.U, decCnt - 1.U) }
  private val record = Wire(new StreamRecord)
  record.index := sIndex
  record.position := pos32
  record.word.sin := sPins.sin; record.word.cos := sPins.cos
  record.word.otrSin := sPins.otrSin; record.word.otrCos := sPins.otrCos
  record.word.present := out.bits.present; record.word.overRange := out.bits.overRange
  record.word.stepFault := out.bits.stepFault; record.word.up := dirNow
  record.word.reserved := 0.U
  record.refCount := sRef
  private val fifo = Module(new OverflowFifo(StreamV1.RecordLayout.refWidth, p.fifoDepth))
  fifo.io.in.valid := take
  fifo.io.in.bits := record.asUInt
  when(fifo.io.dropped && droppedTotal =/= "hffffffff".U) { droppedTotal := droppedTotal + 1.U }
  private val fifoOverflow = sticky(fifo.io.dropped)
  private val otrSinSticky = sticky(sampleValid && otrS)
  private val otrCosSticky = sticky(sampleValid && otrC)

  // ---- burst capture: full-rate samples (ADC words, OTR, reference pins) into block RAM ----
  private val burst = Module(new BurstCapture(p.burst))
  private val lastSpeedPos = RegInit(0.S(32.W))
  private val speed = RegInit(0.S(32.W))
  private val speedCnt = RegInit(0.U(log2Ceil(Registers.SpeedWindow).W))
  when(out.valid) {
    speedCnt := speedCnt + 1.U
    when(speedCnt === (Registers.SpeedWindow - 1).U) { speed := pos32 - lastSpeedPos; lastSpeedPos := pos32 }
  }
  burst.io.in.valid := out.valid
  burst.io.in.bits.word := Cat(refPins, sPins.otrCos, sPins.otrSin, sPins.cos, sPins.sin)
  burst.io.in.bits.position := pos32
  burst.io.in.bits.refCount := sRef
  burst.io.in.bits.speed := speed
  burst.io.in.bits.index := sIndex
  private val burstCfg = RegInit(0.U.asTypeOf(new BurstConfig))
  private val burstArm = WireDefault(false.B)
  private val burstRead = WireDefault(false.B)
  burst.io.config := burstCfg
  burst.io.arm := burstArm
  burst.io.read := burstRead
  private val infoPending = RegInit(false.B)
  burstBusy := burst.io.sending || infoPending
  when(burstRead && burst.io.state === BurstState.Done.U && !burst.io.sending) { infoPending := true.B }

  // ---- UART ----
  private val tx = Module(new UartTx(p.baudDivisor))
  private val rx = Module(new UartRx(p.baudDivisor))
  private val framer = Module(new FrameTx(p.frameRecords, log2Ceil(p.fifoDepth + 1)))
  private val cmdRx = Module(new CommandRx)
  framer.io.records.valid := fifo.io.out.valid
  framer.io.records.bits := fifo.io.out.bits.asTypeOf(new StreamRecord)
  fifo.io.out.ready := framer.io.records.ready
  framer.io.recordCount := fifo.io.count
  framer.io.dropped := fifo.io.dropped
  framer.io.burstInfo.valid := infoPending
  framer.io.burstInfo.bits.length := burst.io.length
  framer.io.burstInfo.bits.pre := burst.io.pre
  framer.io.burstInfo.bits.trigger := burst.io.trigger
  framer.io.burstInfo.bits.last := burst.io.last
  when(framer.io.burstInfo.fire) { infoPending := false.B }
  framer.io.burstWords <> burst.io.out
  // a two-entry queue between the framer and the UART: registers on the byte, its valid and the ready back (the
  // framer's byte mux and the record and burst RAMs behind it no longer reach the UART's shift register)
  tx.io.in <> Queue(framer.io.out, 2)
  io.txd := tx.io.txd
  rx.io.rxd := Synchronizer(io.rxd, init = true, "uart_rxd")
  cmdRx.io.in := rx.io.out

  io.pins.ENC_A_OUT := RegNext(encA, false.B)
  io.pins.ENC_B_OUT := RegNext(encB, false.B)
  io.pins.ENC_Z_OUT := RegNext(encZ, false.B)

  // ---- register file ----
  private val statusFlags = Seq(StatusBit.Overspeed -> status.overspeed, StatusBit.OverRange -> status.overRange,
    StatusBit.StepFault -> status.stepFault, StatusBit.FifoOverflow -> fifoOverflow, StatusBit.OtrSin -> otrSinSticky,
    StatusBit.OtrCos -> otrCosSticky, StatusBit.Present -> present)
  private val statusWord = VecInit(Seq.tabulate(StatusBit.named.map(_._1).max + 1)(statusFlags.toMap.getOrElse(_, false.B))).asUInt
  private val adcFormatValue = if (p.adcFormat == AdcFormat.OffsetBinary) Registers.AdcOffsetBinary else Registers.AdcTwosComplement
  private def readable: Seq[(Int, UInt)] = Seq(
    Registers.Id -> Registers.IdValue.U(32.W), Registers.Version -> StreamV1.Version.U, Registers.Status -> statusWord,
    Registers.Control -> enable.asUInt, Registers.Decimation -> decim, Registers.DroppedTotal -> droppedTotal,
    Registers.CmdErrors -> cmdErrors, Registers.Position -> livePos.asUInt, Registers.AdcClockHz -> p.adcClockHz.U,
    Registers.FrameRecords -> p.frameRecords.U, Registers.CountsPerPeriod -> sp.counts.U,
    Registers.EncoderCount -> qc.io.out.bits, Registers.EncoderZCount -> zCount, Registers.AdcFormat -> adcFormatValue.U,
    Registers.BurstTrigger -> burstCfg.mode, Registers.BurstLength -> burstCfg.length, Registers.BurstPre -> burstCfg.pre,
    Registers.BurstThreshold -> burstCfg.threshold, Registers.BurstTarget -> burstCfg.target.asUInt,
    Registers.BurstState -> Cat(burst.io.sending || infoPending, burst.io.state), Registers.BurstDepth -> p.burst.samples.U
  ).map { case (r, v) => r.addr -> Cat(0.U(32.W), v)(31, 0) } ++
    harmonicKept.zipWithIndex.map { case (v, i) => (Registers.HarmonicBase + i) -> v } ++ adaptIndex
  private val cmd = cmdRx.io.cmd
  private val isWrite = cmd.valid && cmd.bits.write
  clear := isWrite && cmd.bits.addr === Registers.Control.addr.U && cmd.bits.value(ControlBit.Clear)
  when(isWrite && cmd.bits.addr === Registers.Control.addr.U) { enable := cmd.bits.value(ControlBit.Enable) }
  when(isWrite && cmd.bits.addr === Registers.Decimation.addr.U && cmd.bits.value >= 1.U &&
    cmd.bits.value <= Registers.MaxDecimation.U) {
    decim := cmd.bits.value; decCnt := 0.U
  }
  private def written(r: moire.protocol.Reg): Bool = isWrite && cmd.bits.addr === r.addr.U
  when(written(Registers.BurstTrigger)) { burstCfg.mode := cmd.bits.value(BurstLayout.Trigger.bits - 1, 0) }
  when(written(Registers.BurstLength)) { burstCfg.length := cmd.bits.value }
  when(written(Registers.BurstPre)) { burstCfg.pre := cmd.bits.value }
  when(written(Registers.BurstThreshold)) { burstCfg.threshold := cmd.bits.value }
  when(written(Registers.BurstTarget)) { burstCfg.target := cmd.bits.value.asSInt }
  burstArm := written(Registers.BurstControl) && cmd.bits.value(Registers.BurstControlBit.Arm)
  burstRead := written(Registers.BurstControl) && cmd.bits.value(Registers.BurstControlBit.Send)
  // harmonic coefficients (design compensated): written to the compensator, read back from a copy of what it kept
  private val hp = p.harmonicParams
  private val harmonicRegs = hp.harmonics * hp.regsPerSlot
  private val inHarmonic = cmd.bits.addr >= Registers.HarmonicBase.U && cmd.bits.addr < (Registers.HarmonicBase + harmonicRegs).U
  harmonicPort.we := isWrite && inHarmonic && (p.design == BoardDesign.Compensated).B
  harmonicPort.addr := (cmd.bits.addr - Registers.HarmonicBase.U)(hp.addrBits - 1, 0)
  harmonicPort.data := cmd.bits.value
  private val harmonicKept: Seq[UInt] = if (p.design != BoardDesign.Compensated) Nil else Seq.tabulate(harmonicRegs) { i =>
    val r = RegInit(0.U(32.W))
    val v = cmd.bits.value
    val kept = (i % hp.regsPerSlot) match {
      case 0 => v(hp.orderBits - 1, 0).pad(32)
      case 1 => v(hp.coefWidth - 1, 0).asSInt.pad(32).asUInt
      case 2 => v(hp.countBits - 1, 0).pad(32)
      case _ => 0.U(32.W)
    }
    when(harmonicPort.we && cmd.bits.addr === (Registers.HarmonicBase + i).U) { r := kept }
    r
  }
  // the adaptive corrector's read-back (design corrected): its values through a mux of their own, selected by the
  // command's address in the clock it arrives and registered (a value one clock older than the others'), which is one
  // entry of the register file's mux; the index register, written by commands, among the others (a write answers with it)
  private val none = (Seq.empty[(Int, UInt)], Seq.empty[(Bool, UInt)])
  private val (adaptIndex, adaptWord): (Seq[(Int, UInt)], Seq[(Bool, UInt)]) = adapt.fold(none) { case (rb, pr) =>
    import moire.protocol.AdaptRegisters._
    val ap = p.correctedParams.adapt
    val index = RegInit(0.U(rb.tableIndex.getWidth.W))
    when(written(TableIndex)) { index := cmd.bits.value(rb.tableIndex.getWidth - 1, 0) }
    rb.tableIndex := index
    // the preset port: hold kept, the strobes a clock long, the presets kept in their widths; the presets are write-only
    // (read 0: no entry in any read mux; board-reg --load checks what they loaded through the read-back)
    val hold = RegInit(false.B)
    when(written(Control)) { hold := cmd.bits.value(AdaptBit.Hold) }
    pr.hold := hold
    pr.load := RegNext(written(Control) && cmd.bits.value(AdaptBit.Load), false.B)
    pr.tableWrite := RegNext(written(Control) && cmd.bits.value(AdaptBit.TableWrite), false.B)
    pr.pair := (index >> 1).pad(pr.pair.getWidth)
    // the presets take a registered copy of the command (a clock later): the command's registers get one load each
    val late = RegNext(isWrite, false.B)
    val lateAddr = RegNext(cmd.bits.addr)
    val presets = Seq(PresetOffsetSin -> pr.offsetSin, PresetOffsetCos -> pr.offsetCos, PresetGainSin -> pr.gainSin,
      PresetGainCos -> pr.gainCos, PresetPhase -> pr.phase, PresetTableSum -> pr.tableSum, PresetEven -> pr.even, PresetOdd -> pr.odd)
    val lateValue = RegNext(cmd.bits.value(presets.map(_._2.getWidth).max - 1, 0)) // only the bits a preset keeps
    def kept(r: moire.protocol.Reg, port: SInt): Unit = {
      val v = RegInit(0.S(port.getWidth.W))
      when(late && lateAddr === r.addr.U) { v := lateValue(port.getWidth - 1, 0).asSInt }
      port := v
    }
    presets.foreach { case (r, port) => kept(r, port) }
    val l = rb.learned
    def word(v: SInt): UInt = v.pad(32).asUInt
    val values = Seq(OffsetSin -> word(l.offsetSin), OffsetCos -> word(l.offsetCos),
      GainSin -> word(l.gainSin), GainCos -> word(l.gainCos),
      Phase -> word(l.phase),
      Updates -> l.updates,
      Locked -> Cat(0.U(31.W), l.locked),
      TableSum -> word(l.tableSum),
      TableData -> word(l.tableData),
      Format -> moire.adapt.AdaptLearned.format(ap).U(32.W),
      Size -> moire.adapt.AdaptLearned.size(ap).U(32.W))
    val hits = values.map { case (r, _) => cmd.bits.addr === r.addr.U }
    (Seq(TableIndex.addr -> index.pad(32), Control.addr -> Cat(0.U(31.W), hold)), Seq((VecInit(hits).asUInt.orR, RegNext(Mux1H(hits, values.map(_._2))))))
  }
  // The reply reads the register one clock later, so a write answers with the new value. The address is decoded
  // to one select per register beside the command and the selected value registered: a reply takes 2 clocks.
  private val replies = Module(new Queue(new RegReply, 4))
  private val regs = readable
  require(regs.map(_._1).distinct.size == regs.size, "two readable registers share an address")
  private val readSel = RegNext(VecInit(regs.map { case (a, _) => cmd.bits.addr === a.U } ++ adaptWord.map(_._1)))
  private val replyAddr = ShiftRegister(cmd.bits.addr, 2)
  replies.io.enq.valid := ShiftRegister(cmd.valid, 2, false.B, true.B)
  replies.io.enq.bits.addr := replyAddr
  replies.io.enq.bits.value := RegNext(Mux1H(readSel, regs.map(_._2) ++ adaptWord.map(_._2)))
  framer.io.reply <> replies.io.deq
  private val lostReply = replies.io.enq.valid && !replies.io.enq.ready
  when(cmdRx.io.error || lostReply) { cmdErrors := cmdErrors + 1.U }

  // ---- status for the harness's LEDs and displays ----
  private val beat = RegInit(0.U(25.W))
  beat := beat + 1.U
  io.status.present := present
  io.status.overRange := status.overRange || otrSinSticky || otrCosSticky
  io.status.dirUp := dirUp
  io.status.fifoOverflow := fifoOverflow
  io.status.overspeed := status.overspeed
  io.status.stepFault := status.stepFault
  io.status.enabled := enable
  io.status.cmdError := cmdErrors =/= 0.U
  io.status.heartbeat := beat(24)
  io.status.position := livePos.asUInt
}
