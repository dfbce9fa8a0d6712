package moire.monitor

import moire.signal.Adc

/** One record as the monitor holds it: pin codes, the sample index (unwrapped), the position in counts, flag bits. */
final case class LiveRecord(sin: Int, cos: Int, index: Long, position: Long, flags: Int)

object LiveRecord {
  /** Bits of `flags`, as the stream's record word carries them. */
  val Present = 1; val OverRange = 2; val StepFault = 4; val OtrSin = 8; val OtrCos = 16
  val names: Seq[(Int, String)] = Seq(Present -> "present", OverRange -> "over_range", StepFault -> "step_fault", OtrSin -> "otr_sin", OtrCos -> "otr_cos")
  def of(r: moire.stream.Record, index: Long): LiveRecord = LiveRecord(r.sin, r.cos, index, r.position.toLong,
    (if (r.present) Present else 0) | (if (r.overRange) OverRange else 0) | (if (r.stepFault) StepFault else 0) |
      (if (r.otrSin) OtrSin else 0) | (if (r.otrCos) OtrCos else 0))
}

/** What a source tells before its records: rate, ADC, scale, metadata for a saved recording, a name for the page, the
  * longest burst it can capture.
  */
final case class SourceSetup(sampleRateHz: Double, adc: Adc, scale: Scale, meta: Map[String, String], label: String,
                             burstDepth: Option[Long] = None)
