package moire.board

import moire.signal.{Adc, AdcFormat, Motion, SignalParams, SignalSim}

/** Behavioural AD9226: on each rising edge of its own clock it samples the analog sin/cos of the
  * motion (moire.signal) and, 7 edges later, drives that sample's codes and OTR on its pins
  * (the pins change after the edge, tOD). Before the 7th edge the pins carry garbage.
  *
  * @param sampleRateHz the ADC clock rate: edge i samples the signal at t = i / sampleRateHz
  */
final class Ad9226Model(val adc: Adc, signal: SignalParams, motion: Motion, sampleRateHz: Double, val latency: Int = 7) {
  final case class Sample(sin: Int, otrSin: Boolean, cos: Int, otrCos: Boolean, truePeriods: Double)
  private val taken = scala.collection.mutable.ArrayBuffer.empty[Sample]
  private val garbage = Sample(0xA5C & ((1 << adc.bits) - 1), otrSin = true, 0x3C3 & ((1 << adc.bits) - 1), otrCos = true, 0.0)
  /** The word on the pins now. */
  var pins: Sample = garbage

  def edges: Int = taken.size
  def sample(i: Int): Sample = taken(i)

  /** One rising ADC clock edge: sample, then move the pipeline (the pins show sample edges - 7). */
  def edge(): Sample = {
    val t = taken.size / sampleRateHz
    val ph = motion.periods(t)
    val (s, c) = SignalSim.analog(signal, ph)
    val a = adc.sample(s); val b = adc.sample(c)
    taken += Sample(a.code, a.otr, b.code, b.otr, ph)
    pins = if (taken.size > latency) taken(taken.size - 1 - latency) else garbage
    pins
  }
}

object Ad9226Model {
  def apply(format: AdcFormat, signal: SignalParams, motion: Motion, sampleRateHz: Double): Ad9226Model =
    new Ad9226Model(Adc(12, format), signal, motion, sampleRateHz)
}
