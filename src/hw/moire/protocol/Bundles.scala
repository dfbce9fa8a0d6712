package moire.protocol

import chisel3._
import StreamV1.{RecordLayout => R, WordLayout => W}

/** The record word in hardware; field widths from [[StreamV1.WordLayout]]. Fields are declared from the
  * most significant down (asUInt puts the first one highest); ProtocolSpec checks every field's place.
  */
class RecordWord extends Bundle {
  val reserved = UInt(W.Reserved.width.W)
  val up = Bool()         // the "direction" field: 1 = counting up (Data.direction is taken)
  val stepFault = Bool()
  val overRange = Bool()
  val present = Bool()
  val otrCos = Bool()
  val otrSin = Bool()
  val cos = UInt(W.Cos.width.W)
  val sin = UInt(W.Sin.width.W)
}

/** One record in hardware as frames of type 0x05 carry it (128 bits; asUInt bits 7..0 are the record's
  * byte 0), laid out as [[StreamV1.RecordLayout]] with the reference count.
  */
class StreamRecord extends Bundle {
  val refCount = SInt(R.RefCount.width.W)
  val position = SInt(R.Position.width.W)
  val word = new RecordWord
  val index = UInt(R.Index.width.W)
}

/** A register reply: address and value. */
class RegReply extends Bundle {
  val addr = UInt(8.W)
  val value = UInt(32.W)
}

/** A well-formed host command. */
class RegCommand extends Bundle {
  val write = Bool()
  val addr = UInt(8.W)
  val value = UInt(32.W)
}
