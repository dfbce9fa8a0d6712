package moire.stream

import com.fazecast.jSerialComm.{SerialPort, SerialPortInvalidPortException}
import java.nio.file.{Files, Paths}

/** A byte pipe to the board: the serial port, or anything a test puts in its place. */
trait ByteLink extends AutoCloseable {
  /** Port name for messages. */
  def name: String
  def write(a: Array[Byte]): Unit
  /** Reads what is there into `buf`, waiting up to the link's read timeout (about 100 ms); 0 when nothing came. */
  def read(buf: Array[Byte]): Int
}

/** A serial port through jSerialComm, 8N1, no flow control, reads wait at most `readTimeoutMs`.
  * A symlink (a udev name, or a socat pty link) is resolved to the device before opening. (jSerialComm 2.11.4
  * resolves it too, and opens ptys: the tests run it against socat pairs.)
  */
final class SerialLink private (port: SerialPort, val name: String) extends ByteLink {
  def write(a: Array[Byte]): Unit = {
    var off = 0
    while (off < a.length) {
      val n = port.writeBytes(a, a.length - off, off)
      if (n <= 0) throw new StreamError(s"$name: write failed (error ${port.getLastErrorCode}); is the adapter still plugged in?")
      off += n
    }
  }
  def read(buf: Array[Byte]): Int = {
    val n = port.readBytes(buf, buf.length)
    if (n < 0) throw new StreamError(s"$name: read failed (error ${port.getLastErrorCode}); is the adapter still plugged in?")
    n
  }
  def close(): Unit = port.closePort()
}

object SerialLink {
  /** Serial ports the system lists (device paths). */
  def available: Seq[String] = SerialPort.getCommPorts.toSeq.map(_.getSystemPortPath).sorted

  def open(path: String, baud: Int, readTimeoutMs: Int = 100): SerialLink = {
    def missing = new StreamError(s"$path: no such serial port (available: ${Some(available).filter(_.nonEmpty).fold("none")(_.mkString(", "))})")
    if (path.trim.isEmpty) throw new StreamError(s"--port is empty: name a serial port, e.g. /dev/ttyUSB0 (available: ${Some(available).filter(_.nonEmpty).fold("none")(_.mkString(", "))})")
    val p = Paths.get(path)
    if (!Files.exists(p)) throw missing
    if (Files.isDirectory(p)) throw new StreamError(s"$path: is a folder, not a serial port")
    if (Files.isRegularFile(p)) throw new StreamError(s"$path: is a plain file, not a serial port")
    val real = p.toRealPath().toString
    val sp = try SerialPort.getCommPort(real) catch { case _: SerialPortInvalidPortException => throw missing }
    sp.setComPortParameters(baud, 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY)
    sp.setFlowControl(SerialPort.FLOW_CONTROL_DISABLED)
    if (!sp.openPort()) {
      val why = sp.getLastErrorCode match {
        case 13 => "permission denied (on Linux: add yourself to the dialout group)"
        case 16 => "the port is in use by another program"
        case 25 => "not a serial device"
        case 21 => "is a folder, not a serial port"
        case 2 => "no such device"
        case c => s"error $c"
      }
      throw new StreamError(s"$path: cannot open the serial port: $why")
    }
    sp.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING, readTimeoutMs, 0)
    new SerialLink(sp, path)
  }
}
