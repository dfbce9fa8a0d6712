package moire.options

import upickle.core.{ArrVisitor, ObjVisitor, Visitor}

/** JSON as users write it, read as ujson reads it but refusing a key given twice in one object: ujson keeps the last
  * value, so `{"order": 3, "order": 5}` would pass as 5 where the command line and effect specs refuse a repeat.
  */
object StrictJson {
  /** A key that one object of the text holds twice. */
  final class DuplicateKey(val key: String) extends Exception(s"key '$key' is given twice in one object")

  /** The value of `text` (a byte-order mark before it, as editors on Windows write, passed over); `DuplicateKey` for a repeated key, ujson's own exceptions for text that is not JSON. */
  def read(text: String): ujson.Value = ujson.transform(ujson.Readable.fromString(text.stripPrefix("\uFEFF")), new Checked(ujson.Value))

  private final class Checked(v: Visitor[_, ujson.Value]) extends Visitor.Delegate[Any, ujson.Value](v.asInstanceOf[Visitor[Any, ujson.Value]]) {
    // a whole number beyond a long (a seed of 2^63) is a number too, checked by its reader: ujson's own failed with
    // the bare digits as its message ("not valid JSON (9223372036854775808)")
    override def visitFloat64StringParts(s: CharSequence, decIndex: Int, expIndex: Int, index: Int): ujson.Value =
      super.visitFloat64(s.toString.toDouble, index)
    override def visitObject(length: Int, jsonableKeys: Boolean, index: Int): ObjVisitor[Any, ujson.Value] = {
      val d = super.visitObject(length, jsonableKeys, index)
      new ObjVisitor[Any, ujson.Value] {
        private val seen = scala.collection.mutable.HashSet.empty[String]
        def visitKey(index: Int): Visitor[_, _] = d.visitKey(index)
        def visitKeyValue(k: Any): Unit = { if (!seen.add(k.toString)) throw new DuplicateKey(k.toString); d.visitKeyValue(k) }
        def subVisitor: Visitor[_, _] = new Checked(d.subVisitor.asInstanceOf[Visitor[_, ujson.Value]])
        def visitValue(x: Any, index: Int): Unit = d.visitValue(x, index)
        def visitEnd(index: Int): ujson.Value = d.visitEnd(index)
      }
    }
    override def visitArray(length: Int, index: Int): ArrVisitor[Any, ujson.Value] = {
      val d = super.visitArray(length, index)
      new ArrVisitor[Any, ujson.Value] {
        def subVisitor: Visitor[_, _] = new Checked(d.subVisitor.asInstanceOf[Visitor[_, ujson.Value]])
        def visitValue(x: Any, index: Int): Unit = d.visitValue(x, index)
        def visitEnd(index: Int): ujson.Value = d.visitEnd(index)
      }
    }
  }
}
