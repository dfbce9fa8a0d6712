package moire.explain.effects

import moire.explain._

/** One parameter of an effect: its name (the unit in the name), unit and the range it takes. */
final case class Param(name: String, unit: String, range: String)

/** A clearly visible instance of an effect for the registry's forward and backward test: the effect, the motion
  * (`simulate --motion`), lines per revolution when it needs them.
  */
final case class Example(effect: EffectSpec, motion: String = "ramp:20000:200000:0.01", linesPerRev: Option[Double] = None)

/** The axis an effect shows against. It decides the replication splits: each part must cover the effect's whole domain. */
sealed trait Domain
object Domain {
  /** The fringe phase or the mechanical angle: interleaved parts, each covering the whole period. */
  case object Periodic extends Domain
  /** Time (and position along a scan): contiguous parts. */
  case object Time extends Domain
  /** Time from the record's start, where a settling has not yet settled: interleaved blocks, each covering the settling
    * (contiguous halves left the second half its tail alone, where an offset's settling is hardly told from the offset
    * itself: `simulate`'s own warm-up of the offsets with 25 ms in 100 ms did not replicate, 0.0096 against 0.0050).
    */
  case object Settling extends Domain
  /** Speed: interleaved blocks, each spanning the speed range. */
  case object Speed extends Domain
  /** Position along the travel, with local structure (a band): alternate fringe periods, each part covering the travel. */
  case object Position extends Domain
  /** The code histogram: a repair of the data, not refitted on parts. */
  case object Codes extends Domain
}

/** The plot of a finding: the residual before and after against the effect's natural axis. */
sealed trait PlotKind
object PlotKind {
  case object FringePhase extends PlotKind
  /** Phase (and amplitude, unless `phaseOnly`) left in the residual against the fringe frequency. */
  final case class Speed(phaseOnly: Boolean) extends PlotKind
  case object Slope extends PlotKind
  case object Time extends PlotKind
  case object Position extends PlotKind
  case object MechanicalAngle extends PlotKind
  case object Level extends PlotKind
  /** Residual rms against the signal's value less its offset (noise that scales with the signal). */
  case object SignalValue extends PlotKind
  case object Spectrum extends PlotKind
  case object None extends PlotKind
}

/** A physical effect of the measurement chain, in one file like an lmfit Model: its name and parameters, how it is
  * given to the backward model, its backward fit (the searches that propose it), where it shows and how it is split
  * for replication, its look-alikes, its text and its plot. `Effects.all` lists them; the engine knows none by name.
  */
trait Effect {
  def name: String
  def params: Seq[Param]
  /** What it is (the catalogue's words). */
  def what: String
  /** Where it shows in a residual (the located departure it must reduce). */
  def shows: String
  /** The located departures (`Locate`, by the start of their `where`) it must reduce; empty when none measures it. */
  def claims: Seq[String] = Nil
  /** Calibration data (moire-calibration v1) rather than signals. */
  def calibration: Boolean = false
  def domain: Domain
  /** The domain of one of its linear terms (an effect may have a smooth and a local form). */
  def domainOf(t: Term): Domain = domain
  /** Cycles of its domain the record covers (periodic effects: fringe periods travelled; mechanical ones: turns). */
  def cycles(e: SignalEngine): Double = e.travelPeriods
  def plot: PlotKind = PlotKind.FringePhase
  /** A free trajectory over a few fringe periods can share its shape (not identifiable without a reference). */
  def confoundedWithMotion: Boolean = true
  /** Its evidence is direct (a pile-up at one code, which no smooth effect makes): it is tried before the others. */
  def direct: Boolean = false
  /** Simulation only: explain does not search for it (it is reported from the codes, or not at all). */
  def searched: Boolean = true

  /** A clearly visible instance (simulated, then explained, by the registry's test). */
  def example: Example
  /** What explain needs beyond a plain recording to find it (a reference, calibration data); None: a recording will do. */
  def backwardNeeds: Option[String] = None

