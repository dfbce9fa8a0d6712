package moire.board

import moire.board.de2115.{De2115, De2115Pins}
import moire.cordic.SimSupport
import org.scalatest.flatspec.AnyFlatSpec
import scala.sys.process._

/** The reference sheet's pin tables, read from ../shared/reference/de2-115-ad9226.md (beside the repo). */
object ReferencePins {
  val file: os.Path = os.pwd / os.up / "shared" / "reference" / "de2-115-ad9226.md"
  final case class Ref(ball: String, std: String)

  private def cells(line: String): Seq[String] = line.trim.stripPrefix("|").stripSuffix("|").split('|').map(_.trim).toSeq
  private def range(name: String): Seq[String] = {
    val r = """(\w+)\[(\d+)\.\.(\d+)\]""".r
    name match { case r(n, a, b) => (a.toInt to b.toInt).map(i => s"$n[$i]"); case n => Seq(n) }
  }

  /** Port name (as on the top level) -> ball and I/O standard, from the sheet's tables. */
  def load(): Map[String, Ref] = {
    val text = os.read(file)
    val rows = text.linesIterator.filter(_.trim.startsWith("|")).map(cells).filterNot(_.forall(_.matches("-*"))).toSeq
    val m = scala.collection.mutable.Map.empty[String, Ref]
    // section 2, board pins: "Signal | Balls | I/O std | Notes"
    for (r <- rows if r.size == 4 && r(1).matches("""[A-Z]+\d+([ ,]+[A-Z]+\d+)*""") && r(2).matches("""(3\.3-V LVTTL|2\.5 V)""")) {
      val names = r(0).split(",").map(_.trim).toSeq.flatMap(range)
      val balls = r(1).split("[ ,]+").toSeq
      assert(names.size == balls.size, s"reference row $r")
      names.zip(balls).foreach { case (n, b) => m(n) = Ref(b, r(2)) }
    }
    // seven-segment digits: "HEXn | 7 balls | std (maybe [0-1] 2.5 V, [2-6] 3.3-V LVTTL)"
    for (r <- rows if r.size == 9 && r(0).matches("HEX\\d")) {
      val split = """\[0-(\d)\] (.+), \[\d-6\] (.+)""".r
      for (i <- 0 until 7) {
        val std = r(8) match { case split(hi, a, b) => if (i <= hi.toInt) a else b; case s => s }
        m(s"${r(0)}[$i]") = Ref(r(i + 1), std)
      }
    }
    // RS-232 by ball: "Ball | dir | name | name"; all 3.3-V LVTTL
    val rsStd = """RS-232.*all (3\.3-V LVTTL)""".r.findFirstMatchIn(text).get.group(1)
    for (r <- rows if r.size == 4 && r(1).matches("in|out") && r(2) == r(3)) m(r(2)) = Ref(r(0), rsStd)
    // JP5 GPIO table: index -> ball; the SUGGESTED mapping must agree with it
    val gpio = rows.filter(r => r.size == 9 && r(0).matches("\\d+")).flatMap(r => r.grouped(3).map(g => g(0).toInt -> g(1))).toMap
    val jp5Std = """JP5.*bank 4, (3\.3-V LVTTL)""".r.findFirstMatchIn(text).get.group(1)
    for (r <- rows if r.size == 8 && r(1).matches("\\d+") && r(2).matches("\\d+"); g <- r.grouped(4)) {
      assert(gpio(g(1).toInt) == g(3), s"SUGGESTED ${g(0)}: GPIO ${g(1)} is ${gpio(g(1).toInt)}, not ${g(3)}")
      m(g(0).stripSuffix(" (out)")) = Ref(g(3), jp5Std)
    }
    // encoder on EX_IO: "Signal | EX_IO | Ball" x2
    val exStd = """extended I/O header.*bank 8, (3\.3-V LVTTL)""".r.findFirstMatchIn(text).get.group(1)
    for (r <- rows if r.size == 6 && r(0).startsWith("ENC_"); g <- r.grouped(3) if g(0).startsWith("ENC_")) m(g(0)) = Ref(g(2), exStd)
    m.toMap
  }
}

/** The generated Quartus project: every pin against the reference sheet, the files, flash.sh, bad options. */
class QuartusProjectSpec extends AnyFlatSpec {
  private lazy val dir = { val d = os.temp.dir(prefix = "moire-de2-115"); moire.designs.BoardProject.write("de2-115", BoardParams(), d); d }
  private lazy val qsf = os.read(dir / "moire_de2_115.qsf")

