package moire.board

import chiseltest._
import moire.adapt.{AdaptLearned, AdaptParams}
import moire.chain.{AdcPinCodes, CorrectedSubdivModel, CorrectedSubdivParams}
import moire.cordic.SimSupport
import moire.protocol.AdaptRegisters
import moire.signal.{Adc, AdcFormat, Harmonic, SignalParams, SignalSim}
import org.scalatest.flatspec.AnyFlatSpec

/** The adaptive corrector's learned values read by register from the whole DE2-115 top (design corrected): the
  * corrector learns on an imperfect simulated signal, the motion stops (no window closes, the table stops adapting),
  * then every read-back register and every table entry is read over the UART and compared bit for bit with the
  * clock-accurate model fed the same samples; the decoded values match the simulated imperfections.
  */
class BoardCorrectedReadBackSpec extends AnyFlatSpec with ChiselScalatestTester {
  /** Fast loops (as in AdaptRtlSpec), so that everything moves within a short simulation. */
  val adapt = AdaptParams(offsetRate = 1, gainRate = 1, phaseRate = 2, windowBits = 6, harmonicRate = 3,
    pllKp = 4, pllKv = 9, pllKf = 6, lockBits = 4, minSpeedShift = 8, lockShift = 3)
  val p = BoardParams(design = BoardDesign.Corrected, corrected = CorrectedSubdivParams(adapt = adapt), adcClockHz = 25000000, baud = 12500000,
    frameRecords = 4, fifoDepth = 8, decimation = 1 << 24, clockSource = ClockSource.Logic, burstSamples = 256)
  val signal = SignalParams(amplitude = 0.85, offsetSin = 0.03, offsetCos = -0.01, gainCos = 0.95, phaseErrorDeg = -4,
    harmonics = Seq(Harmonic(2, 0.02), Harmonic(3, 0.01, 30)))
  /** 400 kHz fringes (62.5 samples a period at 25 MHz) for `moving` samples, then standing still mid-quadrant. */
  val moving = 40000
  val fringeHz = 400e3
  def periods(i: Int): Double = fringeHz * i / p.adcClockHz

  "The corrected DE2-115 top" should "show the corrector's learned values by register, bit for bit as its model" in {
    test(new BoardHarness(p)).withAnnotations(SimSupport.backend) { c =>
      c.clock.setTimeout(0)
      val stop = periods(moving)
      val still = math.floor(stop) + 0.125 // the last stretch jumps to 45 degrees: away from every quadrant edge
      val adc = new Ad9226Model(Adc(12, p.adcFormat), i => {
        val ph = if (i < moving) periods(i) else still
        val (s, co) = SignalSim.analog(signal, ph)
        AnalogSample(s, co, ph)
      })
      val b = new BoardBench(c, adc)
      b.reset()
      b.runUntil(p.adcDivide * (moving + 20000L), "the motion to stop and settle")(adc.edges >= moving + 12000)
      import AdaptRegisters._
      val ap = p.correctedParams.adapt
      val (format, size) = (b.read(Format.addr), b.read(Size.addr))
      assert(format == AdaptLearned.format(ap) && size == AdaptLearned.size(ap))
      val words = learned.map(r => r -> b.read(r.addr)).toMap
      val table = (0 until ap.harmonicEntries).map { i => assert(b.write(TableIndex.addr, i) == i); b.read(TableData.addr) }
      val n = adc.edges
      // the model, fed every sample the board took as the board does: one every adcDivide clocks (the board's ADC clock
      // drives the AD9226 model, so the board's sample 0 is the model's)
      val model = new CorrectedSubdivModel(p.correctedParams)
      for (i <- 0 until n) {
        val s = adc.sample(i)
        model.clock(valid = true, AdcPinCodes(s.sin, s.cos, s.otrSin, s.otrCos))
        for (_ <- 1 until p.adcDivide) model.clock(valid = false, AdcPinCodes(0, 0))
      }
      val want = model.adapt.learned
      for ((r, v) <- want.words) assert(words(r) == v, s"${r.name}: board 0x${words(r).toHexString}, model 0x${v.toHexString}")
      for (((got, v), i) <- table.zip(want.tableWords).zipWithIndex) assert(got == v, s"table entry $i: board 0x${got.toHexString}, model 0x${v.toHexString}")
      // the board learned (the comparison above checks something) and the readout is the simulated signal's
      assert(want.updates > 20 && want.locked && want.table.count(_ != 0) > ap.harmonicEntries / 2, s"learned too little: $want")
      val layout = Layout.of(format, size).toOption.flatten.get
      val ro = readout(layout, words, table)
      val fs = 2048.0
      info(f"offsets ${ro.offsetSinCodes}%.2f, ${ro.offsetCosCodes}%.2f codes; amplitudes ${ro.amplitudeSinCodes}%.1f, " +
        f"${ro.amplitudeCosCodes}%.1f codes, ratio ${ro.ratio}%.4f; phase ${ro.phaseErrorDeg}%.3f deg; table ${ro.tableDeg.min}%.4f..${ro.tableDeg.max}%.4f deg; " +
        s"${want.updates} updates, $n samples, ${b.cycle} clocks (${SimSupport.backendName})")
      assert(math.abs(ro.offsetSinCodes - signal.offsetSin * fs) < 2 && math.abs(ro.offsetCosCodes - signal.offsetCos * fs) < 2)
      assert(math.abs(ro.amplitudeSinCodes / (signal.amplitude * fs) - 1) < 0.01)
      assert(math.abs(ro.ratio - 1 / signal.gainCos) < 0.005)
      assert(math.abs(ro.phaseErrorDeg - signal.phaseErrorDeg) < 0.2)
      // read-only: a write is ignored (the reply shows the value kept); the index keeps its low bits only
      assert(b.write(OffsetSin.addr, 5) == words(OffsetSin))
      assert(b.write(TableIndex.addr, ap.harmonicEntries + 3) == 3)
    }
  }
}