  /** Keys of which the forward step needs one: without any it changes nothing (`simulate` refuses it). Empty: its
    * defaults act, or `validate` says what it needs.
    */
  def needs: Seq[String] = Nil
  /** Why its parameters make no sense whatever the model (a range, a whole number, two keys that clash), or None.
    * `EffectSpec.parse` calls it: `--effect` and a model file's effects alike.
    */
  def check(e: EffectSpec): Option[String] = None
  /** Checks of a simulated effect's parameters (one line, `ExplainError`). */
  def validate(e: EffectSpec, m: PhysicsModel): Unit = ()
  /** The backward model with this effect (from `explain --model`). */
  def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp
  /** The backward fit: one step per proposal (the progress bar counts them); each gives its candidates. */
  def searches(c: Candidates): Seq[() => Seq[Cand]] = Nil
  /** Readable parameters of a linear term: coefficients b after the six default columns, their sd. */
  def describe(t: Term, b: Array[Double], sd: Array[Double], e: SignalEngine): Effect.Described =
    (Map.empty, Map.empty, "", "both")
  /** The finding's parameters from the final fit, for effects that are not linear terms. */
  def refresh(f: Finding, e: SignalEngine): Finding = f
  /** Why the record cannot support the fitted parameters (physics, with the estimate's uncertainty), or None. */
  def unsupported(c: Cand, e: SignalEngine, fMin: Double, fMax: Double): Option[String] = None
  /** Its largest size as a function of the signal value (full scale), when it is one (quantization can make those). */
  def valueAmplitude(c: Cand, e: SignalEngine): Option[Double] = None
  /** Its size in the signal (full scale) when it is not a change of the prediction (jitter: added noise); NaN: the
    * 99th percentile of the change of the prediction it makes (`Materiality.size`).
    */
  def size(c: Cand, e: SignalEngine): Double = Double.NaN
  /** Alternatives that can predict the same signal in this record, with the measurement that separates them. */
  def lookAlikes(f: Finding, e: SignalEngine): Seq[String] = Nil
  /** True when candidate `c` (of this effect) predicts the same signal as `other` and stands back for it when their
    * evidence is within the threshold (the simpler, more common explanation goes first; the finding names this one).
    */
  def yieldsTo(c: Cand, other: Cand): Boolean = false
  /** `yieldsTo` where the record decides (whether it can tell the two apart). */
  def yieldsTo(c: Cand, other: Cand, e: SignalEngine): Boolean = yieldsTo(c, other)
  /** One plain sentence for a finding. */
  /** Harmonics it adds to the simulated fringe (the model's SignalParams), from its specs in the model. */
  def harmonics(specs: Seq[EffectSpec]): Seq[moire.signal.Harmonic] = Nil
  /** Its forward step (`simulate`) in model `m` with fringe `p`, from its specs there (never empty). */
  def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = Forward.none

  /** True when it may act on one channel (channel=sin|cos); others act on both (or name each channel in their keys). */
  def perChannel: Boolean = false
  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String

  def sinCos(ch: String): String = if (ch == "both") "both channels" else s"the $ch channel"
}

object Effect {
  /** `x` (below `limit`) to two decimals, or to as many more as show it below: 0.4996 is not "0.50, below 0.5". */
  def below(x: Double, limit: Double): String =
    (2 to 6).map(d => s"%.${d}f".formatLocal(java.util.Locale.ROOT, x)).find(_.toDouble < limit).getOrElse(x.toString)

  type Described = (Map[String, Double], Map[String, Double], String, String)

  /** Amplitude and its sd of b0 cos + b1 sin. */
  def amp(b0: Double, b1: Double, s0: Double, s1: Double): (Double, Double) = {
    val a = math.hypot(b0, b1)
    (a, if (a > 0) math.sqrt(b0 * b0 * s0 * s0 + b1 * b1 * s1 * s1) / a else math.hypot(s0, s1))
  }
  def deg(b0: Double, b1: Double, a: Double, sa: Double): (Double, Double) =
    (math.toDegrees(math.atan2(b1, b0)), if (a > 0) math.toDegrees(sa / a) else 180.0)
  def g(p: Map[String, Double], k: String): Double = p.getOrElse(k, Double.NaN)

  /** Why `key` of `e`, when given, is not from `lo` to `hi` (a whole number when `whole`), saying `range`; or None. */
  def within(e: EffectSpec, key: String, lo: Double, hi: Double, range: String, whole: Boolean = false): Option[String] =
    e.params.get(key).filter(v => !(v >= lo && v <= hi) || (whole && v != math.rint(v))).map(v => s"$key must be $range, got ${show(v)}")
  /** A parameter's value as it was most likely typed (3, not 3.0). */
  def show(v: Double): String = if (v == math.rint(v) && math.abs(v) < 1e15) v.toLong.toString else v.toString
}
