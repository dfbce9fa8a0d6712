package moire.signal

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

class SignalSimSpec extends AnyFlatSpec with Matchers {
  "Adc" should "code both AD9226 formats as the data sheet table says" in {
    val ob = Adc(12, AdcFormat.OffsetBinary); val tc = Adc(12, AdcFormat.TwosComplement)
    ob.sample(-1.5) shouldBe AdcSample(0x000, true)
    ob.sample(0.0) shouldBe AdcSample(0x800, false)
    ob.sample(1.0) shouldBe AdcSample(0xfff, true)
    tc.sample(-1.0) shouldBe AdcSample(0x800, false)
    tc.sample(0.0) shouldBe AdcSample(0x000, false)
    tc.sample(1.0 - 1.0 / 2048) shouldBe AdcSample(0x7ff, false)
    for (v <- Seq(-1.0, -0.3, 0.0, 0.7, 0.999)) {
      ob.fromPins(ob.sample(v).code) shouldBe tc.fromPins(tc.sample(v).code)
      (ob.sample(v).code ^ 0x800) shouldBe tc.sample(v).code // binary to two's complement: invert the MSB
    }
  }

  "SignalSim" should "give clean quadrature signals whose atan2 is the true phase within quantization" in {
    val s = SignalSim.generate(SignalParams(), Motion.Constant(100e3), Adc(12), 50e6, 2000)
    val worst = (0 until s.length).map { i =>
      val ph = math.atan2(s.sinSigned(i).toDouble, s.cosSigned(i).toDouble) / (2 * math.Pi)
      val d = ph - s.truePeriods(i); math.abs(d - math.rint(d))
    }.max
    val a = 0.9 * 2048 // amplitude in LSB
    worst should be < 2.0 / (2 * math.Pi * a)
    // Rounding both codes gives a phase error of sigma = 1/(sqrt(12) a) rad; of 2000 samples about 4.5 %
    // lie beyond 2 sigma = 0.58/a, so the worst is above 0.5/a unless the ADC model stopped quantizing.
    worst should be > 0.5 / (2 * math.Pi * a)
  }

  it should "apply offset, gain and phase error as stated" in {
    val p = SignalParams(amplitude = 0.5, offsetSin = 0.02, gainCos = 1.03, phaseErrorDeg = 5)
    val (s0, c0) = SignalSim.analog(p, 0.0)
    s0 shouldBe 0.02 +- 1e-12
    c0 shouldBe 0.5 * 1.03 * math.cos(math.toRadians(5)) +- 1e-12
  }

  "Motion" should "reverse in Oscillate and integrate frequency in Ramp" in {
    val o = Motion.Oscillate(3.0, 10.0)
    val peak = 3.0 * 2 * math.Pi * 10.0 // periods/s at the centre: peak * omega
    o.frequency(0.0) shouldBe peak +- 1e-9
    o.frequency(0.05) shouldBe -peak +- 1e-9
    o.periods(0.025) shouldBe 3.0 +- 1e-12
    val r = Motion.Ramp(0.0, 1000.0, 1.0)
    r.periods(1.0) shouldBe 500.0 +- 1e-9
    r.periods(2.0) shouldBe 1500.0 +- 1e-9
  }
}
