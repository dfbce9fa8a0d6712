package moire.adapt

import moire.cordic.{CordicMode, CordicParams}

/** Parameters of the adaptive signal corrector [[AdaptiveCorrector]] (model: [[AdaptModel]]).
  *
  * Number formats (two's complement; "u" = units of the stated LSB):
  *  - in: sin, cos, `inputBits` signed ADC codes.
  *  - offsets os, oc: input LSB with `offsetFrac` fractional bits, `inputBits + offsetFrac + 1` bits.
  *  - gains ks, kc: output LSB per input LSB, `gainBits` bits with `gainFrac` fractional bits.
  *  - phase term t (tan of the channel phase error): `phaseBits` bits, `phaseBits - 1` fractional bits.
  *  - out: sin, cos, `outputBits` signed; amplitude 2^(outputBits-1)/sqrt(2) after convergence.
  *  - angles: the Atan2 CORDIC gives an `angleBits` binary angle; the harmonic table, the PLL and the
  *    residual use "fine" angles of `fineBits` = angleBits + `fineGuard` bits (one turn = 2^fineBits).
  *
  * Update rates are shifts: a per-period update moves an estimate by 2^-rate of its error
  * (times N / 2^bitlength(N) in [0.5, 1), N = samples in the period); the table moves each entry by
  * 2^-`harmonicRate` of the residual per sample. PLL gains are 2^-pllKp (phase), 2^-pllKv (velocity),
  * 2^-pllKf (frequency-difference aid); the PLL acts on each sample's errors one sample late.
  *
  * @param initialAmplitude amplitude (fraction of input full scale) the start gains assume
  * @param harmonicEntries  entries of the harmonic phase-correction table (power of two, 0 = no table)
  * @param minSpeedShift    the table adapts only while |speed| >= 2^-minSpeedShift turns per sample
  */
