package moire.board

import chiseltest._
import moire.cordic.SimSupport
import moire.protocol.Registers
import moire.signal.{AdcFormat, Motion, SignalParams}
import moire.stream.{Command, RecordFrame, Record}
import moire.subdiv.{SubdivModel, SubdivSample}
import moire.recording.Recording
import moire.stream.{PtyPair, RecordOptions, Recorder}
import org.scalatest.flatspec.AnyFlatSpec
import scala.concurrent.{Await, Future}
import scala.concurrent.ExecutionContext.Implicits.global
import scala.concurrent.duration._

/** Whole-board simulation of the DE2-115 top: AD9226 models on the ADC pins, an encoder source on
  * the encoder inputs, the host on the UART pins (fast baud: clock / 8).
  */
class BoardSimSpec extends AnyFlatSpec with ChiselScalatestTester {
  /** UART bytes of the simulated board before the overflow part (filled by the first test). */
  private var streamBytes: Array[Byte] = Array.empty
  private var streamFrames: Seq[RecordFrame] = Nil
  val clockHz = 50e6
  /** 25 MHz ADC (divider register drives SIN_CLK), n = 4, FIFO 8, decimation 1024. */
  val p = BoardParams(adcClockHz = 25000000, baud = 6250000, frameRecords = 4, fifoDepth = 8, glitchFilter = 8,
    decimation = 1024, clockSource = ClockSource.Logic, burstSamples = 2048)
  val M: Int = p.subdiv.counts
  // Peaks at 1.02 full scale: OTR at the peaks; a reversing ramp: both directions.
  val signal = SignalParams(amplitude = 1.02)
  val motion = Motion.Ramp(-40e3, 40e3, 2.4e-3, start = 0.3)

  /** Positions and directions the datapath gives for samples 0..n-1 (model, in sample order). */
  def expected(adc: Ad9226Model, n: Int): (Array[Int], Array[Boolean]) = {
    val m = new SubdivModel(p.subdiv)
    val pos = new Array[Int](n); val dir = new Array[Boolean](n)
    var last = 0L; var up = true
    for (i <- 0 until n) {
      val s = adc.sample(i)
      val r = m.process(SubdivSample(adc.adc.fromPins(s.sin), adc.adc.fromPins(s.cos), s.otrSin, s.otrCos))
      val v = r.position.toInt.toLong
      if (v > last) up = true else if (v < last) up = false
      last = v; pos(i) = v.toInt; dir(i) = up
    }
    (pos, dir)
  }

  /** Every record matches the model's sample at its index: codes, OTR, position (bit-exact and within
    * one count of the true motion), flags.
    */
  def checkRecords(adc: Ad9226Model, recs: Seq[Record]): Unit = {
    val n = recs.map(_.index.toInt).max + 1
    val (pos, dir) = expected(adc, n)
    for (r <- recs) {
      val i = r.index.toInt
      val s = adc.sample(i)
      assert(r.sin == s.sin && r.cos == s.cos && r.otrSin == s.otrSin && r.otrCos == s.otrCos, s"record $i codes: $r vs $s")
      assert(r.position == pos(i), s"record $i position ${r.position}, model ${pos(i)}")
      val truth = math.floor(s.truePeriods * M).toLong
      assert(math.abs(r.position - truth) <= 1, s"record $i position ${r.position}, true motion $truth")
      assert(r.present && !r.stepFault && r.overRange == (s.otrSin || s.otrCos) && r.direction == dir(i), s"record $i flags: $r")
    }
  }

