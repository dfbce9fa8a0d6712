package moire.adapt

import moire.paper.AccuracyRow
import moire.signal._

/** One measured run of the corrector model on simulated signals. Errors in degrees, times in ms. */
final case class AdaptRun(uncorrected: Double, corrected: Double, rmsCorrected: Double, maxCorrected: Double,
                          meanOffset: Double, convergedMs: Double, floor: Double)

/** Interpolation-error figures of the adaptive corrector (bit-accurate model, not RTL).
  *
  * Interpolation error = the systematic part of (phase of the output - true phase): the error is
  * averaged in `bins` bins of true phase over the measurement window (which averages out noise and
  * quantization), its mean (a fixed position offset) is removed, and the largest |bin| is reported.
  */
object AdaptFigures {
  val sampleRate = 50e6
  val adc: Adc = Adc(12, AdcFormat.TwosComplement)
  val goalDeg = 0.02
  /** Noise level used for the "with noise" rows: 0.5 LSB rms per channel on top of quantization. */
  val noiseLsb = 0.5
  val harmonics = Seq(Harmonic(2, 0.02), Harmonic(3, 0.01))

  /** The issue's imperfect signal: 2 % offset, 3 % gain mismatch, 5 degree phase error, 2 % H2 + 1 % H3. */
  def imperfect(noise: Boolean): SignalParams = SignalParams(amplitude = 0.9, offsetSin = 0.02, offsetCos = -0.02,
    gainSin = 1.0, gainCos = 0.97, phaseErrorDeg = 5.0, harmonics = harmonics,
    noiseRms = if (noise) noiseLsb * adc.lsb else 0.0, seed = 7)
  def harmonicsOnly: SignalParams = SignalParams(amplitude = 0.9, harmonics = harmonics)

  private def deg(r: Double) = math.toDegrees(r)

  /** Systematic error: mean error per phase bin (mean removed), its peak; and that mean. */
  final class Binned(bins: Int) {
    private val sum = new Array[Double](bins); private val cnt = new Array[Long](bins)
    def add(truePeriods: Double, err: Double): Unit = {
      val f = truePeriods - math.floor(truePeriods)
      val b = math.min(bins - 1, (f * bins).toInt)
      sum(b) += err; cnt(b) += 1
    }
    def mean: Double = sum.sum / cnt.sum
    def peak: Double = {
      val m = mean
      sum.indices.filter(cnt(_) > 0).map(i => math.abs(sum(i) / cnt(i) - m)).max
    }
  }

  /** Runs `model` for `totalMs` on the signal and measures over the last `measureMs`; convergence
    * time = end of the last 2^13-sample window whose 16-bin systematic error reaches the goal.
    */
  def run(sp: SignalParams, motion: Motion, model: AdaptModel, totalMs: Double, measureMs: Double): AdaptRun = {
    val p = model.p
    val windowSamples = 1 << 13
    val n = (totalMs * 1e-3 * sampleRate).toInt
    val s = SignalSim.generate(sp, motion, adc, sampleRate, n)
    val measureFrom = n - (measureMs * 1e-3 * sampleRate).toInt
    val unc = new Binned(256); val cor = new Binned(256); val floorB = new Binned(256)
    var win = new Binned(16); var winCount = 0; var lastBad = 0.0
    var sq = 0.0; var mx = 0.0; var cntM = 0L
    val floorSim = SignalSim.generate(SignalParams(amplitude = sp.amplitude), motion, adc, sampleRate, n - measureFrom)
    for (i <- 0 until n + p.latency) {
      val in = if (i < n) Some((s.sinSigned(i).toLong, s.cosSigned(i).toLong)) else None
      val out = model.step(in)
      val k = i - p.latency
      out.foreach { o =>
        val tp = s.truePeriods(k)
        val truth = 2 * math.Pi * tp
        val e = deg(moire.cordic.Fixed.angleDiff(math.atan2(o.sin.toDouble, o.cos.toDouble), truth))
        win.add(tp, e); winCount += 1
        if (winCount == windowSamples) {
          if (win.peak >= goalDeg) lastBad = (k + 1) / sampleRate * 1e3
          win = new Binned(16); winCount = 0
        }
        if (k >= measureFrom) {
          cor.add(tp, e); sq += e * e; mx = math.max(mx, math.abs(e)); cntM += 1
          unc.add(tp, deg(moire.cordic.Fixed.angleDiff(math.atan2(s.sinSigned(k).toDouble, s.cosSigned(k).toDouble), truth)))
          val j = k - measureFrom
          floorB.add(tp, deg(moire.cordic.Fixed.angleDiff(math.atan2(floorSim.sinSigned(j).toDouble, floorSim.cosSigned(j).toDouble),
            2 * math.Pi * floorSim.truePeriods(j))))
        }
      }
    }
    val m = cor.mean
    AdaptRun(unc.peak, cor.peak, math.sqrt(sq / cntM - m * m), mx, m, lastBad, floorB.peak)
  }

