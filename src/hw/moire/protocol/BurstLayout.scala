package moire.protocol

/** One full-rate burst sample (29 bits, docs/recording.md): both ADC codes as on the pins, their OTR
  * flags and the reference encoder's A/B/Z pin states. The low 26 bits are laid out as the record word's
  * ([[StreamV1.WordLayout]]), so one decoder reads both.
  */
object BurstLayout {
  import StreamV1.{WordLayout => W}
  val Sin: Field = W.Sin
  val Cos: Field = W.Cos
  val OtrSin: Field = W.OtrSin
  val OtrCos: Field = W.OtrCos
  val RefA: Field = OtrCos.next("ref_a", 1)
  val RefB: Field = RefA.next("ref_b", 1)
  val RefZ: Field = RefB.next("ref_z", 1)
  val fields: Seq[Field] = Seq(Sin, Cos, OtrSin, OtrCos, RefA, RefB, RefZ)
  /** Bits per stored sample. */
  val width: Int = RefZ.msb + 1

  /** Trigger modes (register `burst_trigger`). */
  object Trigger {
    /** At the first sample once the pre-trigger samples are held. */
    val Immediate = 0
    /** When |speed| rises to the threshold or above. */
    val Speed = 1
    /** At a rising edge of the reference encoder's Z. */
    val RefZ = 2
    /** When the position crosses the target (either direction). */
    val Position = 3
    val named: Seq[(Int, String)] = Seq(Immediate -> "now", Speed -> "speed", RefZ -> "z", Position -> "position")
    val bits: Int = 2
  }
}
