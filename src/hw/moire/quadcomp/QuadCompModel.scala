package moire.quadcomp

import moire.cordic.{CordicModel, CordicWord, Fixed}

/** What one input sample gives. `sin`, `cos`: data words; `diff`: the phase difference measured at
  * this sample (its 45 degree point), if any; `correction`: the correction this sample was built with.
  * Trace fields (`zs`, `zc`, `thetaSin`, `thetaCos`, `psi`, `incSin`, `posCos`) are the inner values, for tests.
  */
final case class QuadCompSample(sin: Long, cos: Long, diff: Option[Long], correction: Long,
                             zs: Long, zc: Long, thetaSin: Long, thetaCos: Long, psi: Long,
                             incSin: Boolean, posCos: Boolean)

/** Bit-accurate model of [[QuadComp]], one call per valid input sample (the RTL adds `latency`). */
class QuadCompModel(val p: QuadCompParams, val gainSin: Long, val gainCos: Long) {
  import Fixed._
  private val a = p.angleBits
  private val quarter = 1L << (a - 2)
  private val half = 1L << (a - 1)
  private val eighth = 1L << (a - 3)
  private val turn = 1L << a
  private val asin = new CordicModel(p.asinP)
  private val acos = new CordicModel(p.acosP)
  private val rebuild = new CordicModel(p.rebuildP)
  /** Width of the averaging accumulator. */
  val accBits: Int = a + p.averageLog2 + 2

  private var acc = 0L
  private var pending = 0L
  private var flag = false
  private var first = true
  private var armed = true
  private var havePrev = false
  private var prevOctant = 0L

  /** The correction now in use, binary angle. */
  def correction: Long = wrap(shift(acc, p.averageLog2, p.rounding), a)

  /** Code times gain, rounded to the data word and saturated. */
  def normalise(code: Long, gain: Long): Long =
    saturate(shift(wrap(code, p.inputBits) * gain, p.normShift, p.rounding), p.width)

  def step(sinCode: Long, cosCode: Long): QuadCompSample = {
    val ns = normalise(sinCode, gainSin)
    val nc = normalise(cosCode, gainCos)
    val zs = asin(CordicWord(0, ns, 0)).z
    val zcRaw = acos(CordicWord(0, nc, 0)).z
    val zc = if (zcRaw < -quarter) zcRaw + turn else zcRaw // acos in [-90, 270) degrees: 180 stays 180
    val d = correction
    // Table 2: quadrant of the sin channel from its polarity and its direction; the direction comes
    // from the cos channel's angle with the correction taken out (lead/lag zones of Fig. 5).
    val incSin = if (ns >= 0) zc - d <= quarter else zc + d <= quarter
    val thetaSin = wrap(if (incSin) zs else half - zs, a)
    val posCos = if (nc >= 0) zs + d >= 0 else zs - d >= 0
    val thetaCos = wrap(if (posCos) zc else -zc, a)
    val nearPeak = zc < eighth || zc > 3 * eighth
    val psi = if (p.fusePeaks && nearPeak) thetaSin else wrap(thetaCos - d, a)
    val cos = rebuild(CordicWord(0, 0, psi)).x
    // 45 degree point of the sin channel, once per period (re-armed in the third quadrant).
    val octant = (thetaSin & (turn - 1)) >> (a - 3)
    val trig = armed && havePrev && ((prevOctant == 0 && octant == 1) || (prevOctant == 1 && octant == 0))
    val meas = wrap(thetaCos - thetaSin, a)
    if (flag) {
      acc = if (first) pending << p.averageLog2 else acc + pending - shift(acc, p.averageLog2, p.rounding)
      require(fits(acc, accBits), s"${p.moduleName}: accumulator $acc overflows $accBits bits")
      first = false
    }
    flag = trig
    if (trig) pending = meas
    armed = if (trig) false else if ((octant >> 1) == 2) true else armed
    prevOctant = octant
    havePrev = true
    QuadCompSample(ns, cos, if (trig) Some(meas) else None, d, zs, zc, thetaSin, thetaCos, psi, incSin, posCos)
  }
}
