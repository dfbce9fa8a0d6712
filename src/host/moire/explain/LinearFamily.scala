package moire.explain

/** The variants of a linear term on the sin channel, the cos channel or both (a harmonic of the fringe, an ADC's
  * nonlinearity) share their columns: the family's columns are made once, their products summed once per channel, and
  * each variant's fit and residual sums of squares are read off those sums (the fit its own columns would give, in one
  * pass over the samples instead of three, and no residual passes). `g` and `r` are the Gram of every column's sin part
  * (the first k) and cos part (the next k) and their products with the residual.
  */
final class LinearFamily(k: Int, g: Array[Array[Double]], r: Array[Double], val hasSin: IndexedSeq[Boolean],
                         val hasCos: IndexedSeq[Boolean], yyS: Double, yyC: Double) {
  /** The fit of the columns `use` with their sin parts where `sin(j)` and their cos parts where `cos(j)`: the solution
    * and each channel's residual sum of squares.
    */
  def fit(use: IndexedSeq[Int], sin: Int => Boolean, cos: Int => Boolean): (LinSol, Double, Double) = {
    val m = use.size
    def gs(a: Int, b: Int) = if (sin(use(a)) && sin(use(b))) g(use(a))(use(b)) else 0.0
    def gc(a: Int, b: Int) = if (cos(use(a)) && cos(use(b))) g(k + use(a))(k + use(b)) else 0.0
    val rs = Array.tabulate(m)(a => if (sin(use(a))) r(use(a)) else 0.0)
    val rc = Array.tabulate(m)(a => if (cos(use(a))) r(k + use(a)) else 0.0)
    val s = LinearFit.normal(Array.tabulate(m, m)((a, b) => gs(a, b) + gc(a, b)), Array.tabulate(m)(a => rs(a) + rc(a)))
    // |y - X b|^2 = y'y - 2 b'X'y + b'X'X b per channel
    def rss(yy: Double, xy: Array[Double], xx: (Int, Int) => Double): Double = {
      var q = yy
      for (a <- 0 until m) { q -= 2 * s.beta(a) * xy(a); for (b <- 0 until m) q += s.beta(a) * s.beta(b) * xx(a, b) }
      math.max(0.0, q)
    }
    (s, rss(yyS, rs, gs), rss(yyC, rc, gc))
  }
}

object LinearFamily {
  /** The family of columns `cols` (the default part's six, then the family's) against the residual (ys, yc). */
  def apply(cols: IndexedSeq[Col], ys: Array[Double], yc: Array[Double], yyS: Double, yyC: Double): LinearFamily = {
    // one Gram of every column's sin part and cos part: the two channels' products apart
    val (g, r) = Gram.of(cols.map(c => Col(c.s, null)) ++ cols.map(c => Col(null, c.c)), ys, yc)
    new LinearFamily(cols.size, g, r, cols.map(_.s != null), cols.map(_.c != null), yyS, yyC)
  }

  /** The term whose columns hold those of `t` and its other-channel variants, with t's channel; None: t has no family. */
  def of(t: Term): Option[(Term, String)] = t match {
    case Term.Harm(k, ch) => Some((Term.Harm(k, "both"), ch))
    case Term.Inl(ch) => Some((Term.Inl("both"), ch))
    case Term.Crosstalk | Term.Drift | Term.Contrast => Some((t, "both"))
    case _ => None
  }
}
