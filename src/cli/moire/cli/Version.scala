package moire.cli

/** moire's version and the git commit it was built from (baked in by the build as moire-version.properties). */
object Version {
  private lazy val props: java.util.Properties = {
    val p = new java.util.Properties
    Option(getClass.getResourceAsStream("/moire-version.properties")).foreach(in => try p.load(in) finally in.close())
    p
  }
  def version: String = props.getProperty("version", "unknown")
  def commit: String = props.getProperty("commit", "unknown")
  def text: String = s"$version (commit $commit)"
}
