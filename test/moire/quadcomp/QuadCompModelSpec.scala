package moire.quadcomp

import moire.cordic.{CordicBound, Fixed, Rounding}
import moire.cordic.CordicBound.roundingLsb
import moire.signal.{Adc, Motion, SignalParams, SignalSim}
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The bit-accurate model against double precision, step by step, within the bounds of its parts. */
class QuadCompModelSpec extends AnyFlatSpec with Matchers {
  val configs: Seq[QuadCompParams] = Seq(
    QuadCompParams(),
    QuadCompParams(iterations = 12, width = 16, peakTableSize = 16, averageLog2 = 0, rounding = Rounding.Truncate),
    QuadCompParams(iterations = 20, width = 24, peakTableSize = 256, averageLog2 = 5),
    QuadCompParams(inputBits = 14, width = 20, peakTableSize = 0, averageLog2 = 2, gainFrac = 15),
    QuadCompParams(fusePeaks = true),
    QuadCompParams(iterations = 14, width = 18, peakTableSize = 32, averageLog2 = 1, fusePeaks = true, rounding = Rounding.Truncate))
  val signals: Seq[(Double, Double, Double)] = Seq( // (phase error deg, fringe Hz, noise LSB)
    (12.0, 100e3, 0.5), (-7.0, -400e3, 0.0), (25.0, 1e6, 1.0), (0.0, 40e3, 0.0))

  def rad(a: Long, p: QuadCompParams): Double = Fixed.angleToRad(a, p.angleBits)
  def dist(a: Double, b: Double): Double = math.abs(Fixed.angleDiff(a, b))

  for (p <- configs; (deg, hz, noise) <- signals) {
    s"${p.moduleName}" should s"follow double precision for $deg deg at ${hz / 1e3} kHz, noise $noise LSB" in {
      val adc = Adc(p.inputBits)
      val sig = SignalParams(phaseErrorDeg = deg, noiseRms = noise * adc.lsb, seed = 11)
      val n = math.min(60000, (12 / math.abs(hz) * 50e6).toInt)
      val s = SignalSim.generate(sig, Motion.Constant(hz, 0.2), adc, 50e6, n)
      val model = QuadCompSim.modelFor(p, sig, adc)
      val lsb = math.pow(2, -p.dataFrac)
      val angLsb = 2 * math.Pi / math.pow(2, p.angleBits)
      val eS = CordicBound.headline(p.asinP).total
      val eC = CordicBound.headline(p.acosP).total
      val eRot = CordicBound.headline(p.rebuildP).total
      val q = math.Pi / 2
      var ema = Option.empty[Double]; var pendingMeas = Option.empty[Double]; var measured = 0
      def clamp(v: Double) = math.max(-1.0, math.min(1.0, v))
      for (i <- 0 until n) {
        val o = model.step(s.sinSigned(i), s.cosSigned(i))
        // normalisation: code / amplitude, rounded once
        for ((got, code, g) <- Seq((o.sin, s.sinSigned(i), model.gainSin), (model.normalise(s.cosSigned(i), model.gainCos), s.cosSigned(i), model.gainCos))) {
          val exact = code.toDouble * g / math.pow(2, p.gainFrac + p.inputBits - 1)
          if (math.abs(exact) < 1.9) math.abs(got * lsb - exact) should be <= roundingLsb(p.rounding) * lsb
        }
        val ns = clamp(o.sin * lsb); val nc = clamp(model.normalise(s.cosSigned(i), model.gainCos) * lsb)
        val asinE = math.asin(ns); val acosE = math.acos(nc)
        dist(rad(o.zs, p), asinE) should be <= eS
        dist(rad(o.zc, p), acosE) should be <= eC
        val d = rad(o.correction, p)
        // decisions as exact arithmetic would take them, except within the error bound of the boundary
        val incE = if (ns >= 0) acosE - d <= q else acosE + d <= q
        if (incE != o.incSin) math.abs(acosE + (if (ns >= 0) -d else d) - q) should be <= eC + angLsb
        val posE = if (nc >= 0) asinE + d >= 0 else asinE - d >= 0
        if (posE != o.posCos) math.abs(asinE + (if (nc >= 0) d else -d)) should be <= eS + angLsb
        // with the model's decisions: full-period angles, the corrected angle and the rebuilt cos
        val thS = if (o.incSin) asinE else math.Pi - asinE
        val thC = if (o.posCos) acosE else -acosE
        dist(rad(o.thetaSin, p), thS) should be <= eS
        // fusePeaks: within 45 degrees of the cos channel's peaks the sin angle is used (o.zc in [-90, 270) deg)
        val eighth = 1L << (p.angleBits - 3)
        val nearPeak = o.zc < eighth || o.zc > 3 * eighth
        if (p.fusePeaks && nearPeak) dist(rad(o.psi, p), thS) should be <= eS
        else dist(rad(o.psi, p), thC - d) should be <= eC
        math.abs(o.cos * lsb - math.cos(rad(o.psi, p))) should be <= eRot
        // correction: the exponential average of the measurements, within one angle LSB
        val corrE = ema.getOrElse(0.0)
        dist(d, corrE) should be <= (if (p.averageLog2 == 0) 1e-12 else angLsb * (1 + roundingLsb(p.rounding)))
        pendingMeas.foreach { m =>
          val w = math.pow(2, -p.averageLog2)
          ema = Some(ema.fold(m)(e => e + w * Fixed.angleDiff(m, e)))
        }
        pendingMeas = o.diff.map(v => rad(v, p))
        o.diff.foreach { v =>
          dist(rad(v, p), thC - thS) should be <= eS + eC
          measured += 1
        }
      }
      measured should be >= 10
    }
  }