  "The .qsf" should "give every top-level port bit the reference sheet's ball and I/O standard" in {
    if (!os.exists(ReferencePins.file)) cancel(s"${ReferencePins.file} is missing (CI clones ../shared beside the repo)")
    val ref = ReferencePins.load()
    assert(ref.size > 100, s"only ${ref.size} reference pins parsed")
    val loc = """set_location_assignment PIN_(\w+) -to (\S+)""".r
    val std = """set_instance_assignment -name IO_STANDARD "([^"]+)" -to (\S+)""".r
    val locs = loc.findAllMatchIn(qsf).map(m => m.group(2) -> m.group(1)).toSeq
    val stds = std.findAllMatchIn(qsf).map(m => m.group(2) -> m.group(1)).toMap
    assert(locs.map(_._1).distinct.size == locs.size && locs.map(_._2).distinct.size == locs.size, "a port or ball twice")
    for ((port, ball) <- locs) {
      val r = ref.getOrElse(port, fail(s"$port is not in the reference sheet"))
      assert(ball == r.ball, s"$port on $ball, the sheet says ${r.ball}")
      assert(stds.get(port).contains(r.std), s"$port standard ${stds.get(port)}, the sheet says ${r.std}")
    }
    // every port bit of the top level has a pin
    val top = os.read(dir / "rtl" / s"${De2115.topName(BoardParams())}.sv")
    val body = top.substring(top.indexOf(s"module ${De2115.topName(BoardParams())}("))
    // "input [11:0] SIN_D," or a continuation "HEX1," that shares the previous declaration's range
    val header = body.substring(body.indexOf('(') + 1, body.indexOf(");")).replaceAll("//[^\n]*", "")
    val decl = """(?:(?:input|output)\s+)?(?:\[(\d+):0\]\s+)?(\w+)""".r
    var width = -1
    val ports = header.split(',').toSeq.map(_.trim).filter(_.nonEmpty).flatMap { d =>
      val m = decl.findPrefixMatchOf(d).getOrElse(fail(s"port declaration '$d'"))
      if (d.startsWith("input") || d.startsWith("output")) width = if (m.group(1) == null) -1 else m.group(1).toInt
      if (width < 0) Seq(m.group(2)) else (0 to width).map(i => s"${m.group(2)}[$i]")
    }
    assert(ports.nonEmpty && ports.toSet == locs.map(_._1).toSet, s"ports without pins: ${ports.toSet -- locs.map(_._1)}; " +
      s"pins without ports: ${locs.map(_._1).toSet -- ports}")
    assert(De2115Pins.all.size == locs.size)
  }

  it should "carry the reference's global settings, the top entity, the SDC and every Verilog file" in {
    for (g <- Seq("FAMILY \"Cyclone IV E\"", "DEVICE EP4CE115F29C7", "DEVICE_FILTER_PIN_COUNT 780",
      "STRATIX_DEVICE_IO_STANDARD \"3.3-V LVTTL\"", "CYCLONEII_RESERVE_NCEO_AFTER_CONFIGURATION \"USE AS REGULAR IO\"",
      s"TOP_LEVEL_ENTITY ${De2115.topName(BoardParams())}", "SDC_FILE moire_de2_115.sdc", "VERILOG_MACRO \"SYNTHESIS=1\"",
      s"SYSTEMVERILOG_FILE rtl/${De2115.topName(BoardParams())}.sv", "VERILOG_FILE rtl/De2115Pll.v"))
      assert(qsf.contains(s"set_global_assignment -name $g"), g)
    val sdc = os.read(dir / "moire_de2_115.sdc")
    for (s <- Seq("create_clock -name CLOCK_50 -period 20.000", "derive_pll_clocks", "derive_clock_uncertainty",
      "-max 7.0 [get_ports {SIN_D[*]", "-min 3.5 [get_ports {SIN_D[*]", "set_output_delay", "set_false_path -from"))
      assert(sdc.contains(s), s)
    assert(os.exists(dir / "moire_de2_115.qpf"))
  }

  "flash.sh" should "compile and program over JTAG, and say so when Quartus is missing" in {
    val f = os.read(dir / "flash.sh")
    assert(f.contains("quartus_sh --flow compile moire_de2_115"))
    assert(f.contains("quartus_pgm -c \"USB-Blaster\" -m JTAG -o \"p;output_files/moire_de2_115.sof\""))
    assert(os.perms(dir / "flash.sh").contains(java.nio.file.attribute.PosixFilePermission.OWNER_EXECUTE))
    if (!SimSupport.onPath("quartus_sh")) {
      val r = os.proc(dir / "flash.sh").call(check = false, stderr = os.Pipe, env = Map("PATH" -> "/usr/bin:/bin"))
      assert(r.exitCode == 2 && r.err.text().contains("quartus_sh not found"), r.err.text())
    }
  }

  "board" should "reject bad options with one line and exit code 2" in {
    for ((args, expected) <- Seq(
      Seq("de2-116") -> "board 'de2-116' is unknown",
      Seq("de2-115", "--adc-clock-hz", "30000000") -> "--adc-clock-hz must be 50 MHz divided by an integer 1..1000",
      Seq("de2-115", "--design", "fast") -> "--design: 'fast' is not a board design",
      Seq("de2-115", "--adc-format", "gray") -> "--adc-format: ADC format 'gray' is unknown",
      Seq("de2-115", "--decimation", "0") -> "--decimation must be in 1..16777216",
      Seq("de2-115", "--baud", "20000000") -> "--baud must be in 300..12000000, got 20000000",
      Seq("de2-115", "--baud", "1") -> "--baud must be in 300..12000000, got 1",
      Seq("de2-115", "--fifo-depth", "4") -> "--fifo-depth must be in 8..65536",
      Seq("de2-115", "--clock-source", "xtal") -> "--clock-source: 'xtal' is unknown")) {
      val (code, _, err) = moire.cli.CliProcess.run("board" +: args: _*)
      val lines = err.linesIterator.filter(_.nonEmpty).toSeq
      assert(code == 2 && lines.size == 1 && lines.head.startsWith(s"moire: $expected"), s"$args: exit $code, $err")
    }
  }
}
