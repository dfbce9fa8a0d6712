package moire.stream

import moire.protocol.{Crc16, Registers}
import moire.protocol.StreamV1._

/** Running totals of a [[Decoder]]. Every byte that is not part of a good frame is accounted for.
  *
  * @param skippedBytes  bytes outside good frames (garbage, corrupted or truncated frames)
  * @param leadingBytes  of these, the bytes before the first good frame (a port opened mid-stream);
  *                      damage there is not counted as CRC errors or bad headers: nothing to compare with
  * @param crcErrors     frames whose CRC failed (a corrupted region counts once, not once per false sync in it)
  * @param badHeaders    sync followed by an unknown type or n = 0
  * @param truncated     1 when the stream ended inside a frame
  * @param seqGaps       places where seq did not go up by 1; `seqMissing` frames missing in total
  * @param indexGaps     places where the sample index did not go up by D; `indexMissing` records missing
  *                      in total (counted where the step is a forward multiple of D)
  * @param dropped       sum of the frames' `dropped` fields (records lost on the board)
  * @param burstGaps     burst sample frames whose offset did not follow the previous one (0 starts a burst);
  *                      `burstMissing` samples missing in total
  */
final case class StreamStats(
  bytes: Long = 0, frames: Long = 0, recordFrames: Long = 0, replies: Long = 0, records: Long = 0,
  skippedBytes: Long = 0, leadingBytes: Long = 0, crcErrors: Long = 0, badHeaders: Long = 0, truncated: Long = 0, truncatedBytes: Long = 0,
  seqGaps: Long = 0, seqMissing: Long = 0, indexGaps: Long = 0, indexMissing: Long = 0, dropped: Long = 0,
  burstInfos: Long = 0, burstFrames: Long = 0, burstSamples: Long = 0, burstGaps: Long = 0, burstMissing: Long = 0
) {
  /** Anything lost or damaged (garbage before the first frame alone does not count). */
  def lost: Boolean = crcErrors + badHeaders + truncated + seqGaps + indexGaps + dropped + burstGaps > 0
}

/** Incremental decoder of board -> host frames: feed bytes in any chunking, get the good frames in order.
  *
  * It hunts for the sync bytes, waits for a whole frame, checks the CRC; on a bad CRC or header it
  * moves on by ONE byte and hunts again, so a real frame starting inside a damaged one is still found.
  * A damaged region counts once: false syncs inside the span of a failed frame are not counted again.
  * seq is checked across all frames, the sample index (step `decimation`) across all records.
  */
final class Decoder(val decimation: Long) {
  require(decimation >= 1 && decimation <= Registers.MaxDecimation, s"decimation must be in 1..${Registers.MaxDecimation}, got $decimation")
  private var buf = new Array[Byte](1 << 12)
  private var start = 0
  private var end = 0
  private var base = 0L          // stream offset of buf(start)
  private var suspectUntil = 0L  // failed candidates starting before this offset are not counted again
  private var pendingTrunc = -1L // finishing: offset of an incomplete frame, truncated unless a good frame follows
  private var lastSeq = -1
  private var lastIndex = -1L
  private var nextOffset = 0L // the burst offset the next burst sample frame should have
  private var frameLen = ReplyBytes // length of the last good record frame: the span assumed for a bad header
  private var finished = false
  private var s = StreamStats()

  def stats: StreamStats = s

  /** Bytes received but not yet decoded (the start of a frame, or bytes still being hunted through). */
  def buffered: Int = end - start

  /** A copy of the buffered bytes, to hand them on to another decoder. */
  def pending: Array[Byte] = java.util.Arrays.copyOfRange(buf, start, end)

  def feed(bytes: Array[Byte]): Vector[Frame] = feed(bytes, 0, bytes.length)

  def feed(bytes: Array[Byte], off: Int, len: Int): Vector[Frame] = {
    if (finished) throw new IllegalStateException("decoder already finished")
    append(bytes, off, len)
    s = s.copy(bytes = s.bytes + len)
    parse(finishing = false)
  }

