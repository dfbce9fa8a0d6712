package moire.io

import chisel3._
import chisel3.util._
import moire.protocol.BurstLayout

/** Parameters of the burst capture.
  * @param samples block-RAM depth: the longest burst (65,536 x 29 bits = 1.9 Mbit: 116 DP16KD after yosys synth_ecp5,
  *                232 M9K by arithmetic at 8K x 1 each)
  */
case class BurstParams(samples: Int = 65536, bankWords: Int = 16384, groupBits: Int = 8) {
  require(samples >= 2 && samples <= (1 << 20), s"burst samples must be in 2..${1 << 20}, got $samples")
  require(bankWords >= 2 && (bankWords & (bankWords - 1)) == 0, s"bank words must be a power of two >= 2, got $bankWords")
  require(groupBits >= 1, s"group bits must be >= 1, got $groupBits")
  val addrBits: Int = log2Ceil(samples)
  /** RAM banks: samples / bankWords when that divides, else one. */
  val banks: Int = if (samples > bankWords && samples % bankWords == 0) samples / bankWords else 1
  /** Address bits inside a bank. */
  val bankAddrBits: Int = log2Ceil(samples / banks)
  /** Each bank's word in groups of `groupBits` bits, each group a RAM of its own with its own address, data and
    * enable registers next to its block RAMs (a register that drives the blocks of a whole bank reaches across
    * the die): the bit ranges (lsb, width) of the groups.
    */
  val groups: Seq[(Int, Int)] =
    (0 until BurstLayout.width by groupBits).map(lsb => (lsb, math.min(groupBits, BurstLayout.width - lsb)))
  /** Bits of a length or pre-trigger count (0..samples). */
  val countBits: Int = log2Ceil(samples + 1)
  /** Clocks from a sample at `in` to its write into the RAM: an input register, the bank's write registers,
    * the group's write registers.
    */
  val latency: Int = 3
  /** Clocks from a read issued (its address in the read register) to the word at the queue: the group's address
    * register, the RAM, the group's output register, the bank mux's register.
    */
  val readLatency: Int = 4
  def moduleName: String = s"BurstCapture_n$samples" + (if (banks > 1) s"_b$banks" else "") + s"_g${groups.size}"
  /** A requested length (a register's u32) as used: 1..samples. */
  def length(requested: Long): Int = math.min(math.max(requested, 1L), samples.toLong).toInt
  /** A requested pre-trigger count as used: 0..length-1. */
  def pre(requested: Long, length: Int): Int = math.min(math.max(requested, 0L), length - 1L).toInt
}

/** A register that follows `d` one clock later and that synthesis keeps as a copy of its own: it loads only when
  * it differs from `d`, an enable that reads its own output, so yosys' opt_merge does not fold the copies of one
  * signal into one register (copies with the same input and no such loop are merged).
  */
object Copy {
  def apply[T <: Data](d: T, init: Option[T] = None): T = {
    val q = init.fold(Reg(chiselTypeOf(d)))(RegInit(_))
    val load = WireDefault(q.asUInt =/= d.asUInt)
    dontTouch(load) // else firtool folds "load d when q differs from d" into "load d"
    when(load) { q := d }
    q
  }
}

/** One full-rate sample offered to the capture: the packed [[BurstLayout]] word, and what the trigger
  * and the anchors read (datapath position, reference count, speed, sample index).
  */
class BurstSample extends Bundle {
  val word = UInt(BurstLayout.width.W)
  val position = SInt(32.W)
  val refCount = SInt(32.W)
  val speed = SInt(32.W)
  val index = UInt(32.W)
}

/** Burst settings as the registers hold them (u32 each); latched at `arm`. */
class BurstConfig extends Bundle {
  val mode = UInt(BurstLayout.Trigger.bits.W)
  val length = UInt(32.W)
  val pre = UInt(32.W)
  val threshold = UInt(32.W)
  val target = SInt(32.W)
}

/** Sample index, position and reference count of one captured sample. */
class BurstAnchor extends Bundle {
  val index = UInt(32.W)
  val position = SInt(32.W)
  val refCount = SInt(32.W)
}

/** States of [[BurstCapture]] (output `state`). */
object BurstState {
  val Idle = 0; val Waiting = 1; val Capturing = 2; val Done = 3
}

