package moire.explain

/** What quantization alone can put into a residual (issue 12, Build 4). With analog noise sigma below about half a
  * quantization step q, the error of rounding is not white: its mean and its variance depend on the signal value,
  * periodically with period q. Their first Fourier terms are q / pi (the sawtooth) and q^2 / pi^2 (its square);
  * Gaussian noise damps both by exp(-2 pi^2 sigma^2 / q^2). The step is known from the code format (`e.step`: the
  * ADC's LSB, or 2^k LSB when the codes use only the top bits).
  */
object Quantization {
  /** Analog noise variance: the residual's, less the uniform part q^2 / 12 of quantization (full scale^2). */
  def analogVar(e: SignalEngine): Double = math.max(0, math.min(e.noise.varS, e.noise.varC) - e.step * e.step / 12)

  def damping(e: SignalEngine): Double = math.exp(-2 * math.Pi * math.Pi * analogVar(e) / (e.step * e.step))

  /** Largest amplitude (full scale) of the quantization error's mean as a function of the signal value. */
  def biasBound(e: SignalEngine): Double = e.step / math.Pi * damping(e)

  /** Largest swing (full scale^2) of the quantization error's variance with the signal value. */
  def varianceModulation(e: SignalEngine): Double = e.step * e.step / (math.Pi * math.Pi) * damping(e)

  /** Effects that are functions of the signal value (harmonics, INL) smaller than the quantization bias are not findings. */
  def why(e: SignalEngine, c: Cand): Option[String] = {
    val amp = effects.Effects(c.effect).flatMap(_.valueAmplitude(c, e)).getOrElse(return None)
    val b = biasBound(e)
    if (amp >= b) None
    else Some(f"its amplitude ${amp / e.step}%.3g step is within what quantization makes at this noise (${b / e.step}%.3g step; " +
      f"analog noise ${math.sqrt(analogVar(e)) / e.step}%.2f step rms)")
  }
}
