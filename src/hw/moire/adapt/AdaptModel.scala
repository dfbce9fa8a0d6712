package moire.adapt

import moire.cordic.{CordicModel, CordicWord, Fixed, Rounding}

/** Output of one clock: corrected (sin, cos) when valid, and the ADC over-range flags passed through. */
final case class AdaptOut(sin: Long, cos: Long, otrSin: Boolean = false, otrCos: Boolean = false)

/** Bit-accurate, clock-accurate model of [[AdaptiveCorrector]]: the same registers, the same
  * integer operations and roundings, advanced once per clock. `step` takes this clock's input
  * (None = in.valid low) and returns what io.out shows during this clock.
  */
class AdaptModel(val p: AdaptParams) {
  import Fixed.{saturate, wrap}
  private val he = Rounding.HalfEven
  private def shR(v: Long, s: Int): Long = Fixed.shift(v, s, he)
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
  var tableSum = 0L
  var theta = 0L; var vel = 0L; private var prevPhic = 0L; var lockCnt = 0L


  // ---- pipeline registers ----
  private final class Stage(var valid: Boolean = false, var a: Long = 0, var b: Long = 0, var c: Long = 0,
                            var d: Long = 0, var e: Long = 0, var f: Long = 0)
  private var inR = new Stage()   // a = sin, b = cos
  private var hR = new Stage()    // a = sp, b = cp, c = s1, d = c1
  private val cq = scala.collection.mutable.Queue.fill(p.cordic.latency)(new Stage()) // a = sp, b = cp, c = phi1
  private var p1 = new Stage()    // a = sp, b = cp, c = phi1, d = idx, e = frac, f = delta
  private var p2 = new Stage()    // a = sp, b = cp, c = dr, d = idx, e = frac, f = phic
  private var outR = new Stage()  // a = sin, b = cos

  def quadrant(sp: Long, cp: Long): Int = (if (sp >= 0) (if (cp >= 0) 0 else 1) else if (cp < 0) 2 else 3)

  private val otrLine = scala.collection.mutable.Queue.fill(p.latency)((false, false))

  /** One clock: `in` = (sin, cos) when in.valid, `otr` = the over-range flags (delayed by `latency`). */
  def step(in: Option[(Long, Long)], otr: (Boolean, Boolean) = (false, false)): Option[AdaptOut] = {
    val flags = otrLine.dequeue(); otrLine.enqueue(otr)
    val shown = if (outR.valid) Some(AdaptOut(outR.a, outR.b, flags._1, flags._2)) else None

    // output stage: small rotation by -delta
    val outN = new Stage(p2.valid)
    if (p2.valid) {
      val (so, co) = AdaptModel.rotate(p, p2.a, p2.b, p2.c)
      outN.a = so; outN.b = co
    }

    // P1: table read and interpolation (reads the table before this clock's write)
    val cOut = cq.dequeue()
    val p1N = new Stage(cOut.valid, cOut.a, cOut.b, cOut.c)
    if (cOut.valid) {
      val u = cOut.c & ((1L << p.angleBits) - 1)
      p1N.d = u >> (p.angleBits - p.tableIndexBits)
      p1N.e = (u >> (p.angleBits - p.tableIndexBits - p.interpBits)) & ((1L << p.interpBits) - 1)
      if (entries > 0) {
        val a = table(p1N.d.toInt); val b = table(((p1N.d + 1) & mask).toInt)
        p1N.f = AdaptModel.interpolate(p, a, b, p1N.e) - shR(tableSum, p.tableIndexBits)
      }
    }
    // P2: radians for the rotation, corrected fine phase
    val p2N = new Stage(p1.valid, p1.a, p1.b, 0, p1.d, p1.e)
    if (p1.valid) {
      p2N.c = AdaptModel.radians(p, p1.f)
      p2N.f = wrap((p1.c << p.fineGuard) - p1.f, F)
    }
    // PLL and table update from P2
    if (p2.valid) pllAndTable(p2.f, p2.d.toInt, p2.e)

    // CORDIC (fixed delay)
    val cIn = new Stage(hR.valid, hR.a, hR.b)
    if (hR.valid) cIn.c = cordic(CordicWord(hR.b, hR.a, 0)).z
    cq.enqueue(cIn)

    // statistics of the corrected signals; the estimates move once per whole period
    val hN = new Stage(inR.valid)
    if (inR.valid) correct(inR.a, inR.b, hN) // uses this clock's estimates
    if (hR.valid) stats(hR.a, hR.b, hR.c, hR.d)

    val inN = new Stage(in.isDefined)
    in.foreach { case (s, c) => inN.a = wrap(s, p.inputBits); inN.b = wrap(c, p.inputBits) }
    inR = inN; hR = hN; p1 = p1N; p2 = p2N; outR = outN
    shown
  }

