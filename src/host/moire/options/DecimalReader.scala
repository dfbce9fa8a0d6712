package moire.options

import mainargs.TokensReader

/** Options of type Double (and Int, Long) read as plain decimal numbers ([[moire.numbers.Decimal]]), not in Java's syntax
  * (`1e6` yes, `1000000d` or `0x1p20` no). Import it where a parser of options is made.
  */
object DecimalReader {
  implicit val decimal: TokensReader.Simple[Double] = new TokensReader.Simple[Double] {
    def shortName = "number"
    def read(strs: Seq[String]): Either[String, Double] =
      moire.numbers.Decimal.double(strs.last).toRight(s"'${strs.last}' is not a decimal number (digits, a point, an exponent like 1e6)")
  }
  /** Whole-number options in the digits 0-9 (Java's own reader takes other scripts' digits too). */
  implicit val int: TokensReader.Simple[Int] = new TokensReader.Simple[Int] {
    def shortName = "int"
    def read(strs: Seq[String]): Either[String, Int] =
      moire.numbers.Decimal.int(strs.last).toRight(s"'${strs.last}' is not a whole number (digits 0-9, within +-2147483647)")
  }
  implicit val long: TokensReader.Simple[Long] = new TokensReader.Simple[Long] {
    def shortName = "long"
    def read(strs: Seq[String]): Either[String, Long] =
      moire.numbers.Decimal.long(strs.last).toRight(s"'${strs.last}' is not a whole number (digits 0-9)")
  }
}