/** Burst capture: `length` consecutive samples into block RAM (a ring buffer), `pre` of them before the
  * trigger sample. `arm` latches the config, forgets the old burst and starts filling; once `pre`
  * samples are held, the first sample that meets the trigger (immediately; |speed| rising to `threshold`
  * or above; a rising edge of Z; the position crossing `target`; edges need two samples seen since arm)
  * is the trigger sample; `length - pre` samples from it on end the burst (state Done). The anchors hold
  * index, position and reference count of the trigger sample (burst sample `pre`) and the last one.
  * `read` (in Done) sends the `length` words, oldest first, on `out`; `arm` is ignored while sending.
  * Latency `p.latency` clocks from `in` to the RAM, `p.readLatency` from a read to the queue. [[BurstModel]] is the bit-accurate model.
  */
class BurstCapture(val p: BurstParams) extends Module {
  override def desiredName: String = p.moduleName
  val io = IO(new Bundle {
    val in = Flipped(Valid(new BurstSample))
    val config = Input(new BurstConfig)
    val arm = Input(Bool())
    val read = Input(Bool())
    val out = Decoupled(UInt(BurstLayout.width.W))
    val state = Output(UInt(2.W))
    val sending = Output(Bool())
    val length = Output(UInt(p.countBits.W))
    val pre = Output(UInt(p.countBits.W))
    val trigger = Output(new BurstAnchor)
    val last = Output(new BurstAnchor)
  })
  val latency: Int = p.latency
  import BurstLayout.Trigger

  private val s = RegNext(io.in, 0.U.asTypeOf(io.in))
  // mems(bank)(group): the group's bits of the bank's words
  private val mems = Seq.fill(p.banks)(p.groups.map { case (_, w) => SyncReadMem(p.samples / p.banks, UInt(w.W)) })
  private def bankOf(a: UInt): UInt = if (p.banks == 1) 0.U else a(p.addrBits - 1, p.bankAddrBits)
  private def inBank(a: UInt): UInt = a(p.bankAddrBits - 1, 0)

  private val state = RegInit(BurstState.Idle.U(2.W))
  private val mode = RegInit(0.U(Trigger.bits.W))
  private val len = RegInit(1.U(p.countBits.W))
  private val pre = RegInit(0.U(p.countBits.W))
  private val threshold = RegInit(0.U(32.W))
  private val negThreshold = RegInit(0.S(35.W))
  private val target = RegInit(0.S(32.W))
  private val wptr = RegInit(0.U(p.addrBits.W))
  private val held = RegInit(0.U(p.countBits.W))
  private val post = RegInit(0.U(p.countBits.W))
  private val trig = RegInit(0.U.asTypeOf(new BurstAnchor))
  private val last = RegInit(0.U.asTypeOf(new BurstAnchor))
  private val prevValid = RegInit(false.B)
  private val prevAbove = RegInit(false.B)
  private val prevBelow = RegInit(false.B)
  private val prevZ = RegInit(false.B)
  private val sending = RegInit(false.B)

  // ---- trigger conditions on the registered sample, with the latched config ----
  // |speed| >= threshold as two compares side by side (no negation in series with a compare): a negative
  // speed against -threshold, latched at arm
  private val above = Mux(s.bits.speed < 0.S, s.bits.speed <= negThreshold, s.bits.speed >= threshold.zext)
  private val below = s.bits.position < target
  private val z = s.bits.word(BurstLayout.RefZ.lsb)
  private val fired = MuxLookup(mode, true.B)(Seq(
    Trigger.Speed.U -> (prevValid && above && !prevAbove),
    Trigger.RefZ.U -> (prevValid && z && !prevZ),
    Trigger.Position.U -> (prevValid && below =/= prevBelow)))
  private def anchor: BurstAnchor = {
    val a = Wire(new BurstAnchor)
    a.index := s.bits.index; a.position := s.bits.position; a.refCount := s.bits.refCount
    a
  }

