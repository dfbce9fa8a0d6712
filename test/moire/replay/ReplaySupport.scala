package moire.replay

import moire.cordic.Rounding
import moire.recording.Recording
import moire.signal.{Adc, AdcFormat, Samples}
import moire.subdiv.{PhaseMethod, SubdivParams, SubdivStimulus}

/** Shared by the replay tests: one cache folder (builds survive between runs), the configurations, stimulus. */
object ReplaySupport {
  val cache: os.Path = os.pwd / "target" / "replay-test-cache"
  System.setProperty("moire.replay.cache", cache.toString)
  def init(): Unit = ()

  /** The sweep: method, M, ADC format, widths (1-, 2-, 4- and 8-byte output ports). */
  val configs: Seq[ReplayDesign.Subdiv] = Seq(
    ReplayDesign.Subdiv(SubdivParams(12, PhaseMethod.Atan2, counts = 4, backlogLimit = 4), AdcFormat.OffsetBinary),
    ReplayDesign.Subdiv(SubdivParams(10, PhaseMethod.AsinDouble, counts = 256, minEdgeClocks = 3, backlogLimit = 16), AdcFormat.TwosComplement),
    ReplayDesign.Subdiv(SubdivParams(14, PhaseMethod.Atan2, counts = 65536, positionWidth = 40, rounding = Rounding.Truncate), AdcFormat.OffsetBinary))
  /** The first configuration as emit-subdiv options (the recording's metadata gives bits, format and M). */
  val firstOpts: Seq[String] = Seq("--backlog-limit", "4")

  /** The subdivider test stimulus (reversals, over-range, low amplitude, steps beyond the limit), every sample valid. */
  def stimulus(adc: Adc, scale: Int, seed: Long): PinStream = {
    val segs = SubdivStimulus.segments(adc, scale, seed)
    PinStream(segs.flatMap(_.sin).toArray, segs.flatMap(_.cos).toArray, segs.flatMap(_.otrSin).toArray, segs.flatMap(_.otrCos).toArray)
  }

  def recording(s: Samples, meta: Map[String, String], extra: Map[String, Array[Double]] = Map.empty): Recording =
    Recording(s.sampleRateHz, s.adc, s.sin, s.cos, meta, extra)

  def harness(d: ReplayDesign): Harness = VerilatorBuild.harness(d.verilog(), d.topName, cache)
}
