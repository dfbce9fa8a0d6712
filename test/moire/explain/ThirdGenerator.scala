package moire.explain

import java.util.Random

/** A third generator, independent of `simulate` and of the second one: a rotary magnetic encoder (one signal
  * period per turn) whose magnet sits off the axis, turned with uneven speed and read by a second encoder, and a
  * linear scale read beside a laser interferometer. Own formulas, own rounding, own CSV text.
  *
  * Rotary: mechanical angle theta(t) = 2 pi (f t - a / (2 pi fw) cos(2 pi fw t + p)), i.e. speed f (1 + a sin(...)).
  * The eccentric magnet (offset ecc of the reading radius, towards angle eccDeg) turns the field the sensor sees:
  * field angle theta + 0.8 ecc sin(theta - eccDeg), field strength (1 + ecc cos(theta - eccDeg)). Channels are the
  * field's components with their own gains, offsets and a quadrature error; the reference encoder reports
  * theta in degrees, quantized to refBits per turn and wrapped to 0 .. 360, sampled `refDelayS` earlier.
  */
object ThirdGenerator {
  final case class Rotary(n: Int = 1000, fs: Double = 5000, turnsPerS: Double = 6.0, unevenRel: Double = 0.15,
                          unevenHz: Double = 2.3, ecc: Double = 0.0, eccDeg: Double = 35, bits: Int = 12, amp: Double = 0.8,
                          noiseLsb: Double = 0.7, refBits: Int = 14, refDelayS: Double = 0.0, withRef: Boolean = true,
                          periodsMeta: Boolean = false, seed: Long = 1)

  final case class Linear(n: Int = 20000, fs: Double = 100e3, umPerS: Double = 2000, unevenRel: Double = 0.3,
                          unevenHz: Double = 7.0, periodUm: Double = 20.0, h3: Double = 0.0, bits: Int = 12, amp: Double = 0.8,
                          noiseLsb: Double = 0.8, refNm: Double = 1.0, seed: Long = 1)

  /** An optical disk of `lines` lines per turn mounted off the axis by `ecc` of its reading radius: the head reads
    * the angle theta + atan2(ecc sin(theta - eccDeg), 1 + ecc cos(theta - eccDeg)); the reference is `ref_deg`.
    */
  final case class Disk(n: Int = 30000, fs: Double = 100e3, turnsPerS: Double = 4.0, unevenRel: Double = 0.1, unevenHz: Double = 5.3,
                        lines: Int = 256, ecc: Double = 0.0, eccDeg: Double = 120, bits: Int = 12, amp: Double = 0.8,
                        noiseLsb: Double = 0.7, refBits: Int = 22, seed: Long = 1)

  def disk(s: Disk): String = {
    val rnd = new Random(s.seed); val noise = s.noiseLsb / (1 << (s.bits - 1))
    val sb = new StringBuilder
    sb.append(s"# moire-recording v1\n# sample_rate_hz: ${s.fs}\n# adc_bits: ${s.bits}\n# lines_per_rev: ${s.lines}\n")
    sb.append("# source: third generator (optical disk off its axis)\nsin,cos,ref_deg\n")
    val q = 360.0 / (1 << s.refBits); val w = 2 * math.Pi * s.unevenHz
    for (i <- 0 until s.n) {
      val t = i / s.fs
      val th = 2 * math.Pi * s.turnsPerS * (t + s.unevenRel / w * math.sin(w * t))
      val x = th - math.toRadians(s.eccDeg)
      val a = s.lines * (th + math.atan2(s.ecc * math.sin(x), 1 + s.ecc * math.cos(x)))
      sb.append(code(0.004 + s.amp * math.sin(a) + noise * rnd.nextGaussian(), s.bits)).append(',')
        .append(code(-0.006 + 0.98 * s.amp * math.cos(a + 0.012) + noise * rnd.nextGaussian(), s.bits)).append(',')
      val r = math.floor(math.toDegrees(th) / q) * q
      sb.append(String.format(java.util.Locale.ROOT, "%.7f", Double.box(r - 360 * math.floor(r / 360)))).append('\n')
    }
    sb.toString
  }

  private def angle(s: Rotary, t: Double): Double = {
    val w = 2 * math.Pi * s.unevenHz
    2 * math.Pi * s.turnsPerS * (t - s.unevenRel / w * (math.cos(w * t + 0.7) - math.cos(0.7)))
  }

