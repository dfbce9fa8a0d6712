package moire.explain.evidence

import moire.explain.{FalseFindingSpec, FringeGenerator, Report}
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

import scala.util.Random

/** Issue 28, Prove it 9: the false-finding sweep grown past 100 clean recordings: the 64 short and middle ones of
  * FalseFindingSpec (its 10^6-sample one runs there) plus new benches and kinds of motion: turntables with a
  * reference, stick-slip stages (followable: slips over milliseconds), sinusoidal scans, slow 3x3-coupler records,
  * 8-bit scope dumps and linear stages with `ref_um`. At most one false finding, counted and printed.
  */
class CleanSweepSpec extends AnyFlatSpec with Matchers {
  import Evidence._

  /** name -> recording text of the new benches, none with an effect beyond the default model. */
  def benches: Seq[(String, () => String)] = {
    val rnd = new Random(28)
    val turntables = for (bits <- Seq(8, 10, 12, 14); k <- 0 until 2) yield {
      val s = Turntable.Spec(turnsPerS = if (k == 0) 1.0 else 2.5, unevenRel = 0.03 + 0.1 * rnd.nextDouble(), unevenHz = 0.5 + 2 * rnd.nextDouble(),
        bits = bits, noiseLsb = Seq(0.6, 1.0, 1.5, 3.0)(k + bits % 3), refBits = if (k == 0) 12 else 16, seed = 100 + bits + k)
      f"turntable $bits bit ${s.turnsPerS}%.1f turns" -> (() => Turntable.text(s))
    }
    val stickSlip = for (k <- 0 until 8) yield {
      val fs = Seq(200e3, 1e6)(k % 2); val n = Seq(20000, 40000)(k / 4)
      val every = n / fs / (3 + 4 * rnd.nextDouble()); val slip = every * (0.2 + 0.3 * rnd.nextDouble())
      val tr = Motions.stickSlip(n, fs, 20 + 200 * rnd.nextDouble(), 1 + 4 * rnd.nextDouble(), every, slip, seed = 200 + k)
      val b = Bench(noiseLsb = Seq(0.7, 1.5)(k % 2), bits = Seq(12, 14, 10, 12)(k % 4), seed = 200 + k)
      val text = if (k < 4) () => LinearStage.text(LinearStage.Spec(tr, fs, b, refNm = Seq(1.0, 5.0)(k % 2))) else () => Interferometer.text(tr, fs, b)
      f"stick-slip $k ($n samples, ${tr.periods.last}%.0f periods${if (k < 4) ", ref_um" else ""})" -> text
    }
    val scans = for (k <- 0 until 8) yield {
      val fs = Seq(1e6, 5e6)(k % 2); val n = Seq(10000, 30000)(k / 4)
      val span = 20 + 200 * rnd.nextDouble(); val rate = fs / n * (0.6 + 2 * rnd.nextDouble())
      val tr = Motions.sinusoidalScan(n, fs, span, rate, 6 * rnd.nextDouble())
      val b = Bench(amp = 0.5 + 0.4 * rnd.nextDouble(), quadDeg = 3 * rnd.nextGaussian(), noiseLsb = Seq(0.5, 1.0, 2.0, 4.0)(k % 4),
        bits = Seq(12, 10, 14, 12)(k % 4), seed = 300 + k)
      f"sinusoidal scan $k ($span%.0f periods at $rate%.0f Hz)" -> (() => Interferometer.text(tr, fs, b))
    }
    val couplers = for (k <- 0 until 6) yield {
      val s = Coupler.Spec(n = Seq(600, 1200, 3600)(k % 3), totalPeriods = Seq(7.5, 3.0, 20.0)(k % 3), walkPeriods = 0.001 * (1 + k),
        noiseLsb = 2 + k, seed = 400 + k)
      f"3x3 coupler $k (${s.n} s, ${s.totalPeriods}%.1f periods)" -> (() => Coupler.text(s))
    }
    val scopes = for (k <- 0 until 8) yield {
      val fs = 2e6; val n = Seq(20000, 50000)(k % 2)
      val tr = k % 4 match {
        case 0 => Motions.chirp(n, fs, 10e3, 40e3)
        case 1 => Motions.sinusoidalScan(n, fs, 150, 2 * fs / n)
        case 2 => Motions.vibrating(n, fs, 20e3, 300, 8)
        case _ => Motions.constant(n, fs, 25e3)
      }
      s"scope dump $k ($n samples, 8 bit)" -> (() => ScopeDump.text(tr, fs, 0.6 + 0.3 * rnd.nextDouble(), Seq(0.3, 0.5)(k % 2), seed = 500 + k))
    }
    val stages = for (k <- 0 until 4) yield {
      val fs = 50e3; val w = 2 * math.Pi * (1 + 5 * rnd.nextDouble()); val v = 200 + 800 * rnd.nextDouble(); val u = 0.05 + 0.2 * rnd.nextDouble()
      val tr = Motions.formula(20000, fs)(t => v * t + u * v / w * math.sin(w * t), t => v * (1 + u * math.cos(w * t)))
      val b = Bench(noiseLsb = 0.8 + k * 0.5, bits = Seq(12, 14)(k % 2), seed = 600 + k)
      f"linear stage $k ($v%.0f periods/s, ref_um)" -> (() => LinearStage.text(LinearStage.Spec(tr, fs, b, periodUm = Seq(20.0, 4.0)(k % 2))))
    }
    turntables ++ stickSlip ++ scans ++ couplers ++ scopes ++ stages
  }

  /** FalseFindingSpec's short and middle recordings (its 10^6-sample one is left to it). */
  def today: Seq[(String, () => String)] = new FalseFindingSpec().sweep.filter(_.n < 1000000).zipWithIndex.map { case (s, k) =>
    f"fringe $k ${s.n} ${s.motion} ${s.bits} bit" -> (() => FringeGenerator.text(s))
  }

  "explain" should "name no effect in all but at most one of more than 100 clean recordings of new benches and motions" in {
    val all = benches ++ today
    all.size should be >= 100
    val t0 = System.nanoTime()
    val results: Seq[(String, Report)] = all.map { case (name, text) => name -> explain(s"clean: $name", text()) }
    val false_ = results.filter(_._2.findings.nonEmpty)
    println(f"clean sweep: ${false_.size} false findings in ${results.size} clean recordings (${benches.size} new benches), " +
      f"${results.count(_._2.unexplained.nonEmpty)} with unexplained structure, ${(System.nanoTime() - t0) / 1e9}%.1f s")
    false_.foreach { case (k, r) => println(s"  false finding: $k: ${line(r)}") }
    false_.size should be <= 1
  }
}