  /** End of stream: decodes what can be decoded and reports an incomplete last frame as truncated. */
  def finish(): Vector[Frame] = {
    if (finished) return Vector.empty
    val out = parse(finishing = true)
    if (end - start == 1) { // a lone trailing byte
      if (buf(start) == Sync0.toByte && base >= suspectUntil && pendingTrunc < 0) pendingTrunc = base
      skip(1)
    }
    if (pendingTrunc >= 0) s = s.copy(truncated = s.truncated + 1, truncatedBytes = s.truncatedBytes + (base - pendingTrunc))
    finished = true
    out
  }

  private def append(bytes: Array[Byte], off: Int, len: Int): Unit = {
    if (end + len > buf.length) {
      val live = end - start
      val nb = if (live + len > buf.length / 2) new Array[Byte](math.max(buf.length * 2, live + len)) else buf
      System.arraycopy(buf, start, nb, 0, live)
      buf = nb; start = 0; end = live
    }
    System.arraycopy(bytes, off, buf, end, len)
    end += len
  }

  private def u8(i: Int): Int = buf(start + i) & 0xFF
  private def u16(i: Int): Int = u8(i) | (u8(i + 1) << 8)
  private def u32(i: Int): Long = u16(i).toLong | (u16(i + 2).toLong << 16)

  private def synced: Boolean = lastSeq >= 0
  private def skip(n: Int): Unit = {
    start += n; base += n
    s = s.copy(skippedBytes = s.skippedBytes + n, leadingBytes = s.leadingBytes + (if (synced) 0 else n))
  }
  /** A failed candidate is counted when it starts after the previous one's span; the span covers at least one usual frame. */
  private def fresh(len: Int): Boolean = {
    val f = synced && base >= suspectUntil
    suspectUntil = math.max(suspectUntil, base + math.max(len, frameLen))
    f
  }

  private def parse(finishing: Boolean): Vector[Frame] = {
    val out = Vector.newBuilder[Frame]
    var go = true
    while (go) {
      val avail = end - start
      if (avail < AtType) go = false
      else if (u8(0) != Sync0 || u8(1) != Sync1) skip(1)
      else {
        // -1: need more bytes, 0: bad header, else the frame length
        val len =
          if (avail <= AtType) -1
          else u8(AtType) match {
            case TypeRecords => if (avail <= AtCount) -1 else if (u8(AtCount) == 0) 0 else recordFrameBytes(u8(AtCount))
            case TypeRefRecords => if (avail <= AtCount) -1 else if (u8(AtCount) == 0) 0 else refRecordFrameBytes(u8(AtCount))
            case TypeReply => ReplyBytes
            case TypeBurstInfo => BurstInfoBytes
            case TypeBurstSamples => if (avail <= AtBurstCount) -1 else if (u8(AtBurstCount) == 0) 0 else burstFrameBytes(u8(AtBurstCount))
            case _ => 0
          }
        if (len == 0) {
          if (fresh(0)) s = s.copy(badHeaders = s.badHeaders + 1)
          skip(1)
        } else if (len < 0 || avail < len) {
          if (!finishing) go = false
          else {
            if (base >= suspectUntil && pendingTrunc < 0) pendingTrunc = base
            suspectUntil = math.max(suspectUntil, base + end - start)
            skip(1)
          }
        } else if (Crc16.of(buf, start + CrcFrom, len - CrcFrom - CrcBytes) != u16(len - CrcBytes)) {
          if (fresh(len)) s = s.copy(crcErrors = s.crcErrors + 1)
          skip(1)
        } else {
          if (pendingTrunc >= 0) { if (synced) s = s.copy(crcErrors = s.crcErrors + 1); pendingTrunc = -1 } // it was a damaged header
          val f = decode(len)
          out += f
          start += len; base += len
          suspectUntil = base
          count(f)
        }
      }
    }
    out.result()
  }

