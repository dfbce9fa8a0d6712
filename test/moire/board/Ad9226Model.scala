package moire.board

import moire.signal.{Adc, AdcFormat, Motion, SignalParams, SignalSim}

/** What the analog front end offers the two ADCs at clock edge i: sin and cos in full-scale units (each
  * already at its own sampling instant) and the true position in fringe periods.
  */
final case class AnalogSample(sin: Double, cos: Double, periods: Double)

/** Behavioural AD9226: on each rising edge of its own clock it samples the analog sin/cos and, 7 edges
  * later, drives that sample's codes and OTR on its pins (the pins change after the edge, tOD). Before the
  * 7th edge the pins carry garbage. `sinPins`/`cosPins` model faults on the data lines (a stuck bit).
  *
  * @param analog the front end at edge i (the edge samples at t = i / sample rate)
  */
final class Ad9226Model(val adc: Adc, analog: Int => AnalogSample, val latency: Int = 7,
                        sinPins: Int => Int = identity, cosPins: Int => Int = identity) {
  case class Sample(sin: Int, otrSin: Boolean, cos: Int, otrCos: Boolean, truePeriods: Double)
  private val taken = scala.collection.mutable.ArrayBuffer.empty[Sample]
  private val garbage = Sample(0xA5C & ((1 << adc.bits) - 1), otrSin = true, 0x3C3 & ((1 << adc.bits) - 1), otrCos = true, 0.0)
  /** The word on the pins now. */
  var pins: Sample = garbage

  def edges: Int = taken.size
  def sample(i: Int): Sample = taken(i)

  /** One rising ADC clock edge: sample, then move the pipeline (the pins show sample edges - 7). */
  def edge(): Sample = {
    val x = analog(taken.size)
    val a = adc.sample(x.sin); val b = adc.sample(x.cos)
    taken += Sample(sinPins(a.code), a.otr, cosPins(b.code), b.otr, x.periods)
    pins = if (taken.size > latency) taken(taken.size - 1 - latency) else garbage
    pins
  }
}

object Ad9226Model {
  /** Both channels from moire.signal's fringe model and a motion. */
  def apply(format: AdcFormat, signal: SignalParams, motion: Motion, sampleRateHz: Double): Ad9226Model =
    new Ad9226Model(Adc(12, format), i => {
      val ph = motion.periods(i / sampleRateHz)
      val (s, c) = SignalSim.analog(signal, ph)
      AnalogSample(s, c, ph)
    })
}
