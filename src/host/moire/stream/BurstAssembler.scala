package moire.stream

import moire.io.Quadrature
import moire.protocol.BurstLayout
import moire.recording.Recording
import moire.signal.{Adc, AdcFormat}

/** How well a burst's reference count rebuilt from the A/B pins agrees with the board's counter.
  * @param refSkips  samples where A and B both changed (the count cannot tell the direction)
  * @param triggerError rebuilt minus board count at the trigger anchor (None when the trigger is too early to check)
  */
final case class BurstCheck(refSkips: Int, triggerError: Option[Long])

/** A full-rate recording (sample rate = ADC clock) from one burst: its [[BurstInfo]] and sample frames.
  * Columns: sin, cos, `otr_sin`, `otr_cos`, `ref_a`, `ref_b`, `ref_z`, `sample_index`, and `ref_counts`:
  * the reference encoder's quadrature count rebuilt from the A/B pin states, placed by the board's count
  * at the last sample and checked at the trigger. The board delays the pins it stores by its counter's
  * latency, so a sample's pins and count are of one instant (`counterLatency` samples apart: 0).
  * The anchors go into the metadata.
  */
object BurstAssembler {
  val counterLatency: Int = 0

  def recording(info: BurstInfo, frames: Seq[BurstSamples], adcClockHz: Double, adc: AdcFormat,
                meta: Map[String, String] = Map.empty): (Recording, BurstCheck) = {
    val n = info.length.toInt
    val words = new Array[Long](n)
    val have = new Array[Boolean](n)
    for (f <- frames; (w, k) <- f.words.zipWithIndex) {
      val i = f.offset + k
      if (i < n) { words(i.toInt) = w; have(i.toInt) = true }
    }
    val missing = have.count(!_)
    if (missing > 0) throw new StreamError(s"burst of $n samples: $missing samples missing (lost frames); the burst is not written")
    def bit(w: Long, f: moire.protocol.Field) = f.get(w)
    val pins = words.map(w => Quadrature.phase(bit(w, BurstLayout.RefA) == 1, bit(w, BurstLayout.RefB) == 1))
    val rel = new Array[Long](n)
    var skips = 0
    for (k <- 1 until n) {
      val d = Math.floorMod(pins(k) - pins(k - 1), 4)
      rel(k) = rel(k - 1) + (d match { case 1 => 1L; case 3 => -1L; case 2 => skips += 1; 0L; case _ => 0L })
    }
    // the board's count at sample k is the pin count of sample k - counterLatency
    val lastAt = n - 1 - counterLatency
    val offset = if (lastAt >= 0) info.last.ref.toLong - rel(lastAt) else info.last.ref.toLong
    val trigAt = info.pre.toInt - counterLatency
    val check = BurstCheck(skips, if (trigAt >= 0) Some(rel(trigAt) + offset - info.trigger.ref) else None)
    def col(f: moire.protocol.Field) = words.map(w => bit(w, f).toDouble)
    val first = info.trigger.index - info.pre
    val extra = Map(
      "otr_sin" -> col(BurstLayout.OtrSin), "otr_cos" -> col(BurstLayout.OtrCos),
      "ref_a" -> col(BurstLayout.RefA), "ref_b" -> col(BurstLayout.RefB), "ref_z" -> col(BurstLayout.RefZ),
      "sample_index" -> Array.tabulate(n)(k => (first + k).toDouble),
      "ref_counts" -> rel.map(r => (r + offset).toDouble))
    val m = meta ++ Map(
      "burst_length" -> n.toString, "burst_pre" -> info.pre.toString,
      "burst_trigger_index" -> info.trigger.index.toString, "burst_trigger_position" -> info.trigger.position.toString,
      "burst_trigger_ref_counts" -> info.trigger.ref.toString,
      "burst_last_index" -> info.last.index.toString, "burst_last_position" -> info.last.position.toString,
      "burst_last_ref_counts" -> info.last.ref.toString,
      "ref_skips" -> skips.toString) ++ check.triggerError.map(e => "ref_trigger_error" -> e.toString)
    val rec = Recording(adcClockHz, Adc(12, adc), words.map(w => bit(w, BurstLayout.Sin).toInt),
      words.map(w => bit(w, BurstLayout.Cos).toInt), m, extra)
    (rec, check)
  }
}