  "The DE2-115 board" should "stream, answer registers, count encoder inputs and report FIFO overflow" in {
    test(new BoardHarness(p)).withAnnotations(SimSupport.backend) { c =>
      c.clock.setTimeout(0)
      val adc = Ad9226Model(AdcFormat.OffsetBinary, signal, motion, p.adcClockHz)
      val b = new BoardBench(c, adc)
      val ab = new QuadDecoder
      var zSeen = 0; var zOff = 0
      var anchor: Option[Long] = None   // HEX position minus the A/B count
      b.onCycle = () => {
        val (a, bb, z) = b.encOut
        ab.update(a, bb)
        if (z) { zSeen += 1; anchor.foreach(o => if (Math.floorMod(ab.count + o, M.toLong) > 1 && Math.floorMod(ab.count + o, M.toLong) < M - 1) zOff += 1) }
      }
      b.reset()

      // ---- constant registers ----
      assert(b.read(Registers.Id.addr) == Registers.IdValue)
      assert(b.read(Registers.Version.addr) == moire.protocol.StreamV1.Version)
      assert(b.read(Registers.BurstDepth.addr) == p.burstSamples)
      assert(b.read(Registers.AdcClockHz.addr) == p.adcClockHz)
      assert(b.read(Registers.FrameRecords.addr) == p.frameRecords)
      assert(b.read(Registers.CountsPerPeriod.addr) == M)
      assert(b.read(Registers.AdcFormat.addr) == 0)
      assert(b.read(Registers.Decimation.addr) == p.decimation)
      assert(b.read(Registers.Control.addr) == 1)

      // ---- encoder inputs: 37 steps up, 12 down, Z at count 30; glitches shorter than the filter ----
      val hold = 24
      def levels(n: Long) = Quadrature(n)
      def Quadrature(n: Long) = moire.io.Quadrature.levels(n)
      var count = 0L
      def setAB(n: Long, z: Boolean = false): Unit = { val (a, bb) = levels(n); b.enc = (a, bb, z) }
      def glitchAll(): Unit = { // a staggered A/B glitch that would count +4 if it got through, and a Z glitch
        val (a, bb) = levels(count)
        b.enc = (!a, bb, false); b.run(2); b.enc = (!a, !bb, false); b.run(1); b.enc = (a, !bb, true); b.run(2)
        b.enc = (a, bb, false); b.run(hold)
      }
      for (k <- 0 until 49) {
        count += (if (k < 37) 1 else -1)
        setAB(count); b.run(hold)
        if (count == 30 && k < 37) { setAB(count, z = true); b.run(hold); setAB(count) ; b.run(hold) }
        else glitchAll()
      }
      b.run(100)
      assert(b.read(Registers.EncoderCount.addr) == 25, "encoder_count after 37 up, 12 down (glitches must be ignored)")
      assert(b.read(Registers.EncoderZCount.addr) == 30, "encoder_z_count latched at the Z pulse (Z glitches ignored)")

      // ---- record stream ----
      b.runUntil(200000, "6 record frames")(b.recordFrames.size >= 6)
      val hex1 = b.hexValue.getOrElse(fail("HEX digits do not show hex"))
      anchor = Some(hex1 - ab.count)
      // the digits show the position of a sample a datapath latency old
      val sNow = adc.edges - 8 - (p.datapathLatency + 4) / p.adcDivide
      val truthNow = math.floor(adc.sample(sNow).truePeriods * M).toLong
      assert(math.abs(hex1.toInt - truthNow) <= 8, s"HEX ${hex1.toInt} vs true position $truthNow")
      val frames1 = b.recordFrames
      assert(b.decoder.stats.crcErrors == 0 && b.decoder.stats.skippedBytes == 0, b.decoder.stats)
      val recs1 = frames1.flatMap(_.records)
      assert(frames1.forall(f => f.dropped == 0 && f.records.size == p.frameRecords))
      assert(recs1.map(_.index).sliding(2).forall { case Seq(x, y) => y - x == p.decimation })
      assert(recs1.exists(r => r.otrSin) && recs1.exists(!_.direction) && recs1.exists(_.direction),
        "the run should show OTR and both directions")
      checkRecords(adc, recs1)
      assert(recs1.last.ref.contains(25), s"records carry the encoder count (25): ${recs1.last.ref}")
      val seqs = b.frames.map(_.seq)
      assert(seqs.zip(seqs.drop(1)).forall { case (x, y) => y == ((x + 1) & 0xFFFF) }, s"seq: $seqs")

      // position register follows the records; the encoder outputs follow the digits
      val posReg = b.read(Registers.Position.addr).toInt
      val hex2 = b.hexValue.get
      assert(math.abs((hex2 - ab.count) - anchor.get) <= 2, s"A/B count ${ab.count} drifted from the digits $hex2")
      val truth2 = math.floor(adc.sample(adc.edges - 8 - (p.datapathLatency + 4) / p.adcDivide).truePeriods * M).toLong
      assert(math.abs(hex2.toInt - truth2) <= 8, s"HEX ${hex2.toInt} vs true $truth2")
      assert(math.abs(posReg - hex2.toInt) <= 100, s"position register $posReg vs digits ${hex2.toInt}")
      assert(zSeen > 0 && zOff == 0, s"Z output: $zSeen clocks high, $zOff away from a multiple of M")
      assert(ab.errors == 0)
      assert((b.read(Registers.Status.addr) & 0x1FF) == 0x132, "status: present (live); over_range, otr_sin, otr_cos (sticky)")

      // ---- writes ----
      assert(b.write(Registers.Id.addr, 7) == Registers.IdValue, "a read-only register keeps its value")
      assert(b.write(Registers.Decimation.addr, 0) == p.decimation, "decimation 0 is refused")
      assert(b.write(Registers.Control.addr, 3) == 1, "clear the sticky flags, stream on")
      val errs0 = b.read(Registers.CmdErrors.addr)
      val bad = moire.stream.Encoder.command(Command.read(Registers.Id.addr)); bad(9) = (bad(9) ^ 1).toByte
      val nReplies = b.replies.size
      b.send(bad); b.run(2000)
      assert(b.replies.size == nReplies, "a command with a bad CRC is not answered")
      assert(b.read(Registers.CmdErrors.addr) == errs0 + 1)

      streamBytes = b.txBytes.toArray // for the recorder test below: the stream before the burst
      streamFrames = b.recordFrames

      // ---- burst: 600 consecutive samples, 100 before the trigger, records paused while it is sent ----
      import moire.stream.{BurstAssembler, BurstInfo, BurstSamples}
      for ((r, v) <- Seq(Registers.BurstLength -> 600L, Registers.BurstPre -> 100L, Registers.BurstTrigger -> 0L))
        assert(b.write(r.addr, v) == v, s"${r.name} write")
      b.write(Registers.BurstControl.addr, 1)
      var polls = 0
      while (b.read(Registers.BurstState.addr) != 3) { polls += 1; assert(polls < 50, "burst not done"); b.run(2000) }
      val f0 = b.frames.size
      b.write(Registers.BurstControl.addr, 2)
      b.runUntil(400000, "the burst's frames")(b.frames.drop(f0).collect { case s: BurstSamples => s.words.size }.sum >= 600)
      val got = b.frames.drop(f0)
      val bi = got.collectFirst { case i: BurstInfo => i }.getOrElse(fail("no burst bi frame"))
      val bursts = got.collect { case s: BurstSamples => s }.toSeq
      val (burstRec, check) = BurstAssembler.recording(bi, bursts, p.adcClockHz, AdcFormat.OffsetBinary)
      val first = bi.trigger.index - bi.pre
      assert(bi.length == 600 && bi.pre == 100 && bi.last.index - first == 599, s"burst bi $bi")
      for (k <- 0 until 600) {
        val s = adc.sample((first + k).toInt)
        assert(burstRec.sin(k) == s.sin && burstRec.cos(k) == s.cos && burstRec.extra("otr_sin")(k) == (if (s.otrSin) 1.0 else 0.0),
          s"burst sample $k (index ${first + k}): ${burstRec.sin(k)}/${burstRec.cos(k)} vs $s")
      }
      val (pos, _) = expected(adc, (bi.last.index + 1).toInt)
      assert(bi.trigger.position == pos(bi.trigger.index.toInt) && bi.last.position == pos(bi.last.index.toInt), "anchor positions")
      assert(burstRec.extra("ref_counts").forall(_ == 25.0) && check.triggerError.contains(0L) && check.refSkips == 0,
        s"reference count in the burst: $check")
      // no record frame between the bi frame and the last sample frame
      val span = got.slice(got.indexOf(bi), got.indexOf(bursts.last))
      assert(!span.exists(_.isInstanceOf[RecordFrame]), "records must pause while the burst is sent")
      assert(burstRec.extra("sample_index").sliding(2).forall(w => w(1) - w(0) == 1.0))
      info(s"burst of 600 samples: ${bursts.size} sample frames, trigger at index ${bi.trigger.index}, records paused meanwhile")

      // ---- forced FIFO overflow: decimation 1 ----
      val before = b.recordFrames.size
      assert(b.write(Registers.Decimation.addr, 1) == 1)
      b.runUntil(200000, "overflow frames")(b.recordFrames.size >= before + 6)
      assert(b.write(Registers.Control.addr, 0) == 0)
      var quiet = 0; var seen = b.frames.size
      b.runUntil(100000, "the stream to stop")({ if (b.frames.size != seen) { seen = b.frames.size; quiet = 0 } else quiet += 1; quiet > 8000 })
      assert(b.write(Registers.Decimation.addr, 1024) == 1024)
      assert(b.write(Registers.Control.addr, 1) == 1)
      val resumed = b.recordFrames.size
      b.runUntil(300000, "frames after the overflow")(b.recordFrames.size >= resumed + 3)
      val all = b.recordFrames
      val droppedSum = all.map(_.dropped.toLong).sum
      val total = b.read(Registers.DroppedTotal.addr)
      assert(droppedSum > 0 && total == droppedSum, s"dropped fields sum $droppedSum, dropped_total $total")
      assert((b.read(Registers.Status.addr) & 0x8) != 0, "status fifo_overflow")
      val over = all.slice(before, resumed).flatMap(_.records)
      // records still spaced by 1024 were taken before the write; the rest were taken at D = 1
      val firstD1 = over.map(_.index).sliding(2).indexWhere { case Seq(x, y) => y - x != 1024 } + 1
      val d1 = over.drop(firstD1).map(_.index)
      val gaps = d1.sliding(2).map { case Seq(x, y) => y - x - 1 }.toSeq
      assert(d1.size >= 8 && gaps.count(_ > 0) > 0 && gaps.sum <= total,
        s"${d1.size} records at D = 1: index gaps ${gaps.sum}, dropped_total $total")
      checkRecords(adc, over ++ all.drop(resumed).flatMap(_.records))
      assert(b.decoder.stats.crcErrors == 0 && b.decoder.stats.skippedBytes == 0, b.decoder.stats)
      info(f"${b.cycle} clocks, ${b.recordFrames.size} record frames, ${b.replies.size} replies, $total records dropped (${SimSupport.backendName})")
    }
  }

