package moire.cost

/** The real width of a multiplier operand. firtool writes a signed product as an unsigned one of
  * the result's width, its operands sign- or zero-extended (`{{12{x[11]}}, x}` for a 12 x 12 signed
  * square): a fitter places the product by the operands' own widths, so the extension bits are
  * not counted. A product by a constant keeps the other operand's sign extension: firtool writes it
  * unsigned (signed x zero-extended constant) and yosys 0.70 `synth_ecp5` maps it at that width (3 blocks
  * for the corrector's 25-bit x 17-bit constant, where a signed product would take 2).
  */
object Operand {
  private sealed trait Elem
  private final case class Bit(name: String, index: Int) extends Elem
  private final case class Range(name: String, msb: Int) extends Elem
  private final case class Whole(name: String) extends Elem
  private final case class Const(bits: String) extends Elem

  private val token = """(\\\S+|\$\S+)(?: \[(\d+)(?::(\d+))?\])?|(\d+)'([01xz]+)""".r

  private def elems(connect: String): Seq[Elem] = {
    val c = connect.trim
    val inner = if (c.startsWith("{") && c.endsWith("}")) c.drop(1).dropRight(1) else c
    token.findAllMatchIn(inner).map { m =>
      if (m.group(4) != null) Const(m.group(5))
      else if (m.group(2) == null) Whole(m.group(1))
      else if (m.group(3) == null) Bit(m.group(1), m.group(2).toInt)
      else Range(m.group(1), m.group(2).toInt)
    }.toSeq
  }

  /** Is the operand a constant? */
  def constant(connect: String): Boolean = { val es = elems(connect); es.nonEmpty && es.forall(_.isInstanceOf[Const]) }

  /** `width` less the leading constant zeros (zero extension) and less the repeated copies of the
    * sign bit (sign extension) of a yosys `connect` text (MSB first); `width` when the text says nothing.
    */
  def realWidth(width: Int, connect: String, dropSignCopies: Boolean = true): Int = {
    val es = elems(connect)
    val zeros = es.headOption match {
      case Some(Const(bits)) => bits.takeWhile(_ == '0').length
      case _ => 0
    }
    val copies = es.headOption match {
      case Some(first @ Bit(name, i)) if dropSignCopies =>
        val k = es.takeWhile(_ == first).size
        es.lift(k) match {
          case Some(Whole(`name`)) => k
          case Some(Range(`name`, `i`)) => k
          case _ => k - 1
        }
      case _ => 0
    }
    math.max(1, width - zeros - copies)
  }
}
