package moire.explain

import moire.explain.effects.Effects
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The registry: docs/explain.md's catalogue is the registry's table, and every registered effect runs forward
  * (simulate changes the codes) and backward (explain finds it on a recording made with it) unless it documents what
  * it needs beyond a recording.
  */
class EffectsSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "docs/explain.md" should "hold exactly the registry's catalogue table" in {
    val doc = os.read(os.pwd / "docs" / "explain.md")
    os.write.over(os.pwd / "target" / "explain-catalogue.md", Effects.markdownTable) // to paste when the registry changed
    withClue(s"regenerate the table from moire.explain.effects.Effects.markdownTable:\n${Effects.markdownTable}\n") {
      doc should include(Effects.markdownTable)
    }
    val rows = doc.linesIterator.filter(_.startsWith("| `")).map(_.drop(3).takeWhile(_ != '`')).toSeq
    rows.sorted shouldBe Effects.names.sorted
  }

  "the registry" should "name each effect once, parse its parameters and list it in --help" in {
    Effects.names.distinct shouldBe Effects.names
    for (e <- Effects.all) {
      val x = e.example.effect
      x.effect shouldBe e.name
      EffectSpec.parse(s"${e.name}:${x.params.map { case (k, v) => s"$k=$v" }.mkString(",")},channel=${x.channel}") shouldBe x
      Effects.help should include(e.name)
    }
  }

  private def record(e: effects.Effect, withEffect: Boolean) = {
    val x = e.example
    sim(if (withEffect) Seq(x.effect) else Nil, motion = PhysicsModel.parseMotion(x.motion), linesPerRev = x.linesPerRev)
  }

  for (e <- Effects.signals) {
    it should s"run ${e.name} forward${if (e.backwardNeeds.isEmpty) " and backward" else ""}" in {
      val plain = record(e, withEffect = false); val made = record(e, withEffect = true)
      // forward: the effect changes the codes
      (plain.sin.toSeq != made.sin.toSeq || plain.cos.toSeq != made.cos.toSeq) shouldBe true
      e.backwardNeeds match {
        case Some(why) => println(s"${e.name}: backward needs $why"); why should not be empty
        case None =>
          val r = explain(made)
          println(s"${e.name}: ${describe(r)}")
          withClue(describe(r)) { r.findings.map(_.effect) should contain(e.name) }
      }
    }
  }
}
