package moire.cordic

/** What a CORDIC instance computes. */
sealed abstract class CordicMode(val name: String) {
  def isAsin: Boolean = false
  def isDouble: Boolean = false
  def isAcos: Boolean = false
}
object CordicMode {
  /** Rotation mode from the constant vector (1/K, 0): out.x = cos(in.z), out.y = sin(in.z). */
  case object SinCos extends CordicMode("sincos")
  /** Rotation mode: (out.x, out.y) = (in.x, in.y) rotated by in.z (times K when gain compensation is off). */
  case object Rotate extends CordicMode("rotate")
  /** Vectoring mode: out.z = atan2(in.y, in.x), out.x = |(in.x, in.y)| (times K when compensation is off). */
  case object Atan2 extends CordicMode("atan2")
  /** Conventional arcsine, seed 002 eq. 8: out.z = asin(in.y). */
  case object Asin extends CordicMode("asin") { override def isAsin = true }
  /** Double-rotation arcsine, seed 002 eqs. 9-13: out.z = asin(in.y). */
  case object AsinDouble extends CordicMode("asin-double") { override def isAsin = true; override def isDouble = true }
  /** Conventional arccosine: out.z = pi/2 - asin(in.y). */
  case object Acos extends CordicMode("acos") { override def isAsin = true; override def isAcos = true }
  /** Double-rotation arccosine: out.z = pi/2 - asin(in.y). */
  case object AcosDouble extends CordicMode("acos-double") {
    override def isAsin = true; override def isDouble = true; override def isAcos = true
  }

  val all: Seq[CordicMode] = Seq(SinCos, Rotate, Atan2, Asin, AsinDouble, Acos, AcosDouble)
  def parse(s: String): Either[String, CordicMode] =
    moire.choice.Choice(all, s, s"--mode: '$s' is not a mode")(_.name)
}

/** How a value loses its low bits: floor (plain arithmetic shift) or round half to even. */
sealed abstract class Rounding(val name: String)
object Rounding {
  case object Truncate extends Rounding("truncate")
  case object HalfEven extends Rounding("half-even")
  val all: Seq[Rounding] = Seq(Truncate, HalfEven)
  def parse(s: String): Either[String, Rounding] =
    moire.choice.Choice(all, s, s"--rounding: '$s' is not a rounding")(_.name)
}

/** Parameters of one CORDIC generator instance.
  *
  * Number formats (all two's complement):
  *  - data in and out (x, y, sine values): `width` bits, `fracBits` fractional bits;
  *    atan2 magnitude: `width + 2` bits, same fractional bits (it may exceed full scale).
  *  - angles in and out: `angleWidth`-bit binary angle, value / 2^angleWidth turns,
  *    read modulo one turn (so the word covers the full circle).
  *  - inside: x, y (and the arcsine target) carry `fracBits + guardBits` fractional bits and
  *    enough integer bits never to overflow; z carries `angleWidth + angleGuardBits` bits.
  *
  * Iterations: conventional modes run i = 0 .. n-1 with angles atan(2^-i) (seed 001 eq. 5);
  * the double-rotation arcsine takes a free +-90 degree first step, then i = 1 .. n with
  * angles 2 atan(2^-i) (seed 002 eqs. 13-14).
  *
  * @param pipelineEvery a register after every k iterations (1 = fully pipelined)
  * @param peakTableSize entries of the arcsine lookup table for [83, 90] degrees (0 = none; seed 000 sec. 3.3)
  * @param taper lean sincos datapath ([[CordicTaper]]): the same arithmetic (bit for bit the same results as
  *              without it), fewer cells: x/y without headroom bits, z words narrowed per stage to the
  *              residual's proven range, the first `taperTable` iterations folded into a constant table,
  *              rounding as the adder's carry in, no saturation where none can occur; latency n clocks
  */
