package moire.recording

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The bounded line reader: LF, CRLF and CR ends, also split across its buffer and across short reads, no line
  * lost or added; a line over the limit refused with its number.
  */
class BoundedLinesSpec extends AnyFlatSpec with Matchers {
  /** A reader that hands out at most `step` characters per read (a pipe, a slow disk). */
  private def chunked(s: String, step: Int): java.io.Reader = new java.io.Reader {
    private var at = 0
    def read(buf: Array[Char], off: Int, len: Int): Int =
      if (at >= s.length) -1 else { val n = math.min(math.min(len, step), s.length - at); s.getChars(at, at + n, buf, off); at += n; n }
    def close(): Unit = ()
  }
  private def all(r: BoundedLines): Seq[String] = Iterator.continually(r.readLine()).takeWhile(_ != null).toSeq
  /** What BufferedReader.readLine makes of the text: the reference. */
  private def reference(s: String): Seq[String] = { val b = new java.io.BufferedReader(new java.io.StringReader(s)); Iterator.continually(b.readLine()).takeWhile(_ != null).toSeq }

  "BoundedLines" should "read what BufferedReader reads, for any line ends and any read sizes" in {
    val rnd = new scala.util.Random(7)
    val pieces = Seq("a", "12,34", "", "\n", "\r\n", "\r", "\r\r\n", "x" * 70000)
    for (_ <- 0 until 300) {
      val text = Seq.fill(rnd.nextInt(12))(pieces(rnd.nextInt(pieces.size))).mkString
      for (step <- Seq(1, 2, 3, 65536, 1 << 20))
        withClue(s"step $step, text ${text.take(40).replace("\r", "\\r").replace("\n", "\\n")}: ") {
          all(new BoundedLines(chunked(text, step), 1 << 20, n => fail(s"line $n too long"))) shouldBe reference(text)
        }
    }
  }

  it should "tell whether the last line had a line end" in {
    for ((text, ended) <- Seq("a\nb\n" -> true, "a\nb" -> false, "a\r\nb\r" -> true, "a\n" -> true, "a" -> false); step <- Seq(1, 65536)) {
      val r = new BoundedLines(chunked(text, step), 1000, n => fail(s"line $n too long"))
      all(r); withClue(text) { r.lastEnded shouldBe ended }
    }
  }

  it should "refuse a line over the limit, naming it, without reading further" in {
    val text = "ok\nfine\n" + "0" * 5000 + "\nnever read\n"
    val r = new BoundedLines(chunked(text, 100), 1000, n => throw new RecordingError(s"line $n"))
    r.readLine() shouldBe "ok"; r.readLine() shouldBe "fine"
    intercept[RecordingError](r.readLine()).getMessage shouldBe "line 3"
  }
}