  /** Noise-free channel values (sin, cos) at mechanical angle th, before the ADC (full-scale units). */
  def field(s: Rotary, th: Double): (Double, Double) = {
    val x = th - math.toRadians(s.eccDeg)
    val a = th + 0.8 * s.ecc * math.sin(x); val m = s.amp * (1 + s.ecc * math.cos(x))
    (0.012 + 1.01 * m * math.sin(a), -0.008 + 0.99 * m * math.cos(a + math.toRadians(0.6)))
  }

  /** The true harmonic `order` of the mechanical angle relative to the fundamental, mean of the two channels,
    * from a dense integral over one turn of `field`.
    */
  def truthH(s: Rotary, order: Int): Double = {
    val m = 4096
    def coef(ch: Int, k: Int): Double = {
      var a = 0.0; var b = 0.0
      for (j <- 0 until m) {
        val th = 2 * math.Pi * j / m; val (vs, vc) = field(s, th); val v = if (ch == 0) vs else vc
        a += v * math.sin(k * th); b += v * math.cos(k * th)
      }
      math.hypot(a, b) * 2 / m
    }
    0.5 * (coef(0, order) / coef(0, 1) + coef(1, order) / coef(1, 1))
  }

  private def code(v: Double, bits: Int): Int = {
    val half = 1 << (bits - 1)
    math.max(0, math.min(2 * half - 1, math.floor(v * half + 0.5).toInt + half))
  }

  def rotary(s: Rotary): String = {
    val rnd = new Random(s.seed); val noise = s.noiseLsb / (1 << (s.bits - 1))
    val sb = new StringBuilder
    sb.append(s"# moire-recording v1\n# sample_rate_hz: ${s.fs}\n# adc_bits: ${s.bits}\n# adc: AS5600-like magnetic head\n")
    sb.append("# source: third generator (rotary, eccentric magnet)\n")
    if (s.periodsMeta) sb.append("# periods_per_turn: 1\n")
    sb.append(if (s.withRef) "sin,cos,ref_deg\n" else "sin,cos\n")
    val q = 360.0 / (1 << s.refBits)
    for (i <- 0 until s.n) {
      val t = i / s.fs; val th = angle(s, t)
      val (vs, vc) = field(s, th)
      sb.append(code(vs + noise * rnd.nextGaussian(), s.bits)).append(',').append(code(vc + noise * rnd.nextGaussian(), s.bits))
      if (s.withRef) {
        val deg = math.toDegrees(angle(s, t - s.refDelayS)); val r = math.floor(deg / q) * q
        sb.append(',').append(String.format(java.util.Locale.ROOT, "%.6f", Double.box(r - 360 * math.floor(r / 360))))
      }
      sb.append('\n')
    }
    sb.toString
  }

  /** A linear scale: position x(t) in um with uneven speed, fringe phase x / period, a 3rd harmonic h3 on both
    * channels; the interferometer's `ref_um` quantized to refNm.
    */
  def linear(s: Linear): String = {
    val rnd = new Random(s.seed); val noise = s.noiseLsb / (1 << (s.bits - 1))
    val sb = new StringBuilder
    sb.append(s"# moire-recording v1\n# sample_rate_hz: ${s.fs}\n# adc_bits: ${s.bits}\n# period_um: ${s.periodUm}\n")
    sb.append("# source: third generator (linear scale, interferometer reference)\nsin,cos,ref_um\n")
    val w = 2 * math.Pi * s.unevenHz
    for (i <- 0 until s.n) {
      val t = i / s.fs
      val x = 5.0 + s.umPerS * (t + s.unevenRel / w * math.sin(w * t))
      val a = 2 * math.Pi * x / s.periodUm
      val vs = 0.005 + s.amp * (math.sin(a) + s.h3 * math.sin(3 * a + 0.4))
      val vc = 0.003 + 1.02 * s.amp * (math.cos(a - 0.01) + s.h3 * math.cos(3 * a + 0.4))
      sb.append(code(vs + noise * rnd.nextGaussian(), s.bits)).append(',').append(code(vc + noise * rnd.nextGaussian(), s.bits))
      sb.append(',').append(String.format(java.util.Locale.ROOT, "%.4f", Double.box(math.floor(x * 1000 / s.refNm) * s.refNm / 1000))).append('\n')
    }
    sb.toString
  }
}
