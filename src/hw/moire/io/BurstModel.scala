package moire.io

import moire.protocol.BurstLayout
import moire.protocol.BurstLayout.Trigger

/** A sample as [[BurstCapture]] sees it (`word` packed as [[BurstLayout]], `index` a u32). */
final case class BurstIn(word: Int, position: Int, ref: Int, speed: Int, index: Long)

/** Burst settings as the registers hold them (`length`, `pre`, `threshold` u32). */
final case class BurstCfg(mode: Int, length: Long, pre: Long, threshold: Long = 0, target: Int = 0)

/** Sample index, position and reference count of a captured sample. */
final case class Anchor(index: Long, position: Int, ref: Int)

/** Bit-accurate, clock-by-clock model of [[BurstCapture]]'s capture: `step` is one clock with the
  * inputs of that clock; `words` the finished burst, oldest first.
  */
final class BurstModel(val p: BurstParams) {
  private val mem = new Array[Int](p.samples)
  private var stage: Option[BurstIn] = None
  var state: Int = BurstState.Idle
  private var cfg = BurstCfg(Trigger.Immediate, 1, 0)
  var length: Int = 1
  var pre: Int = 0
  private var wptr, held, post = 0
  var trigger: Anchor = Anchor(0, 0, 0)
  var last: Anchor = Anchor(0, 0, 0)
  private var prevValid, prevAbove, prevBelow, prevZ = false

  /** One clock: `in` the sample offered at `in` (if valid), `arm` the config if armed this clock. */
  def step(in: Option[BurstIn], arm: Option[BurstCfg]): Unit = {
    val s = stage
    stage = in
    arm match {
      case Some(c) =>
        cfg = c; length = p.length(c.length); pre = p.pre(c.pre, length)
        wptr = 0; held = 0; post = 0; prevValid = false; state = BurstState.Waiting
      case None => s.foreach(sample)
    }
  }

  private def sample(s: BurstIn): Unit = {
    val above = math.abs(s.speed.toLong) >= cfg.threshold
    val below = s.position < cfg.target
    val z = ((s.word >> BurstLayout.RefZ.lsb) & 1) == 1
    val fired = cfg.mode match {
      case Trigger.Speed => prevValid && above && !prevAbove
      case Trigger.RefZ => prevValid && z && !prevZ
      case Trigger.Position => prevValid && below != prevBelow
      case _ => true
    }
    prevValid = true; prevAbove = above; prevBelow = below; prevZ = z
    if (state == BurstState.Waiting || state == BurstState.Capturing) {
      mem(wptr) = s.word
      wptr = if (wptr == length - 1) 0 else wptr + 1
      if (held < length) held += 1
      val start = state == BurstState.Waiting && held - 1 >= pre && fired
      if (start) trigger = Anchor(s.index, s.position, s.ref)
      if (start || state == BurstState.Capturing) {
        post += 1
        if (post == length - pre) { last = Anchor(s.index, s.position, s.ref); state = BurstState.Done }
        else state = BurstState.Capturing
      }
    }
  }

  /** The finished burst, oldest first (state Done). */
  def words: IndexedSeq[Int] = {
    require(state == BurstState.Done, "the burst is not finished")
    IndexedSeq.tabulate(length)(k => mem((wptr + k) % length))
  }
}
