package moire.explain

/** What the two channels' signal paths do to the fundamental at fringe frequency f (Hz): the skew of
  * `sp` (the sin channel sampled half of it early, the cos channel half late), a bandwidth of both
  * channels and one of each (first-order low-pass: gain 1/sqrt(1+u^2), lag atan(u), u = f/fc; the
  * mean lag of the two is taken as the motion's own and left to the phase). For the phase's sin `sn`
  * and cos `cs`, writes into `out` the sin and cos columns of the sin channel, then of the cos channel.
  */
private[explain] final class ChannelResponse(sp: ModelSpec) {
  private val fcB = sp.bw.getOrElse("both", Double.PositiveInfinity)
  private val fcS = sp.bw.getOrElse("sin", Double.PositiveInfinity)
  private val fcC = sp.bw.getOrElse("cos", Double.PositiveInfinity)
  private val w = 2 * math.Pi * sp.skewS

  def apply(f: Double, sn: Double, cs: Double, out: Array[Double]): Unit = {
    var gs = 1.0; var gc = 1.0; var ls = -0.5 * w * f; var lc = 0.5 * w * f
    if (!fcB.isInfinite) { val u = f / fcB; val g = 1 / math.sqrt(1 + u * u); gs *= g; gc *= g }
    var lagS = 0.0; var lagC = 0.0
    if (!fcS.isInfinite) { val u = f / fcS; gs /= math.sqrt(1 + u * u); lagS = math.atan(u) }
    if (!fcC.isInfinite) { val u = f / fcC; gc /= math.sqrt(1 + u * u); lagC = math.atan(u) }
    val m = 0.5 * (lagS + lagC); ls += m - lagS; lc += m - lagC
    val cls = math.cos(ls); val sls = math.sin(ls); val clc = math.cos(lc); val slc = math.sin(lc)
    out(0) = gs * (sn * cls + cs * sls); out(1) = gs * (cs * cls - sn * sls)
    out(2) = gc * (sn * clc + cs * slc); out(3) = gc * (cs * clc - sn * slc)
  }
}
