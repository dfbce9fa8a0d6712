package moire.board

import moire.board.ulx3s.{Ecp5Pll, Ulx3sProject}
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The ULX3S .lpf against ../shared/reference/ulx3s-ad9226.md (sections 2 and 3, parsed), and the PLL's dividers. */
class Ulx3sProjectSpec extends AnyFlatSpec with Matchers {
  private val sheet = os.read(os.pwd / os.up / "shared" / "reference" / "ulx3s-ad9226.md").linesIterator.toSeq
  private def cells(l: String) = l.split('|').map(_.trim).toSeq.drop(1)
  /** gp[i] / gn[i] -> site, from the header table. */
  private val header: Map[String, String] = sheet.filter(_.matches("""\| \d+ \|.*""")).flatMap { l =>
    val c = cells(l)
    Seq(s"gp[${c(0)}]" -> c(1), s"gn[${c(0)}]" -> c(2), s"gp[${c(4)}]" -> c(5), s"gn[${c(4)}]" -> c(6))
  }.toMap
  /** "name[0..n]" or "name" with sites or header pins, expanded to port bit -> site. */
  private def expand(names: String, pins: String): Seq[(String, String)] = {
    val sites = pins.split(' ').toSeq.map(p => header.getOrElse(p, p))
    val range = """(\w+)\[(\d+)\.\.(\d+)\]""".r
    names match {
      case range(n, a, b) => (a.toInt to b.toInt).map(i => s"$n[$i]").zip(sites)
      case n => n.split('/').toSeq match {
        case Seq(one) => Seq(one -> sites.head)
        case parts => // ENC_A/B/Z_IN: first part carries the prefix, the suffix follows the last
          val Array(prefix, first) = parts.head.split("_(?=[^_]+$)")
          val suffix = parts.last.dropWhile(_ != '_')
          (first +: parts.tail.init :+ parts.last.takeWhile(_ != '_')).map(x => s"${prefix}_$x$suffix").zip(sites)
      }
    }
  }
  private val section2 = sheet.dropWhile(!_.startsWith("## 2.")).takeWhile(!_.startsWith("GPIO headers"))
    .filter(l => l.startsWith("| ") && !l.startsWith("| Signal") && !l.startsWith("| sw"))
    .flatMap(l => expand(cells(l)(0), cells(l)(1)))
  private val section3 = sheet.dropWhile(!_.startsWith("## 3.")).filter(l => l.startsWith("| ") && !l.startsWith("| Signal"))
    .flatMap { l => val c = cells(l); expand(c(0).replace(" (out)", ""), c(1)) ++ expand(c(2).replace(" (out)", ""), c(3)) }
  private val expected = (section2 ++ section3).toMap

  private val lpf = Ulx3sProject.lpf(BoardParams())
  private val locate = """LOCATE COMP "([^"]+)" SITE "(\w+)";""".r.findAllMatchIn(lpf).map(m => m.group(1) -> m.group(2)).toSeq

  "The ULX3S .lpf" should "place every port bit on the reference sheet's site, and only those" in {
    header.size shouldBe 56
    expected.size shouldBe 1 + 2 + 8 + 7 + 2 * 14 + 6
    locate.map(_._1).distinct.size shouldBe locate.size
    locate.toMap shouldBe expected
  }

  it should "give every pin LVCMOS33, the ADC inputs no pull, and the 25 MHz clock constraint" in {
    for ((port, _) <- locate) lpf should include(s"""IOBUF PORT "$port" IO_TYPE=LVCMOS33""")
    lpf should include("""IOBUF PORT "SIN_D[0]" IO_TYPE=LVCMOS33 PULLMODE=NONE""")
    lpf should include("""IOBUF PORT "COS_OTR" IO_TYPE=LVCMOS33 PULLMODE=NONE""")
    lpf should include("""FREQUENCY PORT "clk_25mhz" 25 MHZ;""")
  }

  "The ECP5 PLL search" should "make 50 and 65 MHz exactly from 25 MHz and refuse what it cannot make" in {
    val p50 = Ecp5Pll.solve(25000000, 50000000).toOption.get
    (p50.refDiv, p50.fbDiv, p50.outDiv) shouldBe ((1, 2, 12))
    p50.vcoHz shouldBe 600e6
    for (f <- Seq(50000000L, 65000000L, 62500000L, 100000000L)) {
      val q = Ecp5Pll.solve(25000000, f).toOption.get
      q.outHz shouldBe f.toDouble
      q.vcoHz should (be >= 400e6 and be <= 800e6)
      q.pfdHz should be >= 3.125e6
    }
    Ecp5Pll.solve(25000000, 33333333).left.toOption.get should include("33.333333 MHz")
  }
}
