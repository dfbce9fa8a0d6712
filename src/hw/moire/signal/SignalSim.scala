package moire.signal

import scala.util.Random

/** A harmonic of the fringe on one or both channels: amplitude relative to the fundamental. */
final case class Harmonic(order: Int, amplitude: Double, phaseDeg: Double = 0.0, channel: Channel = Channel.Both) {
  require(order >= 2, s"harmonic order must be >= 2, got $order")
}

sealed abstract class Channel(val name: String)
object Channel {
  case object Sin extends Channel("sin")
  case object Cos extends Channel("cos")
  case object Both extends Channel("both")
}

/** Imperfections of a pair of Moire signals. Amplitudes and offsets are fractions of ADC full scale.
  *
  * sin channel: offsetSin + amplitude * gainSin * sin(phi) + harmonics
  * cos channel: offsetCos + amplitude * gainCos * cos(phi + phaseErrorDeg) + harmonics
  */
final case class SignalParams(
  amplitude: Double = 0.9,
  offsetSin: Double = 0.0,
  offsetCos: Double = 0.0,
  gainSin: Double = 1.0,
  gainCos: Double = 1.0,
  phaseErrorDeg: Double = 0.0,
  harmonics: Seq[Harmonic] = Nil,
  noiseRms: Double = 0.0,
  seed: Long = 1L
) {
  require(amplitude > 0, s"amplitude must be > 0, got $amplitude")
  require(noiseRms >= 0, s"noiseRms must be >= 0, got $noiseRms")
}

/** Sampled signals: pin codes and OTR flags per channel, with the true phase in periods. */
final case class Samples(
  sampleRateHz: Double,
  adc: Adc,
  sin: Array[Int],
  cos: Array[Int],
  otrSin: Array[Boolean],
  otrCos: Array[Boolean],
  truePeriods: Array[Double]
) {
  def length: Int = sin.length
  /** Signed ADC values (two's complement) of sample i. */
  def sinSigned(i: Int): Int = adc.fromPins(sin(i))
  def cosSigned(i: Int): Int = adc.fromPins(cos(i))
}

/** The one signal simulator: analog sin/cos from a motion and imperfections, sampled by an ADC. */
object SignalSim {
  /** Analog values (full scale 1) of both channels at fringe phase `periods`. */
  def analog(p: SignalParams, periods: Double): (Double, Double) = {
    val phi = 2 * math.Pi * periods
    var s = p.offsetSin + p.amplitude * p.gainSin * math.sin(phi)
    var c = p.offsetCos + p.amplitude * p.gainCos * math.cos(phi + math.toRadians(p.phaseErrorDeg))
    p.harmonics.foreach { h =>
      val hp = math.toRadians(h.phaseDeg)
      if (h.channel != Channel.Cos) s += p.amplitude * p.gainSin * h.amplitude * math.sin(h.order * phi + hp)
      if (h.channel != Channel.Sin) c += p.amplitude * p.gainCos * h.amplitude * math.cos(h.order * phi + hp)
    }
    (s, c)
  }

  def generate(p: SignalParams, motion: Motion, adc: Adc, sampleRateHz: Double, n: Int): Samples = {
    require(sampleRateHz > 0, s"sample rate must be > 0, got $sampleRateHz")
    require(n >= 0, s"sample count must be >= 0, got $n")
    val rnd = new Random(p.seed)
    val sin = new Array[Int](n); val cos = new Array[Int](n)
    val os = new Array[Boolean](n); val oc = new Array[Boolean](n)
    val tp = new Array[Double](n)
    var i = 0
    while (i < n) {
      val t = i / sampleRateHz
      val ph = motion.periods(t)
      val (s, c) = analog(p, ph)
      val a = adc.sample(s + p.noiseRms * rnd.nextGaussian())
      val b = adc.sample(c + p.noiseRms * rnd.nextGaussian())
      sin(i) = a.code; os(i) = a.otr; cos(i) = b.code; oc(i) = b.otr; tp(i) = ph
      i += 1
    }
    Samples(sampleRateHz, adc, sin, cos, os, oc, tp)
  }
}
