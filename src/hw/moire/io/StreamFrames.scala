package moire.io

import chisel3._
import chisel3.util._
import moire.protocol.{BurstLayout, Crc16, RegCommand, RegReply, StreamRecord}
import moire.protocol.StreamV1._

/** What a finished burst's info frame (type 0x03) carries. */
class BurstInfoBits extends Bundle {
  val length = UInt(32.W)
  val pre = UInt(32.W)
  val trigger = new BurstAnchor
  val last = new BurstAnchor
}

/** Frame sender, stream v1 (moire.protocol.StreamV1), version 2: register replies first, then a burst
  * (its info frame, then its words in sample frames of up to [[BurstFrameWords]]), then records: a
  * record frame (type 0x05, with the reference count) starts when the FIFO holds at least `n` records and
  * takes exactly n; no record frame starts while a burst is being sent. `dropped` pulses (FIFO overflow)
  * are counted, saturating at 65535, and the count since the previous record frame goes into the next one.
  * seq counts frames of all types. Bytes out one at a time (to a [[UartTx]]).
  */
class FrameTx(val n: Int, val countWidth: Int) extends Module {
  require(n >= 1 && n <= MaxFrameRecords, s"frame-records n must be in 1..$MaxFrameRecords, got $n")
  override def desiredName: String = s"FrameTx_n$n"
  val io = IO(new Bundle {
    val records = Flipped(Decoupled(new StreamRecord))
    val recordCount = Input(UInt(countWidth.W))
    val dropped = Input(Bool())
    val reply = Flipped(Decoupled(new RegReply))
    /** A finished burst to send: taken once; then `info.length` words from `burstWords`. */
    val burstInfo = Flipped(Decoupled(new BurstInfoBits))
    val burstWords = Flipped(Decoupled(UInt(BurstLayout.width.W)))
    /** A burst is being sent (from its info frame to its last word). */
    val bursting = Output(Bool())
    val out = Decoupled(UInt(8.W))
  })
  private object Kind { val Records = 0; val Reply = 1; val Info = 2; val Samples = 3 }
  private val recordBytes = RecordLayout.refBytes
  private val seq = RegInit(0.U(16.W))
  private val droppedCnt = RegInit(0.U(16.W))
  private val busy = RegInit(false.B)
  private val kind = RegInit(0.U(2.W))
  private val pos = RegInit(0.U(16.W))     // byte position in the frame
  private val recByte = RegInit(0.U(log2Ceil(recordBytes).W))  // byte within the current record or word
  private val crc = Reg(UInt(16.W))
  // The CRC takes a body byte one clock after it went out, from a registered copy: the byte mux (fed by
  // the record FIFO's block RAM) and the CRC are then in separate clocks. The CRC bytes wait for it.
  private val crcByte = Reg(UInt(8.W))
  private val crcPending = RegInit(false.B)
  private val frameDropped = Reg(UInt(16.W))
  private val reply = Reg(new RegReply)
  private val info = Reg(new BurstInfoBits)
  private val total = RegInit(0.U(32.W))   // words of the burst being sent
  private val sent = RegInit(0.U(32.W))    // of these, words sent
  private val offset = Reg(UInt(32.W))     // first word of the current sample frame
  private val words = Reg(UInt(8.W))       // words in the current sample frame

  private val bursting = sent =/= total
  private val left = total - sent
  private val nextWords = Mux(left > BurstFrameWords.U, BurstFrameWords.U, left)(7, 0)
  moire.emit.Unused("record_count", io.recordCount) // compared with n: firtool reads only the bits that decide
  private val startReply = !busy && io.reply.valid
  private val startInfo = !busy && !io.reply.valid && !bursting && io.burstInfo.valid
  private val startSamples = !busy && !io.reply.valid && bursting
  private val startRec = !busy && !io.reply.valid && !bursting && !io.burstInfo.valid && io.recordCount >= n.U
  io.reply.ready := !busy
  io.burstInfo.ready := startInfo
  io.bursting := bursting || busy && kind === Kind.Info.U
  private val dropNow = io.dropped && droppedCnt =/= MaxDropped.U
  droppedCnt := droppedCnt + dropNow.asUInt
  when(startRec) {
    frameDropped := droppedCnt
    droppedCnt := io.dropped.asUInt
  }
  when(startRec || startReply || startInfo || startSamples) {
    busy := true.B; pos := 0.U; recByte := 0.U; crc := Crc16.Init.U
    kind := Mux(startReply, Kind.Reply.U, Mux(startInfo, Kind.Info.U, Mux(startSamples, Kind.Samples.U, Kind.Records.U)))
  }
  when(startReply) { reply := io.reply.bits }
  when(startInfo) { info := io.burstInfo.bits; total := io.burstInfo.bits.length; sent := 0.U }
  when(startSamples) { offset := sent; words := nextWords }

