package moire.io

import chisel3._
import moire.cordic.SimSupport
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers
import scala.sys.process._

/** Four copies of one 8-bit register made with [[Copy]], four with RegNext (of a register, as in the burst RAM). */
class CopyBank extends Module {
  val io = IO(new Bundle {
    val d = Input(UInt(8.W))
    val copies = Output(Vec(4, UInt(8.W)))
    val plain = Output(Vec(4, UInt(8.W)))
  })
  private val d = RegNext(io.d)
  io.copies := VecInit(Seq.fill(4)(Copy(d)))
  io.plain := VecInit(Seq.fill(4)(RegNext(d)))
}

/** [[Copy]] follows its input one clock later, and its copies survive firtool and yosys' merging of identical
  * registers (what the burst RAM's per-group address registers rely on), where RegNext copies do not.
  */
class CopySpec extends AnyFlatSpec with Matchers {
  "Copy" should "keep each copy through firtool and yosys opt_merge, where RegNext copies fold into one" in {
    SimSupport.requireTool(this, "yosys")
    val dir = os.temp.dir(prefix = "moire-copy-")
    val sv = dir / "CopyBank.sv"
    os.write(sv, moire.emit.Emit.elaborate(new CopyBank, moire.emit.Target.Verilog)._2)
    val log = new StringBuilder
    val code = Seq("yosys", "-q", "-p", s"read_verilog -sv $sv; synth -top CopyBank; tee -o ${dir / "stat.txt"} stat")
      .!(ProcessLogger(l => log.append(l).append('\n'), l => log.append(l).append('\n')))
    withClue(log.toString) { code shouldBe 0 }
    // flip-flop cells after synth: the input register, 4 x 8 copies, and 8 for the four RegNext copies merged into one
    val ffs = os.read.lines(dir / "stat.txt").map(_.trim.split("\\s+"))
      .collect { case Array(t, n) if t.startsWith("$_") && t.contains("DFF") => n.toInt }.sum
    ffs shouldBe 48
  }

  it should "equal its input one clock later (two, behind the input register)" in {
    import chiseltest._
    RawTester.test(new CopyBank) { c =>
      val rnd = new scala.util.Random(3)
      var prev = 0
      for (t <- 0 until 200) {
        val d = rnd.nextInt(256)
        c.io.d.poke(d.U)
        c.clock.step()
        if (t > 0) { c.io.copies.foreach(_.peekInt() shouldBe prev); c.io.plain.foreach(_.peekInt() shouldBe prev) }
        prev = d
      }
    }
  }
}
