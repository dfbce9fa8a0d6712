package moire.cli

/** `./sbt run`'s entry: with no argument it writes the flagship, the DE2-115 project of the subdivider (as
  * `board de2-115`), as it always has; with arguments it is the launcher. The staged `moire` alone prints the overview.
  */
object SbtRun {
  def main(args: Array[String]): Unit = Main.main(if (args.isEmpty) Array("board", moire.board.de2115.De2115.name) else args)
}