case class AdaptParams(
  inputBits: Int = 12,
  outputBits: Int = 16,
  offsetFrac: Int = 12,
  mulFrac: Int = 4,
  gainBits: Int = 24,
  phaseBits: Int = 18,
  offsetRate: Int = 4,
  gainRate: Int = 4,
  phaseRate: Int = 4,
  periodBits: Int = 16,
  windowBits: Int = 10,
  cordicIterations: Int = 18,
  angleBits: Int = 20,
  harmonicEntries: Int = 64,
  interpBits: Int = 8,
  fineGuard: Int = 8,
  tableBits: Int = 22,
  harmonicRate: Int = 8,
  pllKp: Int = 8,
  pllKv: Int = 17,
  pllKf: Int = 12,
  lockBits: Int = 10,
  lockShift: Int = 6,
  meanShift: Int = 4,
  minSpeedShift: Int = 9,
  initialAmplitude: Double = 0.8
) {
  require(inputBits >= 8 && inputBits <= 16, s"inputBits must be in 8..16, got $inputBits")
  require(outputBits >= inputBits && outputBits <= 18, s"outputBits must be in $inputBits..18 (inputBits..18), got $outputBits")
  require(offsetFrac >= 4 && offsetFrac <= 16, s"offsetFrac must be in 4..16, got $offsetFrac")
  require(mulFrac >= 0 && mulFrac <= offsetFrac && inputBits + mulFrac + 2 <= 18,
    s"mulFrac must be in 0..${math.min(offsetFrac, 16 - inputBits)} (multiplier operand <= 18 bits), got $mulFrac")
  /** Integer bits of the gains: room for inputs down to 1/16 of full scale. */
  val gainInt: Int = outputBits - inputBits + 4
  require(gainBits >= gainInt + 8 && gainBits <= 27, s"gainBits must be in ${gainInt + 8}..27, got $gainBits")
  val gainFrac: Int = gainBits - 1 - gainInt
  require(phaseBits >= 10 && phaseBits <= 18, s"phaseBits must be in 10..18, got $phaseBits")
  val phaseFrac: Int = phaseBits - 1
  Seq("offsetRate" -> offsetRate, "gainRate" -> gainRate, "phaseRate" -> phaseRate).foreach { case (n, v) =>
    require(v >= 0 && v <= 12, s"$n must be in 0..12, got $v")
  }
  require(periodBits >= 6 && periodBits <= 20, s"periodBits must be in 6..20, got $periodBits")
  require(windowBits >= 0 && windowBits < periodBits, s"windowBits must be in 0..${periodBits - 1} (below periodBits), got $windowBits")
  require(cordicIterations >= 8 && cordicIterations <= 24, s"cordicIterations must be in 8..24, got $cordicIterations")
  require(angleBits >= 12 && angleBits <= 24, s"angleBits must be in 12..24, got $angleBits")
  require(harmonicEntries == 0 || (harmonicEntries >= 4 && harmonicEntries <= 1024 && (harmonicEntries & (harmonicEntries - 1)) == 0),
    s"harmonicEntries must be 0 or a power of two in 4..1024, got $harmonicEntries")
  val tableIndexBits: Int = if (harmonicEntries == 0) 0 else Integer.numberOfTrailingZeros(harmonicEntries)
  require(interpBits >= 1 && interpBits <= 10 && tableIndexBits + interpBits <= angleBits,
    s"interpBits must be in 1..${math.min(10, angleBits - tableIndexBits)}, got $interpBits")
  require(fineGuard >= 0 && fineGuard <= 12, s"fineGuard must be in 0..12, got $fineGuard")
  val fineBits: Int = angleBits + fineGuard
  require(tableBits >= 8 && tableBits <= fineBits - 6, s"tableBits must be in 8..${fineBits - 6} (table range below 1/64 turn), got $tableBits")
  require(harmonicRate >= 0 && harmonicRate <= 16, s"harmonicRate must be in 0..16, got $harmonicRate")
  require(pllKp >= 1 && pllKp <= 16, s"pllKp must be in 1..16, got $pllKp")
  require(pllKv >= 1 && pllKv <= 30, s"pllKv must be in 1..30, got $pllKv")
  require(pllKf >= 1 && pllKf <= 24, s"pllKf must be in 1..24, got $pllKf")
  // The PLL acts on each sample's error one sample late; its poles stay inside the unit circle for every pllKf
  // when the velocity gain is below the phase gain (pllKv > pllKp, and pllKv >= 3).
  require(pllKv >= math.max(pllKp + 1, 3), s"pllKv must be at least ${math.max(pllKp + 1, 3)} (above pllKp $pllKp and >= 3: the PLL's stable range), got $pllKv")
  require(lockBits >= 1 && lockBits <= 20, s"lockBits must be in 1..20, got $lockBits")
  require(lockShift >= 2 && lockShift <= fineBits - 2, s"lockShift must be in 2..${fineBits - 2}, got $lockShift")
  require(meanShift >= 1 && meanShift <= 16, s"meanShift must be in 1..16, got $meanShift")
  require(minSpeedShift >= 1 && minSpeedShift <= fineBits - 2, s"minSpeedShift must be in 1..${fineBits - 2}, got $minSpeedShift")
  require(initialAmplitude >= 0.0625 && initialAmplitude <= 1.0, s"initialAmplitude must be in 0.0625..1.0, got $initialAmplitude")

  /** Width of the offset registers and of x - offset with offsetFrac fractional bits. */
  val offsetWidth: Int = inputBits + offsetFrac + 1
  val diffWidth: Int = inputBits + offsetFrac + 2
  /** Multiplier operand: x - offset rounded to mulFrac fractional bits. */
  val mulWidth: Int = inputBits + mulFrac + 2
  /** Target mean square of each output channel, R^2 / 2 with R = 2^(outputBits-1) / sqrt 2. */
  val targetSquareLog2: Int = 2 * outputBits - 4
  /** Extra shifts that turn the per-period error sums into gain and phase steps (see the doc). */
  val gainShift: Int = outputBits + inputBits - 3 - gainFrac
  val phaseShift: Int = targetSquareLog2 - phaseFrac
  require(gainShift >= 0 && phaseShift >= 0, s"gainBits/phaseBits too wide for outputBits $outputBits")
  /** Start gain: output amplitude R over the assumed input amplitude, gainFrac fractional bits. */
  val startGain: Long =
    math.round(math.pow(2, outputBits - 1) / math.sqrt(2) / (initialAmplitude * math.pow(2, inputBits - 1)) * math.pow(2, gainFrac))
  require(startGain < (1L << (gainBits - 1)), s"initialAmplitude $initialAmplitude needs a gain beyond gainBits")
  /** Widths of the per-period sums. */
  val countMax: Long = (1L << periodBits) - 1
  val sumOffsetWidth: Int = diffWidth + periodBits
  val sumSquareWidth: Int = 2 * outputBits + periodBits + 1

  /** The reused vectoring CORDIC: atan2 of the offset/gain/phase-corrected (cos, sin). */
  val cordic: CordicParams = CordicParams(CordicMode.Atan2, cordicIterations, outputBits, angleWidth = angleBits,
    guardBits = 2, gainCompensation = false)

  /** 2 pi in 14 fractional bits: turns the table's fine angle into radians for the small rotation. */
  val twoPiFrac: Int = 14
  val twoPi: Long = math.round(2 * math.Pi * (1L << twoPiFrac))
  /** Rotation angle in radians: 18 bits, fractional bits chosen so the table range fits. */
  val rotWidth: Int = 18
  val rotFrac: Int = fineBits - tableBits + 14

  /** Pipeline (one register between stages; see docs/adaptive-correction.md): the correction takes
    * five clocks (offset and round, gain products, round and saturate, phase product, sum and
    * saturate); a closed window moves the estimates `updateDelay` clocks after its statistics clock
    * (snapshot, the rounding's half step added, shifted steps). After the CORDIC, counted from the clock the table is read: the
    * interpolated value at 3, fine phase and radian product at 4, PLL at `pllStage`, rotation
    * products at 6, output register and table leak at `leakStage`, table read-modify-write at `rmwStage`.
    */
  val correctionStages: Int = 5
  val updateDelay: Int = 3
  val pllStage: Int = 5
  val leakStage: Int = 7
  val rmwStage: Int = 8

  /** Clock cycles from in.valid to out.valid: input register, correction, CORDIC, table and rotation. */
  val latency: Int = 1 + correctionStages + cordic.latency + rmwStage

  def moduleName: String =
    s"AdaptiveCorrector_i${inputBits}o${outputBits}_r${offsetRate}${gainRate}${phaseRate}_p$periodBits" +
      s"_n${cordicIterations}a${angleBits}_h${harmonicEntries}r$harmonicRate"
}
