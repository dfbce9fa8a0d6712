package moire.explain

import java.util.concurrent.{ExecutionException, Executors, Future, ThreadFactory}

/** Runs the files of a batch side by side: up to `threads` at a time, started in the given order, and a file only
  * when the heap its running companions hold plus its own stays within `budget` bytes (a file always runs when
  * it is alone, however big). `take` gets each result on the calling thread, in the given order, as soon as it
  * and the ones before it are done.
  */
object Batch {
  /** The fit's peak heap per sample searched (docs/explain.md "Speed and memory": 342-372 MB per million at 1 M, all
    * searched), up to [[SearchedAtMost]] samples; a longer record is searched on a subsample of at most about that many
    * (`Interleaved`), and its other samples take [[HeapPerRow]] (their codes: 4 M 438 MB, 20 M 723-790 MB).
    */
  val HeapPerSample = 380L
  val SearchedAtMost = 2500000L
  val HeapPerRow = 10L
  /** The heap explain needs for a recording of `rows` samples. */
  def heapFor(rows: Long): Long = math.min(rows, SearchedAtMost) * HeapPerSample + rows * HeapPerRow
  /** The share of the heap (`Runtime.maxMemory`) the running files may take together. */
  val HeapShare = 0.7

  def threads(files: Int): Int = math.max(1, math.min(files, Runtime.getRuntime.availableProcessors))
  def budget: Long = (Runtime.getRuntime.maxMemory * HeapShare).toLong

  def run[A](n: Int, threads: Int, budget: Long, cost: Int => Long)(work: Int => A)(take: (Int, A) => Unit): Unit = {
    val gate = new Gate(budget)
    val pool = Executors.newFixedThreadPool(threads, daemons)
    try {
      val futures: Seq[Future[A]] = (0 until n).map { i =>
        pool.submit(() => {
          val c = cost(i)
          gate.enter(i, c)
          try work(i) finally gate.leave(c)
        })
      }
      for ((f, i) <- futures.zipWithIndex) {
        val a = try f.get() catch { case e: ExecutionException => throw e.getCause }
        take(i, a)
      }
    } finally pool.shutdownNow()
  }

  /** Daemon threads: an interrupted command (Ctrl-C) does not wait for them. */
  private val daemons: ThreadFactory = { r =>
    val t = new Thread(r, "moire-explain"); t.setDaemon(true); t
  }

  /** Admits files in their order while the heap allows; the first of the running ones always. */
  private final class Gate(budget: Long) {
    private var next = 0; private var held = 0L; private var running = 0
    def enter(i: Int, cost: Long): Unit = synchronized {
      while (i != next || (running > 0 && held + cost > budget)) wait()
      next += 1; held += cost; running += 1
      notifyAll()
    }
    def leave(cost: Long): Unit = synchronized { held -= cost; running -= 1; notifyAll() }
  }

  /** The heap explain needs for a file: its rows (the file's size over the mean length of its first lines) times
    * `heapFor`; 0 for what cannot be read (its error comes at once).
    */
  def heapOf(p: os.Path): Long =
    try {
      val size = java.nio.file.Files.size(p.toNIO)
      val in = java.nio.file.Files.newInputStream(p.toNIO)
      val head = try in.readNBytes(1 << 16) finally in.close()
      val lines = math.max(1, head.count(_ == '\n'))
      heapFor((size.toDouble / head.length.max(1) * lines).toLong)
    } catch { case _: java.io.IOException | _: SecurityException => 0L }
}
