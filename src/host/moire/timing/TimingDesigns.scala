package moire.timing

import chisel3.RawModule
import moire.board.ClockSource
import moire.board.de2115.De2115
import moire.cordic.CordicParams
import moire.cost.{CostDesign, CostDesigns}

/** The designs `timing` places: the registry's, each with the CORDIC of the emit options. A DE2-115
  * board top is placed with its clock from the pin (`clock-source logic`): the Cyclone IV PLL has
  * no ECP5 counterpart, and out of context the clock is ideal anyway.
  */
object TimingDesigns {
  def all: Seq[CostDesign] = CostDesigns.all

  def gen(d: CostDesign, p: CordicParams): () => RawModule = CostDesigns.boards.get(d.name) match {
    case Some(b) => () => De2115.top(b.copy(clockSource = ClockSource.Logic))
    case None => () => d.gen(p)
  }

  def find(name: String): Either[String, CostDesign] = CostDesigns.find(name)
}
