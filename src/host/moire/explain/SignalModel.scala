package moire.explain

import moire.explain.effects._

/** Linear terms of the backward model (their columns are linear in the parameters); each belongs to one effect. */
sealed trait Term { def effect: Effect; def params: Int; def name: String = effect.name }
object Term {
  final case class Harm(order: Int, ch: String) extends Term { def effect: Effect = Harmonic; val params: Int = if (ch == "both") 4 else 2 }
  case object Drift extends Term { def effect: Effect = effects.Drift; val params = 4 }
  case object Am extends Term { def effect: Effect = AmplitudeModulation; val params = 2 }
  /** INL of one ADC (ch sin or cos) or the same on both. */
  final case class Inl(ch: String) extends Term { def effect: Effect = AdcNonlinearity; val params = 2 }
  case object Crosstalk extends Term { def effect: Effect = effects.Crosstalk; val params = 2 }
  final case class Interference(hz: Double) extends Term { def effect: Effect = effects.Interference; val params = 5 }
  /** Offsets and amplitudes changing along the travel (beam walk, scale contamination): linear in the fringe position. */
  case object Contrast extends Term { def effect: Effect = ContrastAlongTravel; val params = 4 }
  /** Amplitudes as a smooth function of the position: piecewise linear between `knots` (fractions 0..1 of the travel,
    * increasing, from 0 to 1; the first knot's value is the default part's), so a local band (contamination) is
    * representable. The knots are chosen from the data: their inner positions count as parameters (a free-knot spline).
    */
  final case class ContrastSpline(knots: Vector[Double]) extends Term {
    def effect: Effect = ContrastAlongTravel; val params: Int = 2 * (knots.size - 1) + math.max(0, knots.size - 2)
  }
  /** Warm-up: offsets and amplitudes approaching their final values as 1 - exp(-t / tauS) (tauS fitted: 5 parameters). */
  final case class Warmup(tauS: Double) extends Term { def effect: Effect = effects.Warmup; val params = 5 }
  /** Fringe phase modulated at `order` times the mechanical angle (the read angle's error): order 1 is eccentricity. */
  final case class AngleHarm(order: Int) extends Term { def effect: Effect = if (order == 1) Eccentricity else AngleHarmonic; val params = 2 }
}

/** A stuck (stuckAt 0/1) or bridged (wired-AND with bit `bridgedTo`) data line on channel 0 = sin, 1 = cos. */
final case class Fault(ch: Int, bit: Int, stuckAt: Int, bridgedTo: Int) {
  /** The codes the fault can turn into `code`'s pattern (its preimages). */
  def preimages(code: Int): Seq[Int] = {
    val m = 1 << bit
    if (stuckAt >= 0) Seq(code & ~m, code | m)
    else { val o = 1 << bridgedTo; if ((code & m) != 0) Seq(code) else Seq(code, code | m, code | o) }
  }
}

/** Saturation of channel ch (0 sin, 1 cos) at lo / hi (full-scale units; +-inf when absent). */
/** An amplifier's saturation on channel ch (0 sin, 1 cos) at lo and hi (infinite: none). `after`: the converter's noise
  * comes after it (a flat top with the noise on it, spread over a few codes), not before (a pile-up at one code).
  */
final case class Clip(ch: Int, lo: Double, hi: Double, after: Boolean = false) {
  /** The levels, and with the noise after it the variance of that noise alone. */
  def params: Int = (if (lo.isInfinite) 0 else 1) + (if (hi.isInfinite) 0 else 1) + (if (after) 1 else 0)
}

/** The whole backward model: the default part plus accepted effects. Cut-offs are infinite when absent. */
final case class ModelSpec(
  skewS: Double = 0.0,
  hasSkew: Boolean = false,
  bw: Map[String, Double] = Map.empty,
  terms: Vector[Term] = Vector.empty,
  faults: Vector[Fault] = Vector.empty,
  clips: Vector[Clip] = Vector.empty,
  jitter: Boolean = false,
  /** Phase noise of the motion (white per sample, radians of fringe phase): noise in proportion to the slope against
    * the fringe phase, not growing with speed as jitter's does.
    */
  phaseNoise: Boolean = false,
  /** Intensity noise of the light source (relative, white per sample): noise in proportion to the signal's value. */
  intensityNoise: Boolean = false,
  /** A search's stand-in for crosstalk, on the profile only (never fitted): each channel's gain grows by this much
    * per hertz of fringe frequency, as crosstalk makes it (`Candidates.crosstalkJoint`).
    */
  gainPerHz: (Double, Double) = (0.0, 0.0)
) {
  /** The noise model has a slope-dependent part (jitter or phase noise). */
  def slopeNoise: Boolean = jitter || phaseNoise || intensityNoise
  /** Parameters beyond the default part. */
  def extraParams: Int = (if (hasSkew) 1 else 0) + bw.size + terms.map(_.params).sum + faults.size + clips.map(_.params).sum + (if (jitter) 1 else 0) + (if (phaseNoise) 1 else 0) + (if (intensityNoise) 1 else 0)
}
