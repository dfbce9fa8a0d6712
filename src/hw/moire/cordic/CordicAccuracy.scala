package moire.cordic

import CordicMode._
import Fixed._

/** Largest error of the bit-accurate model against double precision over a dense input sweep,
  * next to the a priori bound. `violations` counts inputs whose error exceeds their own bound.
  */
final case class Measured(p: CordicParams, maxError: Double, worstInput: CordicWord, bound: Double,
                          samples: Int, violations: Int, unit: String) {
  def ok: Boolean = violations == 0 && maxError <= bound
  /** The bound is no better than a constant output's error: met, but it says nothing. */
  def vacuous: Boolean = CordicBound.vacuous(p, bound)
}

object CordicAccuracy {
  private def pow2(e: Int): Double = math.pow(2, e)

  /** Input vectors: exhaustive when the input word is 16 bits or less, else dense plus edges. */
  def inputs(p: CordicParams, seed: Long = 1): Seq[CordicWord] = {
    val rnd = new scala.util.Random(seed)
    def span(bits: Int, count: Int): Seq[Long] = {
      val lo = minOf(bits); val hi = maxOf(bits)
      if (bits <= 16) lo to hi
      else (0 until count).map(j => lo + ((hi - lo).toDouble * j / (count - 1)).toLong)
    }
    def randData() = minOf(p.width) + (rnd.nextDouble() * pow2(p.width)).toLong
    p.mode match {
      case SinCos =>
        val q = 1L << (p.angleBits - 2)
        val edges = Seq(0L, q, -q, 2 * q - 1, -2 * q, 1L, -1L, q - 1, q + 1, -q - 1, -q + 1)
        (span(p.angleBits, 1 << 17) ++ edges).map(z => CordicWord(0, 0, z))
      case Rotate =>
        val fs = maxOf(p.width); val lo = minOf(p.width)
        val edges = for (x <- Seq(lo, lo / 2, 0L, fs / 2, fs); y <- Seq(lo, lo / 2, 0L, fs / 2, fs);
                         z <- Seq(0L, 1L << (p.angleBits - 2), minOf(p.angleBits), -(1L << (p.angleBits - 2))))
          yield CordicWord(x, y, z)
        // Rotation keeps |v|: vectors inside the output range's disc (scaled by 1/K without compensation).
        val rMax = pow2(p.width - 1) * (if (p.gainCompensation) 1.0 else 1 / p.gain)
        val disc = Iterator.continually(CordicWord(randData(), randData(), minOf(p.angleBits) + (rnd.nextDouble() * pow2(p.angleBits)).toLong))
          .filter(w => math.hypot(w.x.toDouble, w.y.toDouble) < rMax - 2).take(1 << 15).toSeq
        edges.filter(w => math.hypot(w.x.toDouble, w.y.toDouble) < rMax - 2) ++ disc
      case Atan2 =>
        val fs = maxOf(p.width); val lo = minOf(p.width)
        val edges = for (x <- Seq(lo, -1L, 0L, 1L, fs); y <- Seq(lo, -1L, 0L, 1L, fs)) yield CordicWord(x, y, 0)
        val ring = (0 until (1 << 14)).map { j => // vectors of magnitude 0.5 .. 1 of full scale
          val a = 2 * math.Pi * j / (1 << 14); val rr = (0.5 + 0.5 * rnd.nextDouble()) * pow2(p.dataFrac)
          CordicWord(saturate(math.round(rr * math.cos(a)), p.width), saturate(math.round(rr * math.sin(a)), p.width), 0)
        }
        edges ++ ring ++ (0 until (1 << 14)).map(_ => CordicWord(randData(), randData(), 0))
      case _ =>
        val one = 1L << p.dataFrac
        val codes =
          if (p.dataFrac <= 16) (-one to one)
          else (0 until (1 << 17)).map(j => -one + 2 * one * j / ((1 << 17) - 1)) ++
            ((one - 4096) to one) ++ ((-one) to (-one + 4096))
        val sin83 = math.ceil(math.sin(math.toRadians(83)) * one).toLong
        (codes ++ Seq(sin83 - 1, sin83, -sin83, one + 1, -one - 1)).filter(fits(_, p.width)).map(a => CordicWord(0, a, 0))
    }
  }

  def measure(p: CordicParams, ins: Seq[CordicWord] = Nil): Measured = {
    val model = new CordicModel(p)
    val xs = if (ins.isEmpty) inputs(p) else ins
    val k = p.gain
    val gain = if (p.gainCompensation) 1.0 else k
    var worst = 0.0; var worstIn = CordicWord(0, 0, 0); var bad = 0
    val headline = CordicBound.headline(p).total
    def dat(v: Long) = toDouble(v, p.dataFrac)
    for (in <- xs) {
      val out = model(in)
      val (err, bound, counts) = p.mode match {
        case SinCos =>
          val th = angleToRad(in.z, p.angleBits)
          val e = math.max(math.abs(dat(out.x) - gain * math.cos(th)), math.abs(dat(out.y) - gain * math.sin(th)))
          (e, headline, true)
        case Rotate =>
          val th = angleToRad(in.z, p.angleBits)
          val (x, y) = (dat(in.x), dat(in.y))
          val rx = gain * (x * math.cos(th) - y * math.sin(th)); val ry = gain * (x * math.sin(th) + y * math.cos(th))
          val e = math.max(math.abs(dat(out.x) - rx), math.abs(dat(out.y) - ry))
          (e, CordicBound.rotation(p, math.hypot(x, y)).total, true)
        case Atan2 =>
          val (x, y) = (dat(in.x), dat(in.y))
          val r = math.hypot(x, y)
          if (r == 0) (0.0, 0.0, false)
          else {
            val ea = math.abs(angleDiff(angleToRad(out.z, p.angleBits), math.atan2(y, x)))
            val em = math.abs(dat(out.x) - gain * r)
            val ba = CordicBound.atan2(p, r).total; val bm = CordicBound.magnitude(p, r).total
            if (em > bm) bad += 1
            (ea, ba, r >= 0.5)
          }
        case _ =>
          val a = dat(model.clampSine(in.y))
          val ref = if (p.mode.isAcos) math.acos(a) else math.asin(a)
          (math.abs(angleDiff(angleToRad(out.z, p.angleBits), ref)), headline, true)
      }
      if (err > bound) bad += 1
      if (counts && err > worst) { worst = err; worstIn = in }
    }
    Measured(p, worst, worstIn, headline, xs.size, bad, if (p.mode == SinCos || p.mode == Rotate) "full scale" else "rad")
  }
}