  /** Offset, gain and phase correction of one sample into hN (a = sp, b = cp, c = s1, d = c1). */
  private def correct(s: Long, c: Long, hN: Stage): Unit = {
    val (sp, cp) = AdaptModel.correct(p, s, c, os, oc, ks, kc, t)
    hN.a = sp; hN.b = cp; hN.c = (s << p.offsetFrac) - os; hN.d = (c << p.offsetFrac) - oc
  }

  private def stats(sp: Long, cp: Long, s1: Long, c1: Long): Unit = {
    val q = quadrant(sp, cp)
    val start = q == 0 && prevQ != 0
    val whole = (seen & 0xE) == 0xE && n < p.countMax
    if (start && !(whole && n < (1L << p.windowBits))) {
      // a window of whole periods is complete (update), or the period was broken (discard): restart
      if (whole) update()
      aS = s1; aC = c1; bS = tSquare - sp * sp; bC = tSquare - cp * cp; cX = sp * cp; n = 1; seen = 0
    } else if (n < p.countMax) {
      if (start) seen = 0
      aS += s1; aC += c1; bS += tSquare - sp * sp; bC += tSquare - cp * cp; cX += sp * cp; n += 1
      seen |= 1 << q
    }
    prevQ = q
  }

  private def update(): Unit = {
    val l = 64 - java.lang.Long.numberOfLeadingZeros(n)
    val gMax = (1L << (p.gainBits - 1)) - 1
    os = saturate(os + shUp(aS, l + p.offsetRate), p.offsetWidth)
    oc = saturate(oc + shUp(aC, l + p.offsetRate), p.offsetWidth)
    ks = math.max(1L, math.min(gMax, ks + shUp(bS, l + p.gainRate + p.gainShift)))
    kc = math.max(1L, math.min(gMax, kc + shUp(bC, l + p.gainRate + p.gainShift)))
    t = saturate(t - shUp(cX, l + p.phaseRate + p.phaseShift), p.phaseBits)
    periods += 1
  }

  private def pllAndTable(phic: Long, idx: Int, frac: Long): Unit = {
    val pred = wrap(theta + vel, F)
    val e = wrap(phic - pred, F)
    val d = wrap(phic - prevPhic, F)
    val enable = entries > 0 && lockCnt == lockMax && math.abs(vel) >= (1L << (F - p.minSpeedShift))
    theta = wrap(pred + shR(e, p.pllKp), F)
    vel = wrap(vel + shR(e, p.pllKv) + shR(d - vel, p.pllKf), F)
    prevPhic = phic
    lockCnt = if (math.abs(e) < (1L << (F - p.lockShift))) math.min(lockCnt + 1, lockMax) else 0L
    if (enable) {
      // LMS step split by the interpolation weights, plus a leak of the (unobservable) table mean
      val sh = p.interpBits + p.harmonicRate
      val j = (idx + 1) & mask
      val leak = shR(tableSum, p.tableIndexBits + p.meanShift)
      val t0 = saturate(table(idx) + shR(e * ((1L << p.interpBits) - frac), sh) - leak, p.tableBits)
      val t1 = saturate(table(j) + shR(e * frac, sh) - leak, p.tableBits)
      tableSum += (t0 - table(idx)) + (t1 - table(j))
      table(idx) = t0; table(j) = t1
    }
  }
}

/** The model's combinational pieces, also checked alone against double precision. */
object AdaptModel {
  import Fixed.saturate
  private def shR(v: Long, s: Int): Long = Fixed.shift(v, s, Rounding.HalfEven)

  /** (sp, cp) = ((s - os) ks, (c - oc) kc + sp t) in output LSB. */
  def correct(p: AdaptParams, s: Long, c: Long, os: Long, oc: Long, ks: Long, kc: Long, t: Long): (Long, Long) = {
    val s1 = (s << p.offsetFrac) - os
    val c1 = (c << p.offsetFrac) - oc
    val sp = saturate(shR(shR(s1, p.offsetFrac - p.mulFrac) * ks, p.mulFrac + p.gainFrac), p.outputBits)
    val ca = shR(shR(c1, p.offsetFrac - p.mulFrac) * kc, p.mulFrac + p.gainFrac)
    (sp, saturate(ca + shR(sp * t, p.phaseFrac), p.outputBits))
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
