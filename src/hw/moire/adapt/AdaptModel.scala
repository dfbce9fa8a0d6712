package moire.adapt

import moire.cordic.{CordicModel, CordicWord, Fixed, Rounding}

/** Output of one clock: corrected (sin, cos) when valid, and the ADC over-range flags passed through. */
final case class AdaptOut(sin: Long, cos: Long, otrSin: Boolean = false, otrCos: Boolean = false)

/** Bit-accurate, clock-accurate model of [[AdaptiveCorrector]]: the same registers, the same
  * integer operations and roundings, advanced once per clock. `step` takes this clock's input
  * (None = in.valid low) and returns what io.out shows during this clock.
  *
  * Pure arithmetic is computed where convenient; what reads or writes state happens in the clock
  * the hardware does it (the stage clocks are in [[AdaptParams]]): offsets, gains and phase term
  * at the correction stages that use them, the estimate update `updateDelay` clocks after the
  * window closes, the table read and its mean `tableRead` clocks after the CORDIC, the PLL at
  * `pllStage`, the leak at `leakStage`, the table's read-modify-write at `rmwStage` (exact: the
  * hardware forwards the writes still in flight), the table sum one clock after that.
  */
class AdaptModel(val p: AdaptParams) {
  import Fixed.{saturate, wrap}
  import AdaptModel.shR
  /** Round-half-up shift by a run-time amount (the per-period normalisation). */
  private def shUp(v: Long, s: Int): Long = (v + (1L << (s - 1))) >> s

  private val cordic = new CordicModel(p.cordic)
  private val F = p.fineBits
  private val entries = p.harmonicEntries
  private val mask = math.max(entries - 1, 0)
  private val tSquare = 1L << p.targetSquareLog2
  private val lockMax = (1L << p.lockBits) - 1

  // ---- estimator state ----
  var os = 0L; var oc = 0L; var ks: Long = p.startGain; var kc: Long = p.startGain; var t = 0L
  private var aS = 0L; private var aC = 0L; private var bS = 0L; private var bC = 0L; private var cX = 0L; private var n = 0L
  private var prevQ = 0; private var seen = 0 // bit q set when quadrant q was visited since the last period start
  /** Completed periods used for an update (for tests and figures). */
  var periods = 0L
  // ---- harmonic table and PLL state ----
  val table: Array[Long] = new Array[Long](math.max(entries, 1))
  /** The table sum register: every entry's write is in it one clock after the write. */
  var tableSum = 0L
  private var sumPending = 0L
  var theta = 0L; var vel = 0L; private var prevPhic = 0L; var lockCnt = 0L
  /** The previous sample's phase error and phase increment less velocity: the PLL acts on them one sample late. */
  private var eLast = 0L; private var dvLast = 0L

  /** One sample in flight; fields filled as it passes the stages. */
  private final class Sample(val s: Long, val c: Long) {
    var s1 = 0L; var c1 = 0L; var sr = 0L; var cr = 0L; var ms = 0L; var mc = 0L
    var sp = 0L; var cp = 0L; var ca = 0L; var phi = 0L
    var idx = 0; var frac = 0L; var delta = 0L; var mean = 0L; var phic = 0L
    var e = 0L; var enable = false; var leak = 0L
  }
  /** A delay line: index k = the sample that entered k + 1 clocks ago. */
  private def line[T](k: Int) = scala.collection.mutable.ArrayDeque.fill[Option[T]](k)(None)
  private def shift[T](l: scala.collection.mutable.ArrayDeque[Option[T]], x: Option[T]): Unit = { l.removeLast(); l.prepend(x) }
  /** front(k): the sample in the registers of stage k (input register = 0, correction stages 1..5). */
  private val front = line[Sample](p.correctionStages + 1)
  private val stat = line[Sample](1)
  private val cq = line[Sample](p.cordic.latency)
  /** post(k): the sample whose table read was k + 1 clocks ago. */
  private val post = line[Sample](p.rmwStage)
  private val updates = line[Snapshot](p.updateDelay)
  private final class Snapshot(val aS: Long, val aC: Long, val bS: Long, val bC: Long, val cX: Long, val l: Int)

  /** The corrector's registered hold (preset port): while set, the estimates, statistics, PLL and table stand still.
    * Set it before the clocks it is high in.
    */
  var held = false
  /** The load strobe, called after the clock it is high in: offsets, gains, phase term and table sum from `l`. */
  def load(l: AdaptLearned): Unit = { os = l.offsetSin; oc = l.offsetCos; ks = l.gainSin; kc = l.gainCos; t = l.phase; tableSum = l.tableSum }
  /** The table-write strobe, called after the clock it is high in: entries 2 k and 2 k + 1 (the sum unchanged). */
  def writePair(k: Int, even: Long, odd: Long): Unit = { table(2 * k) = even; table(2 * k + 1) = odd }

