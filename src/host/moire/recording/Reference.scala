package moire.recording

/** A reference trajectory a recording carries beside its signals (a second encoder, a rotary table, an
  * interferometer, the board's own count): `values` in the column's unit, unwrapped, with the fringe periods
  * and the turns one unit stands for where the metadata says (None: not known, to be fitted or not available).
  */
final case class Reference(column: String, unit: String, values: Array[Double], periodsPerUnit: Option[Double],
                           turnsPerUnit: Option[Double], source: String) {
  /** The column and its scale in words, for reports. */
  def describe: String = s"$column ($unit" + periodsPerUnit.map(p => f", ${p}%.6g fringe periods per $unit").getOrElse(", fringe periods per unit fitted") +
    turnsPerUnit.map(t => f", ${t}%.6g turns per $unit").getOrElse("") + s"; $source)"
}

object Reference {
  /** Reference columns in the order they are preferred: a separate encoder first, the board's own count last. */
  val Columns: Seq[String] = Seq("ref_deg", "ref_turns", "ref_counts", "ref_um", "position")

  /** Metadata keys that give the scale of a reference column. */
  val ScaleKeys: Seq[String] = Seq("lines_per_rev", "periods_per_turn", "ref_counts_per_turn", "ref_counts_per_period",
    "period_um", "counts_per_period")

  /** The reference of a recording, if it has one; a scale key that is present but not a positive number is an
    * error (Left, naming the key, the value and what is allowed).
    */
  def of(rec: Recording): Either[String, Option[Reference]] = {
    val bad = ScaleKeys.flatMap(k => rec.meta.get(k).filter(v => !moire.numbers.Decimal.double(v).exists(x => x > 0 && !x.isInfinite))
      .map(v => s"metadata $k '$v' is not a number above 0"))
    if (bad.nonEmpty) return Left(bad.head)
    def key(k: String): Option[Double] = rec.meta.get(k).flatMap(moire.numbers.Decimal.double)
    val (lpr, ppt) = (key("lines_per_rev"), key("periods_per_turn"))
    if (lpr.isDefined && ppt.isDefined && math.abs(lpr.get - ppt.get) > 1e-9 * lpr.get)
      return Left(s"metadata lines_per_rev ${lpr.get} and periods_per_turn ${ppt.get} disagree (both name the fringe periods per turn)")
    val perTurn = ppt.orElse(lpr)
    Right(Columns.find(rec.extra.contains).map { col =>
      val raw = rec.extra(col)
      col match {
        case "ref_deg" =>
          Reference(col, "degree", unwrap(raw, 360), perTurn.map(_ / 360), Some(1.0 / 360), "a reference angle")
        case "ref_turns" =>
          Reference(col, "turn", raw.clone(), perTurn, Some(1.0), "a reference angle")
        case "ref_counts" =>
          val cpt = key("ref_counts_per_turn"); val cpp = key("ref_counts_per_period")
          val turns = cpt.map(1 / _).orElse(cpp.zip(perTurn).map { case (c, p) => 1 / (c * p) }.headOption)
          val periods = cpp.map(1 / _).orElse(cpt.zip(perTurn).map { case (c, p) => p / c }.headOption)
          Reference(col, "count", unwrap(raw, cpt.getOrElse(Counter)), periods, turns, "a reference encoder's count")
        case "ref_um" =>
          Reference(col, "um", raw.clone(), key("period_um").map(1 / _), None, "a reference length")
        case _ =>
          val cpp = key("counts_per_period")
          Reference(col, "count", unwrap(raw, Counter), cpp.map(1 / _), cpp.zip(perTurn).map { case (c, p) => 1 / (c * p) }.headOption,
            "the board's own position, computed from these signals: distortion within a fringe period shows in it too")
      }
    })
  }

  /** A count's wrap: a 32-bit counter (the board's position, an encoder's count) goes from 2^31 - 1 to -2^31 on a
    * long run; no motion steps by half of it between two samples.
    */
  val Counter: Double = 4294967296.0

  /** Undoes wrapping at `modulus` (an angle output that restarts every turn): a step of more than half of it is a wrap. */
  def unwrap(a: Array[Double], modulus: Double): Array[Double] = {
    val out = new Array[Double](a.length)
    var add = 0.0; var i = 0
    while (i < a.length) {
      if (i > 0) {
        val d = a(i) - a(i - 1)
        if (d > 0.5 * modulus) add -= modulus else if (d < -0.5 * modulus) add += modulus
      }
      out(i) = a(i) + add; i += 1
    }
    out
  }
}
