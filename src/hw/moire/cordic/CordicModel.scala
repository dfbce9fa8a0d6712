package moire.cordic

import CordicMode._

/** Raw port values: data in `width`-bit codes, angles in `angleWidth`-bit binary angles. */
final case class CordicWord(x: Long, y: Long, z: Long)

/** Bit-accurate model of [[Cordic]]: the same integer operations, shifts and roundings as the RTL.
  * Each internal value is checked against its register width, so a sizing mistake fails loudly.
  */
class CordicModel(val p: CordicParams) {
  import Fixed._
  private val r = p.rounding
  private val w = p.innerWidth
  private val one = 1L << p.innerFrac
  private val quarterZ = 1L << (p.zWidth - 2)
  private val halfZ = 1L << (p.zWidth - 1)
  val peakTable: Option[PeakTable] = if (p.peakTableSize > 0) Some(PeakTable(p)) else None
  // the steps and their angles as arrays, walked by index: the accuracy sweeps run the model on every input
  private val stepAt: Array[Int] = p.steps.toArray
  private val angleAt: Array[Long] = p.angleTable.toArray

  /** v, checked against the register width (`what` is worded only when it overflows). */
  private def chk(v: Long, what: => String): Long = {
    if (!fits(v, w)) throw new IllegalStateException(s"${p.moduleName}: $what = $v overflows $w bits")
    v
  }

  def apply(in: CordicWord): CordicWord = p.mode match {
    case SinCos | Rotate => rotation(in)
    case Atan2 => vectoring(in)
    case _ => arcsine(in)
  }

  /** Input stage of rotation: fold |angle| >= 90 degrees by negating the vector. */
  private def rotation(in: CordicWord): CordicWord = {
    val a = wrap(in.z, p.angleBits)
    val quarter = 1L << (p.angleBits - 2)
    val fold = a >= quarter || a < -quarter
    val z0 = wrap(if (fold) a + (1L << (p.angleBits - 1)) else a, p.angleBits) << p.zGuard
    val (x0, y0) =
      if (p.mode == SinCos) (p.startX, 0L)
      else (wrap(in.x, p.width) << p.guardBits, wrap(in.y, p.width) << p.guardBits)
    var x = if (fold) -x0 else x0
    var y = if (fold) -y0 else y0
    var z = z0
    var idx = 0
    while (idx < stepAt.length) {
      val i = stepAt(idx); val k = angleAt(idx)
      val up = z >= 0
      // rotationStep's operations, without its pair
      val sx = shift(x, i, r); val sy = shift(y, i, r)
      val nx = if (up) x - sy else x + sy
      val ny = if (up) y + sx else y - sx
      z = wrap(if (up) z - k else z + k, p.zWidth)
      if (p.taper) { // the tapered z registers hold exactly this interval
        val (lo, hi) = p.zRanges(idx)
        if (z < lo || z > hi) throw new IllegalStateException(s"${p.moduleName}: z[$i] = $z outside [$lo, $hi]")
      }
      x = chk(nx, s"x[$i]"); y = chk(ny, s"y[$i]")
      idx += 1
    }
    CordicWord(outData(x), outData(y), 0L)
  }

  /** One rotation-mode iteration i: counter-clockwise when `up` (z >= 0). */
  def rotationStep(x: Long, y: Long, i: Int, up: Boolean): (Long, Long) = {
    val sx = shift(x, i, r); val sy = shift(y, i, r)
    if (up) (x - sy, y + sx) else (x + sy, y - sx)
  }

  /** Tapered sincos: (x, y) after the first `taperTable` iterations, for the fold and their directions
    * (entry index: fold unless it is applied at the output, then up_0 .. up_{m-1}, most significant
    * first), as the RTL's constant table.
    */
  def taperTable: IndexedSeq[(Long, Long)] = {
    val m = p.taperTable
    val foldBit = if (p.taperFoldAtOutput) 0 else 1
    (0 until (1 << (m + foldBit))).map { idx =>
      val fold = foldBit == 1 && ((idx >> m) & 1) == 1
      var x = if (fold) -p.startX else p.startX
      var y = 0L
      for (j <- 0 until m) {
        val (nx, ny) = rotationStep(x, y, p.steps(j), ((idx >> (m - 1 - j)) & 1) == 1)
        x = chk(nx, s"table x[$j]"); y = chk(ny, s"table y[$j]")
      }
      (x, y)
    }
  }

  /** Vectoring: fold x < 0 by a half turn, then drive y to zero. */
  private def vectoring(in: CordicWord): CordicWord = {
    val xi = wrap(in.x, p.width) << p.guardBits
    val yi = wrap(in.y, p.width) << p.guardBits
    val fold = xi < 0
    var x = if (fold) -xi else xi
    var y = if (fold) -yi else yi
    var z = if (fold) -halfZ else 0L
    var idx = 0
    while (idx < stepAt.length) {
      val i = stepAt(idx); val k = angleAt(idx); idx += 1
      val down = y >= 0 // rotate clockwise when y >= 0
      val sx = shift(x, i, r); val sy = shift(y, i, r)
      val nx = if (down) x + sy else x - sy
      val ny = if (down) y - sx else y + sx
      z = wrap(if (down) z + k else z - k, p.zWidth)
      x = chk(nx, s"x[$i]"); y = chk(ny, s"y[$i]")
    }
    CordicWord(outData(x), 0L, outAngle(z))
  }

