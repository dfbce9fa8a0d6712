package moire.subdiv

import moire.cordic.{CordicMode, CordicParams, Rounding}

/** How the subdivider turns (sin, cos) into a phase. */
sealed abstract class PhaseMethod(val name: String)
object PhaseMethod {
  /** Vectoring CORDIC, atan2(sin, cos): independent of the signal amplitude. */
  case object Atan2 extends PhaseMethod("atan2")
  /** Double-rotation arcsine (seed 002 eqs. 9-13) on the smaller channel divided by a nominal
    * amplitude (octant scheme, see [[SubdivParams.asinAmplitude]]).
    */
  case object AsinDouble extends PhaseMethod("asin-double")
  val all: Seq[PhaseMethod] = Seq(Atan2, AsinDouble)
  def parse(s: String): Either[String, PhaseMethod] =
    moire.choice.Choice(all, s, s"--method: '$s' is not a phase method")(_.name)
}

/** Parameters of the digital subdivider ([[Subdivider]], [[SubdivModel]]).
  *
  * Number formats:
  *  - sin, cos in: signed ADC values, `inputBits` wide, full scale +-2^(inputBits-1) = +-1.0.
  *  - phase: unsigned binary angle, `phaseBits` wide, one turn = 2^phaseBits.
  *  - m: the top `countBits` bits of the phase, m = floor(phase / turn * M) (seed 002 eq. 1).
  *  - periods: signed period count, `positionWidth - countBits` bits, wraps.
  *  - position = periods * M + m, signed `positionWidth` bits, wraps (a free-running counter).
  *
  * @param counts          M, counts per grating period: a power of two in 4..65536
  * @param cordicWidth     CORDIC data width (default inputBits + 6); the ADC word enters its top bits
  * @param phaseBits       phase word width (default max(cordicWidth, log2 M + 2))
  * @param minEdgeClocks   A/B edges at least this many clocks apart (1 = an edge every clock)
  * @param backlogLimit    counts the A/B output may lag the position before `overspeed` is set
  * @param presentThreshold signal present when sqrt(sin^2 + cos^2) >= this (fraction of full scale)
  * @param asinAmplitude   asin-double only: nominal signal amplitude (fraction of full scale) that
  *                        the arcsine argument is divided by
  * @param maxStepTurns    a phase step larger than this (turns per sample) sets `stepFault`: the
  *                        motion is too close to the Nyquist limit (0.5) to be counted safely
  */
case class SubdivParams(
  inputBits: Int = 12,
  method: PhaseMethod = PhaseMethod.Atan2,
  counts: Int = 1024,
  iterations: Int = 16,
  cordicWidth: Int = -1,
  guardBits: Int = 2,
  phaseBits: Int = -1,
  positionWidth: Int = 32,
  minEdgeClocks: Int = 1,
  backlogLimit: Int = 64,
  presentThreshold: Double = 0.1,
  asinAmplitude: Double = 0.9,
  maxStepTurns: Double = 0.46875,
  rounding: Rounding = Rounding.HalfEven
) {
  require(inputBits >= 4 && inputBits <= 16, s"input-bits must be in 4..16, got $inputBits")
  require(counts >= 4 && counts <= 65536 && (counts & (counts - 1)) == 0,
    s"counts (M) must be a power of two in 4..65536, got $counts")
  /** log2 M. */
  val countBits: Int = Integer.numberOfTrailingZeros(counts)
  /** CORDIC data width. */
  val width: Int = if (cordicWidth < 0) inputBits + 6 else cordicWidth
  require(width >= inputBits + 1 && width <= 40, s"cordic-width must be in ${inputBits + 1}..40 for $inputBits input bits, got $cordicWidth")
  val angleBits: Int = if (phaseBits < 0) math.max(width, countBits + 2) else phaseBits
  require(angleBits >= math.max(8, countBits) && angleBits <= 40,
    s"phase-bits must be in ${math.max(8, countBits)}..40 for M = $counts, got $phaseBits")
  require(positionWidth >= countBits + 2 && positionWidth <= 62,
    s"position-width must be in ${countBits + 2}..62 for M = $counts, got $positionWidth")
  require(minEdgeClocks >= 1 && minEdgeClocks <= 4096, s"min-edge-clocks must be in 1..4096, got $minEdgeClocks")
  require(backlogLimit >= 1 && backlogLimit.toLong <= (1L << (positionWidth - 2)),
    s"backlog-limit must be in 1..${1L << (positionWidth - 2)}, got $backlogLimit")
  require(presentThreshold >= 0 && presentThreshold < 1, s"present-threshold must be in [0, 1), got $presentThreshold")
  require(asinAmplitude >= 0.25 && asinAmplitude <= 1.0, s"asin-amplitude must be in [0.25, 1], got $asinAmplitude")
  require(maxStepTurns > 0 && maxStepTurns <= 0.5, s"max-step-turns must be in (0, 0.5], got $maxStepTurns")

  val isAsin: Boolean = method == PhaseMethod.AsinDouble
  /** The CORDIC: atan2 without gain compensation (the angle does not need it), or the double-rotation arcsine. */
  val cordic: CordicParams = CordicParams(
    mode = if (isAsin) CordicMode.AsinDouble else CordicMode.Atan2,
    iterations = iterations, width = width, angleWidth = angleBits, guardBits = guardBits,
    rounding = rounding, gainCompensation = isAsin)
  /** Left shift that places an ADC value in the CORDIC's data format (width - 2 fractional bits). */
  val inputShift: Int = cordic.dataFrac - (inputBits - 1)
  /** asin: fractional bits and value of 1 / asinAmplitude. */
  val kFrac: Int = cordic.dataFrac + 2
  val kConst: Long = math.round(math.pow(2, kFrac) / asinAmplitude)
  /** asin: the product sel * kConst has (inputBits - 1) + kFrac fractional bits; this shift brings it to dataFrac. */
  val kShift: Int = inputBits - 1 + kFrac - cordic.dataFrac
  /** Signal present when sin^2 + cos^2 >= this (ADC codes squared). */
  val presentSq: Long = math.ceil(math.pow(presentThreshold * (1L << (inputBits - 1)), 2)).toLong
  /** Largest phase step (phase units) that does not set stepFault. */
  val stepLimit: Long = math.floor(maxStepTurns * math.pow(2, angleBits)).toLong
  val periodBits: Int = positionWidth - countBits

  /** Clocks from in.valid to out.valid: input register, CORDIC, phase register, counter register. */
  val latency: Int = 1 + cordic.latency + 1 + 1

  /** Module name carrying the parameters. */
  def moduleName: String = {
    val m = method.name.replace("-", "_")
    val a = if (isAsin) f"_amp${math.round(asinAmplitude * 1000)}%03d" else ""
    s"Subdiv_${m}_in${inputBits}_M${counts}_n${iterations}_w${width}g${guardBits}_p${angleBits}_pos${positionWidth}_e${minEdgeClocks}$a"
  }
}
