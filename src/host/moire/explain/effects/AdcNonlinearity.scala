package moire.explain.effects

import moire.explain._

/** Integral nonlinearity of the ADCs: a bow (T2) and an S shape (T3) of the transfer curve, per channel or both. */
object AdcNonlinearity extends Effect {
  val name = "adc_nonlinearity"
  val params = Seq(Param("inl2_lsb", "LSB", "any"), Param("inl3_lsb", "LSB", "any"))
  override val needs: Seq[String] = params.map(_.name)
  val what = "INL = inl2 T2(v) + inl3 T3(v) LSB, Chebyshev bow and S shape over full scale (channel=sin|cos|both)"
  override val perChannel = true
  val shows = "against signal level"
  override val claims: Seq[String] = Seq("against fringe phase")
  override def example: Example = Example(EffectSpec(name, Map("inl2_lsb" -> 2.0, "inl3_lsb" -> 1.5)))
  val domain: Domain = Domain.Periodic
  override val plot: PlotKind = PlotKind.Level

  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(terms = sp.terms :+ Term.Inl(e.channel))
  override def searches(c: Candidates): Seq[() => Seq[Cand]] =
    Seq(() => Seq("both", "sin", "cos").flatMap(ch => c.linear(Term.Inl(ch)).map(_._1)))
  override def describe(t: Term, b: Array[Double], sd: Array[Double], e: SignalEngine): Effect.Described = {
    val ch = t match { case Term.Inl(c) => c; case _ => "both" }
    // one ADC's: how much its channel's amplitude changes over the record (what tells it from a harmonic)
    val range = if (ch == "both") Map.empty[String, Double] else Map("amplitude_range_rel" -> amplitudeRange(e, ch))
    (Map("inl2_lsb" -> b(0), "inl3_lsb" -> b(1)) ++ range, Map("inl2_lsb" -> sd(0), "inl3_lsb" -> sd(1)) ++ range.map(_._1 -> 0.0),
      s"against signal level: ${if (ch == "both") "both ADCs" else s"the $ch ADC"}", ch)
  }
  private def amp(c: Cand, e: SignalEngine) = (math.abs(c.params.getOrElse("inl2_lsb", 0.0)) + math.abs(c.params.getOrElse("inl3_lsb", 0.0))) * e.lsb
  override def valueAmplitude(c: Cand, e: SignalEngine): Option[Double] = Some(amp(c, e))
  /** Relative change of a channel's amplitude over the record below which one ADC's bow or S shape and a 2nd or 3rd
    * harmonic on that channel predict the same signal (a harmonic scales with the amplitude, INL stays with the code).
    */
  val ConstantAmplitude = 0.05
  /** Parts of the record whose amplitudes are compared. */
  val Parts = 8

  /** The range of a channel's fitted amplitude over `Parts` contiguous parts of the record (the prediction's rms about
    * its mean, times the root of 2), relative to its mean.
    */
  def amplitudeRange(e: SignalEngine, ch: String): Double = {
    // the prediction read where it is needed (not an array of the record's length)
    val sin = ch == "sin"
    val m = e.n / Parts
    if (m < 16) return 0.0
    val a = (0 until Parts).map { k =>
      var s = 0.0; var q = 0.0; var i = k * m
      while (i < (k + 1) * m) { val p = if (sin) e.predSAt(i) else e.predCAt(i); s += p; q += p * p; i += 1 }
      math.sqrt(2 * math.max(0.0, q / m - (s / m) * (s / m)))
    }
    val mean = a.sum / Parts
    if (mean > 0) (a.max - a.min) / mean else 0.0
  }

  /** One ADC's bow or S shape at constant amplitude is a 2nd or 3rd harmonic on that channel: it stands back for it.
    * Where the amplitude changes, the two are told apart by the data (the harmonic does not replicate, INL does).
    */
  override def yieldsTo(c: Cand, other: Cand, e: SignalEngine): Boolean =
    (c.channel != "both" && other.effect == Harmonic.name && other.channel == c.channel &&
      amplitudeRange(e, c.channel) < ConstantAmplitude) ||
      // the same INL on both ADCs stands back for one ADC's that explains as much
      (c.channel == "both" && other.effect == name && other.channel != "both")
  override def lookAlikes(f: Finding, e: SignalEngine): Seq[String] =
    // one curve on both ADCs is as much the read head's amplifiers before them (a compression, a square law): both are a
    // function of the value (another generator's v - 0.05 v^3 on both channels was told as INL of both ADCs alone)
    if (f.channel == "both") Seq("a curve of the read head's amplifiers before both ADCs (a compression of the large values, a square " +
      "law) predicts the same signal: both are a function of the value; a test of the ADCs with a known input, or a record with " +
      "another gain between the amplifiers and the ADCs, separates them")
    else if (f.params.getOrElse("amplitude_range_rel", 0.0) >= ConstantAmplitude) Nil
    else Seq(s"${Harmonic.name} 2 and 3 on the ${f.channel} channel predict the same signal while its amplitude stays constant, as it " +
      s"does here; a record at another amplitude or offset of the ${f.channel} channel separates them (INL stays with the code)")

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    override val analog = false
    private def on(isSin: Boolean, k: String) = Forward.on(specs, isSin).map(_.p(k, 0.0)).sum
    private val (inl2S, inl3S, inl2C, inl3C) = (on(true, "inl2_lsb"), on(true, "inl3_lsb"), on(false, "inl2_lsb"), on(false, "inl3_lsb"))
    private val lsb = m.adc.lsb
    override def transfer(v: Double, isSin: Boolean): Double = {
      val inl2 = if (isSin) inl2S else inl2C; val inl3 = if (isSin) inl3S else inl3C
      if (inl2 != 0 || inl3 != 0) v + (inl2 * (2 * v * v - 1) + inl3 * (4 * v * v * v - 3 * v)) * lsb else v
    }
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String = {
    val r = p.getOrElse("amplitude_range_rel", 0.0)
    f"ADC integral nonlinearity${if (channel == "both") " (both ADCs)" else s" of the $channel ADC"}: bow ${Effect.g(p, "inl2_lsb")}%.2f LSB, S-shape ${Effect.g(p, "inl3_lsb")}%.2f LSB at full scale" +
      (if (r >= ConstantAmplitude) f"; not a harmonic on that channel: its amplitude changes by ${100 * r}%.0f %% over the record while this stays with the code" else "")
  }
}