  private val capturing = state === BurstState.Waiting.U || state === BurstState.Capturing.U
  // the write port registered per bank (address, data, enable), then per group next to its block RAMs
  private val wEn = RegInit(VecInit(Seq.fill(p.banks)(false.B)))
  private val wAddr = Reg(Vec(p.banks, UInt(p.bankAddrBits.W)))
  private val wData = Reg(Vec(p.banks, UInt(BurstLayout.width.W)))
  wEn.foreach(_ := false.B)
  for (i <- 0 until p.banks; ((lsb, w), g) <- p.groups.zipWithIndex) {
    val en = Copy(wEn(i), Some(false.B))
    val addr = Copy(wAddr(i))
    val data = RegNext(wData(i)(lsb + w - 1, lsb))
    when(en) { mems(i)(g).write(addr, data) }
  }
  private val arm = io.arm && !sending
  when(arm) {
    val l = Mux(io.config.length === 0.U, 1.U, Mux(io.config.length > p.samples.U, p.samples.U, io.config.length))
    len := l
    pre := Mux(io.config.pre >= l, l - 1.U, io.config.pre)
    mode := io.config.mode; threshold := io.config.threshold
    negThreshold := -io.config.threshold.zext; target := io.config.target
    wptr := 0.U; held := 0.U; post := 0.U; prevValid := false.B
    state := BurstState.Waiting.U
  }.elsewhen(s.valid) {
    prevValid := true.B; prevAbove := above; prevBelow := below; prevZ := z
    when(capturing) {
      for (i <- 0 until p.banks) when(bankOf(wptr) === i.U) {
        wEn(i) := true.B; wAddr(i) := inBank(wptr); wData(i) := s.bits.word
      }
      wptr := Mux(wptr === len - 1.U, 0.U, wptr + 1.U)
      held := Mux(held === len, held, held + 1.U)
      val start = state === BurstState.Waiting.U && held >= pre && fired
      when(start) { trig := anchor }
      when(start || state === BurstState.Capturing.U) {
        post := post + 1.U
        when(post + 1.U === len - pre) {
          last := anchor; state := BurstState.Done.U
        }.otherwise { state := BurstState.Capturing.U }
      }
    }
  }

  // ---- read-out: oldest first (the ring is full when Done, so the oldest is at wptr). A read goes through the
  // group's address register, the RAM, the group's output register and the bank mux's register: p.readLatency
  // reads in flight, the queue holds them all ----
  private val q = Module(new Queue(UInt(BurstLayout.width.W), p.readLatency + 1))
  private val raddr = RegInit(0.U(p.addrBits.W))
  private val issued = RegInit(0.U(p.countBits.W))
  private val flight = RegInit(VecInit(Seq.fill(p.readLatency)(false.B)))
  private val inflight = flight.asUInt.orR
  private val issue = sending && issued =/= len && (q.io.count +& PopCount(flight)) < (p.readLatency + 1).U
  flight(0) := issue
  for (k <- 1 until p.readLatency) flight(k) := flight(k - 1)
  q.io.enq.valid := flight(p.readLatency - 1)
  // the bank's read address register is loaded whenever raddr takes a value in that bank, so it holds raddr's
  // offset whenever raddr is in that bank; each group follows it a clock later; every RAM reads every clock
  private val bankAddr = Reg(Vec(p.banks, UInt(p.bankAddrBits.W)))
  private def setRaddr(a: UInt): Unit = {
    raddr := a
    for (i <- 0 until p.banks) when(bankOf(a) === i.U) { bankAddr(i) := inBank(a) }
  }
  private val words = VecInit(mems.zipWithIndex.map { case (groups, i) =>
    Cat(groups.reverse.map(m => RegNext(m.read(Copy(bankAddr(i)), true.B))))
  })
  private val readBank = ShiftRegister(bankOf(raddr), p.readLatency - 1)
  q.io.enq.bits := RegNext(if (p.banks == 1) words(0) else words(readBank))
  io.out <> q.io.deq
  when(io.read && state === BurstState.Done.U && !sending) {
    sending := true.B; setRaddr(wptr); issued := 0.U
  }.elsewhen(sending) {
    when(issue) { setRaddr(Mux(raddr === len - 1.U, 0.U, raddr + 1.U)); issued := issued + 1.U }
    when(issued === len && !inflight && q.io.count === 0.U) { sending := false.B }
  }

  io.state := state
  io.sending := sending
  io.length := len
  io.pre := pre
  io.trigger := trig
  io.last := last
}
