package moire.cordic

import chisel3._
import chiseltest._
import org.scalacheck.Gen
import org.scalacheck.rng.Seed
import org.scalatest.flatspec.AnyFlatSpec
import scala.util.Try

/** Random legal parameters: the model stays within its bound, and the RTL equals the model. */
class CordicPropertySpec extends AnyFlatSpec with ChiselScalatestTester {
  /** Any parameter set the params class accepts (illegal draws are dropped). */
  val params: Gen[Option[CordicParams]] = for {
    mode <- Gen.oneOf(CordicMode.all)
    n <- Gen.choose(4, 40)
    b <- Gen.choose(8, 48)
    fracDrop <- Gen.choose(1, 3)
    guard <- Gen.choose(0, 4)
    k <- Gen.choose(1, 4)
    rounding <- Gen.oneOf(Rounding.all)
    gc <- Gen.oneOf(true, false)
    table <- if (mode.isAsin) Gen.oneOf(0, 4, 32, 256) else Gen.const(0)
  } yield Try(CordicParams(mode, n, b, fracBits = b - fracDrop, guardBits = guard, pipelineEvery = math.min(k, n),
    rounding = rounding, gainCompensation = gc, peakTableSize = table)).toOption

  /** A fixed seed keeps CI repeatable; MOIRE_SEED=<n> MOIRE_CASES=<n> explores further. */
  val seed: Long = sys.env.get("MOIRE_SEED").map(_.toLong).getOrElse(20261121L)
  val cases: Int = sys.env.get("MOIRE_CASES").map(_.toInt).getOrElse(60)
  def draw(count: Int, salt: Long): Seq[CordicParams] =
    Iterator.iterate(Seed(seed + salt))(_.next).flatMap(s => params(Gen.Parameters.default, s).flatten).take(count).toSeq

  "Random legal params" should "keep the model within its error bound" in {
    info(s"seed $seed, $cases cases")
    for (p <- draw(cases, 0)) {
      val ins = CordicAccuracy.inputs(p, seed = p.hashCode)
      val sample = new scala.util.Random(p.hashCode).shuffle(ins).take(3000)
      val m = CordicAccuracy.measure(p, sample)
      assert(m.violations == 0 && m.maxError <= m.bound, s"${p.moduleName}: ${m.maxError} vs bound ${m.bound}")
    }
  }

  it should "give RTL equal to the model (treadle)" in {
    for (p <- draw(math.max(4, cases / 8), 1)) {
      val model = new CordicModel(p)
      val ins = new scala.util.Random(p.hashCode).shuffle(CordicAccuracy.inputs(p, seed = p.hashCode)).take(40)
      test(new Cordic(p)) { dut =>
        val lat = dut.latency
        for (t <- 0 until ins.size + lat) {
          if (t < ins.size) {
            dut.io.in.valid.poke(true.B)
            dut.io.in.bits.x.poke(ins(t).x.S); dut.io.in.bits.y.poke(ins(t).y.S); dut.io.in.bits.z.poke(ins(t).z.S)
          } else dut.io.in.valid.poke(false.B)
          if (t >= lat) {
            val e = model(ins(t - lat))
            dut.io.out.valid.expect(true.B)
            val got = CordicWord(dut.io.out.bits.x.peekInt().toLong, dut.io.out.bits.y.peekInt().toLong, dut.io.out.bits.z.peekInt().toLong)
            assert(got == e, s"${p.moduleName} at ${ins(t - lat)}: rtl $got, model $e")
          } else dut.io.out.valid.expect(false.B)
          dut.clock.step()
        }
      }
    }
  }
}
