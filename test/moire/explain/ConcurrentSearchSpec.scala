package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The candidate searches run side by side on the common pool, and some of them share sums made on all cores. On a
  * 2-core machine the pool has one worker: a search that waited on a lock held across that work held the worker the
  * work needed, and explain hung (a batch in `ReportBrowserSpec`, on CI). The shared sums are made outside any lock.
  */
class ConcurrentSearchSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "searches side by side" should "share the binned sums without waiting on each other for ever" in {
    val e = new SignalEngine(sim(Seq(EffectSpec("channel_skew", Map("skew_s" -> 30e-9))), n = 100000)); e.init()
    val done = new java.util.concurrent.CountDownLatch(2)
    @volatile var made: Seq[ProfileSums] = Nil
    // two threads (a batch's two files) each take part in their own parallel loop of searches beside the pool's
    // worker(s); each search does other work on all cores first (a worker joining it may run another search)
    for (_ <- 0 until 2) {
      val t = new Thread(() => {
        for (_ <- 0 until 30) {
          val c = new Candidates(e); val got = new java.util.concurrent.ConcurrentLinkedQueue[ProfileSums]()
          java.util.stream.IntStream.range(0, 6).parallel().forEach { _ => e.sumSq(e.resS); got.add(c.binned()) }
          made = scala.jdk.CollectionConverters.CollectionHasAsScala(got).asScala.toSeq
        }
        done.countDown()
      })
      t.setDaemon(true); t.start()
    }
    withClue("the searches did not finish in 120 s: ") { done.await(120, java.util.concurrent.TimeUnit.SECONDS) shouldBe true }
    // each round's searches got the one set of sums made for the state
    made.size shouldBe 6
    made.distinct.size shouldBe 1
  }
}
