package moire.explain

import java.util.concurrent.{CountDownLatch, TimeUnit}
import java.util.concurrent.atomic.AtomicInteger

import moire.recording.Recording
import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A batch of files explained side by side: the same results as one at a time, in the given order. */
class ExplainBatchSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  private def record(dir: os.Path, name: String, effects: Seq[EffectSpec], seed: Long): os.Path = {
    val p = dir / name
    Recording.write(p, sim(effects, motion = Motion.Ramp(20e3, 200e3, 0.003), n = 30000, seed = seed))
    p
  }

  "explain" should "explain a batch side by side: each file's JSON as alone, the bad one's one line, the reports in order" in {
    val dir = os.temp.dir()
    val a = record(dir, "a.csv", Seq(EffectSpec("channel_skew", Map("skew_s" -> 30e-9))), 1)
    val bad = dir / "bad.csv"
    os.write(bad, "# moire-recording v1\n# sample_rate_hz: 1e6\n# adc_bits: 12\nsin,cos\n1,2\n3\n")
    val b = record(dir, "b.csv", Seq(EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 0.004), "sin")), 2)
    val c = record(dir, "c.csv", Nil, 3)
    val good = Seq(a, b, c)
    // one at a time
    val alone = good.map(p => ExplainCmd.explain(Seq(p.toString), Some((dir / "alone").toString), None, None, quiet = true).head)

    // the batch, its starts and ends watched, its stdout and stderr kept
    val events = new java.util.concurrent.ConcurrentLinkedQueue[(os.Path, Boolean)]
    ExplainCmd.batchWatch = (p, start) => if (p / os.up == dir) events.add(p -> start)
    val out = new java.io.ByteArrayOutputStream
    val err = new java.io.ByteArrayOutputStream
    val stderr = System.err
    System.setErr(new java.io.PrintStream(err, true))
    val e = try Console.withOut(out) {
      intercept[ExplainError](ExplainCmd.explain(Seq(a, bad, b, c).map(_.toString), Some((dir / "batch").toString), None, None, quiet = false))
    } finally { System.setErr(stderr); ExplainCmd.batchWatch = (_, _) => () }

    e.getMessage shouldBe "1 of 4 files failed (their errors are above); the other reports are complete"
    // the same JSON but for the run's own seconds
    def json(d: String, p: os.Path) = { val j = ujson.read(os.read(dir / d / s"${p.last.stripSuffix(".csv")}.json")); j.obj.remove("seconds"); j }
    for (p <- good) json("batch", p) shouldBe json("alone", p)
    alone.map(_.findings.map(_.effect).headOption) shouldBe Seq(Some("channel_skew"), Some("harmonic"), None)
    os.exists(dir / "batch" / "bad.json") shouldBe false
    val errors = err.toString.linesIterator.filter(_.startsWith("moire:")).toSeq
    errors should have size 1
    errors.head should startWith(s"moire: $bad:6: 1 cells, the header has 2")
    // the reports whole, in the given order (each its own seconds)
    def untimed(s: String) = s.replaceAll("""\([0-9.]+ s\)""", "(s)")
    untimed(out.toString) shouldBe untimed(alone.map(_.text).mkString)
    // progress names each file (stderr is no terminal here: each file's own lines)
    for (p <- good) err.toString should include(s"${p.last.stripSuffix(".csv")}: default fit")

    // the files ran side by side: the most running at one time
    var now = 0; var most = 0
    events.forEach { case (_, start) => now += (if (start) 1 else -1); most = math.max(most, now) }
    events.size shouldBe 8
    info(s"at most $most files running at once, ${Runtime.getRuntime.availableProcessors} cores; stderr's errors: ${errors.mkString(" | ")}")
    if (Runtime.getRuntime.availableProcessors > 1) most should be > 1 else most shouldBe 1
  }

  "Batch" should "run items side by side up to the threads and hand the results over in order" in {
    val both = new CountDownLatch(2)
    val taken = Seq.newBuilder[(Int, Boolean)]
    // each of the first two waits for the other: only side by side do both see the count reach zero
    Batch.run(4, threads = 2, budget = 100, _ => 10) { i =>
      if (i < 2) { both.countDown(); both.await(20, TimeUnit.SECONDS) } else { Thread.sleep(10L * (4 - i)); true }
    }((i, ok) => taken += i -> ok)
    taken.result() shouldBe Seq(0 -> true, 1 -> true, 2 -> true, 3 -> true)
  }

  it should "start a file only while the heap allows, and always one alone however big" in {
    def most(costs: Seq[Long], budget: Long): Int = {
      val now = new AtomicInteger(0); val top = new AtomicInteger(0)
      Batch.run(costs.size, threads = 3, budget = budget, costs) { _ =>
        top.accumulateAndGet(now.incrementAndGet(), math.max(_, _)); Thread.sleep(30); now.decrementAndGet()
      }((_, _) => ())
      top.get
    }
    most(Seq(60, 60, 60, 60), budget = 100) shouldBe 1
    most(Seq(500, 500), budget = 100) shouldBe 1 // each over the budget: each runs, alone
    most(Seq(30, 30, 30, 30, 30, 30), budget = 100) should be > 1
  }

  it should "pass on a failure of one item (not a MoireError) to the caller" in {
    val e = intercept[IllegalStateException](Batch.run(3, threads = 2, budget = 100, _ => 1) { i =>
      if (i == 1) throw new IllegalStateException("boom") else i
    }((_, _) => ()))
    e.getMessage shouldBe "boom"
  }

  "Batch.heapOf" should "estimate a recording's heap from its rows, and 0 for a missing file" in {
    val dir = os.temp.dir()
    val p = record(dir, "r.csv", Nil, 4)
    val rows = os.read.lines(p).size
    // the first 64 KiB stand for the rest: within 10 % of the rows' heap
    Batch.heapOf(p).toDouble shouldBe Batch.heapFor(rows).toDouble +- (0.1 * Batch.heapFor(rows))
    // a long record is searched on a subsample: its heap grows by its codes beyond it (20 M: 723-790 MB measured)
    Batch.heapFor(20000000L) should (be > 790L * 1048576 and be < 1200L * 1048576)
    Batch.heapOf(dir / "none.csv") shouldBe 0L
  }

  "BatchProgress" should "say which files run, their stage and how far, and how many are done" in {
    val err = new java.io.ByteArrayOutputStream
    val stderr = System.err
    System.setErr(new java.io.PrintStream(err, true))
    try {
      val shown = new BatchProgress(3, terminal = true)
      val a = shown.start(0, os.root / "x" / "a.csv")
      val b = shown.start(1, os.root / "x" / "b.csv")
      a.phase("effects, round 2", 10); a.step(4)
      b.phase("default fit", 4)
      shown.status should fullyMatch regex """explain: 0 of 3 done; a\.csv: effects, round 2 40 %; b\.csv: default fit 0 %; [0-9]+ s"""
      shown.finish(0)
      shown.say("moire: c.csv: no such file")
      shown.status should fullyMatch regex """explain: 1 of 3 done; b\.csv: default fit 0 %; [0-9]+ s"""
      shown.close()
    } finally System.setErr(stderr)
    // the message is a line of its own, after the redrawn line was cleared
    err.toString should include("\r\u001b[Kmoire: c.csv: no such file\n")
  }
}
