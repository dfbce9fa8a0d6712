package moire.explain

import java.util.Random

/** A second, deliberately simple generator, independent of `simulate` and moire.signal: explicit chirp
  * formulas, a real first-order IIR low-pass run sample by sample, its own rounding and its own CSV writer.
  */
object SecondGenerator {
  final case class Spec(n: Int = 100000, fs: Double = 10e6, f0: Double = 20e3, f1: Double = 220e3, amp: Double = 0.8,
                        offS: Double = 0.01, offC: Double = -0.005, phaseErrDeg: Double = 1.5, noiseLsb: Double = 1.2,
                        skewS: Double = 0.0, h3Sin: Double = 0.0, iirCutoffHz: Double = 0.0, seed: Long = 1,
                        stepLsb: Double = 0.0)

  def text(s: Spec): String = {
    val rnd = new Random(s.seed)
    val warm = 4000; val total = s.n + warm; val dur = total / s.fs
    def periods(t: Double) = s.f0 * t + 0.5 * (s.f1 - s.f0) / dur * t * t
    val alpha = if (s.iirCutoffHz > 0) 1 - math.exp(-2 * math.Pi * s.iirCutoffHz / s.fs) else 1.0
    var ys = 0.0; var yc = 0.0
    val sb = new StringBuilder
    sb.append("# moire-recording v1\n# sample_rate_hz: ").append(s.fs).append("\n# adc_bits: 12\n# source: second generator\nsin,cos\n")
    for (i <- 0 until total) {
      val t = i / s.fs
      val a = 2 * math.Pi * periods(t); val b = 2 * math.Pi * periods(t + s.skewS)
      val xs = s.amp * (math.sin(a) + s.h3Sin * math.sin(3 * a))
      val xc = s.amp * math.cos(b + math.toRadians(s.phaseErrDeg))
      if (i == 0) { ys = xs; yc = xc } else { ys += alpha * (xs - ys); yc += alpha * (xc - yc) }
      if (i >= warm) {
        def code(v: Double) = math.max(0, math.min(4095, math.round(v * 2048).toInt + 2048))
        val step = if (i - warm >= s.n / 2) s.stepLsb / 2048 else 0.0 // an offset jump: not in the catalogue
        sb.append(code(s.offS + step + ys + s.noiseLsb / 2048 * rnd.nextGaussian())).append(',')
          .append(code(s.offC + yc + s.noiseLsb / 2048 * rnd.nextGaussian())).append('\n')
      }
    }
    sb.toString
  }
}
