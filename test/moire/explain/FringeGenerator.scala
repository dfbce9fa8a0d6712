package moire.explain

import moire.recording.Recording

import java.util.Random

/** A third generator, independent of `simulate`, moire.signal and the fit model: a homodyne interferometer or
  * linear scale with its own motion formulas (constant, chirp, back-and-forth, uneven: a drive plus vibration),
  * intensity-like contrast and offset that change along the travel (beam walk), warm-up and linear drift in time,
  * Gaussian noise, rounding to `bits`-bit offset-binary codes, optionally shifted into a wider `formatBits` word,
  * and its own CSV text.
  */
object FringeGenerator {
  /** motion: "constant" (f0), "chirp" (f0 -> f1), "swell" (f0 up to f1 and back), "reverse" (peak `travel` periods at
    * `rateHz`), "vibration" (a standstill shaken at `rateHz` and 0.185 x it, `travel` scaling), "uneven" (drive f0
    * plus two vibrations whose speed peaks at `wobble` x f0, so it may reverse), "dwell" (moves of `travel` periods at
    * `rateHz` moves a second, each followed by a standstill).
    */
  final case class Spec(n: Int = 50000, fs: Double = 2e6, motion: String = "constant", f0: Double = 20e3, f1: Double = 60e3,
                        travel: Double = 50, rateHz: Double = 100, wobble: Double = 0.5, amp: Double = 0.8, offS: Double = 0.01,
                        offC: Double = -0.008, gainC: Double = 1.01, phaseErrDeg: Double = 1.0, noiseLsb: Double = 1.0,
                        bits: Int = 12, formatBits: Int = 0, seed: Long = 1,
                        contrastPerPeriod: Double = 0.0, offsetPerPeriod: Double = 0.0,
                        warmGain: Double = 0.0, warmOffset: Double = 0.0, warmTauS: Double = 0.01,
                        driftGainPerS: Double = 0.0, driftOffsetPerS: Double = 0.0, humFs: Double = 0.0, humHz: Double = 50.0,
                        h2: Double = 0.0, h2Deg: Double = -60, clipFs: Double = 0.0, noiseAfterLsb: Double = 0.0,
                        holds: Seq[(Int, Int)] = Nil, zeros: Seq[(Int, Int)] = Nil, cuts: Seq[(Int, Int)] = Nil,
                        wanderLsb: Double = 0.0, intensityRel: Double = 0.0,
                        intensityRho: Double = 0.0)

  /** Fringe phase in periods at time t. */
  def periods(s: Spec, t: Double): Double = s.motion match {
    case "constant" => s.f0 * t
    case "chirp" => s.f0 * t + 0.5 * (s.f1 - s.f0) * t * t / (s.n / s.fs)
    case "swell" =>
      // the speed rises from f0 to f1 and falls back over the record: f0 + (f1 - f0) (1 - cos(2 pi t / T)) / 2
      val dur = s.n / s.fs
      s.f0 * t + 0.5 * (s.f1 - s.f0) * (t - dur / (2 * math.Pi) * math.sin(2 * math.Pi * t / dur))
    case "reverse" => s.travel * (1 - math.cos(2 * math.Pi * s.rateHz * t))
    case "uneven" =>
      // vibration at 137 Hz and 311 Hz; their speed amplitudes are wobble * f0 * (0.7, 0.3)
      val w1 = 2 * math.Pi * 137; val w2 = 2 * math.Pi * 311
      s.f0 * t + s.wobble * s.f0 * (0.7 * math.sin(w1 * t + 0.4) / w1 + 0.3 * math.sin(w2 * t + 1.9) / w2)
    case "vibration" =>
      // a standstill shaken at rateHz and 0.185 x rateHz: peak travel * (0.3, 0.1) periods about 0.2
      s.travel * (0.3 * math.sin(2 * math.Pi * s.rateHz * t) + 0.1 * math.sin(2 * math.Pi * 0.185 * s.rateHz * t)) + 0.2
    case "dwell" =>
      // moves of `travel` periods, `rateHz` a second: each an S-curve (no jerk at its ends) over 60 % of its time, then
      // a standstill
      val per = 1 / s.rateHz; val k = math.floor(t / per); val x = math.min(1.0, (t - k * per) / (0.6 * per))
      s.travel * (k + x - math.sin(2 * math.Pi * x) / (2 * math.Pi))
    case "trap" =>
      // moves back and forth with a trapezoid speed (up to f0 in 5 ms, 10 ms at f0, down in 5 ms), 5 ms still at each end:
      // the acceleration steps, which no cubic follows across
      val ta = 0.005; val tc = 0.01; val td = 0.005; val half = 2 * ta + tc + td
      def move(u: Double) = {
        val w = math.min(u, 2 * ta + tc); val u3 = w - ta - tc
        if (w < ta) 0.5 * s.f0 / ta * w * w
        else if (w < ta + tc) 0.5 * s.f0 * ta + s.f0 * (w - ta)
        else 0.5 * s.f0 * ta + s.f0 * tc + s.f0 * u3 - 0.5 * s.f0 / ta * u3 * u3
      }
      val tt = t % (2 * half)
      if (tt < half) move(tt) else move(half) - move(tt - half)
    case other => throw new IllegalArgumentException(s"motion $other")
  }

