package moire.recording

import moire.signal.AdcFormat

/** Codes written in the other ADC format than the file says (or than the default, offset binary). */
object FormatCheck {
  /** Why the codes look written in the other ADC format, or None. Read in the wrong one (offset binary for two's
    * complement or the reverse: the MSB inverted), a signal jumps by nearly the full range where it crosses zero, twice a
    * fringe period; read in its own it does not. Jumps of more than 3/4 of the range between neighbouring samples
    * are counted both ways: many in the file's format and few in the other is that mistake (a fit would take the
    * jumps for harmonics of some 200 % of the fundamental). A stuck or glitching MSB jumps by half the range only, and
    * a clipped fringe (more than 1 % of a channel's samples held at a rail from the sample before) jumps where it slews.
    */
  def mismatch(rec: Recording): Option[String] = {
    val adc = rec.adc; val half = adc.half; val limit = 3 * half / 2
    // (jumps read in the file's format, jumps read in the other) in one pass over a channel
    def jumps(codes: Array[Int]): (Int, Int) = if (codes.isEmpty) (0, 0) else {
      def flip(x: Int) = if (x < 0) x + half else x - half
      var k = 0; var j = 0; var i = 1; var prev = adc.fromPins(codes(0))
      while (i < codes.length) {
        val x = adc.fromPins(codes(i))
        if (math.abs(x - prev) > limit) k += 1
        if (math.abs(flip(x) - flip(prev)) > limit) j += 1
        prev = x; i += 1
      }
      (k, j)
    }
    // an overdriven fast fringe slews by most of the range a sample too, between runs of samples held at a rail (a
    // misread zero crossing may land on a rail code, but not for two samples running)
    def clipped(codes: Array[Int]): Boolean = {
      var k = 0; var i = 1
      while (i < codes.length) { val x = adc.fromPins(codes(i)); if ((x == -half || x == half - 1) && codes(i) == codes(i - 1)) k += 1; i += 1 }
      k > codes.length / 100
    }
    val (s1, s2) = jumps(rec.sin); val (c1, c2) = jumps(rec.cos)
    val own = s1 + c1; val other = s2 + c2
    if (own < 8 || other * 10 > own || clipped(rec.sin) || clipped(rec.cos)) None
    else {
      val is = adc.format.name
      val alt = AdcFormat.all.find(_ != adc.format).get.name
      val stated = rec.meta.contains("adc_format") || rec.meta.get("adc").exists(a => AdcFormat.parse(a).isRight)
      Some(s"the codes look $alt, not $is as read (${if (stated) "the file's adc_format" else "no adc_format line: the default"}): " +
        s"read as $is they jump by more than 3/4 of the ADC's range between neighbouring samples $own times, as $alt " +
        s"$other times; ${if (stated) "correct" else "add"} the line '# adc_format: $alt' before the header")
    }
  }
}