  /** What the corrector has learned now, as the read-back registers of the board show it once it stops moving. */
  def learned: AdaptLearned = AdaptLearned(os, oc, ks, kc, t, math.min(periods, AdaptLearned.MaxUpdates), lockCnt == lockMax,
    tableSum, table.toSeq.take(entries))

  def quadrant(sp: Long, cp: Long): Int = (if (sp >= 0) (if (cp >= 0) 0 else 1) else if (cp < 0) 2 else 3)

  private val otrLine = scala.collection.mutable.Queue.fill(p.latency)((false, false))

  /** One clock: `in` = (sin, cos) when in.valid, `otr` = the over-range flags (delayed by `latency`). */
  def step(in: Option[(Long, Long)], otr: (Boolean, Boolean) = (false, false)): Option[AdaptOut] = {
    val flags = otrLine.dequeue(); otrLine.enqueue(otr)
    // what the output register shows: the sample that reaches the read-modify-write this clock
    val atRmw = post.last
    val shown = atRmw.map { x => val (so, co) = AdaptModel.rotate(p, x.sp, x.cp, AdaptModel.radians(p, x.delta))
      AdaptOut(so, co, flags._1, flags._2) }

    // ---- correction, one stage a clock, each reading the estimates of its clock ----
    front(0).foreach { x => val (s1, sr) = AdaptModel.offset(p, x.s, os); val (c1, cr) = AdaptModel.offset(p, x.c, oc)
      x.s1 = s1; x.sr = sr; x.c1 = c1; x.cr = cr }
    front(1).foreach { x => x.ms = x.sr * ks; x.mc = x.cr * kc }
    front(2).foreach { x => x.sp = saturate(AdaptModel.scaled(p, x.ms), p.outputBits); x.ca = AdaptModel.scaled(p, x.mc) }
    front(3).foreach { x => x.cp = AdaptModel.phased(p, x.ca, x.sp * t) }
    val corrected = front.last // its h registers hold: statistics products and the CORDIC start now
    corrected.foreach(x => x.phi = cordic(CordicWord(x.cp, x.sp, 0)).z)

    // ---- statistics one clock later; an update reaches the estimates updateDelay clocks after ----
    val apply = updates.last
    shift(updates, stat(0).filter(_ => !held).flatMap(x => stats(x.sp, x.cp, x.s1, x.c1)))

    // ---- harmonic table: read, PLL, leak, read-modify-write ----
    val read = cq.last
    read.foreach { x =>
      val u = x.phi & ((1L << p.angleBits) - 1)
      x.idx = (u >> (p.angleBits - p.tableIndexBits)).toInt
      x.frac = (u >> (p.angleBits - p.tableIndexBits - p.interpBits)) & ((1L << p.interpBits) - 1)
      x.mean = shR(tableSum, p.tableIndexBits)
      if (entries > 0) x.delta = AdaptModel.interpolate(p, table(x.idx), table((x.idx + 1) & mask), x.frac) - x.mean
      x.phic = wrap((x.phi << p.fineGuard) - x.delta, F)
    }
    post(p.pllStage - 1).filter(_ => !held).foreach(pll)
    post(p.leakStage - 1).foreach(x => x.leak = shR(tableSum, p.tableIndexBits + p.meanShift))
    tableSum += sumPending; sumPending = 0
    atRmw.foreach(x => if (x.enable) update(x))

    apply.filter(_ => !held).foreach(estimate)
    shift(post, read)
    shift(cq, corrected)
    shift(stat, corrected)
    shift(front, in.map { case (s, c) => new Sample(wrap(s, p.inputBits), wrap(c, p.inputBits)) })
    shown
  }

  /** Statistics of one corrected sample; a closed window's sums when the estimates are to move. */
  private def stats(sp: Long, cp: Long, s1: Long, c1: Long): Option[Snapshot] = {
    val q = quadrant(sp, cp)
    val start = q == 0 && prevQ != 0
    val whole = (seen & 0xE) == 0xE && n < p.countMax
    var snap: Option[Snapshot] = None
    if (start && !(whole && n < (1L << p.windowBits))) {
      // a window of whole periods is complete (update), or the period was broken (discard): restart
      if (whole) snap = Some(new Snapshot(aS, aC, bS, bC, cX, 64 - java.lang.Long.numberOfLeadingZeros(n)))
      aS = s1; aC = c1; bS = tSquare - sp * sp; bC = tSquare - cp * cp; cX = sp * cp; n = 1; seen = 0
    } else if (n < p.countMax) {
      if (start) seen = 0
      aS += s1; aC += c1; bS += tSquare - sp * sp; bC += tSquare - cp * cp; cX += sp * cp; n += 1
      seen |= 1 << q
    }
    prevQ = q
    snap
  }

