package moire.explain.evidence

import moire.recording.Recording

import java.util.Random

/** One harmonic of the fringe on a channel ("sin", "cos" or "both"): rel of the fundamental, at phaseDeg. */
final case class Harmonic(order: Int, rel: Double, phaseDeg: Double = 25, channel: String = "both")

/** The analog chain and the ADC of a bench, with its own formulas (not moire's fit model, not `simulate`):
  * the fringe of a read head with per-channel offset, gain and quadrature error, contrast that may change along
  * the travel (a function of the position in periods from the start), harmonics, warm-up of offset and gain,
  * sampling-clock jitter, phase noise of the motion (fast vibration: an AR(1) process in fringe phase), additive
  * pickup lines (mains hum, a switching line), a one-pole amplifier low-pass run sample by sample, capacitive
  * crosstalk (cos += tau d sin / dt), Gaussian noise, and ADCs with their own bowed transfer curve (INL) and an
  * optional stuck data line. Amplitudes are in full-scale units (1 = half the ADC range).
  * The low-pass acts on `cutoffChannel` (sin, cos or both); `cosCutoffHz`, when set, is the cos channel's own (each
  * channel's amplifier with its own cut-off); `rampFilter`: as the analog filter's exact response to an
  * input linear between samples (the one-pole IIR lags half a sample less than the analog filter, which on one
  * channel alone is a skew of its own). `skewS`: the cos channel sampled that much later than sin.
  */
