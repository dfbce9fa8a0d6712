package moire.stream

import moire.io.{Anchor, Quadrature}
import moire.protocol.BurstLayout
import moire.signal.AdcFormat
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A burst of a known reference motion becomes a full-rate recording with the right columns and count. */
class BurstAssemblerSpec extends AnyFlatSpec with Matchers {
  /** Reference position (counts) of sample k: back and forth, at most one count per sample. */
  private def refPos(k: Int): Long = (20 * math.sin(k / 30.0)).round - 7
  private def word(k: Int): Long = {
    val (a, b) = Quadrature.levels(refPos(k))
    BurstLayout.Sin.put(k % 4096) | BurstLayout.Cos.put((3 * k) % 4096) | BurstLayout.OtrCos.put(k % 2) |
      BurstLayout.RefA.put(if (a) 1 else 0) | BurstLayout.RefB.put(if (b) 1 else 0) | BurstLayout.RefZ.put(if (k == 50) 1 else 0)
  }
  private val L = BurstAssembler.counterLatency

  "BurstAssembler" should "rebuild every sample's reference count from the pins and check it against both anchors" in {
    for ((n, pre, perFrame) <- Seq((400, 100, 255), (64, 0, 7), (10, 9, 1))) withClue(s"n $n, pre $pre: ") {
      val first = 1000L
      // the board's counter lags the pins by L clocks
      def board(k: Int) = Anchor(first + k, k * 11, refPos(k - L).toInt)
      val info = BurstInfo(0, n, pre, board(pre), board(n - 1))
      val frames = (0 until n).map(word).map(_.toLong).grouped(perFrame).zipWithIndex
        .map { case (ws, j) => BurstSamples(1 + j, j.toLong * perFrame, ws.toIndexedSeq) }.toSeq
      val (r, check) = BurstAssembler.recording(info, frames.reverse, 50e6, AdcFormat.OffsetBinary)
      r.sampleRateHz shouldBe 50e6
      r.sin.toSeq shouldBe (0 until n).map(_ % 4096)
      r.cos.toSeq shouldBe (0 until n).map(k => (3 * k) % 4096)
      r.extra("ref_counts").toSeq shouldBe (0 until n).map(k => refPos(k).toDouble)
      r.extra("sample_index").head shouldBe first.toDouble
      r.extra("otr_cos").toSeq shouldBe (0 until n).map(k => (k % 2).toDouble)
      check.refSkips shouldBe 0
      check.triggerError shouldBe (if (pre >= L) Some(0L) else None)
      r.meta("burst_last_position") shouldBe ((n - 1) * 11).toString
    }
  }

  it should "refuse a burst with lost frames, naming how many samples are missing" in {
    val info = BurstInfo(0, 20, 0, Anchor(0, 0, 0), Anchor(19, 0, 0))
    val e = the[StreamError] thrownBy BurstAssembler.recording(info, Seq(BurstSamples(1, 0, IndexedSeq.fill(15)(0L))), 1e6, AdcFormat.OffsetBinary)
    e.getMessage shouldBe "burst of 20 samples: 5 samples missing (lost frames); the burst is not written"
  }
}
