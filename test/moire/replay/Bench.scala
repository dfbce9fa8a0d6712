package moire.replay

import chisel3._
import chiseltest._
import moire.signal.{Adc, AdcFormat, Motion, SignalSim}
import moire.subdiv.{SubdivAccuracy, SubdivAdc, SubdivParams}

/** Samples per second of (a) the Verilator replay harness, (b) chiseltest peek/poke of the same
  * design (SubdivAdc at the emit-subdiv defaults), (c) the clock-level Scala model; builds are timed apart.
  */
object Bench {
  /** Samples per second the issue asks of the harness on one core. */
  val Goal = 20e6

  /** `./sbt "Test/runMain moire.replay.Bench [--json FILE] [--samples N]"` */
  def main(args: Array[String]): Unit = {
    def opt(name: String) = args.sliding(2).collectFirst { case Array(`name`, v) => v }
    run(opt("--json"), opt("--samples").map(_.toInt).getOrElse(4000000))
  }

  def run(json: Option[String], samples: Int): Unit = {
    if (samples < 10000) throw new ReplayError(s"--samples must be at least 10000, got $samples")
    val p = SubdivParams(); val fmt = AdcFormat.OffsetBinary
    val d = ReplayDesign.Subdiv(p, fmt)
    val s = SignalSim.generate(SubdivAccuracy.imperfect, Motion.Oscillate(40, 500), Adc(p.inputBits, fmt), 50e6, samples)
    val pins = PinStream(s.sin, s.cos, s.otrSin, s.otrCos)
    def say(x: String): Unit = System.err.println(s"bench: $x")

    // (a) Verilator harness
    say(s"(a) Verilator harness, ${d.describe}")
    val h = ReplayCmd.build(d, say)
    val te = System.nanoTime()
    val o = Replay.run(h, d, pins)
    val endToEnd = (System.nanoTime() - te) / 1e9
    val check = ModelCheck.run(d, pins, o)
    say(check.text)
    if (!check.ok) throw new IllegalStateException(check.text)
    val vWall = samples / o.loopSeconds; val vCpu = samples / o.cpuSeconds

    // (b) chiseltest peek/poke, Verilator backend when installed
    val hasVerilator = try { VerilatorBuild.verilatorVersion; true } catch { case _: Exception => false }
    val ctCycles = math.min(samples, 200000)
    say(s"(b) chiseltest peek/poke (${if (hasVerilator) "verilator" else "treadle"} backend), $ctCycles cycles")
    val dir = os.temp.dir(prefix = "moire-bench-chiseltest")
    val annos = Seq(firrtl2.options.TargetDirAnnotation(dir.relativeTo(os.pwd).toString)) ++ (if (hasVerilator) Seq(VerilatorBackendAnnotation) else Nil)
    val threads = java.lang.management.ManagementFactory.getThreadMXBean
    def cpuNow = threads.getCurrentThreadCpuTime / 1e9
    var ctLoop = 0.0; var ctCpu = 0.0; var sink = 0L
    val tc = System.nanoTime()
    RawTester.test(d.gen().asInstanceOf[SubdivAdc], annos) { dut => // the registry's design, typed for peek and poke
      dut.io.in.valid.poke(true.B); dut.io.clearStatus.poke(false.B)
      val t0 = System.nanoTime(); val c0 = cpuNow
      var i = 0
      while (i < ctCycles) {
        dut.io.in.bits.sin.poke(pins.sin(i).U); dut.io.in.bits.cos.poke(pins.cos(i).U)
        dut.clock.step()
        sink += dut.io.out.bits.position.peekInt().toLong
        i += 1
      }
      ctLoop = (System.nanoTime() - t0) / 1e9; ctCpu = cpuNow - c0
    }
    val ctBuild = (System.nanoTime() - tc) / 1e9 - ctLoop
    os.remove.all(dir)
    val ct = ctCycles / ctLoop; val ctC = ctCycles / ctCpu

    // (c) clock-level Scala model (after a warm-up run)
    val mN = math.min(samples, 1000000)
    say(s"(c) Scala model (clock-level), $mN samples")
    def modelRun(): (Double, Double) = {
      val m = d.model(); val t0 = System.nanoTime(); val c0 = cpuNow; var i = 0
      while (i < mN) { sink ^= m.clock(true, pins.sin(i), pins.cos(i), false, false).out.position; i += 1 }
      ((System.nanoTime() - t0) / 1e9, cpuNow - c0)
    }
    modelRun()
    val (mWall, mCpu) = modelRun()
    val model = mN / mWall; val modelC = mN / mCpu

    val load = java.lang.management.ManagementFactory.getOperatingSystemMXBean.getSystemLoadAverage
    val cores = Runtime.getRuntime.availableProcessors
    println(s"bench: ${d.describe}, latency ${d.latency} clocks; $cores cores, load average ${f"$load%.1f"} (sink $sink)")
    println(f"  (a) Verilator harness   ${vWall / 1e6}%8.2f M samples/s  ($samples samples, loop ${o.loopSeconds}%.2f s wall, ${vCpu / 1e6}%.2f M/s by CPU time; " +
      f"end to end incl. file I/O ${samples / endToEnd / 1e6}%.2f M/s; build ${if (h.cached) "cached" else f"${h.buildSeconds}%.1f s"})")
    println(f"  (b) chiseltest peek/poke ${ct / 1e6}%8.3f M samples/s  ($ctCycles cycles in ${ctLoop}%.2f s wall, ${ctC / 1e6}%.3f M/s by CPU time; build and start ${ctBuild}%.1f s)")
    println(f"  (c) Scala model          ${model / 1e6}%8.3f M samples/s  ($mN samples, ${modelC / 1e6}%.3f M/s by CPU time)")
    println(f"  ratios (wall): harness / chiseltest ${vWall / ct}%.1f x, harness / model ${vWall / model}%.1f x, model / chiseltest ${model / ct}%.2f x")
    println(f"  ratios (CPU):  harness / chiseltest ${vCpu / ctC}%.1f x, harness / model ${vCpu / modelC}%.1f x, model / chiseltest ${modelC / ctC}%.2f x")
    println(f"  goal ${Goal / 1e6}%.0f M samples/s on one core: the harness reaches ${vWall / Goal * 100}%.0f %% of it (${vCpu / Goal * 100}%.0f %% by CPU time)")
    json.foreach { f =>
      val path = os.Path(f, os.pwd)
      val j = ujson.Obj("verilator_samples_per_s" -> vWall, "chiseltest_samples_per_s" -> ct, "model_samples_per_s" -> model,
        "verilator_cpu_samples_per_s" -> vCpu, "chiseltest_cpu_samples_per_s" -> ctC, "model_cpu_samples_per_s" -> modelC, "verilator_end_to_end_samples_per_s" -> samples / endToEnd,
        "verilator_build_seconds" -> h.buildSeconds, "verilator_build_cached" -> h.cached, "chiseltest_build_seconds" -> ctBuild,
        "chiseltest_backend" -> (if (hasVerilator) "verilator" else "treadle"), "samples" -> samples, "chiseltest_samples" -> ctCycles,
        "model_samples" -> mN, "goal_samples_per_s" -> Goal, "design" -> d.topName, "cores" -> cores, "load_average" -> load)
      os.write.over(path, ujson.write(j, indent = 2), createFolders = true)
      println(s"wrote $path")
    }
  }
}
