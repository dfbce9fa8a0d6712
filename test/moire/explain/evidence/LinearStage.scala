package moire.explain.evidence

/** A linear scale of `periodUm` on a stage, read beside a laser interferometer that writes `ref_um` (quantized
  * to refNm), with `period_um` in the metadata. The motion and the analog chain are given.
  */
object LinearStage {
  final case class Spec(travel: Travel, fs: Double, bench: Bench, periodUm: Double = 20.0, startUm: Double = 1500.0,
                        refNm: Double = 1.0, withRef: Boolean = true)

  def text(s: Spec): String = {
    val ref = s.travel.periods.map(p => math.floor((s.startUm + p * s.periodUm) * 1000 / s.refNm) * s.refNm / 1000)
    BenchText("linear stage (scale beside an interferometer)", s.fs, s.bench.bits, s.bench.codes(s.travel, s.fs),
      Seq("period_um" -> s.periodUm.toString), if (s.withRef) "ref_um" else "", ref, 4)
  }

  /** Contrast lowered by `depth` over a band of the scale from fromUm to toUm after the start (contamination),
    * with edges of `edgeUm`; the argument is the position in periods from the start.
    */
  def band(periodUm: Double, fromUm: Double, toUm: Double, depth: Double, edgeUm: Double = 60): Double => Double = { p =>
    val x = p * periodUm
    1 - depth * 0.5 * (math.tanh((x - fromUm) / edgeUm) - math.tanh((x - toUm) / edgeUm))
  }
}