  private def decode(len: Int): Frame = {
    val seq = u16(AtSeq)
    def anchor(at: Int) = moire.io.Anchor(u32(at), u32(at + 4).toInt, u32(at + 8).toInt)
    if (u8(AtType) == TypeReply) RegisterReply(seq, u8(AtReplyAddr), u32(AtReplyValue))
    else if (u8(AtType) == TypeBurstInfo)
      BurstInfo(seq, math.max(u32(AtBurstLength), 1L), math.min(u32(AtBurstPre), math.max(u32(AtBurstLength), 1L) - 1),
        anchor(AtBurstTrigger), anchor(AtBurstLast))
    else if (u8(AtType) == TypeBurstSamples)
      BurstSamples(seq, u32(AtBurstOffset), IndexedSeq.tabulate(u8(AtBurstCount))(k => u32(AtBurstWords + 4 * k)))
    else {
      frameLen = len
      val n = u8(AtCount)
      val withRef = u8(AtType) == TypeRefRecords
      RecordFrame(seq, u16(AtDropped), IndexedSeq.tabulate(n) { k =>
        val at = AtRecords + RecordLayout.bytesOf(u8(AtType)) * k
        def field(f: moire.protocol.Field) = u32(at + RecordLayout.at(f))
        Record(field(RecordLayout.Index), field(RecordLayout.Word), field(RecordLayout.Position).toInt,
          if (withRef) Some(field(RecordLayout.RefCount).toInt) else None)
      })
    }
  }

  private def count(f: Frame): Unit = {
    var t = s.copy(frames = s.frames + 1)
    if (lastSeq >= 0 && f.seq != ((lastSeq + 1) & 0xFFFF))
      t = t.copy(seqGaps = t.seqGaps + 1, seqMissing = t.seqMissing + ((f.seq - lastSeq - 1) & 0xFFFF))
    lastSeq = f.seq
    f match {
      case r: RegisterReply => t = t.copy(replies = t.replies + 1)
      case b: BurstInfo => t = t.copy(burstInfos = t.burstInfos + 1)
      case b: BurstSamples =>
        if (b.offset != 0 && b.offset != nextOffset)
          t = t.copy(burstGaps = t.burstGaps + 1, burstMissing = t.burstMissing + math.max(0L, b.offset - nextOffset))
        nextOffset = b.offset + b.words.size
        t = t.copy(burstFrames = t.burstFrames + 1, burstSamples = t.burstSamples + b.words.size)
      case r: RecordFrame =>
        var gaps = 0L; var missing = 0L
        r.records.foreach { x =>
          if (lastIndex >= 0) {
            val d = (x.index - lastIndex) & MaxU32
            if (d != decimation) {
              gaps += 1
              if (d % decimation == 0 && d > 0 && d < (1L << 31)) missing += d / decimation - 1
            }
          }
          lastIndex = x.index
        }
        t = t.copy(recordFrames = t.recordFrames + 1, records = t.records + r.records.size, dropped = t.dropped + r.dropped,
          indexGaps = t.indexGaps + gaps, indexMissing = t.indexMissing + missing)
    }
    s = t
  }
}

/** Incremental decoder of host -> board commands, as the board sees them (the fake board in tests uses it).
  * After the sync bytes it takes the next 8 bytes whatever they are; a bad CRC or an unknown op is
  * ignored and counted in `errors` (register cmd_errors), and the hunt for sync starts after them.
  */
final class CommandDecoder {
  private val pending = scala.collection.mutable.ArrayBuffer.empty[Byte]
  private var errs = 0L
  def errors: Long = errs

  def feed(bytes: Array[Byte]): Vector[Command] = {
    val out = Vector.newBuilder[Command]
    bytes.foreach { b =>
      pending += b
      val n = pending.length
      if (n == 1 && (b & 0xFF) != Sync0) pending.clear()
      else if (n == 2 && (b & 0xFF) != Sync1) { pending.clear(); if ((b & 0xFF) == Sync0) pending += b }
      else if (n == CommandBytes) {
        val a = pending.toArray; pending.clear()
        def u(i: Int) = a(i) & 0xFF
        val crcOk = Crc16.of(a, CrcFrom, CommandBytes - CrcFrom - CrcBytes) == (u(CommandBytes - CrcBytes) | (u(CommandBytes - 1) << 8))
        val op = u(AtOp)
        if (!crcOk || (op != OpRead && op != OpWrite)) errs += 1
        else out += Command(op == OpWrite, u(AtCmdAddr), (0 until 4).map(i => u(AtCmdValue + i).toLong << (8 * i)).sum)
      }
    }
    out.result()
  }
}
