package moire.subdiv

import chisel3._
import chiseltest._
import moire.cordic.{Rounding, SimSupport}
import moire.signal.{Adc, AdcFormat}
import org.scalatest.flatspec.AnyFlatSpec

/** RTL (ADC front end + subdivider) against the model, bit for bit and clock for clock. */
class SubdivRtlSpec extends AnyFlatSpec with ChiselScalatestTester {
  import PhaseMethod._
  val configs: Seq[(SubdivParams, AdcFormat)] = Seq(
    SubdivParams(12, Atan2, counts = 4, backlogLimit = 4) -> AdcFormat.OffsetBinary,
    SubdivParams(10, Atan2, counts = 256, minEdgeClocks = 3, backlogLimit = 16) -> AdcFormat.TwosComplement,
    SubdivParams(14, Atan2, counts = 4096, iterations = 18, positionWidth = 24) -> AdcFormat.OffsetBinary,
    SubdivParams(12, Atan2, counts = 65536, minEdgeClocks = 2, rounding = Rounding.Truncate, guardBits = 0) -> AdcFormat.TwosComplement,
    SubdivParams(12, AsinDouble, counts = 4, iterations = 12) -> AdcFormat.TwosComplement,
    SubdivParams(14, AsinDouble, counts = 256, minEdgeClocks = 2, asinAmplitude = 0.7, presentThreshold = 0.2) -> AdcFormat.OffsetBinary,
    SubdivParams(10, AsinDouble, counts = 4096, iterations = 14, rounding = Rounding.Truncate) -> AdcFormat.OffsetBinary,
    SubdivParams(12, AsinDouble, counts = 65536, positionWidth = 40, backlogLimit = 1000) -> AdcFormat.TwosComplement)
  /** Stimulus length factor. */
  val scale: Int = 4
  /** The fallback simulator is far slower: there, 3 configurations and the first 300 clocks of each. */
  val full: Boolean = SimSupport.hasVerilator
  val run: Seq[(SubdivParams, AdcFormat)] = if (full) configs else Seq(configs(1), configs(3), configs(5))

  s"Subdivider RTL" should s"equal the model every clock over ${run.size} configurations (${SimSupport.backendName})" in {
    val configs = run
    val stims = configs.zipWithIndex.map { case ((p, f), k) =>
      val all = SubdivStimulus.cycles(Adc(p.inputBits, f), scale, 11L + k)
      if (full) all else all.take(300)
    }
    val models = configs.map(c => new SubdivModel(c._1))
    val adcs = configs.map(c => Adc(c._1.inputBits, c._2))
    val prev = Array.fill[Option[SubdivSample]](configs.size)(None)
    val prevClear = Array.fill(configs.size)(false)
    var checked = 0
    val seen = scala.collection.mutable.Set[String]()
    test(new SubdivBank(configs)).withAnnotations(SimSupport.backend) { dut =>
      assert(dut.latencies.zip(configs).forall { case (l, c) => l == SubdivAdc.latency(c._1) })
      val cycles = stims.map(_.size).max + dut.latencies.max + 40
      for (t <- 0 until cycles; k <- configs.indices) {
        val st = stims(k)
        val c = if (t < st.size) st(t) else PinCycle(None, false)
        val io = dut.io
        io.in(k).valid.poke(c.in.isDefined.B)
        val s = c.in.getOrElse(AdcSample2(0, 0, false, false))
        io.in(k).bits.sin.poke(s.sin.U); io.in(k).bits.cos.poke(s.cos.U)
        io.in(k).bits.otrSin.poke(s.otrSin.B); io.in(k).bits.otrCos.poke(s.otrCos.B)
        io.clear(k).poke(prevClear(k).B) // the front end delays the data by one clock; delay clear too
        // The subdivider sees the front end's register: last cycle's pins.
        val e = models(k).clock(prev(k), prevClear(k))
        prev(k) = c.in.map(x => SubdivSample(adcs(k).fromPins(x.sin), adcs(k).fromPins(x.cos), x.otrSin, x.otrCos))
        prevClear(k) = c.clear
        val name = s"${configs(k)._1.moduleName} cycle $t"
        val o = io.out(k)
        assert(o.valid.peekBoolean() == e.valid, s"$name valid")
        if (e.valid) {
          val got = SubdivResult(o.bits.position.peekInt().toLong, o.bits.periods.peekInt().toLong, o.bits.m.peekInt().toLong,
            o.bits.phase.peekInt().toLong, o.bits.present.peekBoolean(), o.bits.overRange.peekBoolean(), o.bits.stepFault.peekBoolean())
          assert(got == e.out, s"$name: rtl $got, model ${e.out}")
          checked += 1
          if (e.out.stepFault) seen += "stepFault"
          if (!e.out.present) seen += "absent"
          if (e.out.overRange) seen += "overRange"
          if (e.out.periods < -1) seen += "periods<-1"
          if (e.out.periods > 1) seen += "periods>1"
        }
        val st2 = io.status(k)
        val gotCycle = (io.a(k).peekBoolean(), io.b(k).peekBoolean(), io.z(k).peekBoolean(), st2.backlog.peekInt().toLong,
          st2.overspeed.peekBoolean(), st2.stepFault.peekBoolean(), st2.signalLost.peekBoolean(), st2.overRange.peekBoolean())
        val exp = (e.a, e.b, e.z, e.backlog, e.overspeed, e.stepFault, e.signalLost, e.overRange)
        assert(gotCycle == exp, s"$name (a, b, z, backlog, overspeed, stepFault, signalLost, overRange): rtl $gotCycle, model $exp")
        if (e.overspeed) seen += "overspeed"
        if (e.backlog != 0) seen += "backlog"
        if (e.z) seen += "z"
        if (prevClear(k) && e.signalLost) seen += "clearWhileSet"
        if (k == configs.size - 1) dut.clock.step()
      }
    }
    assert(checked > configs.size * (if (full) 2500 else 250))
    // The stimulus reaches every flag and both directions of the period counter.
    if (full) assert(seen == Set("stepFault", "absent", "overRange", "periods<-1", "periods>1", "overspeed", "backlog", "z", "clearWhileSet"), seen)
  }
}