case class CordicParams(
  mode: CordicMode = CordicMode.SinCos,
  iterations: Int = 16,
  width: Int = 18,
  fracBits: Int = -1,
  angleWidth: Int = -1,
  guardBits: Int = 0,
  angleGuardBits: Int = -1,
  pipelineEvery: Int = 1,
  rounding: Rounding = Rounding.HalfEven,
  gainCompensation: Boolean = true,
  peakTableSize: Int = 0,
  taper: Boolean = false
) {
  require(iterations >= 4 && iterations <= 40, s"iterations must be in 4..40, got $iterations")
  require(width >= 8 && width <= 48, s"width must be in 8..48, got $width")

  /** Fractional bits of data words; default width - 2, so that +-1.0 is exact. */
  val dataFrac: Int = if (fracBits < 0) width - 2 else fracBits
  require(dataFrac >= 1 && dataFrac <= width - 1, s"frac-bits must be in 1..${width - 1} for width $width, got $fracBits")
  /** Angle word width; default the data width. */
  val angleBits: Int = if (angleWidth < 0) width else angleWidth
  require(angleBits >= 8 && angleBits <= 48, s"angle-width must be in 8..48, got $angleWidth")
  require(guardBits >= 0 && guardBits <= 8, s"guard-bits must be in 0..8, got $guardBits")
  /** Extra z bits so that n rounded table entries cost less than one output LSB; default ceil(log2 n) + 1. */
  val zGuard: Int = if (angleGuardBits < 0) CordicParams.log2Ceil(iterations) + 1 else angleGuardBits
  require(zGuard <= 8, s"angle-guard-bits must be in 0..8, got $angleGuardBits")
  require(pipelineEvery >= 1 && pipelineEvery <= iterations,
    s"pipeline-every must be in 1..$iterations (the iteration count), got $pipelineEvery")
  require(peakTableSize >= 0 && peakTableSize <= 4096 && (peakTableSize & (peakTableSize - 1)) == 0,
    s"peak-table must be 0 or a power of two up to 4096, got $peakTableSize")
  require(peakTableSize == 0 || mode.isAsin, s"peak-table applies to the arcsine and arccosine modes only, not ${mode.name}")
  require(gainCompensation || !(mode == CordicMode.Asin || mode == CordicMode.Acos),
    s"gain compensation cannot be turned off for ${mode.name}: its start vector 1/K carries it")

  require(!taper || mode == CordicMode.SinCos, s"taper applies to sincos only, not ${mode.name}")
  require(!taper || pipelineEvery == 1, s"taper needs pipeline-every 1 (one adder between registers), got $pipelineEvery")

  /** Fractional bits of x, y (and the arcsine target) inside the iterations. */
  val innerFrac: Int = dataFrac + guardBits
  /** Integer bits of the input data words (without the sign). */
  val dataInt: Int = width - 1 - dataFrac
  require(gainCompensation || dataInt >= 1 || !(mode == CordicMode.SinCos || mode == CordicMode.Rotate),
    s"${mode.name} without gain compensation outputs K = 1.65 times full scale: frac-bits must leave an integer bit (at most ${width - 2})")
  /** Internal x/y width: sign + headroom for the CORDIC gain and adder transients + fraction.
    * Tapered sincos: |(x, y)| never exceeds K < 2, so sign + one integer bit + fraction.
    */
  val innerWidth: Int = if (taper) 2 + innerFrac else 1 + dataInt + 3 + innerFrac
  require(innerWidth <= 60, s"width plus guard bits too large for the 64-bit model ($innerWidth internal bits)")
  /** Internal angle width (binary angle, one turn = 2^zWidth). */
  val zWidth: Int = angleBits + zGuard
  /** Width of out.x and out.y. */
  val outWidth: Int = if (mode == CordicMode.Atan2) width + 2 else width

  val isDouble: Boolean = mode.isDouble
  /** Iteration indices as the hardware runs them. */
  val steps: Seq[Int] = if (isDouble) 1 to iterations else 0 until iterations

  /** Rotation angle of each step, in radians. */
  def stepAngle(i: Int): Double = if (isDouble) 2 * math.atan(math.pow(2, -i)) else math.atan(math.pow(2, -i))
  /** The arctan table in z units (binary angle with zWidth bits), rounded to nearest. */
  val angleTable: Seq[Long] = steps.map(i => math.round(stepAngle(i) / (2 * math.Pi) * math.pow(2, zWidth)))

  /** CORDIC gain of the conventional iterations, K_n = prod sqrt(1 + 2^-2i), i = 0..n-1. */
  val gain: Double = (0 until iterations).map(i => math.sqrt(1 + math.pow(2, -2 * i))).product
  /** Magnitude of the double-rotation vector after all steps (start 1.0): prod (1 + 2^-2i), i = 1..n. */
  val doubleGain: Double = (1 to iterations).map(i => 1 + math.pow(2, -2 * i)).product

  /** Fractional bits of the 1/K constant used for gain compensation. */
  val kFrac: Int = innerFrac + 2
  /** 1/K in kFrac fractional bits. */
  val invGainConst: Long = math.round(math.pow(2, kFrac) / gain)
  /** Start x for sincos and the conventional arcsine: 1/K (or 1.0 without compensation) in innerFrac bits. */
  val startX: Long =
    if (gainCompensation) math.round(math.pow(2, innerFrac) / gain) else 1L << innerFrac

  /** Does the output stage multiply by 1/K? (rotate and atan2 with compensation on) */
  val postScale: Boolean = gainCompensation && (mode == CordicMode.Rotate || mode == CordicMode.Atan2)

  /** Number of iteration register groups. */
  val groups: Int = (iterations + pipelineEvery - 1) / pipelineEvery
  /** Tapered with round half to even: the quadrant fold negates the vector, so it is applied to the
    * output (round half to even is odd-symmetric, hence -round(v) = round(-v)) instead of the table.
    */
  val taperFoldAtOutput: Boolean = taper && rounding == Rounding.HalfEven
  /** Tapered: iterations 0 .. taperTable-1 come from a constant table indexed by their directions
    * (and the fold unless it is applied at the output): 5 address bits.
    */
  val taperTable: Int =
    if (taper) math.min(CordicParams.taperTableBits - (if (taperFoldAtOutput) 0 else 1), iterations) else 0
  /** Clock cycles from in.valid to out.valid: input stage, iteration groups, output stage(s).
    * Tapered: iterations 0 and 1 are bit logic on the input, so stages 1 .. n-1 and the output.
    */
  val latency: Int = if (taper) iterations else 1 + groups + 1 + (if (postScale) 1 else 0)

  /** Tapered: the interval [lo, hi] of z after iteration i (i = 0 .. n-1), in z units, from the
    * interval after the fold and the rounded table (z >= 0 subtracts the entry, z < 0 adds it).
    */
  lazy val zRanges: IndexedSeq[(Long, Long)] = {
    val q = 1L << (zWidth - 2)
    var lo = -q; var hi = q - (1L << zGuard)
    angleTable.map { k =>
      val pos = if (hi >= 0) Some((math.max(lo, 0L) - k, hi - k)) else None
      val neg = if (lo < 0) Some((lo + k, math.min(hi, -1L) + k)) else None
      val both = pos.toSeq ++ neg.toSeq
      lo = both.map(_._1).min; hi = both.map(_._2).max
      (lo, hi)
    }.toIndexedSeq
  }
  /** Bits of a signed word holding [lo, hi]. */
  def signedBits(lo: Long, hi: Long): Int = {
    var b = 1
    while (lo < -(1L << (b - 1)) || hi > (1L << (b - 1)) - 1) b += 1
    b
  }

  /** Module name carrying the parameters. */
  def moduleName: String = {
    val m = mode.name.replace("-", "_")
    val r = if (rounding == Rounding.Truncate) "tr" else "rne"
    val g = if (gainCompensation) "" else "_nogc"
    val t = if (peakTableSize > 0) s"_lut$peakTableSize" else ""
    val tp = if (taper) "_taper" else ""
    s"Cordic_${m}_n${iterations}_w${width}f${dataFrac}_a${angleBits}_g${guardBits}z${zGuard}_k${pipelineEvery}_$r$g$t$tp"
  }
}

object CordicParams {
  def log2Ceil(x: Int): Int = { var b = 0; while ((1L << b) < x) b += 1; b }
  /** Address bits of the tapered sincos's constant table (a 5-input function per bit). */
  val taperTableBits: Int = 5
}
