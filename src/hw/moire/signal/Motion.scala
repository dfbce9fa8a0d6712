package moire.signal

/** Position of the grating against time, as the fringe phase in periods (1.0 = one grating period). */
sealed trait Motion {
  /** Phase in periods at time t (seconds). */
  def periods(t: Double): Double
  /** Fringe frequency in Hz (periods per second) at time t. */
  def frequency(t: Double): Double
}
object Motion {
  /** Constant fringe frequency `hz` (negative = backwards) from `start` periods. */
  final case class Constant(hz: Double, start: Double = 0.0) extends Motion {
    def periods(t: Double): Double = start + hz * t
    def frequency(t: Double): Double = hz
  }
  /** Frequency ramping linearly from `hz0` to `hz1` over `duration` seconds, then holding. */
  final case class Ramp(hz0: Double, hz1: Double, duration: Double, start: Double = 0.0) extends Motion {
    require(duration > 0, s"ramp duration must be > 0, got $duration")
    private val a = (hz1 - hz0) / duration
    def periods(t: Double): Double =
      if (t <= duration) start + hz0 * t + 0.5 * a * t * t
      else start + hz0 * duration + 0.5 * a * duration * duration + hz1 * (t - duration)
    def frequency(t: Double): Double = if (t <= duration) hz0 + a * t else hz1
  }
  /** Back-and-forth motion: amplitude `periodsPeak` periods, oscillation at `rateHz` (reverses twice per cycle). */
  final case class Oscillate(periodsPeak: Double, rateHz: Double, start: Double = 0.0) extends Motion {
    private val w = 2 * math.Pi * rateHz
    def periods(t: Double): Double = start + periodsPeak * math.sin(w * t)
    def frequency(t: Double): Double = periodsPeak * w * math.cos(w * t)
  }
}