  def run(sp: SignalParams, hz: Double, totalMs: Double = 10, measureMs: Double = 2): AdaptRun =
    run(sp, Motion.Constant(hz, 0.123), new AdaptModel(AdaptParams()), totalMs, measureMs)

  /** Frequencies of the rows; the noise-free rows use them 0.14 % higher so that the sampling phase
    * walks (at exactly 400, 100 or 50 samples per period the 12-bit quantization error repeats every
    * period and is itself a fixed interpolation error of about 0.016 degree: the "floor").
    */
  val freqs: Seq[Double] = Seq(125e3, 500e3, 1e6)
  val walk: Double = 1 + 0.001 * math.sqrt(2)
  val totalMs = 10.0
  val measureMs = 2.0

  private def khz(hz: Double) = f"${hz / 1e3}%.2f kHz"
  private def note(r: AdaptRun) =
    f"uncorrected ${r.uncorrected}%.3f deg; converged after ${r.convergedMs}%.2f ms; per sample rms ${r.rmsCorrected}%.4f max ${r.maxCorrected}%.4f deg; " +
      f"quantization floor ${r.floor}%.4f deg"

  def rows(progress: String => Unit = _ => ()): Seq[AccuracyRow] = {
    val src = "issue3"
    val out = Seq.newBuilder[AccuracyRow]
    progress("adaptive correction (iC-TW8 case)")
    val anchor = run(harmonicsOnly.copy(noiseRms = noiseLsb * adc.lsb), 125e3)
    out += AccuracyRow("iC-TW8", "2 % H2 + 1 % H3 at 125.00 kHz, corrected interpolation error", 0.04, anchor.corrected, "deg",
      anchor.corrected <= 0.04, f"ours uncorrected ${anchor.uncorrected}%.3f deg (iC-TW8: 1.88); 12-bit ADC at 50 MS/s, 0.5 LSB rms noise")
    for (hz <- freqs) {
      progress(s"adaptive correction ${khz(hz)}")
      val r = run(imperfect(noise = true), hz, totalMs, measureMs)
      out += AccuracyRow(src, s"adaptive: all imperfections, ${khz(hz)}, 0.5 LSB noise, interpolation error", goalDeg, r.corrected,
        "deg", r.corrected < goalDeg, "paper column = the issue's goal; " + note(r))
      out += AccuracyRow(src, s"adaptive: convergence time, ${khz(hz)}, 0.5 LSB noise", ujson.Str("-"), r.convergedMs, "ms",
        r.convergedMs < totalMs - measureMs, f"last 8192-sample window with a 16-bin error >= $goalDeg deg ends here")
      val q = run(imperfect(noise = false), hz * walk, totalMs, measureMs)
      out += AccuracyRow(src, s"adaptive: all imperfections, ${khz(hz * walk)}, no noise, interpolation error", goalDeg, q.corrected,
        "deg", q.corrected < goalDeg, note(q))
    }
    out.result()
  }

  /** The figures of docs/adaptive-correction.md: `./sbt "runMain moire.adapt.AdaptFigures"`. */
  def main(args: Array[String]): Unit = {
    println("case                                   freq kHz   uncorr deg  corr deg  rms deg  max deg  conv ms  floor deg")
    def line(name: String, hz: Double, r: AdaptRun): Unit =
      println(f"$name%-38s ${hz / 1e3}%9.2f  ${r.uncorrected}%10.3f  ${r.corrected}%8.4f  ${r.rmsCorrected}%7.4f  ${r.maxCorrected}%7.4f  ${r.convergedMs}%7.2f  ${r.floor}%9.4f")
    for (hz <- freqs.flatMap(f => Seq(f, f * walk)); noise <- Seq(true, false))
      line(s"all imperfections, ${if (noise) "0.5 LSB noise" else "no noise"}", hz, run(imperfect(noise), hz, totalMs, measureMs))
    line("H2 + H3 only (iC-TW8 case), 0.5 LSB", 125e3, run(harmonicsOnly.copy(noiseRms = noiseLsb * adc.lsb), 125e3))
    line("all, backwards, 0.5 LSB", -500e3, run(imperfect(true), -500e3, totalMs, measureMs))
    line("all, no harmonic table, 0.5 LSB", 500e3,
      run(imperfect(true), Motion.Constant(500e3, 0.123), new AdaptModel(AdaptParams(harmonicEntries = 0)), totalMs, measureMs))
    line("all, 2 LSB noise", 500e3, run(imperfect(true).copy(noiseRms = 2 * adc.lsb), 500e3, totalMs, measureMs))
  }
}
