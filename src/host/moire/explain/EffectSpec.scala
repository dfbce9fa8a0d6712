package moire.explain


/** One named effect of the physics model with its physical parameters (units in the names). */
final case class EffectSpec(effect: String, params: Map[String, Double] = Map.empty, channel: String = "both") {
  def p(name: String, default: Double = Double.NaN): Double = params.getOrElse(name, default)
  def json: ujson.Obj = {
    val o = ujson.Obj("effect" -> effect, "channel" -> channel)
    params.toSeq.sortBy(_._1).foreach { case (k, v) => o(k) = v }
    o
  }
  /** As `--effect` takes it: `harmonic:order=3,amplitude_rel=0.001,channel=sin`. */
  def text: String = {
    val kv = params.toSeq.sortBy(_._1).map { case (k, v) => s"$k=${effects.Effect.show(v)}" } ++ (if (channel == "both") Nil else Seq(s"channel=$channel"))
    if (kv.isEmpty) effect else s"$effect:${kv.mkString(",")}"
  }
}

/** The catalogue is the registry (`effects.Effects`): each effect, the parameters it takes and what it means. */
object EffectSpec {
  val catalogue: Seq[(String, Seq[String], String)] = effects.Effects.signals.map(e => (e.name, e.params.map(_.name), e.what))
  val calibrationEffects: Seq[(String, Seq[String], String)] = effects.Effects.all.filter(_.calibration).map(e => (e.name, e.params.map(_.name), e.what))
  val names: Seq[String] = effects.Effects.names

  /** Parses `name:key=value,key=value` (channel=sin|cos|both allowed among the keys, each key once); the effect
    * checks the values (`Effect.check`).
    */
  def parse(s: String): EffectSpec = {
    val (name, rest) = s.indexOf(':') match { case -1 => (s.trim, ""); case i => (s.take(i).trim, s.drop(i + 1)) }
    val allowed = (catalogue ++ calibrationEffects).find(_._1 == name)
      .getOrElse(throw new ExplainError(s"--effect: '$name' is not an effect; allowed: ${catalogue.map(_._1).mkString(", ")} " +
        s"(and for calibration data: ${calibrationEffects.map(_._1).mkString(", ")})"))
    var channel = "both"; val ps = Map.newBuilder[String, Double]
    val seen = scala.collection.mutable.Set.empty[String]
    if (rest.trim.nonEmpty && rest.split(",", -1).exists(_.trim.isEmpty))
      throw new ExplainError(s"--effect $name: an empty entry in '${rest.trim}' (key=value pairs, one comma between each)")
    rest.split(",").map(_.trim).filter(_.nonEmpty).foreach { kv =>
      val k = kv.takeWhile(_ != '=').trim
      if (kv.contains('=') && !seen.add(k)) throw new ExplainError(s"--effect $name: key '$k' given twice")
      kv.split("=", 2) match {
        case Array("channel", v) =>
          channel = checkChannel(v.trim)
          if (channel != "both" && !effects.Effects(name).exists(_.perChannel))
            throw new ExplainError(s"--effect $name: channel=$channel does not apply: $name acts on both channels" +
              (if (allowed._2.nonEmpty) s" (its keys: ${allowed._2.mkString(", ")})" else ""))
        case Array(k, v) if allowed._2.contains(k.trim) =>
          ps += k.trim -> moire.numbers.Decimal.double(v).filter(x => !x.isNaN && !x.isInfinite)
            .getOrElse(throw new ExplainError(s"--effect $name: $k '$v' is not a finite number"))
        case _ => throw new ExplainError(s"--effect $name: '$kv' is not key=value with a key in ${(allowed._2 :+ "channel").mkString(", ")}")
      }
    }
    val spec = EffectSpec(name, ps.result(), channel)
    effects.Effects(name).flatMap(_.check(spec)).foreach(m => throw new ExplainError(s"--effect $name: $m"))
    spec
  }

  def checkChannel(v: String): String =
    if (Set("sin", "cos", "both").contains(v)) v else throw new ExplainError(s"channel '$v' must be sin, cos or both")

  def fromJson(v: ujson.Value, where: String): EffectSpec = {
    val o = v.objOpt.getOrElse(throw new ExplainError(s"$where: each effect must be a JSON object"))
    val name = o.get("effect").flatMap(_.strOpt).getOrElse(throw new ExplainError(s"$where: an effect has no \"effect\" name"))
    val text = o.toSeq.filter(_._1 != "effect").map { case (k, x) =>
      s"$k=${x.strOpt.getOrElse(x.numOpt.map(_.toString).getOrElse(throw new ExplainError(s"$where: $name.$k must be a number")))}"
    }.mkString(",")
    try parse(s"$name:$text") catch { case e: moire.MoireError => throw new ExplainError(s"$where: ${e.getMessage.replaceFirst("^--effect:? ", "")}") }
  }
}
