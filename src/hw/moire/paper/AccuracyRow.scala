package moire.paper

/** One line of the `accuracy` report: a paper's figure beside ours. */
final case class AccuracyRow(source: String, item: String, paper: ujson.Value, ours: ujson.Value, unit: String,
                             holds: Boolean, note: String = "") {
  def json: ujson.Obj = ujson.Obj("source" -> source, "item" -> item, "paper" -> paper, "ours" -> ours,
    "unit" -> unit, "holds" -> holds, "note" -> note)
}