  /** Little-endian bytes of `x`. */
  private def le(x: UInt, bytes: Int): Seq[UInt] = Seq.tabulate(bytes)(i => x.pad(8 * bytes)(8 * i + 7, 8 * i))
  /** `v(i)`, `i` cut to the index width. */
  private def pick(v: Vec[UInt], i: UInt): UInt = v(i(log2Ceil(v.size) - 1, 0))
  private def anchorBytes(a: BurstAnchor): Seq[UInt] = le(a.index, 4) ++ le(a.position.asUInt, 4) ++ le(a.refCount.asUInt, 4)
  // The record's bytes come from a copy of the record FIFO's output registered twice: synthesis folds the
  // first register into the block RAM's read port, whose clock-to-output (5.6 ns on the ECP5) then reaches
  // only the second. After a record is taken the copy is two clocks late, so the first byte of the next
  // record waits those clocks (`recFresh`).
  private val recHeld = RegNext(RegNext(io.records.bits.asUInt))
  private val taken = RegNext(io.records.fire, false.B)
  private val recFresh = RegNext(!io.records.fire && !taken, false.B)
  private val recBytes = VecInit(le(recHeld, recordBytes))
  private val wordBytes = VecInit(le(io.burstWords.bits, 4))
  private val replyBytes = VecInit(Seq(reply.addr) ++ le(reply.value, 4))
  private val infoBytes = VecInit(le(info.length, 4) ++ le(info.pre, 4) ++ anchorBytes(info.trigger) ++ anchorBytes(info.last))
  private val offsetBytes = VecInit(le(offset, 4))
  private val frameType = VecInit(Seq(TypeRefRecords, TypeReply, TypeBurstInfo, TypeBurstSamples).map(_.U(8.W)))(kind)
  private val header = VecInit(Seq(Sync0.U(8.W), Sync1.U(8.W), frameType) ++ le(seq, 2))
  require(header.size == HeaderBytes && replyBytes.size == ReplyBytes - CrcBytes - AtReplyAddr &&
    infoBytes.size == BurstInfoBytes - CrcBytes - AtBurstLength)
  private val isRecords = kind === Kind.Records.U
  private val isSamples = kind === Kind.Samples.U
  // Where pos is, as flags registered beside it (no compare of pos with the frame's end in front of the byte mux or
  // the handshake): the header, the records or words, the first and the second CRC byte. pos only goes to 0 (a frame
  // starts) or up by one (a byte goes out), so each flag's next value is known from pos one clock ahead.
  // bodyEndLess1, the position before the first CRC byte, is registered from kind and words: on a frame's first
  // byte it still holds the previous frame's value, which is above the header like every kind's, so the flags for
  // pos 1 hold.
  private val bodyEndLess1 = RegNext(VecInit(Seq(
    (refRecordFrameBytes(n) - CrcBytes).U(16.W), (ReplyBytes - CrcBytes).U(16.W), (BurstInfoBytes - CrcBytes).U(16.W),
    (AtBurstWords.U(16.W) + (words << 2)).pad(16)))(kind) - 1.U, "hffff".U)
  private val bodyStartLess1 = Mux(isRecords, (AtRecords - 1).U, (AtBurstWords - 1).U)
  private val atHeader = RegInit(false.B)
  private val inBody = RegInit(false.B)
  private val atCrcLo = RegInit(false.B)
  private val atCrcHi = RegInit(false.B)
  private val inRecords = isRecords && inBody
  private val inWords = isSamples && inBody
  private val byte = WireDefault(0.U(8.W))
  when(atHeader) { byte := pick(header, pos) }
    .elsewhen(atCrcLo) { byte := crc(7, 0) }
    .elsewhen(atCrcHi) { byte := crc(15, 8) }
    .elsewhen(kind === Kind.Reply.U) { byte := pick(replyBytes, pos - AtReplyAddr.U) }
    .elsewhen(kind === Kind.Info.U) { byte := pick(infoBytes, pos - AtBurstLength.U) }
    .elsewhen(isSamples && pos < AtBurstCount.U) { byte := pick(offsetBytes, pos - AtBurstOffset.U) }
    .elsewhen(isSamples && pos === AtBurstCount.U) { byte := words }
    .elsewhen(isSamples) { byte := pick(wordBytes, recByte) }
    .elsewhen(pos === AtCount.U) { byte := n.U }
    .elsewhen(pos === AtDropped.U) { byte := frameDropped(7, 0) }
    .elsewhen(pos === (AtDropped + 1).U) { byte := frameDropped(15, 8) }
    .otherwise { byte := recBytes(recByte) }
  // a sample frame waits for its next word (the burst RAM answers within a few clocks), a record's first
  // byte for the registered copy, the CRC bytes for the CRC to take the last body byte
  io.out.valid := busy && !(inWords && !io.burstWords.valid) && !(inRecords && !recFresh) && !(atCrcLo && crcPending)
  io.out.bits := byte
  io.records.ready := io.out.valid && inRecords && io.out.ready && recByte === (recordBytes - 1).U
  io.burstWords.ready := busy && inWords && io.out.ready && recByte === 3.U
  when(io.burstWords.fire) { sent := sent + 1.U }
  // crcByte takes every byte (no enable: the handshake does not reach its flip-flops); crcPending says whether the
  // CRC takes it
  crcByte := byte
  crcPending := io.out.fire && pos >= CrcFrom.U && !atCrcLo && !atCrcHi
  when(crcPending) { crc := Crc16.next(crc, crcByte) }
  when(io.out.fire) {
    pos := pos + 1.U
    atHeader := pos < (HeaderBytes - 1).U
    inBody := pos === bodyStartLess1 || inBody && pos =/= bodyEndLess1
    atCrcLo := pos === bodyEndLess1
    atCrcHi := atCrcLo
    when(inRecords) { recByte := Mux(recByte === (recordBytes - 1).U, 0.U, recByte + 1.U) }
    when(inWords) { recByte := Mux(recByte === 3.U, 0.U, recByte + 1.U) }
    when(atCrcHi) { busy := false.B; seq := seq + 1.U }
  }
  when(startRec || startReply || startInfo || startSamples) {
    atHeader := true.B; inBody := false.B; atCrcLo := false.B; atCrcHi := false.B
  }
}

