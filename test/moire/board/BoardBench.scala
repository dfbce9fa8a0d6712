package moire.board

import chisel3._
import chiseltest._
import moire.board.de2115.{De2115Ports, De2115Top, SevenSeg}
import moire.board.ulx3s.{Ulx3sPorts, Ulx3sTop}
import moire.io.Quadrature
import moire.stream.{Command, Decoder, Encoder, Frame, RecordFrame, RegisterReply}
import scala.collection.mutable

/** A board top as chiseltest drives it: a Module around the top with its clock input tied to the test clock. */
trait BenchTop extends Module {
  def p: BoardParams
  /** The ADC and encoder pins (shared by both boards). */
  def adcPins: AdcEncoderPins
  /** UART, host -> board. */
  def uartIn: Bool
  /** UART, board -> host. */
  def uartOut: Bool
  /** Holds the board's reset button down or lets it go. */
  def pressReset(down: Boolean): Unit
}

/** The DE2-115 top (CLOCK_50 = the test clock). */
class BoardHarness(val p: BoardParams) extends BenchTop {
  val io = IO(new De2115Ports)
  private val top = Module(new De2115Top(p))
  top.CLOCK_50 := clock
  top.pins <> io
  def adcPins: AdcEncoderPins = io
  def uartIn: Bool = io.UART_RXD
  def uartOut: Bool = io.UART_TXD
  def pressReset(down: Boolean): Unit = io.KEY.poke((if (down) 0xE else 0xF).U)
}

/** The ULX3S top (clk_25mhz = the test clock; clock source logic). */
class Ulx3sHarness(val p: BoardParams) extends BenchTop {
  val io = IO(new Ulx3sPorts)
  private val top = Module(new Ulx3sTop(p))
  top.clk_25mhz := clock
  top.pins <> io
  def adcPins: AdcEncoderPins = io
  def uartIn: Bool = io.ftdi_txd
  def uartOut: Bool = io.ftdi_rxd
  /** btn[0] is PWRn (1 = not pressed); btn[1] FIRE1 resets (1 = pressed). */
  def pressReset(down: Boolean): Unit = io.btn.poke((if (down) 3 else 1).U)
}

/** Drives the board's pins clock by clock: the AD9226 model on the ADC pins (edges seen on SIN_CLK,
  * or every clock when the ADC runs at 50 MHz), scripted encoder levels, commands bit-banged into
  * UART_RXD; bytes captured from UART_TXD and decoded with moire.stream.Decoder.
  */
final class BoardBench(c: BenchTop, val adc: Ad9226Model) {
  val p: BoardParams = c.p
  private val div = p.baudDivisor
  var cycle: Long = 0
  private var lastClk = false
  // UART RX (host -> board) bit queue and TX (board -> host) sampler
  private val rxBits = mutable.Queue.empty[Boolean]
  private var rxLevel = true; private var rxLeft = 0
  private var txState = -1; private var txTimer = 0; private var txByte = 0; private var txBit = 0
  val txBytes: mutable.ArrayBuffer[Byte] = mutable.ArrayBuffer.empty
  val decoder = new Decoder(1)
  val frames: mutable.ArrayBuffer[Frame] = mutable.ArrayBuffer.empty
  /** Encoder input levels (A, B, Z) by clock, set by the test. */
  var enc: (Boolean, Boolean, Boolean) = (false, false, false)
  private var encPoked = (true, true, true)
  /** Per-clock hook (after the edge), e.g. to decode the encoder outputs. */
  var onCycle: () => Unit = () => ()

  def reset(): Unit = {
    c.pressReset(true)
    c.uartIn.poke(true.B)
    pokeAdc()
    c.clock.step(40)
    c.pressReset(false)
  }

  private def pokeAdc(): Unit = {
    val s = adc.pins
    val pins = c.adcPins
    pins.SIN_D.poke(s.sin.U); pins.SIN_OTR.poke(s.otrSin.B)
    pins.COS_D.poke(s.cos.U); pins.COS_OTR.poke(s.otrCos.B)
  }

