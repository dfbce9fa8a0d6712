package moire.calibration

import moire.harmonic._

import moire.paper.AccuracyRow
import moire.cordic.PaperBounds

/** Seed 001 section 4.1: eq. 19 through the compensator, against double precision. */
object HarmonicReproduce {
  /** The compensator as the paper sizes it: 16384 lines x 1024, m = 4, n = 16, b = 18. */
  val paperParams: HarmonicParams = HarmonicParams()

  /** Eq. 19 as register slots (order k, c_k, phi_k). */
  def eq19Slots(p: HarmonicParams): Seq[HarmonicSlot] = {
    val s = PaperBounds.seed001Eq19.map { case (k, c, phi) => HarmonicSlot.of(p, k, c, phi) }
    s ++ Seq.fill(p.harmonics - s.size)(HarmonicSlot.off)
  }

  /** `n` angles equally spaced on [0, 360) degrees, rounded to the count grid. */
  def angles(p: HarmonicParams, n: Int = 10000): Seq[Long] =
    (0 until n).map(j => math.round(j.toDouble / n * p.countsPerTurn) % p.countsPerTurn)

  /** |f read from the output - f in double precision| in arcsec, for one output word. */
  def error(p: HarmonicParams, model: HarmonicModel, theta: Long, out: Long): Double =
    math.abs(model.fArcsec(theta, out) - HarmonicReference.f(p, theta, PaperBounds.seed001Eq19))

  /** Largest error of the bit-accurate model over the angles, arcsec. */
  def modelMax(p: HarmonicParams = paperParams, n: Int = 10000): Double = {
    val model = new HarmonicModel(p)
    val slots = eq19Slots(p)
    angles(p, n).map(t => error(p, model, t, model(t, slots).out)).max
  }

  def rows(): Seq[AccuracyRow] = {
    val p = paperParams
    val sumC = PaperBounds.seed001Eq19.map(c => math.abs(c._2)).sum
    val pmax = math.min(PaperBounds.seed001Pmax(16, 18, sumC), 1.19e-3) // eq. 16, and the paper's printed value
    val ours = modelMax(p)
    Seq(AccuracyRow("seed001", "sec. 4.1 compensator theta - f(theta), eq. 19, 10,000 angles, n=16 b=18", 9.36e-4, ours,
      "arcsec", ours < pmax,
      f"holds when below P_max = $pmax%.3g (paper); bit-accurate model of HarmonicCompensator (m=4, 2^24 counts/turn, " +
        f"c_k ${p.coefFrac} frac bits, output ${p.outFrac} frac bits of a count), proven bit-exact to the RTL over " +
        "the same 10,000 angles by HarmonicRtlSpec (Verilator)"))
  }
}
