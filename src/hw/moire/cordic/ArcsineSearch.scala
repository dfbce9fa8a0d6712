package moire.cordic

/** Exact worst error of the conventional arcsine (seed 002 eq. 8) over all inputs, by branch and bound.
  *
  * The output is z = sum d_i atan 2^-i: only the directions d_i matter, and d_i = +1 when A >= y_i. The
  * ideal y_i does not track sin z_i (its vector has length K_i / K < 1), which is why the directions go
  * wrong near |A| = 1, and why no closed form exists. But the directions split [-1, 1] into intervals,
  * one per reachable direction sequence, so a walk of the decision tree with each node's input interval
  * finds the supremum of |z - asin A| exactly: on a leaf's interval [lo, hi] it is
  * max(z - asin lo, asin hi - z). A sampled grid misses it (n = 4: 0.225112 on 2^16 points, 0.225122 exact).
  *
  * Rounding: the model's y_i differs from the ideal y_i of the same directions by at most e_i (the start
  * 1/K rounded, one rounded shift per component from step 1, grown by ||P(j)|| = sqrt(1 + 2^-2j)), so a
  * node also takes the direction the ideal would not whenever A is within e_i of y_i. That covers every
  * direction sequence the fixed-point model can take; z itself carries no x/y rounding.
  *
  * A node's remaining steps move z by at most R_i = sum_{j >= i} atan 2^-j: nodes that cannot beat the
  * worst error found so far are cut (a few dozen nodes remain for any n <= 40). Past `budget` nodes, a
  * node's own bound max(z + R_i - asin lo, asin hi - z + R_i) stands in for its subtree: still an upper bound.
  */
object ArcsineSearch {
  /** Double round-off of the search: x, y stay within 1, each of <= 40 steps adds < 2^-52 (grown by
    * < K = 1.65), z and asin are within a few ulps: all far below 1e-12, which is added to each e_i and to
    * the result so the answer stays an upper bound of the exact arithmetic.
    */
  val roundOff: Double = 1e-12
  val budget: Int = 1 << 20

  /** Largest |z - asin A| over |A| <= aMax; with `rounded`, over every direction sequence the model's
    * rounding allows (radians, before the table's and the output's rounding).
    */
  def worst(p: CordicParams, aMax: Double, rounded: Boolean): Double = {
    val n = p.iterations
    val k = p.gain
    val angle = Array.tabulate(n)(i => math.atan(math.pow(2, -i)))
    val rest = Array.tabulate(n + 1)(i => angle.drop(i).sum)
    val slack = slackOf(p, rounded)
    // a node: step, ideal x, y, z, input interval
    val stack = scala.collection.mutable.Stack.empty[(Int, Double, Double, Double, Double, Double)]
    stack.push((0, 1 / k, 0.0, 0.0, -aMax, aMax))
    var best = 0.0; var nodes = 0
    while (stack.nonEmpty) {
      val (i, x, y, z, lo, hi) = stack.pop()
      val bound = math.max(z + rest(i) - math.asin(lo), math.asin(hi) - z + rest(i))
      if (bound > best) {
        if (i == n || nodes >= budget) best = bound // a leaf: rest(n) = 0, exact; else the subtree's bound
        else {
          nodes += 1
          val t = math.pow(2, -i); val e = slack(i)
          if (hi >= y - e) stack.push((i + 1, x - t * y, y + t * x, z + angle(i), math.max(lo, y - e), hi))
          if (lo < y + e) stack.push((i + 1, x + t * y, y - t * x, z - angle(i), lo, math.min(hi, y + e)))
        }
      }
    }
    best + roundOff
  }

  /** e_i: how far the model's y_i can be from the ideal y_i after i steps (plus the search's round-off). */
  private def slackOf(p: CordicParams, rounded: Boolean): Array[Double] = {
    val e = new Array[Double](p.iterations + 1)
    if (rounded) {
      val eps = CordicBound.roundingLsb(p.rounding) * math.pow(2, -p.innerFrac)
      e(0) = math.abs(p.startX * math.pow(2, -p.innerFrac) - 1 / p.gain)
      for (i <- 0 until p.iterations)
        e(i + 1) = e(i) * math.sqrt(1 + math.pow(2, -2 * i)) + (if (i > 0) math.sqrt(2) * eps else 0.0)
    }
    e.map(_ + roundOff)
  }
}
