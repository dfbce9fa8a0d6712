package moire.explain

import moire.recording.{Recording, Reference}
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** explain with a reference column (issue 12, Build 2) on the third generator's recordings: a magnetic rotary
  * encoder with one period per turn whose eccentric magnet adds a 2nd harmonic of the mechanical angle, and a
  * linear scale beside an interferometer.
  */
class ReferenceSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport.describe

  private def run(text: String): Report = {
    val rec = Recording.parse("third", text.split("\n").toIndexedSeq)
    SignalExplain.run("third", rec, Nil, Progress.none).report
  }

  /** Findings other than harmonics the generator's formula really has (above 1e-5 of the fundamental). */
  private def stories(r: Report, s: ThirdGenerator.Rotary): Seq[Finding] = r.findings.filterNot(f =>
    f.effect == "harmonic" && ThirdGenerator.truthH(s, f.params("order").toInt) > 1e-5)

  /** The 2nd harmonic and its sd: from the finding on both channels, or the mean of one-channel findings. */
  private def h2(r: Report): Option[(Double, Double)] = {
    val fs = r.findings.filter(f => f.effect == "harmonic" && f.params("order") == 2.0)
    if (fs.isEmpty) None
    else Some((fs.map(_.params("amplitude_rel")).sum / fs.size, math.sqrt(fs.map(f => math.pow(f.unc("amplitude_rel"), 2)).sum) / fs.size))
  }

  "explain with a ref_deg column" should "report the 2nd harmonic of an eccentric magnet at 0.5, 1, 2, 4 % in order, each within 3 sd of the truth, at 8, 10, 12 and 14 bits" in {
    for (bits <- Seq(8, 10, 12, 14)) {
      val est = for (ecc <- Seq(0.005, 0.01, 0.02, 0.04)) yield {
        val s = ThirdGenerator.Rotary(ecc = ecc, bits = bits, seed = bits)
        val r = run(ThirdGenerator.rotary(s))
        val truth = ThirdGenerator.truthH(s, 2)
        withClue(s"$bits bits, eccentricity $ecc: ${describe(r)}") {
          h2(r) shouldBe defined
          stories(r, s) shouldBe empty
          r.unexplained shouldBe empty
        }
        val (a, sd) = h2(r).get
        info(f"$bits%2d bits, eccentricity ${100 * ecc}%.1f %%: 2nd harmonic ${100 * a}%.4f +- ${100 * sd}%.4f %% (truth ${100 * truth}%.4f %%, " +
          f"${(a - truth) / sd}%+.2f sd); ${r.notes.find(_.startsWith("reference")).map(_.replaceAll(".*follows? it within ", "follows within ")).getOrElse("")}")
        withClue(s"$bits bits, eccentricity $ecc") { math.abs(a - truth) should be <= 3 * sd }
        a
      }
      est shouldBe est.sorted
      est.distinct.size shouldBe est.size
    }
  }

  it should "name nothing in clean rotary recordings (no eccentricity), and say which reference it used" in {
    for (bits <- Seq(8, 10, 12, 14); seed <- 1 to 2) {
      val r = run(ThirdGenerator.rotary(ThirdGenerator.Rotary(bits = bits, seed = 10 * bits + seed, periodsMeta = seed == 2)))
      withClue(s"$bits bits, seed $seed: ${describe(r)}") { r.findings shouldBe empty; r.unexplained shouldBe empty }
      val note = r.notes.find(_.startsWith("reference ref_deg")).getOrElse(fail(s"no reference note: ${r.notes}"))
      note should include(if (seed == 2) "from the metadata" else "fitted")
      r.baseline("reference_periods_per_unit") shouldBe (1.0 / 360 +- 1e-5)
      r.untested.exists(_.contains("not identifiable without a reference")) shouldBe false
    }
    info(run(ThirdGenerator.rotary(ThirdGenerator.Rotary())).notes.mkString("\n"))
  }

  "explain without a reference" should "call motion-confounded effects not identifiable in a one-period rotary recording, and name nothing" in {
    for (ecc <- Seq(0.0, 0.01, 0.04); bits <- Seq(8, 12)) {
      val r = run(ThirdGenerator.rotary(ThirdGenerator.Rotary(ecc = ecc, bits = bits, withRef = false, seed = 5)))
      withClue(s"eccentricity $ecc, $bits bits: ${describe(r)}") {
        r.findings shouldBe empty
        r.unexplained shouldBe empty
        r.untested.exists(_.contains("not identifiable without a reference")) shouldBe true
      }
    }
    info(run(ThirdGenerator.rotary(ThirdGenerator.Rotary(ecc = 0.04, withRef = false))).untested.mkString("\n"))
  }

  "explain with ref_um and period_um" should "find a 3rd harmonic of a linear scale moving unevenly, and nothing in its clean recording" in {
    val clean = run(ThirdGenerator.linear(ThirdGenerator.Linear()))
    withClue(describe(clean)) { clean.findings shouldBe empty; clean.unexplained shouldBe empty }
    clean.notes.exists(n => n.startsWith("reference ref_um") && n.contains("from the metadata")) shouldBe true
    clean.baseline("reference_periods_per_unit") shouldBe (1.0 / 20 +- 1e-9)
    val r = run(ThirdGenerator.linear(ThirdGenerator.Linear(h3 = 5e-4, seed = 2)))
    withClue(describe(r)) { r.findings.map(f => (f.effect, f.params("order"))) shouldBe Seq(("harmonic", 3.0)) }
    val f = r.findings.head
    info(f"linear scale: 3rd harmonic ${100 * f.params("amplitude_rel")}%.4f +- ${100 * f.unc("amplitude_rel")}%.4f %% (truth 0.0500 %%)")
    math.abs(f.params("amplitude_rel") - 5e-4) should be <= 3 * f.unc("amplitude_rel")
  }

  "explain on an optical disk off its axis, with ref_deg and lines_per_rev" should "report the eccentricity at three sizes in order, each within 3 sd of the truth, and nothing when centred" in {
    val clean = run(ThirdGenerator.disk(ThirdGenerator.Disk()))
    withClue(describe(clean)) { clean.findings shouldBe empty; clean.unexplained shouldBe empty }
    val est = for (ecc <- Seq(2e-6, 5e-6, 2e-5)) yield {
      val r = run(ThirdGenerator.disk(ThirdGenerator.Disk(ecc = ecc, seed = 4)))
      val f = r.findings.find(_.effect == "eccentricity")
      withClue(s"eccentricity $ecc: ${describe(r)}") { f shouldBe defined; r.findings.map(_.effect) shouldBe Seq("eccentricity") }
      val (a, sd) = (f.get.params("eccentricity_rel"), f.get.unc("eccentricity_rel"))
      info(f"disk off its axis by ${ecc * 1e6}%.1f ppm of the radius: eccentricity ${a * 1e6}%.3f +- ${sd * 1e6}%.3f ppm " +
        f"(${(a - ecc) / sd}%+.2f sd), ${f.get.params("angle_error_arcsec")}%.3f arcsec: ${f.get.summary}")
      math.abs(a - ecc) should be <= 3 * sd
      a
    }
    est shouldBe est.sorted
  }

  "the physics model's eccentricity" should "be found by the fit when the true angle is given as ref_turns" in {
    val base = moire.signal.SignalParams(amplitude = 0.8, noiseRms = 0.7 / 2048, seed = 9)
    val m = PhysicsModel(base, moire.signal.Motion.Ramp(800, 1200, 0.03), 100e3, 30000, moire.signal.Adc(12), Some(300),
      Seq(EffectSpec("eccentricity", Map("eccentricity_rel" -> 1e-5, "phase_deg" -> 40))))
    val (rec, truth) = m.generate()
    val r = SignalExplain.run("sim", rec.copy(extra = Map("ref_turns" -> truth.map(_ / 300))), Nil, Progress.none).report
    withClue(describe(r)) { r.findings.map(_.effect) shouldBe Seq("eccentricity") }
    val f = r.findings.head
    info(f"simulate eccentricity 10 ppm at 40 degree: found ${f.params("eccentricity_rel") * 1e6}%.3f +- ${f.unc("eccentricity_rel") * 1e6}%.3f ppm at ${f.params("phase_deg")}%.1f degree")
    math.abs(f.params("eccentricity_rel") - 1e-5) should be <= 3 * f.unc("eccentricity_rel")
    math.abs(f.params("phase_deg") - 40) should be <= 3 * f.unc("phase_deg") + 1
  }

  "a reference the signals do not follow" should "not be used, and the report says so" in {
    val text = ThirdGenerator.rotary(ThirdGenerator.Rotary(ecc = 0.0, seed = 3)).split("\n").map { l =>
      val c = l.split(",")
      // the reference bent by 60 degree three times per turn: no smooth map takes the signals onto it
      if (c.length == 3 && c(2) != "ref_deg") { val d = c(2).toDouble; s"${c(0)},${c(1)},${d + 60 * math.sin(math.toRadians(3 * d))}" } else l
    }.mkString("\n")
    val r = run(text)
    r.notes.exists(n => n.startsWith("reference ref_deg") && n.contains("not used")) shouldBe true
    r.findings shouldBe empty
  }

  "a reference with a corrupted row" should "not be used, the report naming the row, and explain as without it (finite figures)" in {
    val lines = ThirdGenerator.linear(ThirdGenerator.Linear()).split("\n")
    val first = lines.indexWhere(_.startsWith("sin,cos")) + 1
    val without = run(lines.map(l => if (l.startsWith("# period_um")) "" else if (l.count(_ == ',') == 2) l.split(",").init.mkString(",") else l)
      .filter(_.nonEmpty).mkString("\n"))
    for (big <- Seq("1e100", "1e160")) {
      // one row's ref_um from a broken link (a number, but no position the stage was at)
      val text = lines.zipWithIndex.map { case (l, i) => if (i == first + 500) l.split(",").init.mkString(",") + "," + big else l }.mkString("\n")
      val r = run(text)
      withClue(s"ref_um $big: ${describe(r)} | ${r.notes.mkString("; ")}") {
        r.notes.exists(n => n.startsWith("reference ref_um") && n.contains("between samples 499 and 500") && n.contains("not used")) shouldBe true
        r.findings.map(_.effect) shouldBe without.findings.map(_.effect)
        r.unexplained.map(_.where) shouldBe without.unexplained.map(_.where)
        Seq(r.baselineRms, r.baselineBic, r.finalRms, r.finalBic).forall(x => !x.isNaN && !x.isInfinite) shouldBe true
        r.finalBic shouldBe without.finalBic
      }
    }
  }

  "Reference.of" should "unwrap angles, scale counts and refuse bad scale metadata with one line" in {
    def rec(meta: Map[String, String], col: String, v: Array[Double]) = Recording(1000, moire.signal.Adc(12), Array.fill(v.length)(2048),
      Array.fill(v.length)(2048), meta, Map(col -> v))
    val deg = Reference.of(rec(Map.empty, "ref_deg", Array(350.0, 359.0, 3.0, 12.0, 355.0))).toOption.flatten.get
    deg.values.toSeq shouldBe Seq(350.0, 359.0, 363.0, 372.0, 355.0)
    deg.turnsPerUnit shouldBe Some(1.0 / 360)
    deg.periodsPerUnit shouldBe None
    val cnt = Reference.of(rec(Map("ref_counts_per_turn" -> "4096", "lines_per_rev" -> "2048"), "ref_counts", Array(4090.0, 4095.0, 3.0))).toOption.flatten.get
    cnt.values.toSeq shouldBe Seq(4090.0, 4095.0, 4099.0)
    cnt.periodsPerUnit shouldBe Some(0.5)
    Reference.of(rec(Map("period_um" -> "-20"), "ref_um", Array(1.0))) shouldBe Left("metadata period_um '-20' is not a number above 0")
    Reference.of(rec(Map("lines_per_rev" -> "100", "periods_per_turn" -> "50"), "ref_turns", Array(1.0))).isLeft shouldBe true
    Reference.of(rec(Map.empty, "other", Array(1.0))) shouldBe Right(None)
    val pos = Reference.of(rec(Map("counts_per_period" -> "64"), "position", Array(1.0))).toOption.flatten.get
    pos.periodsPerUnit shouldBe Some(1.0 / 64)
    pos.source should include("computed from these signals")
    // a 32-bit count on a long run wraps from 2^31 - 1 to -2^31: no motion steps by half of that
    val wrapped = Reference.of(rec(Map("counts_per_period" -> "64"), "position", Array(2147483646.0, 2147483647.0, -2147483648.0, -2147483647.0))).toOption.flatten.get
    wrapped.values.toSeq shouldBe Seq(2147483646.0, 2147483647.0, 2147483648.0, 2147483649.0)
    val count = Reference.of(rec(Map.empty, "ref_counts", Array(-2147483647.0, -2147483648.0, 2147483647.0))).toOption.flatten.get
    count.values.toSeq shouldBe Seq(-2147483647.0, -2147483648.0, -2147483649.0)
  }
}
