package moire.subdiv

import moire.signal._
import org.scalatest.flatspec.AnyFlatSpec

final case class Decoded(count: Long, edges: Int, minSpacing: Int, zRises: Int, zWrong: Int, overspeed: Boolean,
                         maxBacklog: Long, position: Long)

/** The A/B/Z output of the (clock-exact) model, decoded as an encoder counter would. */
class SubdivPulseSpec extends AnyFlatSpec {
  /** Streams samples (one per clock) then `tail` idle clocks; decodes A/B with a x4 quadrature decoder. */
  def decode(p: SubdivParams, s: Samples, tail: Int): Decoded = {
    val m = new SubdivModel(p)
    var started = false; var count = 0L; var base = 0L
    var lastAB = (false, false); var lastZ = false; var lastEdge = -1000000
    var edges = 0; var minSp = Int.MaxValue; var zr = 0; var zw = 0; var maxB = 0L; var pos = 0L; var ovs = false
    val gray = Map((false, false) -> 0, (true, false) -> 1, (true, true) -> 2, (false, true) -> 3)
    for (t <- 0 until s.length + tail) {
      val in = if (t < s.length) Some(SubdivSample(s.sinSigned(t), s.cosSigned(t))) else None
      val c = m.clock(in)
      if (c.valid) pos = c.out.position
      if (c.valid && !started) { started = true; base = c.out.position }
      val ab = (c.a, c.b)
      if (started && ab != lastAB && t > p.latency + 1) {
        val step = ((gray(ab) - gray(lastAB)) % 4 + 4) % 4
        assert(step == 1 || step == 3, s"A and B changed together at clock $t")
        count += (if (step == 1) 1 else -1)
        edges += 1; minSp = math.min(minSp, t - lastEdge); lastEdge = t
      }
      if (c.z && !lastZ) zr += 1
      if (started && t > p.latency + 1 && c.z != (Math.floorMod(base + count, p.counts.toLong) == 0)) zw += 1
      lastAB = ab; lastZ = c.z
      maxB = math.max(maxB, math.abs(c.backlog)); ovs = ovs || c.overspeed
    }
    Decoded(count, edges, minSp, zr, zw, ovs, maxB, pos - base)
  }

  "A/B/Z" should "follow slow reversing motion: one edge per count, edges spaced, Z once per period at m = 0" in {
    val p = SubdivParams(counts = 64, minEdgeClocks = 3)
    // 2.5 periods peak at 2 kHz: at most 2.5 * 2 pi * 2e3 * 64 = 2 counts per microsecond, well inside 1 per 3 clocks.
    val s = SignalSim.generate(SignalParams(amplitude = 0.9), Motion.Oscillate(2.5, 2e3, start = 0.01), Adc(12), 50e6, 40000)
    val d = decode(p, s, 200)
    assert(d.count == d.position, d)
    assert(d.minSpacing >= 3 && d.edges >= 300, d)
    assert(d.zWrong == 0 && d.zRises >= 2, d)
    assert(!d.overspeed, d)
  }

  "A/B/Z" should "flag overspeed when motion outruns the edge spacing, then catch up without dropping a count" in {
    val p = SubdivParams(counts = 4096, minEdgeClocks = 2, backlogLimit = 100)
    // 0.05 fs = 205 counts per clock against 0.5 the output can show; then the motion stops.
    val s = SignalSim.generate(SignalParams(amplitude = 0.9), Motion.Ramp(0.05 * 50e6, 0.0, 20e-6), Adc(12), 50e6, 1500)
    val d = decode(p, s, 700000)
    assert(d.overspeed && d.maxBacklog > 100000, d)
    assert(d.count == d.position, d) // every count came out in the end
    assert(d.minSpacing >= 2, d)
  }

  "The pulse generator" should "start at the first position without emitting the start-up offset as edges" in {
    val p = SubdivParams(counts = 256)
    val s = SignalSim.generate(SignalParams(amplitude = 0.9), Motion.Constant(0.0, 0.6), Adc(12), 50e6, 200)
    val d = decode(p, s, 50)
    assert(d.edges <= 4 && math.abs(d.count) <= 1, d)
  }
}
