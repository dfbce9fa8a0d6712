package moire.designs

import scala.sys.process._

/** Verilator's strict lint and Debian yosys' reading of emitted Verilog files. Vendor primitives a board
  * instantiates (altpll, EHXPLLL) are declared from yosys' own black-box libraries, copied into a
  * `vendor/` folder that waivers.vlt exempts: their declarations are not moire's code.
  */
object Lint {
  val yosysShare: os.Path = os.Path("/usr/share/yosys")
  /** Vendor module -> the yosys library that declares it. */
  private val vendorLibs = Seq("altpll" -> yosysShare / "intel" / "common" / "altpll_bb.v", "EHXPLLL" -> yosysShare / "ecp5" / "cells_bb.v")

  /** The vendor modules `files` instantiate, each cut out of its library into `dir/vendor/NAME.v`. */
  def vendor(files: Seq[os.Path], dir: os.Path): Seq[os.Path] = {
    val text = files.map(os.read(_)).mkString
    vendorLibs.filter { case (m, _) => s"""(?m)^\\s*$m\\b""".r.findFirstIn(text).nonEmpty }.map { case (m, lib) =>
      val src = os.read(lib)
      val from = s"(?m)^module $m\\b".r.findFirstMatchIn(src).getOrElse(sys.error(s"no module $m in $lib")).start
      val to = src.indexOf("endmodule", from) + "endmodule".length
      val f = dir / "vendor" / s"$m.v"
      os.write.over(f, src.substring(from, to) + "\n", createFolders = true)
      f
    }
  }

  private def run(cmd: Seq[String]): (Int, String) = {
    val log = new StringBuilder
    val code = cmd.!(ProcessLogger(l => log.append(l).append('\n'), l => log.append(l).append('\n')))
    (code, log.toString)
  }

  /** `verilator --lint-only -Wall` with the waivers file; (exit code, output). */
  def verilator(top: String, files: Seq[os.Path], vendorFiles: Seq[os.Path], waivers: os.Path): (Int, String) =
    run(Seq("verilator", "--lint-only", "-Wall", "--top-module", top, waivers.toString) ++ (vendorFiles ++ files).map(_.toString))

  /** Debian yosys: `read_verilog -sv` the files, the vendor declarations as a library, `hierarchy -check`. */
  def yosys(top: String, files: Seq[os.Path], vendorFiles: Seq[os.Path]): (Int, String) = {
    val script = (Seq(s"read_verilog -sv ${files.map(f => "\"" + f + "\"").mkString(" ")}") ++
      vendorFiles.map(f => s"read_verilog -lib \"$f\"") :+ s"hierarchy -check -top $top").mkString("; ")
    run(Seq("yosys", "-q", "-p", script))
  }
}