  def recording(s: Spec): Recording = Recording.parse("fringe", text(s).split("\n").toIndexedSeq)

  def text(s: Spec): String = {
    val rnd = new Random(s.seed)
    val fb = if (s.formatBits > 0) s.formatBits else s.bits
    val shift = fb - s.bits
    val top = (1 << s.bits) - 1; val half = 1 << (s.bits - 1)
    val x0 = periods(s, 0)
    val sb = new StringBuilder(s.n * 12)
    sb.append("# moire-recording v1\n# sample_rate_hz: ").append(s.fs).append("\n# adc_bits: ").append(fb)
      .append("\n# adc_format: offset-binary\n# source: fringe generator\nsin,cos\n")
    val pe = math.toRadians(s.phaseErrDeg)
    var last = ""
    // a random walk of both offsets (1/f-like wander of the read head's electronics), wanderLsb per sample
    val wrnd = new Random(s.seed + 7); var wander = 0.0; var power = 0.0
    var i = 0
    while (i < s.n) {
      if (s.wanderLsb > 0) wander += s.wanderLsb / half * wrnd.nextGaussian()
      // the light source's power, the same factor on both channels' fringe
      // (intensityRho: an AR(1) process of that correlation from sample to sample, the same rms: a modulation, not white)
      if (s.intensityRel > 0) power = s.intensityRho * power + math.sqrt(1 - s.intensityRho * s.intensityRho) * s.intensityRel * wrnd.nextGaussian()
      val light = 1 + power
      val t = i / s.fs
      val x = periods(s, t); val a = 2 * math.Pi * x
      val warm = 1 - math.exp(-t / s.warmTauS)
      val g = light * (1 + s.contrastPerPeriod * (x - x0)) * (1 + s.warmGain * warm + s.driftGainPerS * t)
      // a pickup line (mains hum) common to both channels
      val o = wander + s.offsetPerPeriod * (x - x0) + s.warmOffset * warm + s.driftOffsetPerS * t + s.humFs * math.sin(2 * math.Pi * s.humHz * t)
      // a 2nd harmonic of the fringe turning with it on both channels (relative to the amplitude)
      val h = 2 * a + math.toRadians(s.h2Deg)
      val vs = s.offS + o + s.amp * g * (math.sin(a) + s.h2 * math.sin(h)) + s.noiseLsb / half * rnd.nextGaussian()
      val vc = s.offC + o + s.amp * s.gainC * g * (math.cos(a + pe) + s.h2 * math.cos(h)) + s.noiseLsb / half * rnd.nextGaussian()
      def code(v: Double) = math.max(0, math.min(top, math.floor(v * half + 0.5).toInt + half)) << shift
      // an amplifier that saturates at +- clipFs on both channels, after the read head's noise
      def clip(v: Double) = if (s.clipFs > 0) math.max(-s.clipFs, math.min(s.clipFs, v)) else v
      // the converter's own noise, after the amplifier (and its saturation)
      def adc(v: Double) = if (s.noiseAfterLsb > 0) v + s.noiseAfterLsb / half * rnd.nextGaussian() else v
      // data lost: runs [a, b) cut out, or where a FIFO repeats the last word, or where both converters read 0
      val (cs, cc) = (code(adc(clip(vs))), code(adc(clip(vc))))
      // samples cut out of the capture: the next one follows with no gap in the rows (a FIFO that overflowed)
      if (s.cuts.exists { case (a, b) => i >= a && i < b }) ()
      else if (s.zeros.exists { case (a, b) => i >= a && i < b }) sb.append("0,0\n")
      else if (s.holds.exists { case (a, b) => i >= a && i < b }) sb.append(last)
      else { last = s"$cs,$cc\n"; sb.append(last) }
      i += 1
    }
    sb.toString
  }
}
