package moire.stream

/** Prints how fast the decoder runs (MB/s and records/s), to compare with the UART rate:
  * ./sbt "Test/runMain moire.stream.DecoderBench"
  */
object DecoderBench {
  def main(args: Array[String]): Unit = {
    val n = 8
    val recs = BoardStreamFixture.records(n * 20000, 1000, 50e6)
    val bytes = Encoder.frames(recs.grouped(n).zipWithIndex.map { case (rs, k) => RecordFrame(k & 0xFFFF, 0, rs) }.toSeq)
    for (round <- 0 until 3) {
      val d = new Decoder(1000)
      val t0 = System.nanoTime
      var at = 0
      while (at < bytes.length) { val c = math.min(4096, bytes.length - at); d.feed(bytes, at, c); at += c }
      d.finish()
      val dt = (System.nanoTime - t0) / 1e9
      require(d.stats.records == recs.size && !d.stats.lost, s"decoder lost records: ${d.stats}")
      if (round == 2) println(f"decoder: ${bytes.length / dt / 1e6}%.1f MB/s, ${recs.size / dt / 1e6}%.2f M records/s " +
        f"(${bytes.length} bytes in 4096-byte chunks, $dt%.3f s); 115200 baud is 0.0115 MB/s")
    }
  }
}
