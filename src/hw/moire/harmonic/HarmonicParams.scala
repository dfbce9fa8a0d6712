package moire.harmonic

import moire.cordic.{CordicMode, CordicParams}

/** Parameters of the turntable harmonic compensator (seed 001, sections 1.2 and 3.2).
  *
  * Number formats:
  *  - theta: unsigned count of `countBits` = log2(lines * subdivision) bits, one turn = 2^countBits
  *    counts, so a count is also a binary angle (fraction of a turn).
  *  - order k: unsigned, `orderBits` bits (0 .. maxOrder).
  *  - c_k: two's complement arcsec, `coefWidth` bits with `coefFrac` fractional bits.
  *  - phi_k: binary angle, `countBits` bits (phi / 360 degrees * 2^countBits, modulo one turn).
  *  - sine: CORDIC sincos output, b + 2 bits with b = `dataBits` fractional bits (seed 001's b).
  *  - f(theta) and theta - f(theta): counts with `outFrac` fractional bits; f signed, the
  *    compensated angle unsigned modulo one turn (countBits + outFrac bits).
  *
  * @param lines       grating lines per turn (power of two)
  * @param subdivision interpolation factor of the read head (power of two)
  * @param harmonics   m, the number of parallel CORDIC sines (one per harmonic)
  * @param iterations  CORDIC iterations n
  * @param dataBits    CORDIC data bits b (fractional bits of the sine)
  * @param kFrac       fractional bits of the arcsec-to-counts constant
  */
case class HarmonicParams(
  lines: Int = 16384,
  subdivision: Int = 1024,
  harmonics: Int = 4,
  iterations: Int = 16,
  dataBits: Int = 18,
  coefWidth: Int = 28,
  coefFrac: Int = 20,
  maxOrder: Int = 255,
  outFrac: Int = 16,
  kFrac: Int = 24,
  pipelineEvery: Int = 1
) {
  private def isPow2(x: Long) = x > 0 && (x & (x - 1)) == 0
  require(isPow2(lines) && lines <= (1 << 24), s"lines must be a power of two in 1..2^24, got $lines")
  require(isPow2(subdivision) && subdivision <= (1 << 16), s"subdivision must be a power of two in 1..65536, got $subdivision")
  /** Counts per turn, lines * subdivision. */
  val countsPerTurn: Long = lines.toLong * subdivision
  /** Width of theta and phi_k: one turn = 2^countBits. */
  val countBits: Int = java.lang.Long.numberOfTrailingZeros(countsPerTurn)
  require(countBits >= 8 && countBits <= 32, s"lines * subdivision must be 2^8 .. 2^32 counts per turn, got 2^$countBits")
  require(harmonics >= 1 && harmonics <= 32, s"harmonics (m) must be in 1..32, got $harmonics")
  require(dataBits >= 6 && dataBits <= 40, s"data-bits (b) must be in 6..40, got $dataBits")
  require(coefWidth >= 8 && coefWidth <= 32, s"coef-width must be in 8..32 (the register data width), got $coefWidth")
  require(coefFrac >= 0 && coefFrac <= coefWidth - 2, s"coef-frac must be in 0..${coefWidth - 2} for coef-width $coefWidth, got $coefFrac")
  require(maxOrder >= 1 && maxOrder <= 65535, s"max-order must be in 1..65535, got $maxOrder")
  require(outFrac >= 0 && outFrac <= 24, s"out-frac must be in 0..24, got $outFrac")
  require(kFrac >= 8 && kFrac <= 40, s"k-frac must be in 8..40, got $kFrac")

  /** The rotation-mode sine CORDIC of each harmonic; angle input = the count word. */
  val cordic: CordicParams =
    CordicParams(CordicMode.SinCos, iterations, dataBits + 2, angleWidth = countBits, pipelineEvery = pipelineEvery)

  val orderBits: Int = CordicParams.log2Ceil(maxOrder + 1)
  /** Register data word width. */
  val regWidth: Int = 32
  /** Registers per harmonic slot: 0 order, 1 c_k, 2 phi_k (3 unused). */
  val regsPerSlot: Int = 4
  val addrBits: Int = math.max(1, CordicParams.log2Ceil(harmonics * regsPerSlot))

  /** Counts per arcsec, 2^countBits / 1296000. */
  val countsPerArcsec: Double = countsPerTurn.toDouble / 1296000.0
  val arcsecPerCount: Double = 1296000.0 / countsPerTurn.toDouble
  /** countsPerArcsec with kFrac fractional bits (unsigned). */
  val kConst: Long = math.round(countsPerArcsec * math.pow(2, kFrac))
  require(kConst > 0 && kConst < (1L << 48), s"k-frac $kFrac gives a counts-per-arcsec constant of $kConst, out of range")
  val kBits: Int = 64 - java.lang.Long.numberOfLeadingZeros(kConst)

  /** Width of c_k * sin: both signed. */
  val prodWidth: Int = coefWidth + cordic.outWidth
  /** Width of the sum of m products. */
  val sumWidth: Int = prodWidth + CordicParams.log2Ceil(harmonics)
  /** Fractional bits of the sum (arcsec). */
  val sumFrac: Int = coefFrac + cordic.dataFrac
  /** Right shift from sum * kConst to f in counts with outFrac bits. */
  val fShift: Int = sumFrac + kFrac - outFrac
  require(fShift >= 1, s"out-frac $outFrac too large for coef-frac + data-bits + k-frac")
  /** Width of f(theta) in counts with outFrac fractional bits (sum * K, shifted, plus a rounding bit). */
  val fWidth: Int = sumWidth + kBits + 1 - fShift + 1
  /** Width of the compensated angle theta - f(theta), modulo one turn. */
  val outWidth: Int = countBits + outFrac

  /** Clock cycles from in.valid to out.valid: angle stage, CORDIC, product ([[PieceMul]], three
    * clocks), sum, scale to counts (PieceMul again), rounding, subtract; the angle stage is two clocks (k theta, + phi).
    */
  val latency: Int = 2 + cordic.latency + 2 * PieceMul.latency + 3

  def moduleName: String =
    s"HarmonicComp_m${harmonics}_c$countBits" + s"_n${iterations}_b$dataBits" +
      s"_cw${coefWidth}f${coefFrac}_o${orderBits}_of${outFrac}_k$pipelineEvery"

  /** c_k in arcsec to its register word (two's complement value, not yet masked). */
  def coefWord(arcsec: Double): Long = {
    val v = math.round(arcsec * math.pow(2, coefFrac))
    require(v >= -(1L << (coefWidth - 1)) && v < (1L << (coefWidth - 1)),
      f"c_k = $arcsec%.6g arcsec does not fit coef-width $coefWidth with coef-frac $coefFrac (range +-${math.pow(2, coefWidth - 1 - coefFrac)}%.1f arcsec)")
    v
  }
  /** phi_k in degrees to its binary angle word, 0 .. 2^countBits - 1. */
  def phaseWord(deg: Double): Long = {
    val turn = 1L << countBits
    Math.floorMod(math.round(deg / 360.0 * turn), turn)
  }
}
