package moire.calibration

import moire.harmonic._

import org.scalatest.flatspec.AnyFlatSpec
import scala.sys.process._

/** `moire calibrate` in a fresh JVM: files written, exit codes, one-line errors naming file and line. */
class CalibrateCliSpec extends AnyFlatSpec {
  def run(args: String*): (Int, String, String) = moire.cli.CliProcess.run(args: _*)

  "calibrate" should "write the coefficient file, register listing and plot, and report the reversal" in {
    val dir = os.temp.dir()
    val (code, out, err) = run("calibrate", "--input", "docs/calibration-sample-cw-ccw.csv", "--out", dir.toString, "--harmonics", "3")
    assert(code == 0, err)
    val stem = "calibration-sample-cw-ccw"
    // and the folder's list of what moire wrote there (their hashes: the next run replaces them, not a user's file)
    assert(os.list(dir).map(_.last).toSet == Set(s"$stem.coefficients.json", s"$stem.registers.txt", s"$stem.png", moire.files.SafeWrite.Manifest))
    val json = ujson.read(os.read(dir / s"$stem.coefficients.json"))
    assert(json("harmonics").arr.map(_("order").num.toInt) == Seq(1, 2, 3))
    assert(json("registers").arr.size == 9 && json("reversal_cw_minus_ccw")("shared_angles").num == 36)
    assert(os.read.lines(dir / s"$stem.registers.txt").count(l => !l.startsWith("#")) == 9)
    assert(os.size(dir / s"$stem.png") > 10000)
    assert(out.contains("reversal cw - ccw over 36 angles"))
  }

  it should "exit 2 with one line naming the file and line for a bad row or option" in {
    val bad = os.temp(CalibrationData.magic + "\nangle_deg,error_arcsec\n0,1\n10,oops\n", suffix = ".csv")
    for ((args, expected) <- Seq(
      // the file as given, as explain names it (it was the bare name, another tool's fuzz sweep F20)
      Seq("--input", bad.toString) -> s"moire: $bad:4: error_arcsec 'oops' is not a number",
      Seq("--input", "docs/calibration-sample.csv", "--harmonics", "0") -> "moire: --harmonics (m) must be in 1..32, got 0",
      Seq("--input", "/nonexistent.csv") -> "moire: /nonexistent.csv: no such file")) {
      val (code, _, err) = run("calibrate" +: args :+ "--out" :+ os.temp.dir().toString: _*)
      val lines = err.linesIterator.filter(_.nonEmpty).toSeq
      assert(code == 2 && lines.size == 1 && lines.head.startsWith(expected), s"$args: exit $code, stderr:\n$err")
    }
  }

  it should "refuse a user's image, JSON or notes under its outputs' names before the fit, and write again over its own" in {
    val stem = "calibration-sample"
    val args = Seq("calibrate", "--input", s"docs/$stem.csv", "--out")
    val own = os.temp.dir()
    assert(run(args :+ own.toString: _*)._1 == 0)
    val files = Seq(s"$stem.png", s"$stem.coefficients.json", s"$stem.registers.txt")
    // a user's file of each name, alone in a folder moire never wrote into (no .moire-files): kept, one line, nothing written
    for ((name, bytes) <- Seq(files(0) -> os.read.bytes(own / files(0)), files(1) -> """{"mine":1}""".getBytes, files(2) -> "my own notes\n".getBytes)) {
      val d = os.temp.dir(); os.write(d / name, bytes)
      val (code, out, err) = run(args :+ d.toString: _*)
      val lines = err.linesIterator.filter(_.nonEmpty).toSeq
      assert(code == 2 && lines.size == 1 && (lines.head.contains("is not as moire wrote it") || lines.head.contains("holds text")), s"$name: exit $code, stderr:\n$err")
      assert(lines.head.contains(name) && !out.contains("harmonics up to order"), s"$name: $err\n$out")
      assert(os.list(d).map(_.last) == Seq(name) && os.read.bytes(d / name).sameElements(bytes), name)
    }
    // its own files again (and an earlier version's, without the list, as that wrote them)
    assert(run(args :+ own.toString: _*)._1 == 0)
    os.remove(own / moire.files.SafeWrite.Manifest)
    val (code, _, err) = run(args :+ own.toString: _*)
    assert(code == 0, err)
    assert(os.list(own).map(_.last).toSet == files.toSet + moire.files.SafeWrite.Manifest)
  }
}
