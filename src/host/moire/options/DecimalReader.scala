package moire.options

import mainargs.TokensReader

/** Options of type Double read as plain decimal numbers ([[moire.numbers.Decimal]]), not in Java's syntax
  * (`1e6` yes, `1000000d` or `0x1p20` no). Import it where a parser of options is made.
  */
object DecimalReader {
  implicit val decimal: TokensReader.Simple[Double] = new TokensReader.Simple[Double] {
    def shortName = "number"
    def read(strs: Seq[String]): Either[String, Double] =
      moire.numbers.Decimal.double(strs.last).toRight(s"'${strs.last}' is not a decimal number (digits, a point, an exponent like 1e6)")
  }
}
