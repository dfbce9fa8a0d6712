package moire.subdiv

import org.scalatest.flatspec.AnyFlatSpec

class SubdivParamsSpec extends AnyFlatSpec {
  def msg(f: => SubdivParams): String = intercept[IllegalArgumentException](f).getMessage

  "SubdivParams" should "reject out-of-range settings with a message naming the parameter" in {
    assert(msg(SubdivParams(counts = 3)).contains("counts (M) must be a power of two in 4..65536, got 3"))
    assert(msg(SubdivParams(counts = 131072)).contains("counts (M)"))
    assert(msg(SubdivParams(inputBits = 20)).contains("input-bits must be in 4..16"))
    assert(msg(SubdivParams(cordicWidth = 12)).contains("cordic-width must be in 13..40"))
    assert(msg(SubdivParams(counts = 65536, phaseBits = 12)).contains("phase-bits must be in 16..40"))
    assert(msg(SubdivParams(counts = 1024, positionWidth = 11)).contains("position-width must be in 12..62"))
    assert(msg(SubdivParams(minEdgeClocks = 0)).contains("min-edge-clocks"))
    assert(msg(SubdivParams(backlogLimit = 0)).contains("backlog-limit"))
    assert(msg(SubdivParams(presentThreshold = 1.0)).contains("present-threshold"))
    assert(msg(SubdivParams(asinAmplitude = 0.1)).contains("asin-amplitude"))
    assert(msg(SubdivParams(maxStepTurns = 0.6)).contains("max-step-turns"))
    assert(msg(SubdivParams(iterations = 2)).contains("iterations must be in 4..40"))
  }

  it should "derive latency, phase width and names from the parameters" in {
    val a = SubdivParams()
    assert(a.latency == a.cordic.latency + 3 && a.angleBits == 18 && a.countBits == 10)
    assert(SubdivParams(counts = 65536).angleBits == 18 && SubdivParams(inputBits = 14, counts = 65536).angleBits == 20)
    assert(a.moduleName != SubdivParams(counts = 2048).moduleName)
    assert(a.moduleName != SubdivParams(method = PhaseMethod.AsinDouble).moduleName)
    assert(PhaseMethod.parse("asin").isLeft && PhaseMethod.parse("atan2") == Right(PhaseMethod.Atan2))
  }
}
