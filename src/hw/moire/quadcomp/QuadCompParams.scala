package moire.quadcomp

import moire.cordic.{CordicMode, CordicParams, Rounding}

/** Parameters of the quadrature-error compensator (seed 000).
  *
  * Number formats (two's complement):
  *  - inputs: signed ADC values, `inputBits` bits (AD9226: 12), full scale +-2^(inputBits-1).
  *  - gains: unsigned, `gainBits` bits with `gainFrac` fractional bits; normalised value =
  *    code * gain / 2^(inputBits-1), so gain = full scale / amplitude ([[gainFor]]).
  *  - signals inside and out (normalised sin, rebuilt cos): `width` bits, `dataFrac` = width - 2
  *    fractional bits (+-1.0 exact).
  *  - angles (phase difference, correction): `angleBits` = width bits, binary angle
  *    (2^angleBits = one turn).
  *
  * @param iterations    CORDIC iterations of all three CORDICs (paper: 16)
  * @param peakTableSize arcsine lookup table for [83, 90] degrees (0 = none, power of two)
  * @param averageLog2   the correction is an exponential average of the per-period measurements
  *                      with weight 2^-averageLog2 (0 = the paper: each period's value as it is)
  * @param pipelineEvery a register every k CORDIC iterations
  * @param fusePeaks     beyond the paper: within 45 degrees of the cos channel's peaks, where its
  *                      arccosine turns noise into angle, rebuild the cos from the sin channel's angle
  */
case class QuadCompParams(
  inputBits: Int = 12,
  iterations: Int = 16,
  width: Int = 18,
  peakTableSize: Int = 64,
  gainBits: Int = 18,
  gainFrac: Int = 16,
  averageLog2: Int = 3,
  pipelineEvery: Int = 1,
  rounding: Rounding = Rounding.HalfEven,
  fusePeaks: Boolean = false
) {
  require(inputBits >= 4 && inputBits <= 24, s"inputBits must be in 4..24, got $inputBits")
  require(width >= inputBits + 2 && width <= 32, s"width must be in ${inputBits + 2}..32 (inputBits + 2 ..), got $width")
  require(iterations >= 8 && iterations <= 32, s"iterations must be in 8..32, got $iterations")
  require(gainBits >= 4 && gainBits <= 24, s"gainBits must be in 4..24, got $gainBits")
  require(gainFrac >= 1 && gainFrac < gainBits, s"gainFrac must be in 1..${gainBits - 1}, got $gainFrac")
  require(averageLog2 >= 0 && averageLog2 <= 8, s"averageLog2 must be in 0..8, got $averageLog2")

  private def cordic(mode: CordicMode, table: Int) =
    CordicParams(mode, iterations, width, pipelineEvery = pipelineEvery, rounding = rounding, peakTableSize = table)
  /** Phase resolution of the sin channel: double-rotation arcsine with the peak table. */
  val asinP: CordicParams = cordic(CordicMode.AsinDouble, peakTableSize)
  /** Phase resolution of the cos channel: double-rotation arccosine with the peak table. */
  val acosP: CordicParams = cordic(CordicMode.AcosDouble, peakTableSize)
  /** Signal reconstruction: rotation mode from (1/K, 0), out.x = cos(z). */
  val rebuildP: CordicParams = cordic(CordicMode.SinCos, 0)

  val dataFrac: Int = asinP.dataFrac
  val angleBits: Int = asinP.angleBits
  /** Right shift from code * gain to the data word. */
  val normShift: Int = inputBits - 1 + gainFrac - dataFrac
  require(normShift >= 0, s"gainFrac must be at least ${dataFrac - inputBits + 1} for width $width, got $gainFrac")

  /** Clocks from in.valid to out.valid: normalise, arcsine, quadrant mapping, rebuild. */
  val latency: Int = 1 + asinP.latency + 1 + rebuildP.latency

  def moduleName: String = {
    val r = if (rounding == Rounding.Truncate) "tr" else "rne"
    val f = if (fusePeaks) "_fuse" else ""
    s"QuadComp_i${inputBits}_n${iterations}_w${width}_lut${peakTableSize}_g${gainBits}f${gainFrac}_avg${averageLog2}_k${pipelineEvery}_$r$f"
  }

  /** Gain word that maps an amplitude of `amplitudeCodes` ADC codes to 1.0. */
  def gainFor(amplitudeCodes: Double): Long = {
    require(amplitudeCodes > 0, s"amplitude must be > 0 codes, got $amplitudeCodes")
    val g = math.round(math.pow(2, gainFrac + inputBits - 1) / amplitudeCodes)
    require(g < (1L << gainBits), s"amplitude $amplitudeCodes codes needs a gain above the $gainBits-bit gain word")
    g
  }
}
