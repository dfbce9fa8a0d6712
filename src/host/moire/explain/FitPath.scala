package moire.explain

/** Which arithmetic the fit uses on this thread: the fast path (blocked sums on all cores, the channel response without
  * atan, one refining step per convergence iteration) or the reference path it replaced (plain loops on one thread,
  * the formulas as written, a plain solve before each refining step), kept so that a test can compare the two.
  */
object FitPath {
  private val ref = new ThreadLocal[Boolean] { override def initialValue(): Boolean = false }
  /** True while `reference` runs on this thread. */
  def isReference: Boolean = ref.get
  /** Runs `body` on the reference path. */
  def reference[A](body: => A): A = {
    val was = ref.get; ref.set(true)
    try body finally ref.set(was)
  }
}
