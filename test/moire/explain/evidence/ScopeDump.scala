package moire.explain.evidence

/** An oscilloscope dump: two 8-bit channels, the signals filling 60-90 % of the screen, a probe's offsets,
  * the scope's own noise of a fraction of an LSB and its 8-bit codes.
  */
object ScopeDump {
  def text(travel: Travel, fs: Double, amp: Double, noiseLsb: Double, seed: Long): String = {
    val b = Bench(amp = amp, offS = 0.03, offC = -0.045, gainC = 0.96, quadDeg = 2.5, noiseLsb = noiseLsb, bits = 8, seed = seed)
    BenchText("scope dump (8-bit, CH1 = sin, CH2 = cos)", fs, 8, b.codes(travel, fs), Seq("adc" -> "oscilloscope 8 bit"))
  }
}
