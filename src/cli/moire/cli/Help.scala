package moire.cli

import mainargs.{ArgSig, MainData, TokensReader}

/** The launcher's words: the overview (`moire` alone, `--help`, `help`), one command's help with its defaults
  * (`help CMD`, `CMD --help`) and the version.
  */
object Help {
  /** The subcommands by task, in the order a newcomer meets them; a command not named here is listed under "other". */
  val groups: Seq[(String, Seq[String])] = Seq(
    "generate Verilog" -> Seq("emit", "emit-subdiv", "emit-harmonic", "emit-datapath", "designs"),
    "boards" -> Seq("board", "board-reg"),
    "record and explain" -> Seq("record", "simulate", "explain", "replay", "calibrate"),
    "measure" -> Seq("accuracy", "bounds", "design", "cost", "timing", "explain-bench"))

  private def name(m: MainData[_, _]): String = m.name(mainargs.Util.kebabCaseNameMapper)
  private def firstSentence(doc: Option[String]): String = doc.getOrElse("").split("(?<=\\.)\\s", 2).head.stripSuffix(".")

  def overview(mains: Seq[MainData[_, _]]): String = {
    val byName = mains.map(m => name(m) -> m).toMap
    val other = mains.map(name).filterNot(n => groups.exists(_._2.contains(n)))
    val width = mains.map(name(_).length).max + 2
    val sections = (groups ++ Seq("other" -> other).filter(_._2.nonEmpty)).map { case (g, names) =>
      s"$g:\n" + names.flatMap(byName.get).map(m => s"  ${name(m).padTo(width, ' ')}${firstSentence(m.doc)}").mkString("\n")
    }
    s"""moire ${Version.text}: Chisel generators for optical-grating (encoder) signal processing, board projects
       |for the DE2-115 and ULX3S, and host tools to record, replay, explain and calibrate.
       |
       |Usage: moire COMMAND [options]
       |
       |${sections.mkString("\n\n")}
       |
       |moire help COMMAND (or moire COMMAND --help): a command's options and defaults.
       |moire --version: the version and git commit.
       |More: README.md, and docs/ (recording.md, explain.md, boards in boards/README.md).""".stripMargin
  }

  /** One command's usage, every option with its doc and default; `extra` is appended (e.g. simulate's effects). */
  def command(m: MainData[_, _], base: Any, extra: String = ""): String = {
    val rows = options(m.argSigs0, base)
    val width = math.min(rows.map(_._1.length).maxOption.getOrElse(0) + 2, 34)
    val lines = rows.map { case (l, d) => if (l.length + 2 > width) s"  $l\n  ${" " * width}$d" else s"  ${l.padTo(width, ' ')}$d" }
    s"""Usage: ${name(m)} [options]
       |  ${m.doc.getOrElse("")}
       |
       |${lines.mkString("\n")}""".stripMargin + (if (extra.nonEmpty) "\n\n" + extra else "")
  }

  /** (left column, doc with its default) per option; the options of a class (e.g. the CORDIC's) expanded. */
  private def options(sigs: Seq[ArgSig], base: Any): Seq[(String, String)] = sigs.filterNot(_.hidden).flatMap { a =>
    a.reader match {
      case c: TokensReader.Class[_] => options(c.main.argSigs0, c.companion())
      case r =>
        val flag = r.isFlag
        val long = a.longName(mainargs.Util.kebabCaseNameMapper).map("--" + _)
        val left = if (r.isLeftover) s"${long.getOrElse("").stripPrefix("--").toUpperCase}..." else long.getOrElse("") + (if (flag) "" else s" <${shortName(r)}>")
        val doc = a.doc.getOrElse("")
        val dflt = if (flag || doc.contains("default")) None else a.default.flatMap(f => shown(f(base)))
        val required = a.default.isEmpty && !flag && !r.isLeftover
        Seq(left -> (doc + dflt.fold("")(v => s" (default $v)") + (if (required) " (required)" else "")).trim)
    }
  }

  private def shortName(r: TokensReader[_]): String = r match {
    case s: TokensReader.ShortNamed[_] => s.shortName
    case _ => "value"
  }

  /** A default worth printing: not None, not an empty list. */
  private def shown(v: Any): Option[String] = v match {
    case None | Nil => None
    case Some(x) => Some(x.toString)
    case s: Seq[_] if s.isEmpty => None
    case d: Double => Some(BigDecimal(d).bigDecimal.stripTrailingZeros.toPlainString)
    case x => Some(x.toString)
  }
}
