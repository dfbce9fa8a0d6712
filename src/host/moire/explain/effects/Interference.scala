package moire.explain.effects

import moire.explain._

/** A fixed-frequency pickup (mains, switching supply) on both channels. */
object Interference extends Effect {
  val name = "interference"
  val params = Seq(Param("frequency_hz", "Hz", "1e-6..1e12"), Param("amplitude_fs", "full scale", "0..1"), Param("phase_deg", "degree", "-180..180"))
  override val needs: Seq[String] = Seq("amplitude_fs")
  override def validate(e: EffectSpec, m: PhysicsModel): Unit =
    if (!e.params.contains("frequency_hz")) throw new ExplainError(s"$name needs frequency_hz (the line's frequency in Hz)")
  override def check(e: EffectSpec): Option[String] =
    Effect.within(e, "frequency_hz", 1e-6, 1e12, "from 1e-6 Hz to 1e12 Hz").orElse(Effect.within(e, "amplitude_fs", 0, 1, "from 0 to 1 full scale"))
  val what = "a fixed-frequency pickup (mains, switching supply) on both channels"
  val shows = "a spectral line"
  override val claims: Seq[String] = Seq("spectrum")
  override def example: Example = Example(EffectSpec(name, Map("frequency_hz" -> 12345.0, "amplitude_fs" -> 0.0015)))
  val domain: Domain = Domain.Time
  override val plot: PlotKind = PlotKind.Spectrum
  /** A line must complete this many cycles in the record to be told from a slow change (judged with its uncertainty and
    * the record's resolution of half a cycle).
    */
  val MinCycles = 10.0
  /** A record resolves a line's cycle count to about one cycle (its Fourier resolution is 1 / duration): half of it. */
  val Resolution = 0.5
  /** Standard deviations by which the cycle count must fall short of `MinCycles` to refuse the line. */
  val Sd = 3.0

  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(terms = sp.terms :+ Term.Interference(e.p("frequency_hz", 50)))
  override def searches(c: Candidates): Seq[() => Seq[Cand]] = Seq(() => c.interference().toSeq)
  override def describe(t: Term, b: Array[Double], sd: Array[Double], e: SignalEngine): Effect.Described = {
    val hz = t match { case Term.Interference(h) => h; case _ => Double.NaN }
    val (a, sa) = Effect.amp(b(0), b(1), sd(0), sd(1)); val (c, sc) = Effect.amp(b(2), b(3), sd(2), sd(3))
    // Cramer-Rao bound of a sinusoid's frequency in white noise, both channels' power together (the noise variance
    // from the amplitude's sd: sd^2 = 2 v / n for a unit sinusoid over n samples)
    val v = 0.25 * (sd(0) * sd(0) + sd(1) * sd(1) + sd(2) * sd(2) + sd(3) * sd(3)) * e.n / 2
    val n = e.n.toDouble
    val sdF = e.fs / (2 * math.Pi) * math.sqrt(24 * v / math.max(1e-300, (a * a + c * c) * n * n * n))
    (Map("frequency_hz" -> hz, "amplitude_sin_fs" -> a, "amplitude_cos_fs" -> c, "amplitude_fs" -> 0.5 * (a + c)),
      Map("frequency_hz" -> sdF, "amplitude_sin_fs" -> sa, "amplitude_cos_fs" -> sc, "amplitude_fs" -> 0.5 * math.hypot(sa, sc)),
      f"spectrum: a line at $hz%.1f Hz on both channels", "both")
  }
  override def unsupported(c: Cand, e: SignalEngine, fMin: Double, fMax: Double): Option[String] = {
    val seconds = e.n / e.fs
    tooFewCycles(c.params.getOrElse("frequency_hz", Double.NaN), c.unc.getOrElse("frequency_hz", 0.0), seconds)
  }

