package moire.cordic

import chisel3._
import chiseltest._
import org.scalatest.flatspec.AnyFlatSpec

/** The tapered sincos (CordicParams.taper): RTL equal to the model, the model equal to the untapered one,
  * the narrowed words sized from the proven ranges.
  */
class CordicTaperSpec extends AnyFlatSpec with ChiselScalatestTester {
  val sweep: Seq[CordicParams] = Seq(
    CordicParams(iterations = 16, width = 20, taper = true),
    CordicParams(iterations = 17, width = 20, guardBits = 2, taper = true),
    CordicParams(iterations = 12, width = 16, rounding = Rounding.Truncate, taper = true),
    CordicParams(iterations = 8, width = 12, guardBits = 1, angleGuardBits = 0, taper = true),
    CordicParams(iterations = 20, width = 24, angleWidth = 18, guardBits = 3, taper = true),
    CordicParams(iterations = 4, width = 10, taper = true),
    CordicParams(iterations = 5, width = 9, taper = true, fracBits = 8), // no integer bit: saturates
    CordicParams(iterations = 14, width = 16, gainCompensation = false, angleWidth = 20, taper = true),
    CordicParams(iterations = 24, width = 32, rounding = Rounding.Truncate, guardBits = 4, taper = true))

  "The tapered model" should "give the untapered model's results bit for bit" in {
    for (p <- sweep) {
      val lean = new CordicModel(p); val plain = new CordicModel(p.copy(taper = false))
      val ins = CordicAccuracy.inputs(p)
      for (in <- ins) assert(lean(in) == plain(in), s"${p.moduleName} at $in")
      info(s"${p.moduleName}: ${ins.size} angles")
    }
  }

  it should "stay within the error bound against double precision" in {
    for (p <- sweep) {
      val m = CordicAccuracy.measure(p)
      assert(m.ok, s"${p.moduleName}: ${m.maxError} vs ${m.bound}, ${m.violations} violations")
    }
  }

  "The z ranges" should "shrink with the iterations and hold every residual the model meets" in {
    val p = CordicParams(iterations = 17, width = 20, guardBits = 2, taper = true)
    val widths = p.zRanges.map { case (lo, hi) => p.signedBits(lo, hi) }
    info(s"z widths after iterations 0 .. 16: ${widths.mkString(" ")} (untapered: ${p.zWidth})")
    assert(widths.head == p.zWidth - 2)
    assert(widths.zip(widths.tail).forall { case (a, b) => b <= a })
    assert(widths.last < p.zWidth / 2, "the residual after 16 iterations needs far fewer bits than the input angle")
    // the model throws when a residual leaves its range: every 20-bit angle
    val model = new CordicModel(p)
    for (z <- Fixed.minOf(p.angleBits) to Fixed.maxOf(p.angleBits) by 7) model(CordicWord(0, 0, z))
  }

  "Taper" should "be refused for other modes and for pipeline-every > 1" in {
    val e = intercept[IllegalArgumentException](CordicParams(CordicMode.Atan2, taper = true))
    assert(e.getMessage.contains("taper applies to sincos only"))
    val k = intercept[IllegalArgumentException](CordicParams(pipelineEvery = 2, taper = true))
    assert(k.getMessage.contains("pipeline-every 1"))
    assert(CordicParams(taper = true).moduleName.endsWith("_taper"))
    assert(CordicParams(iterations = 17, taper = true).latency == 17)
  }

  "The tapered RTL" should s"equal the model bit for bit over the sweep (${SimSupport.backendName})" in {
    val count = if (SimSupport.hasVerilator) 400 else 60
    val models = sweep.map(new CordicModel(_))
    val vecs = sweep.map { p =>
      val all = CordicAccuracy.inputs(p, seed = p.hashCode)
      val rnd = new scala.util.Random(p.hashCode)
      val q = 1L << (p.angleBits - 2)
      val edges = Seq(0L, 1L, -1L, q, q - 1, q + 1, -q, -q - 1, -q + 1, 2 * q - 1, -2 * q, q / 2, -q / 2, q / 2 - 1)
      edges.map(z => CordicWord(0, 0, Fixed.wrap(z, p.angleBits))) ++ Seq.fill(count)(all(rnd.nextInt(all.size)))
    }
    test(new CordicBank(sweep)).withAnnotations(SimSupport.backend) { dut =>
      val lat = dut.latencies
      assert(lat == sweep.map(_.latency))
      for (t <- 0 until vecs.map(_.size).max + lat.max + 1) {
        for (k <- sweep.indices) {
          val live = t < vecs(k).size
          dut.io.in(k).valid.poke(live.B)
          dut.io.in(k).bits.x.poke(0.S); dut.io.in(k).bits.y.poke(0.S)
          dut.io.in(k).bits.z.poke((if (live) vecs(k)(t).z else 0L).S)
        }
        for (k <- sweep.indices) {
          val src = t - lat(k)
          val valid = src >= 0 && src < vecs(k).size
          dut.io.out(k).valid.expect(valid.B, s"${sweep(k).moduleName} valid at cycle $t")
          if (valid) {
            val e = models(k)(vecs(k)(src)); val o = dut.io.out(k).bits
            val got = CordicWord(o.x.peekInt().toLong, o.y.peekInt().toLong, o.z.peekInt().toLong)
            assert(got == e, s"${sweep(k).moduleName} input ${vecs(k)(src)}: rtl $got, model $e")
          }
        }
        dut.clock.step()
      }
    }
  }
}
