package moire.cordic

/** The error models of the papers, written as the papers write them.
  * Seed 001: Zhu et al., harmonic error function of a turntable (eqs. 9-16).
  * Seed 002: Zhu, Ye, Huang, Xue, Metrol. Meas. Syst. 27 (2020) 151-164 (eqs. 16, 25-28).
  */
object PaperBounds {
  private def pow2(e: Double): Double = math.pow(2, e)

  /** Seed 001 eq. 9: approximation error of n conventional iterations, in degrees as the paper uses it. */
  def seed001ApproxDeg(n: Int): Double = math.toDegrees(math.atan(pow2(-(n - 1))))

  /** Seed 001 eq. 11: G(n) = 1 + sum_{j=1..n} prod_{i=j..n} sqrt(1 + 2^-2i). */
  def seed001G(n: Int): Double =
    1 + (1 to n).map(j => (j to n).map(i => math.sqrt(1 + pow2(-2 * i))).product).sum

  /** Seed 001 eq. 10: rounding error 2^(-b-0.5) G(n). */
  def seed001Rounding(n: Int, b: Int): Double = pow2(-b - 0.5) * seed001G(n)

  /** Seed 001 eq. 15: L_max, the error of one CORDIC sine. The paper adds the approximation term
    * in degrees to the rounding term before converting with pi/180; that is how Table 1 comes out.
    */
  def seed001Lmax(n: Int, b: Int): Double = (seed001ApproxDeg(n) + seed001Rounding(n, b)) * math.Pi / 180

  /** Seed 001 eq. 16: P_max = L_max * sum |c_k|, in the unit of the coefficients (arcsec). */
  def seed001Pmax(n: Int, b: Int, sumAbsC: Double): Double = seed001Lmax(n, b) * sumAbsC

  /** Seed 001 eq. 17: per-sine error budget, 10 % of one count (0.077 arcsec) over sum |c_k| = 200 arcsec. */
  val seed001Lerr: Double = 0.077 * 0.1 / 200

  /** Seed 001 eq. 19: the turntable's harmonic error function, c_k in arcsec, phi_k in degrees. */
  val seed001Eq19: Seq[(Int, Double, Double)] =
    Seq((1, -11.1, -53.47), (2, -13.1, 9.68), (3, 8.3, -35.79), (4, -5.7, 5.59))

  /** Seed 002 eq. 16: approximation error of n double-rotation iterations, 2 atan 2^-n (radians). */
  def seed002Approx(n: Int): Double = 2 * math.atan(pow2(-n))

  /** Seed 002 eq. 25: G(n) = 1 + sum_{j=1..n} prod_{i=j..n} (1 + 2^-2i). */
  def seed002G(n: Int): Double = 1 + (1 to n).map(j => (j to n).map(i => 1 + pow2(-2 * i)).product).sum

  /** Seed 002 eq. 27: rounding error of the double-rotation arcsine, worst at the peak (radians). */
  def seed002Rounding(n: Int, b: Int, g: Int => Double = seed002G): Double =
    math.Pi / 2 - math.asin(1 - pow2(-b - 0.5) * g(n))

  /** Seed 002 eq. 28: overall quantization error bound, 2^(1-n) + eq. 27 (radians). */
  def seed002Oqe(n: Int, b: Int, g: Int => Double = seed002G): Double = pow2(1 - n) + seed002Rounding(n, b, g)

  /** Seed 002 Table 1: Delta_OQEs (bound) and Delta_OQEp (circuit) in 1e-4 rad, keyed by (n, b). */
  val seed002Table1: Map[(Int, Int), (Double, Double)] = Map(
    (13, 26) -> (6.80733, 3.12919), (14, 26) -> (5.82284, 1.90849), (15, 26) -> (5.43715, 1.29813),
    (13, 28) -> (4.62437, 2.45193), (14, 28) -> (3.52177, 1.40353), (15, 28) -> (3.02375, 1.14327),
    (13, 30) -> (3.53289, 2.44758), (14, 30) -> (2.37124, 1.22688), (15, 30) -> (1.81705, 0.94804),
    (13, 32) -> (2.98715, 2.43569), (14, 32) -> (1.79597, 1.21499), (15, 32) -> (1.21370, 0.61007))

  /** Seed 001 Table 3: P_max_s (model) and P_max_c (circuit) in 1e-4 arcsec, keyed by (n, b). */
  val seed001Table3: Map[(Int, Int), (Double, Double)] = Map(
    (15, 19) -> (23.4404, 20.0221), (16, 19) -> (11.7976, 9.6377), (17, 19) -> (5.9807, 4.7346),
    (15, 20) -> (23.3720, 20.0145), (16, 20) -> (11.7247, 9.5329), (17, 20) -> (5.9033, 4.7261),
    (15, 21) -> (23.3378, 19.8550), (16, 21) -> (11.6883, 9.2552), (17, 21) -> (5.8646, 4.5972),
    (15, 22) -> (23.3207, 19.7823), (16, 22) -> (11.6700, 9.1462), (17, 22) -> (5.8473, 4.5108))

  /** Seed 002 Table 2: subdivision achieved, (M, n, b) -> (conventional, improved). */
  val seed002Table2: Map[(Int, Int, Int), (Boolean, Boolean)] = Map(
    (256, 8, 16) -> (false, true), (256, 9, 18) -> (false, true), (256, 10, 20) -> (false, true),
    (512, 8, 16) -> (false, false), (512, 9, 18) -> (false, true), (512, 10, 20) -> (false, true),
    (1024, 8, 16) -> (false, false), (1024, 9, 18) -> (false, false), (1024, 10, 20) -> (false, true))
}
