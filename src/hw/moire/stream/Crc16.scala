package moire.stream

/** CRC-16/CCITT-FALSE: poly 0x1021, init 0xFFFF, no reflection, xorout 0 (check value 0x29B1 for "123456789"). */
object Crc16 {
  val Init: Int = 0xFFFF

  /** The CRC register after one more byte. */
  def step(crc: Int, b: Int): Int = {
    var c = crc ^ ((b & 0xFF) << 8)
    var i = 0
    while (i < 8) { c = if ((c & 0x8000) != 0) (c << 1) ^ 0x1021 else c << 1; i += 1 }
    c & 0xFFFF
  }

  /** CRC of `len` bytes of `bytes` from `off`. */
  def of(bytes: Array[Byte], off: Int, len: Int): Int = {
    var c = Init; var i = off
    while (i < off + len) { c = step(c, bytes(i)); i += 1 }
    c
  }

  def of(bytes: Array[Byte]): Int = of(bytes, 0, bytes.length)
}