  /** A line of `hz` +- `sdHz` in a record of `seconds`: refused when its cycle count is short of `MinCycles` by more than
    * `Sd` of its own uncertainty and the record's `Resolution` (9.996 +- 0.001 cycles is not fewer than 10).
    */
  def tooFewCycles(hz: Double, sdHz: Double, seconds: Double): Option[String] = {
    val cycles = hz * seconds; val sd = math.abs(sdHz) * seconds
    if (cycles + Sd * sd + Resolution >= MinCycles) None
    else Some(f"a line at $hz%.4g Hz completes ${cycles}%.3g +- ${sd}%.2g cycles in the ${seconds}%.3g s record (at least ${MinCycles}%.0f needed)")
  }

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    private val amp = specs.map(_.p("amplitude_fs", 0.0)).toArray; private val hz = specs.map(_.p("frequency_hz", 0.0)).toArray
    private val phase = specs.map(_.p("phase_deg", 0.0)).toArray
    override def add(v0: Double, a: At): Double = {
      var v = v0; var i = 0
      while (i < amp.length) { v += amp(i) * math.sin(2 * math.Pi * hz(i) * a.t + math.toRadians(phase(i))); i += 1 }
      v
    }
  }

  /** The Gauss-Newton step of a line's frequency (Hz) from the residual, and the frequency's uncertainty: the line's
    * derivative by its frequency at time from the record's middle (orthogonal to its own sin and cos), each channel
    * weighted by its noise variance.
    */
  def frequencyStep(e: SignalEngine, hz: Double, b: Array[Double]): (Double, Double) = {
    val w = 2 * math.Pi * hz / e.fs; val mid = 0.5 * (e.n - 1); val vS = e.noise.varS; val vC = e.noise.varC
    val m = Par.sums(e.n, 2) { (lo, hi, o) =>
      var s = math.sin(w * lo); var c = math.cos(w * lo); val sw = math.sin(w); val cw = math.cos(w)
      var num = 0.0; var den = 0.0; var i = lo
      while (i < hi) {
        val tt = 2 * math.Pi * (i - mid) / e.fs
        val gs = tt * (b(0) * c - b(1) * s); val gc = tt * (b(2) * c - b(3) * s)
        num += e.resS(i) * gs / vS + e.resC(i) * gc / vC; den += gs * gs / vS + gc * gc / vC
        val s1 = s * cw + c * sw; c = c * cw - s * sw; s = s1; i += 1
      }
      o(0) += num; o(1) += den
    }
    if (m(1) > 0) (m(0) / m(1), 1 / math.sqrt(m(1))) else (0.0, Double.PositiveInfinity)
  }

  /** A line at a harmonic's order times a fringe frequency of the record stands back for that harmonic when the two
    * predict about the same signal (at one speed they are one signal): the fringe's own shape needs no pickup that
    * happens to sit at a multiple of the fringe frequency.
    */
  override def yieldsTo(c: Cand, other: Cand, e: SignalEngine): Boolean = other.effect == Harmonic.name && {
    val hz = c.params.getOrElse("frequency_hz", Double.NaN); val k = other.params.getOrElse("order", Double.NaN)
    val (lo, hi) = e.speedRange
    hz >= k * lo * (1 - SameLine) && hz <= k * hi * (1 + SameLine)
  }
  /** Relative distance of a line from a harmonic's frequencies within which it is taken as at them. */
  val SameLine = 0.01

  /** The candidate with its line's frequency where the fit moved it (`SignalExplain.retune`). */
  def at(c: Cand, hz: Double): Cand = c.copy(params = c.params + ("frequency_hz" -> hz))

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String =
    f"pickup at ${hz(Effect.g(p, "frequency_hz"))}, ${Effect.g(p, "amplitude_fs")}%.3g full scale amplitude"

  /** A frequency to 6 significant digits in Hz, kHz or MHz (21.0000 MHz, not 20999990.8 Hz: the line's frequency is
    * known to about 1e-6 of itself in a record of 10^5 samples).
    */
  def hz(x: Double): String = if (x.isNaN || x.isInfinite) s"$x Hz" else {
    val (v, u) = if (math.abs(x) >= 1e6) (x / 1e6, "MHz") else if (math.abs(x) >= 1e3) (x / 1e3, "kHz") else (x, "Hz")
    s"${new java.math.BigDecimal(v).round(new java.math.MathContext(6)).toPlainString} $u"
  }
}