/** Command receiver, stream v1: hunts for the sync bytes, collects op, addr, value (u32 LE) and the
  * CRC (LE, over op..value). A good CRC with op 'R' or 'W' gives one `cmd` pulse; a bad CRC or an
  * unknown op pulses `error`.
  */
class CommandRx extends Module {
  val io = IO(new Bundle {
    val in = Flipped(Valid(UInt(8.W)))
    val cmd = Valid(new RegCommand)
    val error = Output(Bool())
  })
  // state = position in the command of the byte expected next: 0 and 1 the sync bytes
  private val state = RegInit(0.U(log2Ceil(CommandBytes).W))
  private val buf = Reg(Vec(CommandBytes - AtOp, UInt(8.W)))   // bytes AtOp.. of the command
  private def at(pos: Int): UInt = buf(pos - AtOp)
  private val crcAt = CommandBytes - CrcBytes
  private val crc = Reg(UInt(16.W))
  private val cmdV = RegInit(false.B)
  private val wr = RegInit(false.B)
  private val err = RegInit(false.B)
  cmdV := false.B
  err := false.B
  private val b = io.in.bits
  when(io.in.valid) {
    switch(state) {
      is(0.U) { when(b === Sync0.U) { state := 1.U } }
      is(1.U) {
        when(b === Sync1.U) { state := AtOp.U; crc := Crc16.Init.U }
          .elsewhen(b =/= Sync0.U) { state := 0.U }
      }
    }
    when(state >= AtOp.U) {
      buf((state - AtOp.U)(log2Ceil(buf.size) - 1, 0)) := b
      when(state < crcAt.U) { crc := Crc16.next(crc, b) }
      state := Mux(state === (CommandBytes - 1).U, 0.U, state + 1.U)
      when(state === (CommandBytes - 1).U) {
        val got = Cat(b, at(crcAt))
        val op = at(AtOp)
        val ok = got === crc && (op === OpRead.U || op === OpWrite.U)
        cmdV := ok
        wr := op === OpWrite.U // decoded here, beside cmdV: the op compare is not in series with the core's writes
        err := !ok
      }
    }
  }
  io.cmd.valid := cmdV
  io.cmd.bits.write := wr
  io.cmd.bits.addr := at(AtCmdAddr)
  io.cmd.bits.value := Cat((0 until 4).reverse.map(i => at(AtCmdValue + i)))
  io.error := err
}
