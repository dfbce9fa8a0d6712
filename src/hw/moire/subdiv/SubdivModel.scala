package moire.subdiv

import moire.cordic.{CordicModel, CordicWord, Fixed}
import scala.collection.mutable

/** One input sample: signed ADC values and the over-range flags. */
final case class SubdivSample(sin: Int, cos: Int, otrSin: Boolean = false, otrCos: Boolean = false)

/** One output word of the subdivider (formats in [[SubdivParams]]). */
final case class SubdivResult(position: Long, periods: Long, m: Long, phase: Long,
                              present: Boolean, overRange: Boolean, stepFault: Boolean)

/** Everything the subdivider shows in one clock cycle. `out` is meaningful when `valid`. */
final case class SubdivCycle(valid: Boolean, out: SubdivResult, a: Boolean, b: Boolean, z: Boolean, backlog: Long,
                             overspeed: Boolean, stepFault: Boolean, signalLost: Boolean, overRange: Boolean)

/** Phase of one sample, before the period counter: phase word, signal present, over-range. */
final case class PhaseWord(phase: Long, present: Boolean, overRange: Boolean)

/** Bit-accurate, clock-accurate model of [[Subdivider]].
  * `phaseOf` and `count` are the datapath; `clock` adds the pipeline delay and the A/B/Z generator.
  */
class SubdivModel(val p: SubdivParams) {
  import Fixed._
  private val cordic = new CordicModel(p.cordic)
  private val pb = p.angleBits
  private val mask = (1L << pb) - 1
  private val quarter = 1L << (pb - 2)
  private val half = 1L << (pb - 1)

  /** Phase of a sample (pure function: input register, CORDIC and octant stage). */
  def phaseOf(s: SubdivSample): PhaseWord = {
    val sn = wrap(s.sin, p.inputBits); val cs = wrap(s.cos, p.inputBits)
    val present = sn * sn + cs * cs >= p.presentSq
    val ph = if (!p.isAsin) {
      cordic(CordicWord(cs << p.inputShift, sn << p.inputShift, 0)).z & mask
    } else {
      val useSin = math.abs(sn) <= math.abs(cs)
      val sel = if (useSin) sn else cs
      val v = saturate(shift(sel * p.kConst, p.kShift, p.rounding), p.width)
      val z = cordic(CordicWord(0, v, 0)).z
      val r = if (useSin) { if (cs < 0) half - z else z } else { if (sn < 0) z - quarter else quarter - z }
      r & mask
    }
    PhaseWord(ph, present, s.otrSin || s.otrCos)
  }

  // ---- period counter state ----
  private var started = false
  private var prevU = 0L
  private var periods = 0L

  /** Period counter: one phase word in, one result out (state kept between calls). */
  def count(w: PhaseWord): SubdivResult = {
    val d = wrap(w.phase - prevU, pb)
    val update = w.present
    var stepFault = false
    if (update) {
      val fwd = started && d > 0 && w.phase < prevU
      val bwd = started && d < 0 && w.phase > prevU
      stepFault = started && math.abs(d) > p.stepLimit
      periods = if (!started) 0L else wrap(periods + (if (fwd) 1 else 0) - (if (bwd) 1 else 0), p.periodBits)
      prevU = w.phase
      started = true
    }
    val m = prevU >> (pb - p.countBits)
    val pos = wrap((periods << p.countBits) | m, p.positionWidth)
    SubdivResult(pos, periods, m, w.phase, w.present, w.overRange, stepFault)
  }

  /** Sets the period counter's state, as after a run whose last present sample had phase `prevPhase` and
    * left `periods` (lets a long replay be checked in windows). `started` false = no present sample yet.
    */
  def seedCounter(started: Boolean, prevPhase: Long, periods: Long): Unit = {
    this.started = started; prevU = if (started) prevPhase & mask else 0L; this.periods = if (started) wrap(periods, p.periodBits) else 0L
  }

  /** Convenience for host-side runs: phase and count of each sample in order (no pulse generator). */
  def process(s: SubdivSample): SubdivResult = count(phaseOf(s))

  // ---- clock-level state: pipeline, output register, A/B/Z generator, sticky flags ----
  private val pipe = mutable.Queue.fill[Option[PhaseWord]](p.latency - 1)(None)
  private var outValid = false
  private var outBits = SubdivResult(0, 0, 0, 0, false, false, false)
  private var genStarted = false
  private var outPos = 0L
  private var waitCnt = 0
  private var sOverspeed = false; private var sStep = false; private var sLost = false; private var sOtr = false

  /** One clock: returns what the outputs show during this cycle, then takes the clock edge. */
  def clock(in: Option[SubdivSample], clear: Boolean = false): SubdivCycle = {
    val pending = wrap(outBits.position - outPos, p.positionWidth)
    val q = outPos & 3
    val seen = SubdivCycle(outValid, outBits, a = q == 1 || q == 2, b = q >= 2,
      z = genStarted && (outPos & (p.counts - 1)) == 0, backlog = if (genStarted) pending else 0,
      sOverspeed, sStep, sLost, sOtr)
    // sticky flags (set wins over clear)
    val over = genStarted && math.abs(pending) > p.backlogLimit
    sOverspeed = (sOverspeed && !clear) || over
    sStep = (sStep && !clear) || (outValid && outBits.stepFault)
    sLost = (sLost && !clear) || (outValid && !outBits.present)
    sOtr = (sOtr && !clear) || (outValid && outBits.overRange)
    // A/B/Z generator
    if (!genStarted) {
      if (outValid) { outPos = outBits.position; genStarted = true }
    } else if (waitCnt == 0 && pending != 0) {
      outPos = wrap(outPos + (if (pending > 0) 1 else -1), p.positionWidth)
      waitCnt = p.minEdgeClocks - 1
    } else if (waitCnt > 0) waitCnt -= 1
    // counter stage and pipeline
    pipe.dequeue() match {
      case Some(w) => outBits = count(w); outValid = true
      case None => outValid = false
    }
    pipe.enqueue(in.map(phaseOf))
    seen
  }
}