  /** Arcsine and arccosine, conventional (seed 002 eq. 8) or double rotation (seed 002 eq. 13). */
  private def arcsine(in: CordicWord): CordicWord = {
    val aIn = clampSine(in.y)
    var t = aIn << p.guardBits
    var x = 0L; var y = 0L; var z = 0L
    if (p.isDouble) {
      val pos = t >= 0
      y = if (pos) one else -one
      z = if (pos) quarterZ else -quarterZ
      var idx = 0
      while (idx < stepAt.length) {
        val i = stepAt(idx); val k = angleAt(idx); idx += 1
        // Right half-plane: compare with the target; left of the y axis: turn back towards it.
        val ccw = if (x < 0) y < 0 else y <= t
        val sx2 = shift(x, 2 * i, r); val sy2 = shift(y, 2 * i, r)
        val sx1 = shift(x, i - 1, r); val sy1 = shift(y, i - 1, r)
        val nx = if (ccw) x - sx2 - sy1 else x - sx2 + sy1
        val ny = if (ccw) y - sy2 + sx1 else y - sy2 - sx1
        z = wrap(if (ccw) z + k else z - k, p.zWidth)
        t = chk(t + shift(t, 2 * i, r), s"t[$i]")
        x = chk(nx, s"x[$i]"); y = chk(ny, s"y[$i]")
      }
    } else {
      x = p.startX
      var idx = 0
      while (idx < stepAt.length) {
        val i = stepAt(idx); val k = angleAt(idx); idx += 1
        val ccw = t >= y
        val sx = shift(x, i, r); val sy = shift(y, i, r)
        val nx = if (ccw) x - sy else x + sy
        val ny = if (ccw) y + sx else y - sx
        z = wrap(if (ccw) z + k else z - k, p.zWidth)
        x = chk(nx, s"x[$i]"); y = chk(ny, s"y[$i]")
      }
    }
    val zOut = peakTable.flatMap(_.lookup(aIn)) match {
      case Some(v) => if (p.mode.isAcos) wrap((1L << (p.angleBits - 2)) - v, p.angleBits) else v
      case None => outAngle(if (p.mode.isAcos) wrap(quarterZ - z, p.zWidth) else z)
    }
    CordicWord(0L, 0L, zOut)
  }

  /** Sine inputs beyond +-1.0 are clamped to +-1.0. */
  def clampSine(a: Long): Long = {
    val oneIn = 1L << p.dataFrac
    math.max(-oneIn, math.min(oneIn, wrap(a, p.width)))
  }

  private def outAngle(z: Long): Long = wrap(shift(z, p.zGuard, r), p.angleBits)

  private def outData(v: Long): Long = {
    val scaled =
      if (p.postScale) shift(BigInt(v) * BigInt(p.invGainConst), p.kFrac + p.guardBits, r).toLong
      else shift(v, p.guardBits, r)
    // Tapered sincos with an integer bit: |v| <= K < 2 cannot saturate, and the RTL has no saturation.
    if (p.taper && p.dataInt >= 1 && !fits(scaled, p.outWidth))
      throw new IllegalStateException(s"${p.moduleName}: output $scaled overflows ${p.outWidth} bits")
    saturate(scaled, p.outWidth)
  }
}

/** Local lookup table for arcsine near the peak, [83, 90] degrees (seed 000 sec. 3.3).
  * Covers input codes from `start` (the first code at or above sin 83 degrees) to 1.0 in
  * `size` bins of 2^binShift codes; each entry is the mid-range arcsine of its bin, in output
  * angle units.
  */
final case class PeakTable(p: CordicParams) {
  val size: Int = p.peakTableSize
  val oneCode: Long = 1L << p.dataFrac
  val start: Long = math.ceil(math.sin(math.toRadians(83)) * oneCode).toLong
  val binShift: Int = { var s = 0; while ((size.toLong << s) < oneCode - start + 1) s += 1; s }
  val entries: Seq[Long] = (0 until size).map { j =>
    val lo = start + (j.toLong << binShift)
    val hi = math.min(lo + (1L << binShift) - 1, oneCode)
    if (lo > oneCode) 1L << (p.angleBits - 2)
    else {
      val mid = (math.asin(lo.toDouble / oneCode) + math.asin(hi.toDouble / oneCode)) / 2
      Fixed.radToAngle(mid, p.angleBits)
    }
  }
  /** Largest distance from an entry to the arcsine of any code in its bin, radians. */
  val binError: Double = (0 until size).map { j =>
    val lo = start + (j.toLong << binShift)
    val hi = math.min(lo + (1L << binShift) - 1, oneCode)
    if (lo > oneCode) 0.0 else (math.asin(hi.toDouble / oneCode) - math.asin(lo.toDouble / oneCode)) / 2
  }.max

  /** Signed table angle for a clamped input code, or None outside the peak interval. */
  def lookup(a: Long): Option[Long] = {
    val m = math.abs(a)
    if (m < start) None
    else {
      val v = entries(((m - start) >> binShift).toInt)
      Some(if (a < 0) -v else v)
    }
  }
}
