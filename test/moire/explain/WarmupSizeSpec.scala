package moire.explain

import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A warm-up whose time constant is three times the record's length changes the signal by what it settles within the
  * record, about its mean (the default offsets take the rest). Its size was the whole change from the record's start,
  * twice that: a 0.2 LSB offset step of helper sweep 18 became a material "warmup 1.06 LSB" (its numpy record; this one, of our
  * model, gives a negligible drift first either way, and guards the slow warm-up's size).
  */
class WarmupSizeSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "explain" should "size a slow warm-up by its change about its mean within the record" in {
    // a warm-up of 1 s over a 0.1 s ramp: 3.4 LSB settling, 0.32 LSB of it within the record, +-0.16 about its mean
    // (floor 0.25 LSB); the fit's time constant stops at its 0.3 s bound
    val rec = sim(Seq(EffectSpec("warmup", Map("offset_sin_step_fs" -> 3.4 * lsb12, "time_constant_s" -> 1.0))),
      motion = Motion.Ramp(20e3, 200e3, 0.1), n = 400000, fs = 4e6, noiseLsb = 1.0)
    val r = explain(rec)
    withClue(s"${describe(r)}; negligible ${r.negligible.map(x => s"${x.effect} ${x.sizeLsb}")}: ") {
      r.findings shouldBe empty
      r.negligible should not be empty
      r.negligible.foreach(_.sizeLsb should be < 0.25)
    }
  }
}