  def step(): Unit = {
    if (enc != encPoked) {
      val pins = c.adcPins
      pins.ENC_A_IN.poke(enc._1.B); pins.ENC_B_IN.poke(enc._2.B); pins.ENC_Z_IN.poke(enc._3.B); encPoked = enc
    }
    if (rxLeft == 0 && rxBits.nonEmpty) { val b = rxBits.dequeue(); if (b != rxLevel) { c.uartIn.poke(b.B); rxLevel = b }; rxLeft = div }
    if (rxLeft > 0) rxLeft -= 1
    c.clock.step(1)
    cycle += 1
    val edge = if (p.adcDivide == 1) true else {
      val clk = c.adcPins.SIN_CLK.peekBoolean(); val rose = clk && !lastClk; lastClk = clk; rose
    }
    if (edge) { adc.edge(); pokeAdc() }
    sampleTx(c.uartOut.peekBoolean())
    onCycle()
  }

  private def sampleTx(level: Boolean): Unit = {
    if (txState < 0) {
      if (!level) { txState = 0; txTimer = div / 2 }
    } else if (txTimer > 1) txTimer -= 1
    else {
      txTimer = div
      if (txState == 0) { if (level) txState = -1 else { txState = 1; txByte = 0; txBit = 0 } }
      else if (txState == 1) {
        if (level) txByte |= 1 << txBit
        txBit += 1
        if (txBit == 8) txState = 2
      } else {
        txState = -1
        if (level) { txBytes += txByte.toByte; frames ++= decoder.feed(Array(txByte.toByte)) }
        else throw new AssertionError(s"UART_TXD stop bit low at cycle $cycle")
      }
    }
  }

  def run(n: Long): Unit = { var i = 0L; while (i < n) { step(); i += 1 } }
  def runUntil(limit: Long, what: String)(cond: => Boolean): Unit = {
    val end = cycle + limit
    while (!cond) { if (cycle >= end) throw new AssertionError(s"timeout after $limit clocks waiting for $what"); step() }
  }

  /** Bit-bang raw bytes into UART_RXD (8N1). */
  def send(bytes: Array[Byte]): Unit = bytes.foreach { b =>
    rxBits += false
    for (i <- 0 until 8) rxBits += (((b >> i) & 1) == 1)
    rxBits += true
  }
  def replies: Seq[RegisterReply] = frames.collect { case r: RegisterReply => r }.toSeq
  def recordFrames: Seq[RecordFrame] = frames.collect { case r: RecordFrame => r }.toSeq

  /** Sends a command and waits for its reply. */
  def command(cmd: Command): Long = {
    val before = replies.size
    send(Encoder.command(cmd))
    runUntil(40L * div * 12 + 4 * 140L * div, s"reply to $cmd")(replies.size > before)
    val r = replies(before)
    assert(r.addr == cmd.addr, s"reply for 0x${r.addr.toHexString}, asked 0x${cmd.addr.toHexString}")
    r.value
  }
  def read(addr: Int): Long = command(Command.read(addr))
  def write(addr: Int, value: Long): Long = command(Command.write(addr, value))

  /** The 32-bit value the eight digits show (HEX7 = high nibble), or None if a digit is not a hex pattern. */
  def hexValue: Option[Long] = {
    val ds = c.asInstanceOf[BoardHarness].io.hex.map(h => SevenSeg.lit.indices.find(d => SevenSeg.activeLow(d) == h.peek().litValue.toInt))
    if (ds.exists(_.isEmpty)) None else Some(ds.zipWithIndex.map { case (d, i) => d.get.toLong << (4 * i) }.sum)
  }

  def encOut: (Boolean, Boolean, Boolean) = (c.adcPins.ENC_A_OUT.peekBoolean(), c.adcPins.ENC_B_OUT.peekBoolean(), c.adcPins.ENC_Z_OUT.peekBoolean())
}

/** Decodes a quadrature pair clock by clock into a count. */
final class QuadDecoder {
  var count: Long = 0
  var errors: Int = 0
  private var last = -1
  def update(a: Boolean, b: Boolean): Unit = {
    val ph = Quadrature.phase(a, b)
    if (last >= 0) Math.floorMod(ph - last, 4) match {
      case 1 => count += 1
      case 3 => count -= 1
      case 2 => errors += 1
      case _ =>
    }
    last = ph
  }
}
