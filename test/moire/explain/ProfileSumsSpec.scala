package moire.explain

import moire.recording.Reference
import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The binned profile (`ProfileSums`) against the profile on every sample: the same -2 ln L, up to the bins' cubic
  * term, for skews and cut-offs across the search ranges (down to a fifth of the highest fringe frequency), on all
  * samples and on a fold; the searches' minima and curvatures are those of the exact profile.
  */
class ProfileSumsSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  private def engine(effects: Seq[EffectSpec], motion: Motion) = {
    val rec = sim(effects, motion = motion, n = 60000)
    val e = new SignalEngine(rec, Reference.of(rec).toOption.flatten)
    e.init(); e
  }

  private def compare(e: SignalEngine, specs: Seq[ModelSpec], idx: Array[Int] = null, minSpread: Double = 100.0): Unit = {
    val c = new Candidates(e)
    val exact = specs.map(c.profile(_, 1, idx)); val binned = specs.map(c.binned(idx).m2ll)
    // the spread of the values is what a search reads: it must be far larger than the difference (at one speed a skew
    // is a phase error and a cut-off a gain, both taken up by the default part: the profile is nearly flat)
    val spread = exact.max - exact.min
    spread should be > minSpread
    for ((sp, (x, b)) <- specs.zip(exact.zip(binned))) withClue(s"$sp: exact $x binned $b: ") {
      math.abs(x - b) should be <= 1e-3
    }
  }

  "the binned profile" should "match the exact one for skews and cut-offs on a ramp, on all samples and on a fold" in {
    val e = engine(Seq(EffectSpec("channel_skew", Map("skew_s" -> 30e-9)), EffectSpec("bandwidth", Map("cutoff_hz" -> 300e3), "both")),
      Motion.Ramp(20e3, 250e3, 0.006))
    val fMax = e.speedRange._2
    val skews = Seq(-200e-9, -20e-9, 0.0, 10e-9, 30e-9, 45e-9, 300e-9).map(t => ModelSpec(hasSkew = true, skewS = t))
    val cuts = for (ch <- Seq("both", "sin", "cos"); k <- Seq(0.2, 0.5, 1.0, 2.0, 7.0, 40.0)) yield ModelSpec(bw = Map(ch -> k * fMax))
    val mixed = Seq(ModelSpec(hasSkew = true, skewS = 25e-9, bw = Map("both" -> 1.2 * fMax, "sin" -> 0.3 * fMax)))
    compare(e, skews ++ cuts ++ mixed)
    compare(e, skews ++ cuts, Array.range(0, e.n / 2))
  }

  it should "match it on a motion that turns (negative fringe frequencies) and at one constant speed" in {
    val turn = engine(Seq(EffectSpec("bandwidth", Map("cutoff_hz" -> 400e3), "sin")), Motion.Oscillate(60, 400))
    val fMax = turn.speedRange._2
    compare(turn, Seq(0.3, 1.0, 3.0).map(k => ModelSpec(bw = Map("sin" -> k * fMax))) ++ Seq(ModelSpec(hasSkew = true, skewS = 40e-9)))
    val still = engine(Seq(EffectSpec("channel_skew", Map("skew_s" -> 30e-9))), Motion.Constant(120e3))
    compare(still, Seq(0.3, 1.0, 3.0).map(k => ModelSpec(bw = Map("both" -> k * 120e3))) ++ Seq(-50e-9, 0.0, 30e-9, 80e-9).map(t => ModelSpec(hasSkew = true, skewS = t)), minSpread = 1.0)
  }

  it should "give way to the exact profile where its bins are too coarse for a cut-off within a bin's width of standstill" in {
    val e = engine(Nil, Motion.Oscillate(60, 400))
    val c = new Candidates(e)
    val sp = ModelSpec(bw = Map("sin" -> 50.0))
    c.binned().m2ll(sp).isNaN shouldBe true
    c.searched(sp, 1) shouldBe c.profile(sp, 1)
  }

  "the response table" should "give the channel response's columns to 1e-10 across the speeds, and refuse a range it cannot hold" in {
    val o1 = new Array[Double](4); val o2 = new Array[Double](4)
    for (sp <- Seq(ModelSpec(hasSkew = true, skewS = 40e-9, bw = Map("both" -> 300e3)), ModelSpec(bw = Map("sin" -> 90e3, "cos" -> 120e3)))) {
      val r = new ChannelResponse(sp)
      val t = new ResponseTable(r, -250e3, 250e3, SignalEngine.ResponseBins, 1e-10)
      t.ok shouldBe true
      val rnd = new scala.util.Random(5)
      for (_ <- 0 until 2000) {
        val f = -250e3 + 500e3 * rnd.nextDouble(); val a = 2 * math.Pi * rnd.nextDouble()
        r(f, math.sin(a), math.cos(a), o1); t(f, math.sin(a), math.cos(a), o2)
        for (j <- 0 until 4) math.abs(o1(j) - o2(j)) should be <= 2e-10
      }
    }
    new ResponseTable(new ChannelResponse(ModelSpec(bw = Map("both" -> 1e3))), 0, 5e6, SignalEngine.ResponseBins, 1e-10).ok shouldBe false
  }
}
