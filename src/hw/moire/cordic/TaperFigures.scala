package moire.cordic

import moire.paper.AccuracyRow

/** The lean sincos CORDIC against seed 001 Table 1 (n = 16, b = 18: accuracy 3.13e-5, 2769 LEs,
  * 15 clocks). The accuracy rows (source "taper", so that the seed 001 rows stay the paper's own)
  * are computed here; the cell count needs yosys and is in docs/cordic-taper.md.
  */
object TaperFigures {
  /** Seed 001 Table 1's accuracy. */
  val paperAccuracy: Double = 3.13e-5

  /** The cheapest tapered configuration found whose a priori bound meets the paper's accuracy:
    * n = 17 (the n = 16 approximation term alone is 3.05e-5), 20 internal fractional bits.
    */
  val lean: CordicParams = CordicParams(CordicMode.SinCos, iterations = 17, width = 20, guardBits = 2,
    angleGuardBits = 3, taper = true)

  def rows(): Seq[AccuracyRow] = {
    val b = CordicBound.headline(lean).total
    val every = (Fixed.minOf(lean.angleBits) to Fixed.maxOf(lean.angleBits)).map(z => CordicWord(0, 0, z))
    val m = CordicAccuracy.measure(lean, every)
    Seq(
      AccuracyRow("taper", s"seed 001 Table 1 accuracy, lean CORDIC bound (${lean.moduleName})", paperAccuracy, b,
        "1 (full scale)", b <= paperAccuracy, f"our a priori bound; latency ${lean.latency} clocks (paper 15)"),
      AccuracyRow("taper", "seed 001 Table 1 accuracy, lean CORDIC measured", paperAccuracy, m.maxError, "1 (full scale)",
        m.ok && m.maxError <= paperAccuracy, s"bit-accurate model over all ${m.samples} input angles, max of the sin and cos errors"))
  }
}
