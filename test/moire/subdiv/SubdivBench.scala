package moire.subdiv

import moire.signal._

/** Prints how fast the model runs (samples per second), for sizing long replays:
  * ./sbt "Test/runMain moire.subdiv.SubdivBench"
  */
object SubdivBench {
  def main(args: Array[String]): Unit = {
    val n = 1 << 20
    val s = SignalSim.generate(SubdivAccuracy.imperfect, Motion.Oscillate(40, 500), Adc(12), 50e6, n)
    for (method <- PhaseMethod.all; round <- 0 until 2) {
      val m = new SubdivModel(SubdivParams(method = method, counts = 4096))
      val t0 = System.nanoTime
      var i = 0; var sink = 0L
      while (i < n) { sink ^= m.clock(Some(SubdivSample(s.sinSigned(i), s.cosSigned(i)))).backlog; i += 1 }
      val dt = (System.nanoTime - t0) / 1e9
      if (round == 1) println(f"${method.name}%-12s clock-level model: ${n / dt / 1e6}%.2f M samples/s ($n samples, ${dt}%.2f s; sink $sink)")
    }
  }
}
