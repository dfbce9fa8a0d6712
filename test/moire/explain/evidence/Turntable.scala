package moire.explain.evidence

/** A magnetic rotary encoder with one signal period per turn on a turntable, read beside a reference encoder that
  * writes `ref_deg` (quantized to refBits per turn, wrapped to 0 .. 360): by default 1000 samples over about one
  * turn at uneven speed. The magnet's eccentricity gives a 2nd harmonic of the angle, on average `h2` of the
  * fundamental: (1 + h2Split) h2 on sin and (1 - h2Split) h2 on cos, 30 degree apart (phase and amplitude modulation
  * mix differently on the two field components); a non-sinusoidal magnet adds `h3`. The reference encoder is read
  * `refDelayS` late and has its own eccentricity error of `refEccArcsec` once per turn.
  */
object Turntable {
  final case class Spec(n: Int = 1000, fs: Double = 1000, turnsPerS: Double = 1.0, unevenRel: Double = 0.06, unevenHz: Double = 1.7,
                        h2: Double = 0.0, h2Deg: Double = 40, h2Split: Double = 0.15, h3: Double = 0.0, bits: Int = 12, noiseLsb: Double = 1.5, refBits: Int = 12,
                        refDelayS: Double = 0.4e-3, refEccArcsec: Double = 25, withRef: Boolean = true, seed: Long = 1) {
    def bench: Bench = Bench(amp = 0.75, offS = 0.018, offC = -0.011, gainC = 0.985, quadDeg = 1.3, noiseLsb = noiseLsb, bits = bits,
      harmonics = (if (h2 > 0) Seq(Harmonic(2, h2 * (1 + h2Split), h2Deg, "sin"), Harmonic(2, h2 * (1 - h2Split), h2Deg + 30, "cos")) else Nil) ++
        (if (h3 > 0) Seq(Harmonic(3, h3, 10)) else Nil), seed = seed)
  }

  def text(s: Spec): String = {
    val tr = Motions.turntable(s.n, s.fs, s.turnsPerS, s.unevenRel, s.unevenHz)
    val q = 360.0 / (1 << s.refBits)
    val late = Motions.turntable(s.n, s.fs, s.turnsPerS, s.unevenRel, s.unevenHz, delayS = s.refDelayS)
    val ref = late.periods.map { turns =>
      val deg = turns * 360 + s.refEccArcsec / 3600 * math.sin(2 * math.Pi * turns + 1.1)
      val r = math.floor(deg / q) * q; r - 360 * math.floor(r / 360)
    }
    BenchText("turntable (magnetic encoder, one period per turn)", s.fs, s.bits, s.bench.codes(tr, s.fs),
      Seq("adc" -> "magnetic angle sensor"), if (s.withRef) "ref_deg" else "", ref, 5)
  }
}
