package moire.stream

import moire.protocol.StreamV1

/** A fake board on a pty for trying `record` and `board-reg` without hardware (needs socat):
  * ./sbt "Test/runMain moire.stream.FakeBoardDemo 60"  then, in another shell, the printed commands.
  * Streams 500 records/s (D 80000 at 40 MHz) of the simulated signal for the given seconds (default 60).
  */
object FakeBoardDemo {
  def main(args: Array[String]): Unit = {
    val seconds = args.headOption.flatMap(_.toDoubleOption).getOrElse(60.0)
    if (PtyPair.socat.isEmpty) { System.err.println("moire: socat is not installed (apt-get install socat)"); sys.exit(2) }
    val pty = PtyPair.open()
    val board = new FakeBoard(pty, FakeBoard.registers(), harmonicSlots = 4)
    try {
      val n = 8; val d = 80000L
      val recs = BoardStreamFixture.records((seconds * 500).toInt + n, d, 40e6)
      board.stream(recs.grouped(n).map(rs => Planned(rs)), StreamV1.recordFrameBytes(n) * 500 / n)
      println(s"fake board on ${pty.host} for $seconds s; try:")
      println(s"""  ./sbt "run board-reg --port ${pty.host}"""")
      println(s"""  ./sbt "run record --port ${pty.host} --seconds 5 --out rec.csv"""")
      Thread.sleep((seconds * 1000).toLong)
    } finally { board.close(); pty.close() }
  }
}