  private def estimate(u: Snapshot): Unit = {
    val gMax = (1L << (p.gainBits - 1)) - 1
    os = saturate(os + shUp(u.aS, u.l + p.offsetRate), p.offsetWidth)
    oc = saturate(oc + shUp(u.aC, u.l + p.offsetRate), p.offsetWidth)
    ks = math.max(1L, math.min(gMax, ks + shUp(u.bS, u.l + p.gainRate + p.gainShift)))
    kc = math.max(1L, math.min(gMax, kc + shUp(u.bC, u.l + p.gainRate + p.gainShift)))
    t = saturate(t - shUp(u.cX, u.l + p.phaseRate + p.phaseShift), p.phaseBits)
    periods += 1
  }

  /** The PLL at one sample: its error e (for the table), then theta, vel and the lock count moved by the previous
    * sample's errors (a register in the loop, one sample of delay: the gains are small shifts).
    */
  private def pll(x: Sample): Unit = {
    val pred = wrap(theta + vel, F)
    x.e = wrap(x.phic - pred, F)
    x.enable = entries > 0 && lockCnt == lockMax && math.abs(vel) >= (1L << (F - p.minSpeedShift))
    val dv = wrap(x.phic - prevPhic - vel, F)
    theta = wrap(pred + shR(eLast, p.pllKp), F)
    vel = wrap(vel + shR(eLast, p.pllKv) + shR(dvLast, p.pllKf), F)
    lockCnt = if (math.abs(eLast) < (1L << (F - p.lockShift))) math.min(lockCnt + 1, lockMax) else 0L
    prevPhic = x.phic; eLast = x.e; dvLast = dv
  }

  /** LMS step split by the interpolation weights, plus a leak of the (unobservable) table mean. */
  private def update(x: Sample): Unit = {
    val sh = p.interpBits + p.harmonicRate
    val j = (x.idx + 1) & mask
    val t0 = saturate(table(x.idx) + shR(x.e * ((1L << p.interpBits) - x.frac), sh) - x.leak, p.tableBits)
    val t1 = saturate(table(j) + shR(x.e * x.frac, sh) - x.leak, p.tableBits)
    sumPending = (t0 - table(x.idx)) + (t1 - table(j))
    table(x.idx) = t0; table(j) = t1
  }
}

/** The model's combinational pieces, also checked alone against double precision. */
object AdaptModel {
  import Fixed.saturate
  private[adapt] def shR(v: Long, s: Int): Long = Fixed.shift(v, s, Rounding.HalfEven)

  /** x - offset with offsetFrac fractional bits, and that rounded to the multiplier operand (mulFrac). */
  def offset(p: AdaptParams, x: Long, o: Long): (Long, Long) = {
    val d = (x << p.offsetFrac) - o
    (d, shR(d, p.offsetFrac - p.mulFrac))
  }
  /** A gain product in output LSB (rounded, not saturated). */
  def scaled(p: AdaptParams, prod: Long): Long = shR(prod, p.mulFrac + p.gainFrac)
  /** cp = ca + sp t, from the gain-corrected cos and the phase product sp t, saturated. */
  def phased(p: AdaptParams, ca: Long, spt: Long): Long = saturate(ca + shR(spt, p.phaseFrac), p.outputBits)

  /** (sp, cp) = ((s - os) ks, (c - oc) kc + sp t) in output LSB. */
  def correct(p: AdaptParams, s: Long, c: Long, os: Long, oc: Long, ks: Long, kc: Long, t: Long): (Long, Long) = {
    val sp = saturate(scaled(p, offset(p, s, os)._2 * ks), p.outputBits)
    (sp, phased(p, scaled(p, offset(p, c, oc)._2 * kc), sp * t))
  }

  /** Table value between entries a and b at fraction frac / 2^interpBits. */
  def interpolate(p: AdaptParams, a: Long, b: Long, frac: Long): Long = a + shR((b - a) * frac, p.interpBits)

  /** A fine angle (2^-fineBits turn) in radians with rotFrac fractional bits, saturated to rotWidth. */
  def radians(p: AdaptParams, delta: Long): Long =
    saturate(shR(delta * p.twoPi, p.twoPiFrac + p.fineBits - p.rotFrac), p.rotWidth)

  /** (sin, cos) turned by -dr radians (small angle: sin dr ~ dr, cos dr ~ 1). */
  def rotate(p: AdaptParams, sp: Long, cp: Long, dr: Long): (Long, Long) =
    (saturate(sp - shR(dr * cp, p.rotFrac), p.outputBits), saturate(cp + shR(dr * sp, p.rotFrac), p.outputBits))
}
