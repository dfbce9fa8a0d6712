package moire.loop

import moire.board.AnalogSample

/** An independent bench for the end-to-end test, with its own formulas (not moire.signal, not explain's
  * physics model): a grating read head on a stage whose speed wobbles, and a reference encoder on the same
  * stage.
  *
  * Position in fringe periods: p(t) = v t + (v w / (2 pi f)) (1 - cos(2 pi f t)), so the speed is
  * v (1 + w sin(2 pi f t)). Fringe with a symmetric distortion of order `order` (relative `harmonic`):
  * cos channel cos(th) + h cos(k th), sin channel its quarter-period shift. The cos ADC's clock arrives
  * `skewS` late: the cos channel is taken at t + skewS. Offsets, gains, a quadrature error and Gaussian
  * noise (full-scale units, seeded). The reference encoder counts `refPerPeriod` per fringe period; its Z
  * marks every speed / wobbleHz periods, that is the start of each wobble cycle (the speed only changes
  * sign for wobble > 1), so a burst triggered at Z starts at the same point of the motion.
  */
final case class BenchHead(
  fs: Double, speed: Double, wobble: Double = 0.5, wobbleHz: Double = 2e3,
  amplitude: Double = 0.8, offsetSin: Double = 0.006, offsetCos: Double = -0.004, gainCos: Double = 0.985,
  quadratureDeg: Double = 0.8, harmonic: Double = 0.0, order: Int = 3, skewS: Double = 0.0,
  noiseFs: Double = 0.6 / 2048, seed: Long = 11, refPerPeriod: Int = 16) {
  private val rnd = new java.util.Random(seed)
  private val twoPi = 2 * math.Pi

  def periods(t: Double): Double = speed * t + speed * wobble / (twoPi * wobbleHz) * (1 - math.cos(twoPi * wobbleHz * t))

  /** The fringe at phase th (radians): (sin channel, cos channel) before offsets and gains. */
  def fringe(th: Double): (Double, Double) = {
    val k = order
    // cos(th) + h cos(k th) shifted by a quarter period for the sin channel: th -> th - pi/2
    (math.sin(th) + harmonic * math.cos(k * (th - math.Pi / 2)), math.cos(th) + harmonic * math.cos(k * th))
  }

  def analog(i: Int): AnalogSample = {
    val t = i / fs
    val ps = periods(t); val pc = periods(t + skewS)
    val s = amplitude * fringe(twoPi * ps)._1 + offsetSin + noiseFs * rnd.nextGaussian()
    val c = amplitude * gainCos * fringe(twoPi * pc + math.toRadians(quadratureDeg))._2 + offsetCos + noiseFs * rnd.nextGaussian()
    AnalogSample(s, c, ps)
  }

  /** The reference encoder's count at time t. */
  def refCount(t: Double): Long = math.floor(periods(t) * refPerPeriod).toLong
  /** Counts between Z marks. */
  val zCounts: Long = math.round(speed / wobbleHz * refPerPeriod)
  /** The reference encoder's Z level at count n. */
  def refZ(n: Long): Boolean = Math.floorMod(n, zCounts) == 0
}
