package moire.numbers

/** The one number syntax of moire's options and file metadata: plain decimal, as a person writes it on a
  * bench (`1000000`, `-2.5`, `.5`, `1e6`, `2.5E-3`), and the words NaN and Infinity (which callers refuse with
  * their own message). Java's further forms (`1000000d`, `0x1p20`, a trailing `f`) are not numbers here.
  */
object Decimal {
  /** The value of `s` (surrounding blanks ignored), or None when it is not a decimal number. */
  def double(s: String): Option[Double] = {
    val t = s.trim
    t match {
      case "NaN" => Some(Double.NaN)
      case "Infinity" | "+Infinity" => Some(Double.PositiveInfinity)
      case "-Infinity" => Some(Double.NegativeInfinity)
      case _ => if (isDecimal(t)) Some(java.lang.Double.parseDouble(t)) else None
    }
  }

  /** An integer in decimal digits 0-9 (an optional sign), or None (also when it does not fit a Long). Other scripts'
    * digits (Java reads `١٢` and `１２` as 12) are not plain decimal.
    */
  def long(s: String): Option[Long] = {
    val t = s.trim
    if (t.nonEmpty && t.forall(c => (c >= '0' && c <= '9') || c == '-' || c == '+')) t.toLongOption else None
  }

  /** As [[long]], for an Int: read in one pass (a recording's codes are read with it, two a row). */
  def int(s: String): Option[Int] = {
    var i = 0; var n = s.length
    while (i < n && s.charAt(i) <= ' ') i += 1
    while (n > i && s.charAt(n - 1) <= ' ') n -= 1
    val neg = i < n && s.charAt(i) == '-'
    if (i < n && (s.charAt(i) == '-' || s.charAt(i) == '+')) i += 1
    if (i == n) return None
    var v = 0L
    while (i < n) {
      val c = s.charAt(i)
      if (c < '0' || c > '9') return None
      v = v * 10 + (c - '0'); if (v > 2147483648L) return None
      i += 1
    }
    val r = if (neg) -v else v
    if (r > Int.MaxValue) None else Some(r.toInt)
  }

  /** [+-] digits [. digits] [(e|E) [+-] digits], with at least one digit before the exponent. */
  def isDecimal(t: String): Boolean = {
    var i = 0; val n = t.length
    def digits(): Int = { val s = i; while (i < n && t.charAt(i) >= '0' && t.charAt(i) <= '9') i += 1; i - s }
    if (i < n && (t.charAt(i) == '+' || t.charAt(i) == '-')) i += 1
    var mantissa = digits()
    if (i < n && t.charAt(i) == '.') { i += 1; mantissa += digits() }
    if (mantissa == 0) return false
    if (i < n && (t.charAt(i) == 'e' || t.charAt(i) == 'E')) {
      i += 1
      if (i < n && (t.charAt(i) == '+' || t.charAt(i) == '-')) i += 1
      if (digits() == 0) return false
    }
    i == n
  }
}
