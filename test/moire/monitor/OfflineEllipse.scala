package moire.monitor

import org.hipparchus.linear.{ArrayRealVector, Array2DRowRealMatrix, RealVector}
import org.hipparchus.optim.nonlinear.vector.leastsquares.{LeastSquaresBuilder, LevenbergMarquardtOptimizer, MultivariateJacobianFunction}
import org.hipparchus.util.Pair

/** An independent ellipse fit for the tests (not the monitor's algebraic one): Levenberg-Marquardt on the parameters
  * (ox, oy, ax, ay, phi) themselves, residual = radius of the corrected point - 1, numerical Jacobian, started from the
  * channels' means and standard deviations. Full-scale values; phi in degrees, the convention of [[moire.lissajous.Ellipse]].
  */
object OfflineEllipse {
  final case class Fit(offsetCos: Double, offsetSin: Double, ampCos: Double, ampSin: Double, phaseErrorDeg: Double) {
    def ratio: Double = ampSin / ampCos
  }

  def fit(xs: Array[Double], ys: Array[Double]): Fit = {
    val n = xs.length
    def mean(a: Array[Double]) = a.sum / n
    def sd(a: Array[Double]) = { val m = mean(a); math.sqrt(a.map(v => (v - m) * (v - m)).sum / n) }
    def res(p: Array[Double]): Array[Double] = {
      val Array(ox, oy, ax, ay, phi) = p
      Array.tabulate(n) { i =>
        val c = (xs(i) - ox) / ax; val s = ((ys(i) - oy) / ay + c * math.sin(phi)) / math.cos(phi)
        math.sqrt(c * c + s * s) - 1
      }
    }
    val model: MultivariateJacobianFunction = (point: RealVector) => {
      val p = point.toArray; val r0 = res(p)
      val jac = Array.ofDim[Double](n, 5)
      for (k <- 0 until 5) {
        val q = p.clone(); val h = 1e-7 * math.max(1.0, math.abs(p(k))); q(k) += h
        val r1 = res(q); for (i <- 0 until n) jac(i)(k) = (r1(i) - r0(i)) / h
      }
      new Pair(new ArrayRealVector(r0), new Array2DRowRealMatrix(jac))
    }
    val start = Array(mean(xs), mean(ys), sd(xs) * math.sqrt(2), sd(ys) * math.sqrt(2), 0.0)
    val problem = new LeastSquaresBuilder().model(model).target(new Array[Double](n)).start(start)
      .maxEvaluations(1000).maxIterations(1000).build()
    val p = new LevenbergMarquardtOptimizer().optimize(problem).getPoint.toArray
    Fit(p(0), p(1), p(2), p(3), math.toDegrees(p(4)))
  }
}
