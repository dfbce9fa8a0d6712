package moire.cordic

import chisel3._
import chiseltest._
import org.scalatest.flatspec.AnyFlatSpec

/** RTL against the bit-accurate model, bit for bit, over the n x b sweep for every mode. */
class CordicRtlSpec extends AnyFlatSpec with ChiselScalatestTester {
  val ns = Seq(8, 12, 16, 20, 24)
  val bs = Seq(12, 16, 18, 24, 32)
  /** Random vectors per configuration (besides the edges): fewer on the slow fallback simulator. */
  val count: Int = if (SimSupport.hasVerilator) 300 else 40

  /** Edge vectors (zero, full scale, quadrant boundaries, arcsine peak) and random ones. */
  def vectors(p: CordicParams, count: Int): Seq[CordicWord] = {
    val all = CordicAccuracy.inputs(p, seed = p.hashCode)
    val rnd = new scala.util.Random(p.hashCode)
    val one = 1L << p.dataFrac
    val sin83 = math.ceil(math.sin(math.toRadians(83)) * one).toLong
    val q = 1L << (p.angleBits - 2)
    val fs = Fixed.maxOf(p.width); val lo = Fixed.minOf(p.width)
    val edges = Seq(
      CordicWord(0, 0, 0), CordicWord(fs, 0, q), CordicWord(lo, lo, -q), CordicWord(0, fs, Fixed.minOf(p.angleBits)),
      CordicWord(fs / 2, fs / 2, 2 * q - 1), CordicWord(0, one, q - 1), CordicWord(0, -one, -q + 1),
      CordicWord(0, sin83, q + 1), CordicWord(0, one - 1, -q - 1), CordicWord(lo, fs, 1), CordicWord(fs, lo, -1))
      .filter(w => p.mode != CordicMode.Rotate || math.hypot(w.x.toDouble, w.y.toDouble) < math.pow(2, p.width - 1) / p.gain)
    def sat(w: CordicWord) = CordicWord(Fixed.saturate(w.x, p.width), Fixed.saturate(w.y, p.width), Fixed.wrap(w.z, p.angleBits))
    edges.map(sat) ++ Seq.fill(count)(all(rnd.nextInt(all.size)))
  }

  def check(ps: Seq[CordicParams], count: Int): Unit = {
    val models = ps.map(new CordicModel(_))
    val vecs = ps.map(vectors(_, count))
    test(new CordicBank(ps)).withAnnotations(SimSupport.backend) { dut =>
      val lat = dut.latencies
      val cycles = vecs.map(_.size).max + lat.max + 1
      for (t <- 0 until cycles) {
        for (k <- ps.indices) {
          val v = vecs(k)
          val live = t < v.size
          dut.io.in(k).valid.poke(live.B)
          val w = if (live) v(t) else CordicWord(0, 0, 0)
          dut.io.in(k).bits.x.poke(w.x.S)
          dut.io.in(k).bits.y.poke(w.y.S)
          dut.io.in(k).bits.z.poke(w.z.S)
        }
        for (k <- ps.indices) {
          val src = t - lat(k)
          val expectValid = src >= 0 && src < vecs(k).size
          dut.io.out(k).valid.expect(expectValid.B, s"${ps(k).moduleName} valid at cycle $t")
          if (expectValid) {
            val e = models(k)(vecs(k)(src))
            val o = dut.io.out(k).bits
            val got = CordicWord(o.x.peekInt().toLong, o.y.peekInt().toLong, o.z.peekInt().toLong)
            assert(got == e, s"${ps(k).moduleName} input ${vecs(k)(src)}: rtl $got, model $e")
          }
        }
        dut.clock.step()
      }
    }
  }

  for (mode <- CordicMode.all) {
    s"${mode.name} RTL" should s"equal the model bit for bit for n in $ns x b in $bs (${SimSupport.backendName})" in {
      check(for (n <- ns; b <- bs) yield CordicParams(mode = mode, iterations = n, width = b), count)
    }
  }

  "Variants" should "equal the model: truncation, no gain compensation, guard bits, k = 3, peak tables" in {
    val variants = Seq(
      CordicParams(CordicMode.SinCos, 14, 16, rounding = Rounding.Truncate, pipelineEvery = 3),
      CordicParams(CordicMode.SinCos, 12, 16, gainCompensation = false, angleWidth = 20, angleGuardBits = 0),
      CordicParams(CordicMode.Rotate, 16, 18, gainCompensation = false, guardBits = 2),
      CordicParams(CordicMode.Rotate, 10, 14, rounding = Rounding.Truncate, pipelineEvery = 4, fracBits = 11),
      CordicParams(CordicMode.Atan2, 16, 18, gainCompensation = false, pipelineEvery = 2),
      CordicParams(CordicMode.Atan2, 20, 24, rounding = Rounding.Truncate, guardBits = 3, angleWidth = 28),
      CordicParams(CordicMode.AsinDouble, 16, 18, peakTableSize = 64),
      CordicParams(CordicMode.AcosDouble, 15, 16, peakTableSize = 8, rounding = Rounding.Truncate),
      CordicParams(CordicMode.Asin, 12, 14, peakTableSize = 16, pipelineEvery = 5),
      CordicParams(CordicMode.AsinDouble, 24, 32, peakTableSize = 1024, guardBits = 4),
      CordicParams(CordicMode.Acos, 9, 12, peakTableSize = 2, fracBits = 11),
      // one entry, one register group: the table read sits between the input stage and the last iteration's
      CordicParams(CordicMode.AcosDouble, 10, 12, peakTableSize = 1, pipelineEvery = 10),
      // Shifts of 2i >= 64 bits (n = 34): once wrong in the model, where JVM shifts wrap mod 64.
      CordicParams(CordicMode.AsinDouble, 34, 31, fracBits = 28, pipelineEvery = 2, rounding = Rounding.Truncate),
      CordicParams(CordicMode.AcosDouble, 40, 48, guardBits = 4))
    check(variants, count)
  }
}
