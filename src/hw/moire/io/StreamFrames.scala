package moire.io

import chisel3._
import chisel3.util._
import moire.protocol.{Crc16, RegCommand, RegReply, StreamRecord}
import moire.protocol.StreamV1._

/** Frame sender, stream v1 (moire.protocol.StreamV1): register replies have priority; a record frame
  * starts when the FIFO holds at least `n` records and takes exactly n. `dropped` pulses (FIFO
  * overflow) are counted, saturating at 65535, and the count since the previous record frame goes
  * into the next one. seq counts frames of both types. Bytes out one at a time (to a [[UartTx]]).
  */
class FrameTx(val n: Int, val countWidth: Int) extends Module {
  require(n >= 1 && n <= MaxFrameRecords, s"frame-records n must be in 1..$MaxFrameRecords, got $n")
  override def desiredName: String = s"FrameTx_n$n"
  val io = IO(new Bundle {
    val records = Flipped(Decoupled(new StreamRecord))
    val recordCount = Input(UInt(countWidth.W))
    val dropped = Input(Bool())
    val reply = Flipped(Decoupled(new RegReply))
    val out = Decoupled(UInt(8.W))
  })
  private val recordBytes = RecordLayout.bytes
  private val seq = RegInit(0.U(16.W))
  private val droppedCnt = RegInit(0.U(16.W))
  private val busy = RegInit(false.B)
  private val isReply = Reg(Bool())
  private val pos = RegInit(0.U(16.W))     // byte position in the frame
  private val recByte = RegInit(0.U(log2Ceil(recordBytes).W))  // byte within the current record
  private val crc = Reg(UInt(16.W))
  private val frameDropped = Reg(UInt(16.W))
  private val reply = Reg(new RegReply)

  private val bodyEnd = Mux(isReply, (ReplyBytes - CrcBytes).U, (recordFrameBytes(n) - CrcBytes).U) // first CRC byte
  private val startRec = !busy && !io.reply.valid && io.recordCount >= n.U
  moire.emit.Unused("record_count", io.recordCount) // compared with n: firtool reads only the bits that decide
  private val startReply = !busy && io.reply.valid
  io.reply.ready := !busy
  private val dropNow = io.dropped && droppedCnt =/= MaxDropped.U
  droppedCnt := droppedCnt + dropNow.asUInt
  when(startRec) {
    frameDropped := droppedCnt
    droppedCnt := io.dropped.asUInt
  }
  when(startRec || startReply) {
    busy := true.B; isReply := startReply; pos := 0.U; recByte := 0.U; crc := Crc16.Init.U
  }
  when(startReply) { reply := io.reply.bits }

  /** Little-endian bytes of `x`. */
  private def le(x: UInt, bytes: Int): Seq[UInt] = Seq.tabulate(bytes)(i => x(8 * i + 7, 8 * i))
  /** `v(i)`, `i` cut to the index width. */
  private def pick(v: Vec[UInt], i: UInt): UInt = v(i(log2Ceil(v.size) - 1, 0))
  private val recBytes = VecInit(le(io.records.bits.asUInt, recordBytes))
  private val replyBytes = VecInit(Seq(reply.addr) ++ le(reply.value, 4))
  private val header = VecInit(Seq(Sync0.U(8.W), Sync1.U(8.W), Mux(isReply, TypeReply.U(8.W), TypeRecords.U(8.W))) ++ le(seq, 2))
  require(header.size == HeaderBytes && replyBytes.size == ReplyBytes - CrcBytes - AtReplyAddr)
  private val inRecords = !isReply && pos >= AtRecords.U && pos < bodyEnd
  private val byte = WireDefault(0.U(8.W))
  when(pos < HeaderBytes.U) { byte := pick(header, pos) }
    .elsewhen(pos === bodyEnd) { byte := crc(7, 0) }
    .elsewhen(pos === bodyEnd + 1.U) { byte := crc(15, 8) }
    .elsewhen(isReply) { byte := pick(replyBytes, pos - AtReplyAddr.U) }
    .elsewhen(pos === AtCount.U) { byte := n.U }
    .elsewhen(pos === AtDropped.U) { byte := frameDropped(7, 0) }
    .elsewhen(pos === (AtDropped + 1).U) { byte := frameDropped(15, 8) }
    .otherwise { byte := recBytes(recByte) }
  io.out.valid := busy
  io.out.bits := byte
  io.records.ready := busy && inRecords && io.out.ready && recByte === (recordBytes - 1).U
  when(busy && io.out.ready) {
    pos := pos + 1.U
    when(pos >= CrcFrom.U && pos < bodyEnd) { crc := Crc16.next(crc, byte) }
    when(inRecords) { recByte := Mux(recByte === (recordBytes - 1).U, 0.U, recByte + 1.U) }
    when(pos === bodyEnd + 1.U) { busy := false.B; seq := seq + 1.U }
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
        err := !ok
      }
    }
  }
  io.cmd.valid := cmdV
  io.cmd.bits.write := at(AtOp) === OpWrite.U
  io.cmd.bits.addr := at(AtCmdAddr)
  io.cmd.bits.value := Cat((0 until 4).reverse.map(i => at(AtCmdValue + i)))
  io.error := err
}
