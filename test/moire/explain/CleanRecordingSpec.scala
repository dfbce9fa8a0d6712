package moire.explain

import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

import scala.util.Random

/** Clean recordings (default model only, random imperfections and motions): explain must name nothing. */
class CleanRecordingSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "explain" should "name no effect in at least 19 of 20 random clean recordings" in {
    val rnd = new Random(2024)
    val reports = (0 until 20).map { k =>
      val motion = k % 3 match {
        case 0 => Motion.Ramp(10e3 + 20e3 * rnd.nextDouble(), 150e3 + 100e3 * rnd.nextDouble(), 0.005)
        case 1 => Motion.Constant(30e3 + 150e3 * rnd.nextDouble())
        case _ => Motion.Oscillate(40 + 40 * rnd.nextDouble(), 200 + 200 * rnd.nextDouble())
      }
      val r = explain(sim(Nil, motion = motion, n = 50000, noiseLsb = 0.7 + 2 * rnd.nextDouble(), phaseErrorDeg = 4 * rnd.nextDouble() - 2,
        seed = 100 + k, amplitude = 0.6 + 0.3 * rnd.nextDouble()))
      info(s"$k ${motion}: ${describe(r)} | unexplained ${r.unexplained.map(_.where).mkString(", ")}")
      r
    }
    reports.count(_.findings.nonEmpty) should be <= 1
    reports.count(_.unexplained.nonEmpty) should be <= 1
  }
}