  it should "give a byte stream that the host recorder turns into a moire-recording v1 (through a socat pty pair)" in {
    if (streamBytes.isEmpty) cancel("the board simulation above did not run")
    PtyPair { pty =>
      val out = pty.dir / "rec.csv"
      val o = RecordOptions(pty.host.toString, seconds = 1.5, out.toString, baud = 115200, decimation = Some(p.decimation.toLong),
        adcClockHz = Some(p.adcClockHz.toDouble), adcFormat = Some("offset-binary"), countsPerPeriod = Some(M.toLong),
        listenOnly = true, quiet = true)
      val said = new java.util.concurrent.ConcurrentLinkedQueue[String]
      val job = Future(Recorder.run(o, said.add(_), said.add(_)))
      Thread.sleep(500)
      pty.feed(streamBytes, bytesPerSecond = 11520)
      val r = Await.result(job, 20.seconds)
      val rec = Recording.read(out)
      // the recorder starts after the first frame whose records are D apart: here the first record frame
      val expected = streamFrames.drop(1).flatMap(_.records)
      assert(r.rows == expected.size && rec.length == expected.size, s"${rec.length} rows, ${expected.size} records sent")
      assert(rec.sin.toSeq == expected.map(_.sin) && rec.cos.toSeq == expected.map(_.cos))
      assert(rec.extra("sample_index").toSeq == expected.map(_.index.toDouble))
      assert(rec.extra("position").toSeq == expected.map(_.position.toDouble))
      assert(rec.extra("ref_counts").toSeq == expected.map(_.ref.get.toDouble))
      assert(rec.extra("direction").toSeq == expected.map(x => if (x.direction) 1.0 else 0.0))
      assert(rec.extra("otr_sin").toSeq == expected.map(x => if (x.otrSin) 1.0 else 0.0))
      assert(rec.sampleRateHz == p.adcClockHz.toDouble / p.decimation)
      for ((k, v) <- Seq("source" -> "de2-115", "decimation" -> "1024", "adc_clock_hz" -> "25000000", "counts_per_period" -> "1024",
        "crc_errors" -> "0", "gaps" -> "0", "dropped_records" -> "0", "seq_gaps" -> "0"))
        assert(rec.meta.get(k).contains(v), s"metadata $k = ${rec.meta.get(k)}, expected $v")
    }
  }
}
