package moire.explain

import moire.recording.Recording
import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A long record's terms are not held (issue 14: 20,000,000 rows in the default heap): their columns are made a block
  * of samples at a time where they are read. That must give the same numbers, to the last bit, as holding them.
  */
class HeldColumnsSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "ColGroups" should "solve and form residuals exactly as one solve over all columns, held or made a block at a time" in {
    val rnd = new scala.util.Random(5); val n = 30000
    def arr() = Array.fill(n)(rnd.nextGaussian())
    val groups = IndexedSeq(IndexedSeq(Col(arr(), null), Col(null, arr())), IndexedSeq(Col(arr(), arr()), Col(arr(), null)),
      IndexedSeq(Col(null, arr())), IndexedSeq(Col(arr(), arr()), Col(null, arr()), Col(arr(), null)))
    val ys = arr(); val yc = arr()
    val all = LinearFit.solve(groups.flatten, ys, yc)
    // a generator that copies a group's columns block by block, counting the samples it makes
    var blockSamples = 0L
    def gen(cols: IndexedSeq[Col]) = new ColGen(cols.map(_.s != null).toArray, cols.map(_.c != null).toArray, (lo, hi, o, at) => {
      synchronized(blockSamples += hi - lo)
      for ((col, j) <- cols.zipWithIndex) {
        if (col.s != null) System.arraycopy(col.s, lo, o(2 * j), at, hi - lo)
        if (col.c != null) System.arraycopy(col.c, lo, o(2 * j + 1), at, hi - lo)
      }
    })
    var made = 0
    for ((keep, gens) <- Seq((true, IndexedSeq()), (false, IndexedSeq()), (false, null +: groups.tail.map(gen)))) {
      made = 0; blockSamples = 0
      val g = new ColGroups(groups.map(c => () => { made += 1; c }), keep, IndexedSeq(), gens)
      val s = g.solve(ys, yc)
      s.beta shouldBe all.beta
      s.inv.map(_.toSeq).toSeq shouldBe all.inv.map(_.toSeq).toSeq
      g.offsets shouldBe Seq(0, 2, 4, 5, 8)
      val r = ys.clone(); val rc = yc.clone(); g.addToBoth(r, rc, s.beta, -1.0)
      r shouldBe LinearFit.minus(ys, groups.flatten, all.beta, sinCh = true)
      rc shouldBe LinearFit.minus(yc, groups.flatten, all.beta, sinCh = false)
      // held: each group made once; with generators only the first, the rest a block at a time in each of the two passes
      made shouldBe (if (gens.isEmpty) 4 else 1)
      blockSamples shouldBe (if (gens.isEmpty) 0 else 2L * 3 * n)
    }
  }

  "A contrast spline's columns" should "be made a block at a time, and whole, as their definition gives them, to the bit" in {
    val e = new SignalEngine(sim(Seq(EffectSpec("contrast_along_travel", Map("gain_sin_per_period" -> 2e-5))), n = 30000)); e.init()
    val k = Vector(0.0, 0.25, 0.6, 1.0)
    // the definition: the position as a fraction of the travel's range, each knot's hat function times u per channel
    val x = e.travel; val (lo, hi) = (x.min, x.max); val z = x.map(v => (v - lo) / math.max(1e-12, hi - lo))
    def col(j: Int, u: Int => Double) = Array.tabulate(e.n) { i => val w = effects.ContrastAlongTravel.hat(k, j, z(i)); if (w != 0) u(i) * w else 0.0 }
    val want = (1 until k.size).flatMap(j => Seq((col(j, e.us), null), (null, col(j, e.uc))))
    want.flatMap(w => Option(w._1)).exists(_.exists(_ != 0)) shouldBe true
    val g = e.termGen(Term.ContrastSpline(k)).get
    g.size shouldBe want.size
    // two blocks into the same buffers: the second at its offset
    val o = g.buffers(e.n); g.fill(0, 12345, o, 0); g.fill(12345, e.n, o, 12345)
    val whole = effects.ContrastAlongTravel.splineCols(e, k)
    for (((ws, wc), j) <- want.zipWithIndex) {
      Option(o(2 * j)).map(_.toSeq) shouldBe Option(ws).map(_.toSeq); Option(o(2 * j + 1)).map(_.toSeq) shouldBe Option(wc).map(_.toSeq)
      Option(whole(j).s).map(_.toSeq) shouldBe Option(ws).map(_.toSeq); Option(whole(j).c).map(_.toSeq) shouldBe Option(wc).map(_.toSeq)
    }
  }

  "explain" should "give the same report with its terms' columns made again as with them held" in {
    val rec = sim(Seq(EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 5e-4), "sin"),
      EffectSpec("drift", Map("offset_sin_per_s" -> 0.02, "gain_cos_per_s" -> 0.05)),
      EffectSpec("adc_nonlinearity", Map("inl2_lsb" -> 2.0, "inl3_lsb" -> 1.5))), motion = Motion.Ramp(20e3, 250e3, 0.01))
    def run(hold: Long) = SignalExplain.run("held", rec, Nil, Progress.none, holdBytes = hold).report
    val held = run(Long.MaxValue); val made = run(0)
    withClue(describe(held)) { held.findings.size should be >= 3 }
    made.findings shouldBe held.findings
    made.finalBic shouldBe held.finalBic
    made.unexplained shouldBe held.unexplained
  }

  it should "give the same report with a reference (the prediction's slope from made-again harmonics)" in {
    val s = ThirdGenerator.Rotary(ecc = 0.02, bits = 12, seed = 12)
    val rec = Recording.parse("third", ThirdGenerator.rotary(s).split("\n").toIndexedSeq)
    def run(hold: Long) = SignalExplain.run("third", rec, Nil, Progress.none, holdBytes = hold).report
    val held = run(Long.MaxValue); val made = run(0)
    withClue(describe(held)) { held.findings should not be empty }
    made.findings shouldBe held.findings
    made.finalBic shouldBe held.finalBic
  }
}
