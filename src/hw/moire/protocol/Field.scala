package moire.protocol

/** A bit field of a packed word: its lowest bit and its width (1..32 bits). */
final case class Field(name: String, lsb: Int, width: Int) {
  require(lsb >= 0 && width >= 1 && width <= 32, s"field $name: lsb $lsb, width $width (1..32)")
  def msb: Int = lsb + width - 1
  /** Largest value the field holds. */
  def maxValue: Long = (1L << width) - 1
  /** The field's bits in place. */
  def mask: BigInt = BigInt(maxValue) << lsb
  /** The field's value in `x` (a word of at most 63 bits). */
  def get(x: Long): Long = { require(msb < 63, s"field $name: bit $msb is beyond a Long"); (x >>> lsb) & maxValue }
  /** `v` moved to the field's place (`v` must fit). */
  def put(v: Long): Long = {
    require(msb < 63 && v >= 0 && v <= maxValue, s"field $name: $v does not fit $width bits at bit $lsb of a Long")
    v << lsb
  }
  /** The field right above this one. */
  def next(name: String, width: Int): Field = Field(name, msb + 1, width)
}