final case class Bench(amp: Double = 0.8, offS: Double = 0.011, offC: Double = -0.007, gainC: Double = 1.012, quadDeg: Double = 0.9,
                       noiseLsb: Double = 1.0, bits: Int = 12, harmonics: Seq[Harmonic] = Nil,
                       contrast: Double => Double = _ => 1.0,
                       warmOffsetLsb: Double = 0, warmGainRel: Double = 0, warmTauS: Double = 1,
                       jitterS: Double = 0, phaseNoiseDeg: Double = 0, phaseNoiseTauS: Double = 0,
                       lines: Seq[(Double, Double)] = Nil,
                       cutoffHz: Double = 0, crosstalkTauS: Double = 0, cutoffChannel: String = "both", rampFilter: Boolean = false,
                       cosCutoffHz: Double = 0,
                       skewS: Double = 0,
                       inlSinLsb: Double = 0, inlCosLsb: Double = 0,
                       stuck: Option[(String, Int, Int)] = None, flickerLsb: Double = 0, seed: Long = 1) {
  require(jitterS == 0 || cutoffHz == 0, "jitter is modelled before the low-pass; use one or the other")
  def half: Int = 1 << (bits - 1)
  def lsb: Double = 1.0 / half

  /** The rms of noise and rounding in full-scale units: the floor a model that follows the signal reaches. */
  def floorRms: Double = math.sqrt(noiseLsb * noiseLsb + 1.0 / 12) * lsb

  /** ADC codes (offset binary) of both channels for a travel sampled at fs. */
  def codes(tr: Travel, fs: Double): (Array[Int], Array[Int]) = {
    val rnd = new Random(seed); val pn = new Random(seed + 7919)
    val n = tr.n
    val cs = new Array[Int](n); val cc = new Array[Int](n)
    val quad = math.toRadians(quadDeg)
    // each channel's cut-off (0: none) and its one-pole: y += alpha (x - y), or the ramp-invariant
    // y[i] = e y[i-1] + b0 x[i] + b1 x[i-1]
    val fcS = if (cutoffChannel != "cos") cutoffHz else 0.0
    val fcC = if (cosCutoffHz > 0) cosCutoffHz else if (cutoffChannel != "sin") cutoffHz else 0.0
    final case class Pole(fc: Double) {
      val on: Boolean = fc > 0
      val alpha: Double = if (on) 1 - math.exp(-2 * math.Pi * fc / fs) else 1.0
      private val wc = 2 * math.Pi * fc / fs
      val e1: Double = math.exp(-wc)
      val b0: Double = if (on) 1 - (1 - e1) / wc else 1.0; val b1: Double = if (on) (1 - e1) / wc - e1 else 0.0
      def next(y: Double, x: Double, xPrev: Double): Double = if (rampFilter) e1 * y + b0 * x + b1 * xPrev else y + alpha * (x - y)
      /** The steady state's gain and lag at fringe frequency f. */
      def at(f: Double): (Double, Double) = { val r = f / fc; (1 / math.sqrt(1 + r * r), math.atan(r)) }
    }
    val pS = Pole(fcS); val pC = Pole(fcC)
    var xsPrev = 0.0; var xcPrev = 0.0
    val rho = if (phaseNoiseTauS > 0) math.exp(-1 / (phaseNoiseTauS * fs)) else 0.0
    val pnStep = math.toRadians(phaseNoiseDeg) * math.sqrt(1 - rho * rho)
    var phaseNoise = math.toRadians(phaseNoiseDeg) * pn.nextGaussian()
    var ys = 0.0; var yc = 0.0
    val x0 = tr.periods(0)
    // 1/f noise of each channel (amplifier flicker, a supply's wander): one-pole noises with corners a decade apart
    // from 1 Hz to 10 kHz, each of the same variance, their sum flickerLsb rms; its own random numbers
    val fl = new Random(seed + 104729); val corners = Seq(1.0, 10.0, 100.0, 1e3, 1e4)
    val flRho = corners.map(fc => math.exp(-2 * math.Pi * fc / fs)).toArray
    val flSd = flickerLsb * lsb / math.sqrt(corners.size)
    val flS = Array.fill(corners.size)(flSd * fl.nextGaussian()); val flC = Array.fill(corners.size)(flSd * fl.nextGaussian())
    for (i <- 0 until n) {
      val t = i / fs
      if (i > 0) phaseNoise = rho * phaseNoise + pnStep * pn.nextGaussian()
      val dt = if (jitterS > 0) jitterS * rnd.nextGaussian() else 0.0
      val a = 2 * math.Pi * (tr.periods(i) + tr.speed(i) * dt) + phaseNoise
      val warm = 1 - math.exp(-t / warmTauS)
      val g = amp * contrast(tr.periods(i) - x0) * (1 + warmGainRel * warm)
      val ac = a + 2 * math.Pi * tr.speed(i) * skewS // the cos channel sampled skewS later
      var s = math.sin(a); var c = math.cos(ac + quad)
      for (h <- harmonics) {
        val hp = math.toRadians(h.phaseDeg)
        if (h.channel != "cos") s += h.rel * math.sin(h.order * a + hp)
        if (h.channel != "sin") c += h.rel * math.cos(h.order * (ac + quad) + hp)
      }
      var vs = g * s; var vc = gainC * g * c
      if (crosstalkTauS > 0) vc += crosstalkTauS * g * math.cos(a) * 2 * math.Pi * tr.speed(i)
      if (pS.on || pC.on) {
        if (i == 0) { // the filters' steady state at the first sample's frequency: no switch-on transient
          if (pS.on) { val (gain, lag) = pS.at(tr.speed(0)); ys = g * gain * math.sin(a - lag) }
          if (pC.on) { val (gain, lag) = pC.at(tr.speed(0)); yc = gainC * g * gain * math.cos(ac + quad - lag) }
        } else { ys = pS.next(ys, vs, xsPrev); yc = pC.next(yc, vc, xcPrev) }
        xsPrev = vs; xcPrev = vc
        if (pS.on) vs = ys
        if (pC.on) vc = yc
      }
      var pick = warmOffsetLsb * lsb * warm
      var flickS = 0.0; var flickC = 0.0
      if (flickerLsb > 0) for (k <- corners.indices) {
        val q = math.sqrt(1 - flRho(k) * flRho(k)) * flSd
        flS(k) = flRho(k) * flS(k) + q * fl.nextGaussian(); flC(k) = flRho(k) * flC(k) + q * fl.nextGaussian()
        flickS += flS(k); flickC += flC(k)
      }
      for ((hz, l) <- lines) pick += l * lsb * math.sin(2 * math.Pi * hz * t + 0.4)
      cs(i) = adc(offS + vs + pick + flickS + noiseLsb * lsb * rnd.nextGaussian(), inlSinLsb, "sin")
      cc(i) = adc(offC + vc + pick + flickC + noiseLsb * lsb * rnd.nextGaussian(), inlCosLsb, "cos")
    }
    (cs, cc)
  }

  /** A converter whose transfer curve bows by `bowLsb` at mid-scale (INL = bow (1 - u^2), u = -1 .. 1 over the range). */
  private def adc(v: Double, bowLsb: Double, ch: String): Int = {
    val u = math.max(-1.0, math.min(1.0, v))
    val c = math.max(0, math.min(2 * half - 1, math.floor(v * half + bowLsb * (1 - u * u) + 0.5).toInt + half))
    stuck match {
      case Some((`ch`, bit, 0)) => c & ~(1 << bit)
      case Some((`ch`, bit, _)) => c | (1 << bit)
      case _ => c
    }
  }
}

/** The recording's CSV text, written here and not by moire: metadata, a header, the codes and any reference. */
object BenchText {
  /** `refName` and `ref` (one value per sample, written with `refDigits` decimals) are optional. */
  def apply(source: String, fs: Double, bits: Int, codes: (Array[Int], Array[Int]), meta: Seq[(String, String)] = Nil,
            refName: String = "", ref: Array[Double] = null, refDigits: Int = 4): String = {
    val (s, c) = codes
    val sb = new StringBuilder(s.length * 20)
    sb.append("# moire-recording v1\n# sample_rate_hz: ").append(fs).append("\n# adc_bits: ").append(bits).append('\n')
    meta.foreach { case (k, v) => sb.append("# ").append(k).append(": ").append(v).append('\n') }
    sb.append("# source: ").append(source).append('\n')
    sb.append(if (refName.isEmpty) "sin,cos\n" else s"sin,cos,$refName\n")
    val fmt = s"%.${refDigits}f"
    for (i <- s.indices) {
      sb.append(s(i)).append(',').append(c(i))
      if (refName.nonEmpty) sb.append(',').append(String.format(java.util.Locale.ROOT, fmt, Double.box(ref(i))))
      sb.append('\n')
    }
    sb.toString
  }

  def recording(name: String, text: String): Recording = Recording.parse(name, text.split("\n").toIndexedSeq)
}
