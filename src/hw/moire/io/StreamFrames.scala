package moire.io

import chisel3._
import chisel3.util._

/** Stream v1 (docs/board-de2-115.md, the coordinator's stream brief): one 12-byte record, little endian:
  * u32 index, u32 word, s32 position. Packed with byte 0 in bits 7..0.
  */
object StreamRecord {
  val bytes: Int = 12
  val width: Int = 8 * bytes
  def pack(index: UInt, word: UInt, position: SInt): UInt = Cat(position.asUInt(31, 0), word(31, 0), index(31, 0))
}

/** A register reply: address and value. */
class RegReply extends Bundle {
  val addr = UInt(8.W)
  val value = UInt(32.W)
}

/** A well-formed host command. */
class RegCommand extends Bundle {
  val write = Bool()
  val addr = UInt(8.W)
  val value = UInt(32.W)
}

/** Frame sender, stream v1: register replies (type 0x02) have priority; a record frame (type 0x01)
  * starts when the FIFO holds at least `n` records and takes exactly n. `dropped` pulses (FIFO
  * overflow) are counted, saturating at 65535, and the count since the previous record frame goes
  * into the next one. seq counts frames of both types. Bytes out one at a time (to a [[UartTx]]).
  */
class FrameTx(val n: Int, val countWidth: Int) extends Module {
  require(n >= 1 && n <= 255, s"frame-records n must be in 1..255, got $n")
  override def desiredName: String = s"FrameTx_n$n"
  val io = IO(new Bundle {
    val records = Flipped(Decoupled(UInt(StreamRecord.width.W)))
    val recordCount = Input(UInt(countWidth.W))
    val dropped = Input(Bool())
    val reply = Flipped(Decoupled(new RegReply))
    val out = Decoupled(UInt(8.W))
  })
  private val seq = RegInit(0.U(16.W))
  private val droppedCnt = RegInit(0.U(16.W))
  private val busy = RegInit(false.B)
  private val isReply = Reg(Bool())
  private val pos = RegInit(0.U(16.W))     // byte position in the frame
  private val recByte = RegInit(0.U(4.W))  // byte within the current record
  private val crc = Reg(UInt(16.W))
  private val frameDropped = Reg(UInt(16.W))
  private val reply = Reg(new RegReply)

  private val bodyEnd = Mux(isReply, 10.U, (8 + StreamRecord.bytes * n).U)   // first CRC byte
  private val startRec = !busy && !io.reply.valid && io.recordCount >= n.U
  private val startReply = !busy && io.reply.valid
  io.reply.ready := !busy
  private val dropNow = io.dropped && droppedCnt =/= 0xFFFF.U
  droppedCnt := droppedCnt + dropNow.asUInt
  when(startRec) {
    frameDropped := droppedCnt
    droppedCnt := io.dropped.asUInt
  }
  when(startRec || startReply) {
    busy := true.B; isReply := startReply; pos := 0.U; recByte := 0.U; crc := Crc16.init.U
  }
  when(startReply) { reply := io.reply.bits }

  private val recBytes = VecInit(Seq.tabulate(StreamRecord.bytes)(i => io.records.bits(8 * i + 7, 8 * i)))
  private val replyBytes = VecInit(Seq(reply.addr) ++ Seq.tabulate(4)(i => reply.value(8 * i + 7, 8 * i)))
  private val header = VecInit(0xA5.U(8.W), 0x5A.U(8.W), Mux(isReply, 2.U(8.W), 1.U(8.W)), seq(7, 0), seq(15, 8))
  private val inRecords = !isReply && pos >= 8.U && pos < bodyEnd
  private val byte = WireDefault(0.U(8.W))
  when(pos < 5.U) { byte := header(pos(2, 0)) }
    .elsewhen(pos === bodyEnd) { byte := crc(7, 0) }
    .elsewhen(pos === bodyEnd + 1.U) { byte := crc(15, 8) }
    .elsewhen(isReply) { byte := replyBytes((pos - 5.U)(2, 0)) }
    .elsewhen(pos === 5.U) { byte := n.U }
    .elsewhen(pos === 6.U) { byte := frameDropped(7, 0) }
    .elsewhen(pos === 7.U) { byte := frameDropped(15, 8) }
    .otherwise { byte := recBytes(recByte) }
  io.out.valid := busy
  io.out.bits := byte
  io.records.ready := busy && inRecords && io.out.ready && recByte === (StreamRecord.bytes - 1).U
  when(busy && io.out.ready) {
    pos := pos + 1.U
    when(pos >= 2.U && pos < bodyEnd) { crc := Crc16.next(crc, byte) }
    when(inRecords) { recByte := Mux(recByte === (StreamRecord.bytes - 1).U, 0.U, recByte + 1.U) }
    when(pos === bodyEnd + 1.U) { busy := false.B; seq := seq + 1.U }
  }
}

/** Command receiver, stream v1: hunts for sync 0xA5 0x5A, collects op, addr, value (u32 LE) and the
  * CRC (LE, over op..value). A good CRC with op 'R' or 'W' gives one `cmd` pulse; a bad CRC or an
  * unknown op pulses `error`.
  */
class CommandRx extends Module {
  val io = IO(new Bundle {
    val in = Flipped(Valid(UInt(8.W)))
    val cmd = Valid(new RegCommand)
    val error = Output(Bool())
  })
  private val state = RegInit(0.U(4.W)) // 0: want A5, 1: want 5A, 2..9: bytes 2..9
  private val buf = Reg(Vec(8, UInt(8.W)))
  private val crc = Reg(UInt(16.W))
  private val cmdV = RegInit(false.B)
  private val err = RegInit(false.B)
  cmdV := false.B
  err := false.B
  private val b = io.in.bits
  when(io.in.valid) {
    switch(state) {
      is(0.U) { when(b === 0xA5.U) { state := 1.U } }
      is(1.U) {
        when(b === 0x5A.U) { state := 2.U; crc := Crc16.init.U }
          .elsewhen(b =/= 0xA5.U) { state := 0.U }
      }
    }
    when(state >= 2.U) {
      buf((state - 2.U)(2, 0)) := b
      when(state < 8.U) { crc := Crc16.next(crc, b) }
      state := Mux(state === 9.U, 0.U, state + 1.U)
      when(state === 9.U) {
        val got = Cat(b, buf(6))
        val op = buf(0)
        val ok = got === crc && (op === 0x52.U || op === 0x57.U)
        cmdV := ok
        err := !ok
      }
    }
  }
  io.cmd.valid := cmdV
  io.cmd.bits.write := buf(0) === 0x57.U
  io.cmd.bits.addr := buf(1)
  io.cmd.bits.value := Cat(buf(5), buf(4), buf(3), buf(2))
  io.error := err
}
