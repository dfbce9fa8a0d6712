package moire.files

/** The stem of an input's name that names its outputs (`<stem>.json`, `<stem>_*.png`): the name less `.csv`, or the
  * name less its leading dot when that leaves nothing (an input named `.csv` would write hidden files named `.json`).
  */
object Stem {
  def of(name: String): String = { val s = name.stripSuffix(".csv"); if (s.isEmpty) name.stripPrefix(".") else s }
  def of(p: os.Path): String = of(p.last)
}
