package moire.explain.effects

/** One channel at one sampling instant, as an effect's forward step sees it: sin or cos, time (s), fringe frequency
  * (Hz), true fringe phase (periods), travel since the start (periods) and the phase after the read-head low-pass.
  */
final case class At(isSin: Boolean, t: Double, f: Double, q: Double, x: Double, ph: Double)

/** Slow terms of one channel: gains (relative) and offsets (full scale) per unit of time (s), of travel (fringe
  * periods) and of the warm-up curve (1 - exp(-t / tau)). The model sums them over the effects.
  */
final case class Slow(gainT: Double = 0, gainX: Double = 0, gainW: Double = 0, offsetT: Double = 0, offsetX: Double = 0, offsetW: Double = 0) {
  def +(o: Slow): Slow = Slow(gainT + o.gainT, gainX + o.gainX, gainW + o.gainW, offsetT + o.offsetT, offsetX + o.offsetX, offsetW + o.offsetW)
}

/** An effect's forward step (`simulate`), built once from its EffectSpecs in a model (`Effect.forward`). The model
  * (PhysicsModel.generate) calls the hooks per sample in the order of the chain: sampling instants -> read angle and
  * fringe phase -> low-pass -> slow terms -> gain -> additive terms -> white noise -> front end -> ADC transfer ->
  * quantizer -> pins. Every hook leaves the signal as it is unless the effect overrides it.
  */
trait Forward {
  /** It changes the analog chain (false: its hooks up to `add` are not called, and without any such effect the model
    * keeps its plain path, the fringe as SignalSim makes it).
    */
  def analog: Boolean = true
  /** This sample's shift of both sampling instants (s); it draws its own noise, once per sample. */
  def timeShift(): Double = 0.0
  /** The cos channel's sampling delay after sin (s). */
  def cosDelay: Double = 0.0
  /** This sample's shift of the fringe phase on both channels (periods); it draws its own noise, once per sample. */
  def phaseShift(): Double = 0.0
  /** Read-angle errors of the mechanical angle: (order, amplitude in turns, phase in degrees). */
  def angleErrors: Seq[(Int, Double, Double)] = Nil
  /** Low-pass cutoffs (Hz) of a channel's read head. */
  def cutoffs(isSin: Boolean): Seq[Double] = Nil
  /** Slow gain and offset terms of a channel. */
  def slow(isSin: Boolean): Slow = Slow()
  /** The warm-up time constant (s) when it has a warm-up curve. */
  def warmupTau: Option[Double] = None
  /** The signal (offset removed) times its gain terms. */
  def gain(v: Double, a: At): Double = v
  /** The signal with its additive terms. */
  def add(v: Double, a: At): Double = v
  /** The analog front end before the ADC (full scale). */
  def frontEnd(v: Double, isSin: Boolean): Double = v
  /** The ADC's transfer function (its nonlinearity) before quantization. */
  def transfer(v: Double, isSin: Boolean): Double = v
  /** A quantizer replacing the ADC's own: full scale -> pin code. */
  def quantizer: Option[Double => Int] = None
  /** The pin code as read (data line faults). */
  def pins(code: Int, isSin: Boolean): Int = code
}

object Forward {
  /** No forward step (calibration effects, effects absent from a model). */
  val none: Forward = new Forward { override val analog = false }

  /** The specs on a channel: theirs, or both. */
  def on(specs: Seq[moire.explain.EffectSpec], isSin: Boolean): Seq[moire.explain.EffectSpec] =
    specs.filter(e => e.channel == "both" || (e.channel == "sin") == isSin)
}
