package moire.explain

/** Writes the README's worked examples: `Test/runMain moire.explain.ThirdGeneratorDemo DIR` writes DIR/rotary_ref.csv
  * (magnetic rotary encoder, 2 % eccentricity, ref_deg) and DIR/rotary_noref.csv (the same without the reference).
  */
object ThirdGeneratorDemo {
  def main(args: Array[String]): Unit = {
    val dir = os.Path(args.headOption.getOrElse("docs/examples"), os.pwd)
    os.makeDir.all(dir)
    val s = ThirdGenerator.Rotary(ecc = 0.02, bits = 12, seed = 7)
    os.write.over(dir / "rotary_ref.csv", ThirdGenerator.rotary(s))
    os.write.over(dir / "rotary_noref.csv", ThirdGenerator.rotary(s.copy(withRef = false)))
    println(f"wrote $dir/rotary_ref.csv and rotary_noref.csv: true 2nd harmonic ${100 * ThirdGenerator.truthH(s, 2)}%.4f %%")
  }
}
