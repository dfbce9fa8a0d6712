package moire.explain.evidence

/** A homodyne interferometer (or a read head without reference) sampled fast: the motion and the analog chain are
  * given; no reference column.
  */
object Interferometer {
  def text(travel: Travel, fs: Double, bench: Bench, meta: Seq[(String, String)] = Nil): String =
    BenchText("interferometer (no reference)", fs, bench.bits, bench.codes(travel, fs), meta)
}
