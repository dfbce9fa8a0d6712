package moire.cordic

/** Picks the cheapest (n, b) whose a priori bound meets a target, then checks it by simulation. */
final case class Design(function: String, target: Double, p: CordicParams, bound: Double, measured: Measured, adderBits: Int) {
  def report: String = {
    // the sine and cosine (one SinCos unit) are values of full scale 1; the inverse functions' results are angles
    val unit = if (p.mode == CordicMode.SinCos) "(full scale 1.0)" else "rad"
    f"""$function with max error $target%.3e $unit
       |  cheapest: iterations n = ${p.iterations}, width b = ${p.width} (${p.dataFrac} fractional bits), mode ${p.mode.name}
       |  error bound ${bound}%.3e, measured ${measured.maxError}%.3e over ${measured.samples} inputs: ${if (measured.ok && measured.maxError <= target) "confirmed" else "NOT confirmed"}
       |  cost proxy: $adderBits adder bits${if (p.peakTableSize > 0) s" + ${p.peakTableSize} x ${p.angleBits} table bits" else ""}; latency ${p.latency} clocks
       |  emit it: moire emit --mode ${p.mode.name} --iterations ${p.iterations} --width ${p.width}$tableOpt""".stripMargin + paperNote
  }

  private def tableOpt: String = if (p.peakTableSize > 0) s" --peak-table ${p.peakTableSize}" else ""
  /** Seed 001 sec. 3.1 picks n = 16, b = 18 for the same sine budget: say what our bound makes of it. */
  private def paperNote: String = if (p.mode != CordicMode.SinCos) "" else {
    val theirs = CordicParams(CordicMode.SinCos, 16, 20, rounding = p.rounding)
    f"""
       |  seed 001 sec. 3.1 chose n = 16, b = 18 fractional bits (width 20 here): our bound for it is ${CordicBound.headline(theirs).total}%.3e,
       |  because eq. 15 converts the rounding term with pi/180 as if it were degrees""".stripMargin
  }
}

object Designer {
  def modeFor(function: String): Either[String, CordicMode] = function match {
    case "sin" | "cos" | "sincos" => Right(CordicMode.SinCos)
    case "asin" => Right(CordicMode.AsinDouble)
    case "acos" => Right(CordicMode.AcosDouble)
    case "atan2" => Right(CordicMode.Atan2)
    case other => Left(s"--function: '$other' is not supported; allowed: sin (or cos, sincos), asin (or acos), atan2")
  }

  /** Adder bits of the iterations, a proxy for logic cells. */
  def adderBits(p: CordicParams): Int =
    if (p.isDouble) p.iterations * (5 * p.innerWidth + p.zWidth) else p.iterations * (2 * p.innerWidth + p.zWidth)

  def cheapest(function: String, target: Double, r: Rounding, peakTable: Int = 0): Either[String, Design] = modeFor(function).flatMap { mode =>
    def make(n: Int, b: Int) = CordicParams(mode, n, b, rounding = r, peakTableSize = peakTable)
    val check = scala.util.Try(make(16, 18)).toEither.left.map(e =>
      "--" + e.getMessage.stripPrefix("requirement failed: "))
    // a target a constant output meets asks nothing of a design, and a bound that large guarantees nothing
    val half = mode match { case CordicMode.SinCos => "1 full scale"; case CordicMode.Atan2 => "pi radians"; case _ => "pi/2 radians" }
    val inRange = check.flatMap(p => if (target < CordicBound.constantError(p)) Right(())
      else Left(s"--max-error must be below half the output's range ($half), which a constant output meets; got $target"))
    def meets(p: CordicParams) = { val b = CordicBound.headline(p).total; b <= target && !CordicBound.vacuous(p, b) }
    val candidates = if (inRange.isLeft) Nil else for {
      n <- 4 to 40
      b <- (8 to 48).find(b => meets(make(n, b)))
    } yield make(n, b)
    inRange.flatMap(_ =>
    if (candidates.isEmpty) Left(f"--max-error: $target%.3e is below what n <= 40 and b <= 48 can guarantee" +
      (if (peakTable > 0) s" with a $peakTable-entry peak table" else ""))
    else {
      val best = candidates.minBy(p => (adderBits(p) + p.peakTableSize * p.angleBits, p.iterations))
      Right(Design(function, target, best, CordicBound.headline(best).total, CordicAccuracy.measure(best), adderBits(best)))
    })
  }
}
