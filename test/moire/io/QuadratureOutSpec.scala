package moire.io

import chisel3._
import chiseltest._
import moire.cordic.SimSupport
import org.scalatest.flatspec.AnyFlatSpec

/** QuadratureOut against its definition, clock by clock: follow the target one count per step (at least
  * minEdgeClocks apart), wrapping modulo 2^width; A/B from the followed position's two low bits, Z on
  * multiples of 2^zBits; backlog = target - pos.
  */
class QuadratureOutSpec extends AnyFlatSpec with ChiselScalatestTester {
  /** The definition, one clock: returns (a, b, z, backlog) before the clock edge. */
  final class Reference(width: Int, zBits: Int, minEdge: Int) {
    private val mask = (1L << width) - 1
    private def signed(v: Long) = { val x = v & mask; if (x >= (1L << (width - 1))) x - (1L << width) else x }
    var started = false; var target = 0L; var pos = 0L; var hold = 0
    def outputs: (Boolean, Boolean, Boolean, Long) = {
      val q = pos & 3
      (q == 1 || q == 2, (q & 2) != 0, started && (pos & ((1L << zBits) - 1)) == 0, if (started) signed(target - pos) else 0L)
    }
    def clock(in: Option[Long]): Unit = {
      val pending = signed(target - pos)
      if (!started) { in.foreach { v => pos = v & mask; started = true } }
      else if (hold == 0 && pending != 0) { pos = (pos + (if (pending > 0) 1 else -1)) & mask; hold = minEdge - 1 }
      else if (hold != 0) hold -= 1
      in.foreach(v => target = v & mask)
    }
  }

  for ((width, zBits, minEdge) <- Seq((8, 4, 1), (32, 10, 1), (12, 2, 3))) {
    s"QuadratureOut w$width z$zBits e$minEdge" should s"follow its target clock by clock, across the wrap (${SimSupport.backendName})" in {
      test(new QuadratureOut(width, zBits, minEdge)).withAnnotations(SimSupport.backend) { dut =>
        val rnd = new scala.util.Random(width * 31 + minEdge)
        val ref = new Reference(width, zBits, minEdge)
        val mask = (1L << width) - 1
        var t = (1L << width) - 20 // start near the wrap
        for (cycle <- 0 until 4000) {
          val in = if (cycle > 3 && rnd.nextInt(4) == 0) {
            t = t + (rnd.nextInt(3) match { case 0 => rnd.nextInt(7) - 3; case 1 => rnd.nextInt(41) - 20; case _ => 0 })
            Some(t & mask)
          } else None
          val (a, b, z, backlog) = ref.outputs
          dut.io.a.expect(a.B, s"a at clock $cycle"); dut.io.b.expect(b.B, s"b at clock $cycle")
          dut.io.z.expect(z.B, s"z at clock $cycle"); dut.io.backlog.expect(backlog.S, s"backlog at clock $cycle")
          dut.io.in.valid.poke(in.isDefined.B)
          dut.io.in.bits.poke((in.getOrElse(0L) - (if ((in.getOrElse(0L) >> (width - 1)) != 0) 1L << width else 0L)).S)
          dut.clock.step()
          ref.clock(in)
        }
      }
    }
  }
}
