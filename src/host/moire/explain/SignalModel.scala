package moire.explain

/** Linear terms of the backward model (their columns are linear in the parameters). */
sealed trait Term { def name: String; def params: Int }
object Term {
  final case class Harm(order: Int, ch: String) extends Term { val name = "harmonic"; val params: Int = if (ch == "both") 4 else 2 }
  case object Drift extends Term { val name = "drift"; val params = 4 }
  case object Am extends Term { val name = "amplitude_modulation"; val params = 2 }
  case object Inl extends Term { val name = "adc_nonlinearity"; val params = 2 }
  case object Crosstalk extends Term { val name = "crosstalk"; val params = 2 }
  final case class Interference(hz: Double) extends Term { val name = "interference"; val params = 5 }
  /** Offsets and amplitudes changing along the travel (beam walk, scale contamination): linear in the fringe position. */
  case object Contrast extends Term { val name = "contrast_along_travel"; val params = 4 }
  /** Warm-up: offsets and amplitudes approaching their final values as 1 - exp(-t / tauS) (tauS fitted: 5 parameters). */
  final case class Warmup(tauS: Double) extends Term { val name = "warmup"; val params = 5 }
  /** Fringe phase modulated at `order` times the mechanical angle (the read angle's error): order 1 is eccentricity. */
  final case class AngleHarm(order: Int) extends Term { val name: String = if (order == 1) "eccentricity" else "angle_harmonic"; val params = 2 }
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
final case class Clip(ch: Int, lo: Double, hi: Double) { def params: Int = (if (lo.isInfinite) 0 else 1) + (if (hi.isInfinite) 0 else 1) }

/** The whole backward model: the default part plus accepted effects. Cut-offs are infinite when absent. */
final case class ModelSpec(
  skewS: Double = 0.0,
  hasSkew: Boolean = false,
  bw: Map[String, Double] = Map.empty,
  terms: Vector[Term] = Vector.empty,
  faults: Vector[Fault] = Vector.empty,
  clips: Vector[Clip] = Vector.empty,
  jitter: Boolean = false
) {
  /** Parameters beyond the default part. */
  def extraParams: Int = (if (hasSkew) 1 else 0) + bw.size + terms.map(_.params).sum + faults.size + clips.map(_.params).sum + (if (jitter) 1 else 0)
}
