package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

import scala.util.Random

/** The false-finding sweep of issue 12: clean recordings of the independent generator (default model only) across
  * lengths (one fringe period to 10^6 samples), speeds, reversals, noise levels and 8/10/12/14 bits. explain may
  * name an effect in at most one of them.
  */
class FalseFindingSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport.describe

  /** 64 short and middle recordings and one of 10^6 samples. */
  def sweep: Seq[FringeGenerator.Spec] = {
    val rnd = new Random(12)
    val lengths = Seq(1000, 3000, 8000, 20000, 40000)
    val motions = Seq("constant", "chirp", "reverse", "uneven")
    val short = (0 until 64).map { k =>
      val n = lengths(k % lengths.size); val fs = Seq(1e6, 2e6, 10e6)(k % 3)
      val motion = motions((k / 5) % 4)
      // the first of each group holds about one fringe period
      val f0 = if (k % 10 == 0) fs / n else fs / (20 + 200 * rnd.nextDouble())
      FringeGenerator.Spec(n = n, fs = fs, motion = motion, f0 = f0, f1 = f0 * (1.5 + 3 * rnd.nextDouble()),
        travel = 3 + n * f0 / fs * rnd.nextDouble(), rateHz = fs / n * (1 + 3 * rnd.nextDouble()), wobble = 0.3 + 1.2 * rnd.nextDouble(),
        amp = 0.5 + 0.4 * rnd.nextDouble(), offS = 0.02 * rnd.nextGaussian(), offC = 0.02 * rnd.nextGaussian(),
        gainC = 1 + 0.03 * rnd.nextGaussian(), phaseErrDeg = 3 * rnd.nextGaussian(), noiseLsb = Seq(0.5, 1.0, 2.0, 4.0)(k % 4),
        bits = Seq(8, 10, 12, 14)((k / 4) % 4), seed = 1000 + k)
    }
    short :+ FringeGenerator.Spec(n = 1000000, fs = 10e6, motion = "uneven", f0 = 150e3, wobble = 0.8, bits = 12, noiseLsb = 1.0, seed = 99)
  }

  "explain" should "name no effect in at least all but one of 65 clean recordings of the independent generator" in {
    val t0 = System.nanoTime()
    val results = sweep.zipWithIndex.map { case (s, k) =>
      val r = SignalExplain.run("clean", FringeGenerator.recording(s), Nil, Progress.none).report
      println(f"clean $k%2d: ${s.n}%7d samples ${s.motion}%-8s ${s.bits}%2d bit noise ${s.noiseLsb}%.1f LSB ${s.n * s.f0 / s.fs}%8.1f periods: " +
        s"findings [${describe(r)}] unexplained ${r.unexplained.size}")
      r
    }
    val falseFindings = results.count(_.findings.nonEmpty)
    val withUnexplained = results.count(_.unexplained.nonEmpty)
    println(f"false-finding sweep: $falseFindings false findings in ${results.size} clean recordings ($withUnexplained with unexplained structure), ${(System.nanoTime() - t0) / 1e9}%.1f s")
    falseFindings should be <= 1
  }
}