  "The measured phase difference" should "be the set one within the quantisation bound on clean signals" in {
    val p = QuadCompParams()
    for (deg <- Seq(-35.0, -12.0, -0.5, 0.0, 3.0, 12.0, 35.0); hz <- Seq(40e3, -100e3, 1e6)) {
      val run = QuadCompSim.run(p, QuadCompSim.signal(deg, noiseLsb = 0), hz, 20)
      val aCodes = QuadCompSim.amplitude * 2048
      val step = 2 * math.Pi * math.abs(hz) / QuadCompSim.sampleRate
      // half an ADC LSB on each channel, seen through asin at 45 degrees (+ one step) and acos at 45 + deg
      val quant = 0.5 / aCodes * (1 / math.cos(math.Pi / 4 + step) + 1 / math.sin(math.toRadians(45 + deg) - step))
      val bound = CordicBound.headline(p.asinP).total + CordicBound.headline(p.acosP).total + quant +
        2 * math.Pi / math.pow(2, p.angleBits)
      run.diffsDeg.size should be >= 15
      for (m <- run.diffsDeg) math.abs(math.toRadians(m - deg)) should be <= bound
      math.abs(math.toRadians(run.finalCorrectionDeg - deg)) should be <= bound
    }
  }

  "Compensation" should "remove most of the quadrature error, forwards and backwards" in {
    for ((hz, deg) <- Seq(100e3 -> -12.0, -100e3 -> -12.0, 100e3 -> 8.0, -100e3 -> 8.0, 1e6 -> 30.0, -1e6 -> -30.0,
                          3e6 -> -35.0, 40e3 -> 35.0)) {
      val run = QuadCompSim.run(QuadCompParams(), QuadCompSim.signal(deg, noiseLsb = 0), hz, 12)
      val model = QuadCompSim.modelFor(run.p, QuadCompSim.signal(deg), run.samples.adc)
      val range = run.periodStart(4) until run.samples.length
      val after = range.map(i => math.abs(run.pairError(i))).max
      val before = range.map(i => math.abs(run.rawPairError(i, model))).max
      before should be > 0.9 * math.abs(deg)
      after should be < 0.02 * math.abs(deg)
    }
  }

  "QuadCompParams" should "reject bad values with a message naming them" in {
    the[IllegalArgumentException] thrownBy QuadCompParams(inputBits = 2) should have message
      "requirement failed: inputBits must be in 4..24, got 2"
    the[IllegalArgumentException] thrownBy QuadCompParams(width = 12) should have message
      "requirement failed: width must be in 14..32 (inputBits + 2 ..), got 12"
    the[IllegalArgumentException] thrownBy QuadCompParams(averageLog2 = 9) should have message
      "requirement failed: averageLog2 must be in 0..8, got 9"
    the[IllegalArgumentException] thrownBy QuadCompParams(peakTableSize = 3) should have message
      "requirement failed: peak-table must be 0 or a power of two up to 4096, got 3"
    the[IllegalArgumentException] thrownBy QuadCompParams(gainFrac = 2) should have message
      "requirement failed: gainFrac must be at least 5 for width 18, got 2"
    QuadCompParams().latency shouldBe 1 + 18 + 1 + 18
    QuadCompParams(pipelineEvery = 2).moduleName shouldBe "QuadComp_i12_n16_w18_lut64_g18f16_avg3_k2_rne"
    QuadCompParams(fusePeaks = true).moduleName shouldBe "QuadComp_i12_n16_w18_lut64_g18f16_avg3_k1_rne_fuse"
  }

  "The seed 000 rows" should "all hold, with the paper's values beside ours" in {
    val rows = QuadCompPaper.rows()
    rows.size shouldBe 11 + 24
    rows.filterNot(_.holds).map(_.item) shouldBe empty
    rows.head.paper.num shouldBe -0.019
  }
}
