package moire.emit

import chisel3._
import chisel3.util.Cat

/** Bits a design drops on purpose (two's complement wrap-around, the carry-in bit of a rounding
  * adder, inputs a mode does not read, spare pins) go into a wire named `unused_<what>`. Verilator's
  * lint skips signals whose name matches its default `--unused-regexp *unused*`, so `-Wall` still
  * reports every bit dropped by mistake. The wire drives nothing: synthesis removes it, no logic is added.
  */
object Unused {
  def apply(what: String, bits: Bits*): Unit = {
    val live = bits.filter(_.getWidth > 0)
    if (live.nonEmpty) {
      val sink = WireDefault(Cat(live.map(_.asUInt)))
      sink.suggestName(s"unused_$what")
      dontTouch(sink)
    }
  }
}
