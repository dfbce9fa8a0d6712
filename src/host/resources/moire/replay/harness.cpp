// moire replay harness: streams ADC pin codes through the Verilated design, one sample per clock.
// Usage: harness IN.bin OUT.bin LATENCY INPUT_BITS
// IN.bin: per sample u16 sin code, u16 cos code (little-endian); bit 15 = OTR when INPUT_BITS <= 15.
// OUT.bin: per sample (row i = outputs for input sample i, LATENCY clocks later): position, phase
// (each as wide as the Verilated port: 1, 2, 4 or 8 bytes, little-endian), then one flag byte:
// bit0 out.valid, 1 present, 2 overRange, 3 stepFault, 4 a, 5 b, 6 z, 7 status.overspeed.
// Prints "cycles N rows N seconds S cpu C" on stderr: wall and CPU time of the loop only, without start-up.
#include "Vtop.h"
#include "verilated.h"
#include <chrono>
#include <ctime>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

static const size_t kBlock = 1 << 20;

int main(int argc, char** argv) {
  if (argc != 5) { std::fprintf(stderr, "usage: harness IN.bin OUT.bin LATENCY INPUT_BITS\n"); return 2; }
  FILE* in = std::fopen(argv[1], "rb");
  if (!in) { std::fprintf(stderr, "harness: cannot read %s\n", argv[1]); return 2; }
  FILE* out = std::fopen(argv[2], "wb");
  if (!out) { std::fprintf(stderr, "harness: cannot write %s\n", argv[2]); return 2; }
  const long latency = std::atol(argv[3]);
  const int inputBits = std::atoi(argv[4]);
  const uint32_t codeMask = inputBits >= 16 ? 0xFFFFu : ((1u << inputBits) - 1);
  const bool otrBit = inputBits <= 15;

  VerilatedContext ctx;
  Vtop top{&ctx};
  const size_t posBytes = sizeof(top.io_out_bits_position);
  const size_t phaseBytes = sizeof(top.io_out_bits_phase);
  const size_t rec = posBytes + phaseBytes + 1;

  top.io_in_valid = 0; top.io_clearStatus = 0; top.reset = 1;
  for (int k = 0; k < 4; k++) { top.clock = 0; top.eval(); top.clock = 1; top.eval(); }
  top.reset = 0;

  std::vector<uint16_t> ib(2 * kBlock);
  std::vector<uint8_t> ob(kBlock * rec);
  long cycle = 0, written = 0;
  auto t0 = std::chrono::steady_clock::now();
  std::clock_t c0 = std::clock();
  for (;;) {
    size_t n = std::fread(ib.data(), 4, kBlock, in);
    bool last = n < kBlock;
    // after the last sample, LATENCY - 1 clocks with in.valid low bring out its result
    size_t total = n + (last && latency > 0 ? (size_t)(latency - 1) : 0);
    uint8_t* o = ob.data();
    for (size_t i = 0; i < total; i++) {
      if (i < n) {
        uint32_t s = ib[2 * i], c = ib[2 * i + 1];
        top.io_in_valid = 1;
        top.io_in_bits_sin = s & codeMask;
        top.io_in_bits_cos = c & codeMask;
        top.io_in_bits_otrSin = otrBit ? (s >> 15) & 1 : 0;
        top.io_in_bits_otrCos = otrBit ? (c >> 15) & 1 : 0;
      } else {
        top.io_in_valid = 0;
      }
      top.clock = 0; top.eval();
      top.clock = 1; top.eval();
      cycle++;
      if (cycle >= latency) {  // the outputs now show the result of sample cycle - latency
        std::memcpy(o, &top.io_out_bits_position, posBytes); o += posBytes;
        std::memcpy(o, &top.io_out_bits_phase, phaseBytes); o += phaseBytes;
        *o++ = (uint8_t)(top.io_out_valid | (top.io_out_bits_present << 1) | (top.io_out_bits_overRange << 2) |
          (top.io_out_bits_stepFault << 3) | (top.io_a << 4) | (top.io_b << 5) | (top.io_z << 6) |
          (top.io_status_overspeed << 7));
        written++;
      }
    }
    size_t bytes = o - ob.data();
    if (bytes && std::fwrite(ob.data(), 1, bytes, out) != bytes) { std::fprintf(stderr, "harness: write failed\n"); return 1; }
    if (last) break;
  }
  double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
  top.final();
  std::fclose(in);
  if (std::fclose(out) != 0) { std::fprintf(stderr, "harness: write failed\n"); return 1; }
  std::fprintf(stderr, "cycles %ld rows %ld seconds %.6f cpu %.6f\n", cycle, written, s, cpu);
  return 0;
}
