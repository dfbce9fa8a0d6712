package moire.calibration

import moire.harmonic._

import org.scalatest.flatspec.AnyFlatSpec

/** The moire-calibration v1 reader: good files parse, each kind of bad row names its file and line. */
class CalibrationDataSpec extends AnyFlatSpec {
  val head = "# moire-calibration v1\n# table: test\nangle_deg,error_arcsec\n"

  "A good file" should "parse metadata, rows and directions, and treat 360 like 0" in {
    val d = CalibrationData.parse("t.csv", "# moire-calibration v1\r\n# table: air bearing\n\nangle_deg,error_arcsec,direction\n" +
      "0,1.5,cw\n10,-2,CCW\n0,1.25,ccw\n350,3e-1,cw\n")
    assert(d.meta == Map("table" -> "air bearing"))
    assert(d.points.map(p => (p.angleDeg, p.errorArcsec, p.direction, p.line)) == Seq(
      (0.0, 1.5, Some("cw"), 5), (10.0, -2.0, Some("ccw"), 6), (0.0, 1.25, Some("ccw"), 7), (350.0, 0.3, Some("cw"), 8)))
    assert(d.directions == Seq("cw", "ccw"))
    assert(CalibrationData.parse("u.csv", head + "360,1\n").points.head.angleDeg == 0.0)
  }

  "Bad input" should "raise one message naming the file and the line" in {
    val cases = Seq(
      "angle_deg,error_arcsec\n0,1\n" -> "t.csv:1: first line must be '# moire-calibration v1'",
      "# moire-calibration v2\nangle_deg,error_arcsec\n" -> "t.csv:1: first line",
      "# moire-calibration v1\n#table: x\n" -> "t.csv:2: metadata must read '# key: value'",
      "# moire-calibration v1\n# measured on the rotary table\n" -> "t.csv:2: no header row", // a comment, as in a recording
      "# moire-calibration v1\n0,1.0\n10,2.0\n" -> "t.csv:2: header row must be 'angle_deg,error_arcsec'",
      "# moire-calibration v1\nangle,error\n" -> "t.csv:2: header row",
      "# moire-calibration v1\n# a: b\n" -> "t.csv:2: no header row",
      head -> "t.csv:3: no data rows",
      head + "0,1\n10,2,3\n" -> "t.csv:5: 3 fields, the header has 2",
      head + "0\n" -> "t.csv:4: 1 fields, the header has 2",
      head + "0,1\nten,2\n" -> "t.csv:5: angle_deg 'ten' is not a number",
      head + "0,abc\n" -> "t.csv:4: error_arcsec 'abc' is not a number",
      head + "0,NaN\n" -> "t.csv:4: error_arcsec is NaN",
      head + "Infinity,1\n" -> "t.csv:4: angle_deg is Infinity",
      head + "0,1\n,2\n" -> "t.csv:5: missing angle_deg",
      head + "0,\n" -> "t.csv:4: missing error_arcsec",
      head + "0,1\n10,2\n10.0,3\n" -> "t.csv:6: angle 10.0 repeats line 5",
      head + "0,1\n360,1.1\n" -> "t.csv:5: angle 360.0 repeats line 4",
      head + "-5,1\n" -> "t.csv:4: angle_deg -5.0 is outside [0, 360]",
      "# moire-calibration v1\nangle_deg,error_arcsec,direction\n0,1,up\n" -> "t.csv:3: direction 'up' must be cw or ccw",
      "# moire-calibration v1\nangle_deg,error_arcsec,direction\n0,1,cw\n0,2,cw\n" -> "t.csv:4: angle 0.0 repeats line 3 (cw)",
      "# moire-calibration v1\n# step_deg: 90\nangle_deg,error_arcsec\n0,1\n90,1\n270,1\n" ->
        "t.csv: angle 180 deg missing (step_deg: 90.0 on line 2)",
      "# moire-calibration v1\n# step_deg: 7\nangle_deg,error_arcsec\n0,1\n" -> "t.csv:2: step_deg 7.0 does not divide 360")
    for ((text, expected) <- cases) {
      val e = intercept[CalibrationError](CalibrationData.parse("t.csv", text))
      assert(e.getMessage.startsWith(expected), s"for\n$text\ngot: ${e.getMessage}")
      assert(!e.getMessage.contains("\n"))
    }
  }

  "Gaps in an even grid without step_deg" should "be listed, and not when step_deg is given" in {
    val rows = (0 until 360 by 30).filterNot(Set(60, 270)).map(a => s"$a,1").mkString("\n")
    assert(CalibrationData.parse("g.csv", head + rows).gridGaps == Seq(("", 30.0, Seq(60.0, 270.0))))
    assert(CalibrationData.parse("g.csv", head + (0 until 360 by 30).map(a => s"$a,1").mkString("\n")).gridGaps.isEmpty)
    assert(CalibrationData.parse("g.csv", head + "0,1\n7,1\n100,2\n").gridGaps.isEmpty)
  }

  "The sample files in docs/" should "be what CalibrationSample generates, and parse" in {
    for ((name, text) <- CalibrationSample.files) {
      val path = os.pwd / "docs" / name
      assert(os.read(path) == text, s"$path is stale: ./sbt \"runMain moire.calibration.CalibrationSample docs\"")
      assert(CalibrationData.read(path).points.size % 36 == 0)
    }
  }

  "A file whose last row has no line end" should "keep the row and say it may be cut short (a file ending with a line end: nothing)" in {
    val dir = os.temp.dir()
    val cut = dir / "cut.csv"; os.write(cut, head + "0,1\n10,2\n20,3.2")
    val whole = dir / "whole.csv"; os.write(whole, head + "0,1\n10,2\n20,3.2\n")
    val d = CalibrationData.read(cut)
    assert(d.points.map(_.errorArcsec) == Seq(1.0, 2.0, 3.2) && d.cutShort.contains(6))
    assert(d.notes.head.startsWith("line 6, the last, has no line end"))
    val w = CalibrationData.read(whole)
    assert(w.points == d.points && w.cutShort.isEmpty && w.notes.isEmpty)
    // a last line that is a comment is no row
    val com = dir / "com.csv"; os.write(com, head + "0,1\n10,2\n# end: here")
    assert(CalibrationData.read(com).cutShort.isEmpty)
  }
}
