package moire.replay

import java.nio.{ByteBuffer, ByteOrder}

/** ADC pin codes to replay, one entry per clock (every ADC sample, none skipped). `otr` may be empty. */
final case class PinStream(sin: Array[Int], cos: Array[Int], otrSin: Array[Boolean], otrCos: Array[Boolean]) {
  require(sin.length == cos.length, "sin and cos must have the same length")
  def length: Int = sin.length
  def otrS(i: Int): Boolean = otrSin.nonEmpty && otrSin(i)
  def otrC(i: Int): Boolean = otrCos.nonEmpty && otrCos(i)
}

/** The design's outputs: row i belongs to input sample i (taken `latency` clocks after it entered).
  * position is sign-extended, phase unsigned; flags as in harness.cpp (bit0 valid, 1 present, 2 overRange,
  * 3 stepFault, 4 a, 5 b, 6 z, 7 overspeed). `loopSeconds` is the harness's clocking loop alone.
  */
final case class ReplayOutput(position: Array[Long], phase: Array[Long], flags: Array[Byte], loopSeconds: Double, cpuSeconds: Double) {
  def length: Int = position.length
  def flag(i: Int, bit: Int): Boolean = ((flags(i) >> bit) & 1) != 0
}

object Replay {
  val Valid = 0; val Present = 1; val OverRange = 2; val StepFault = 3; val A = 4; val B = 5; val Z = 6; val Overspeed = 7

  /** Bytes of a Verilated port of this width. */
  def portBytes(bits: Int): Int = if (bits <= 8) 1 else if (bits <= 16) 2 else if (bits <= 32) 4 else 8

  /** Writes the harness input: u16 sin, u16 cos per sample, OTR in bit 15 when the ADC has at most 15 bits. */
  def writeInput(path: os.Path, pins: PinStream, inputBits: Int): Unit = {
    val hasOtr = (0 until pins.length).exists(i => pins.otrS(i) || pins.otrC(i))
    if (hasOtr && inputBits > 15) throw new ReplayError("replay carries OTR flags only for ADCs of at most 15 bits")
    val ch = java.nio.channels.FileChannel.open(path.toNIO, java.nio.file.StandardOpenOption.CREATE,
      java.nio.file.StandardOpenOption.WRITE, java.nio.file.StandardOpenOption.TRUNCATE_EXISTING)
    try {
      val buf = ByteBuffer.allocateDirect(1 << 22).order(ByteOrder.LITTLE_ENDIAN)
      var i = 0
      while (i < pins.length) {
        if (buf.remaining < 4) { buf.flip(); while (buf.hasRemaining) ch.write(buf); buf.clear() }
        buf.putShort((pins.sin(i) | (if (pins.otrS(i)) 0x8000 else 0)).toShort)
        buf.putShort((pins.cos(i) | (if (pins.otrC(i)) 0x8000 else 0)).toShort)
        i += 1
      }
      buf.flip(); while (buf.hasRemaining) ch.write(buf)
    } finally ch.close()
  }

  /** Runs the harness over the pins; `progress(rowsDone)` is called while it runs. */
  def run(h: Harness, d: ReplayDesign, pins: PinStream, progress: Long => Unit = _ => ()): ReplayOutput = {
    val dir = os.temp.dir(prefix = "moire-replay")
    try {
      val in = dir / "in.bin"; val outFile = dir / "out.bin"
      writeInput(in, pins, d.inputBits)
      val pb = portBytes(d.out.positionWidth); val hb = portBytes(d.out.angleBits); val rec = pb + hb + 1
      val proc = os.proc(h.exe, in, outFile, d.latency, d.inputBits).spawn(stderr = os.Pipe, stdout = os.Pipe)
      while (proc.isAlive()) {
        proc.waitFor(200)
        if (os.exists(outFile)) progress(os.size(outFile) / rec)
      }
      val err = proc.stderr.text()
      if (proc.exitCode() != 0) throw new ReplayError(s"replay harness failed (exit ${proc.exitCode()}): ${err.linesIterator.toSeq.lastOption.getOrElse("")}")
      val stats = """cycles (\d+) rows (\d+) seconds ([\d.]+) cpu ([\d.]+)""".r.findFirstMatchIn(err)
        .getOrElse(throw new IllegalStateException(s"replay harness: no statistics line in '$err'"))
      val n = pins.length
      if (stats.group(2).toLong != n || os.size(outFile) != n.toLong * rec)
        throw new IllegalStateException(s"replay harness wrote ${stats.group(2)} rows for $n samples")
      val position = new Array[Long](n); val phase = new Array[Long](n); val flags = new Array[Byte](n)
      val pw = d.out.positionWidth
      val ch = java.nio.channels.FileChannel.open(outFile.toNIO)
      try {
        val buf = ByteBuffer.allocateDirect(rec * (1 << 18)).order(ByteOrder.LITTLE_ENDIAN)
        var i = 0
        def get(bytes: Int): Long = bytes match {
          case 1 => buf.get() & 0xffL
          case 2 => buf.getShort() & 0xffffL
          case 4 => buf.getInt() & 0xffffffffL
          case _ => buf.getLong()
        }
        while (i < n) {
          buf.clear()
          buf.limit(math.min(buf.capacity, (n - i) * rec))
          while (buf.hasRemaining && ch.read(buf) >= 0) {}
          buf.flip()
          while (buf.remaining >= rec) {
            val p = get(pb)
            position(i) = (p << (64 - pw)) >> (64 - pw)
            phase(i) = get(hb)
            flags(i) = buf.get()
            i += 1
          }
        }
      } finally ch.close()
      ReplayOutput(position, phase, flags, stats.group(3).toDouble, stats.group(4).toDouble)
    } finally os.remove.all(dir)
  }
}
