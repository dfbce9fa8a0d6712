package moire.explain.evidence

import java.util.Random

/** A motion sampled at the recording's instants: the fringe phase in periods and its rate in periods/s. */
final case class Travel(periods: Array[Double], speed: Array[Double]) {
  def n: Int = periods.length
  /** Both motions at once (a scan with shocks on top). */
  def plus(o: Travel): Travel = Travel(Array.tabulate(n)(i => periods(i) + o.periods(i)), Array.tabulate(n)(i => speed(i) + o.speed(i)))
}

/** Kinds of motion a bench has, each from its own formula (not the fit model's cubic trajectory): steady drives,
  * chirps, sinusoidal scans that turn round, stick-slip, shocks that ring, vibration, turntables and slow wander.
  */
object Motions {
  /** Samples x(t) and its rate v(t) given as formulas. */
  def formula(n: Int, fs: Double)(x: Double => Double, v: Double => Double): Travel = {
    val p = new Array[Double](n); val s = new Array[Double](n)
    for (i <- 0 until n) { val t = i / fs; p(i) = x(t); s(i) = v(t) }
    Travel(p, s)
  }

  /** The rate by central differences, for motions built sample by sample. */
  def fromPeriods(p: Array[Double], fs: Double): Travel = {
    val n = p.length
    val s = Array.tabulate(n)(i => (p(math.min(n - 1, i + 1)) - p(math.max(0, i - 1))) * fs / (math.min(n - 1, i + 1) - math.max(0, i - 1)))
    Travel(p, s)
  }

  def constant(n: Int, fs: Double, hz: Double): Travel = formula(n, fs)(hz * _, _ => hz)

  /** Fringe frequency going linearly from f0 to f1 over the record. */
  def chirp(n: Int, fs: Double, f0: Double, f1: Double): Travel = {
    val d = n / fs
    formula(n, fs)(t => f0 * t + 0.5 * (f1 - f0) * t * t / d, t => f0 + (f1 - f0) * t / d)
  }

  /** A stage scanned to and fro: x = span/2 (1 - cos(2 pi rate t + start)), turning round at both ends. */
  def sinusoidalScan(n: Int, fs: Double, spanPeriods: Double, rateHz: Double, startRad: Double = 0.3): Travel = {
    val w = 2 * math.Pi * rateHz
    formula(n, fs)(t => spanPeriods / 2 * (1 - math.cos(w * t + startRad)), t => spanPeriods / 2 * w * math.sin(w * t + startRad))
  }

  /** A drive at f0 (periods/s) with mechanical vibration at vibHz of vibPeriods peak. */
  def vibrating(n: Int, fs: Double, f0: Double, vibHz: Double, vibPeriods: Double): Travel = {
    val w = 2 * math.Pi * vibHz
    formula(n, fs)(t => f0 * t + vibPeriods * math.sin(w * t + 0.8), t => f0 + vibPeriods * w * math.cos(w * t + 0.8))
  }

  /** Stick-slip: the stage creeps at `creep` periods/s while the friction holds, then slips `slipPeriods` forward
    * within `slipS` seconds (a raised-cosine speed pulse); slips come every `everyS` seconds, +-30 % at random.
    */
  def stickSlip(n: Int, fs: Double, creep: Double, slipPeriods: Double, everyS: Double, slipS: Double, seed: Long): Travel = {
    val rnd = new Random(seed)
    val p = new Array[Double](n)
    var next = everyS * (0.3 + 0.7 * rnd.nextDouble())
    var slips = 0.0 // periods slipped before the current slip
    var cur = -1.0 // start of the current slip, -1 when stuck
    var size = slipPeriods
    for (i <- 0 until n) {
      val t = i / fs
      if (cur < 0 && t >= next) { cur = next; size = slipPeriods * (0.7 + 0.6 * rnd.nextDouble()) }
      var inSlip = 0.0
      if (cur >= 0) {
        val u = (t - cur) / slipS
        if (u >= 1) { slips += size; cur = -1; next = t + everyS * (0.7 + 0.6 * rnd.nextDouble()) }
        else inSlip = size * (u - math.sin(2 * math.Pi * u) / (2 * math.Pi))
      }
      p(i) = creep * t + slips + inSlip
    }
    fromPeriods(p, fs)
  }

  /** A drive at f0 hit by shocks at random instants (mean interval `meanS`): each moves the stage by up to
    * `kickPeriods` (either way), and the stage rings into place at `resonanceHz` with quality factor `q`.
    */
  def jerky(n: Int, fs: Double, f0: Double, kickPeriods: Double, meanS: Double, resonanceHz: Double, q: Double, seed: Long): Travel = {
    val rnd = new Random(seed)
    val p = Array.tabulate(n)(i => f0 * i / fs)
    val w = 2 * math.Pi * resonanceHz; val z = 1 / (2 * q); val wd = w * math.sqrt(1 - z * z)
    val settle = math.min(n, (10 / (z * w) * fs).toInt)
    var t = meanS * rnd.nextDouble()
    while (t < n / fs) {
      val kick = kickPeriods * (2 * rnd.nextDouble() - 1)
      val i0 = math.ceil(t * fs).toInt
      for (i <- i0 until n) {
        val tau = i / fs - t
        // step response of a damped oscillator: 1 - e^(-z w tau) (cos wd tau + z / sqrt(1 - z^2) sin wd tau)
        val h = if (i - i0 < settle) 1 - math.exp(-z * w * tau) * (math.cos(wd * tau) + z / math.sqrt(1 - z * z) * math.sin(wd * tau)) else 1.0
        p(i) += kick * h
      }
      t += -meanS * math.log(1 - rnd.nextDouble())
    }
    fromPeriods(p, fs)
  }

  /** A turntable: mechanical angle in turns, speed turnsPerS (1 + unevenRel sin(2 pi unevenHz t + 0.7)); sampled
    * `delayS` late (a reference read with latency) when given.
    */
  def turntable(n: Int, fs: Double, turnsPerS: Double, unevenRel: Double, unevenHz: Double, delayS: Double = 0): Travel = {
    val w = 2 * math.Pi * unevenHz
    formula(n, fs)(t => 0.13 + turnsPerS * (t - delayS - unevenRel / w * (math.cos(w * (t - delayS) + 0.7) - math.cos(0.7))),
      t => turnsPerS * (1 + unevenRel * math.sin(w * (t - delayS) + 0.7)))
  }

  /** Slow wander, as an interferometer arm drifting with temperature: a smooth S-shaped drift of `totalPeriods`
    * plus a random walk of `walkPeriods` rms per sample, low-passed over `smoothSamples` samples.
    */
  def wander(n: Int, fs: Double, totalPeriods: Double, walkPeriods: Double, smoothSamples: Double, seed: Long): Travel = {
    val rnd = new Random(seed)
    val p = new Array[Double](n)
    var walk = 0.0; var rate = 0.0; val a = 1 / smoothSamples
    for (i <- 0 until n) {
      rate += a * (walkPeriods * rnd.nextGaussian() - rate)
      walk += rate
      val u = i.toDouble / n
      p(i) = totalPeriods * (u - math.sin(2 * math.Pi * u) / (2 * math.Pi)) + walk
    }
    fromPeriods(p, fs)
  }
}
