// moire board-in-the-loop harness: a whole board top (LoopTop) in Verilator, its ADC pins fed from a
// stimulus file through a behavioural AD9226 (7-clock pipeline), its UART on a pseudo-terminal.
// Usage: board_loop STIM.bin PTY BAUD_DIVISOR MAX_CLOCKS
// STIM.bin: u32 n, then n samples of u16 sin pins (bit 12 OTR), u16 cos pins (bit 12 OTR), u8 encoder
// levels (bit0 A, bit1 B, bit2 Z), little-endian. Sample i is taken at ADC edge i and appears on the pins
// after edge i + 7; the encoder levels of sample i are set after edge i. Samples repeat after n.
// UART: the board's output is sampled every clock (8N1, BAUD_DIVISOR clocks per bit) and written to the
// pty; bytes read from the pty are sent to the board. Runs until MAX_CLOCKS or SIGTERM.
#include "Vtop.h"
#include "verilated.h"
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <csignal>
#include <deque>
#include <vector>
#include <fcntl.h>
#include <unistd.h>
#include <termios.h>

static volatile sig_atomic_t stop = 0;
static void on_term(int) { stop = 1; }

double sc_time_stamp() { return 0; }

int main(int argc, char** argv) {
  if (argc != 5) { std::fprintf(stderr, "usage: board_loop STIM.bin PTY BAUD_DIVISOR MAX_CLOCKS\n"); return 2; }
  FILE* in = std::fopen(argv[1], "rb");
  if (!in) { std::fprintf(stderr, "board_loop: cannot open %s\n", argv[1]); return 2; }
  uint32_t n = 0;
  if (std::fread(&n, 4, 1, in) != 1 || n == 0) { std::fprintf(stderr, "board_loop: bad stimulus\n"); return 2; }
  std::vector<uint8_t> stim((size_t)n * 5);
  if (std::fread(stim.data(), 5, n, in) != n) { std::fprintf(stderr, "board_loop: short stimulus\n"); return 2; }
  std::fclose(in);
  int fd = open(argv[2], O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (fd < 0) { std::fprintf(stderr, "board_loop: cannot open %s\n", argv[2]); return 2; }
  struct termios tio; if (tcgetattr(fd, &tio) == 0) { cfmakeraw(&tio); tcsetattr(fd, TCSANOW, &tio); }
  const long div = std::atol(argv[3]);
  const long maxClocks = std::atol(argv[4]);
  std::signal(SIGTERM, on_term);

  Vtop top;
  auto u16 = [&](size_t i, int at) { return (uint16_t)(stim[i * 5 + at] | (stim[i * 5 + at + 1] << 8)); };
  top.reset_btn = 1; top.uart_in = 1; top.clk = 0;
  top.sin_d = 0xA5C; top.sin_otr = 1; top.cos_d = 0x3C3; top.cos_otr = 1;  // garbage before the 7th edge
  top.enc_a = 0; top.enc_b = 0; top.enc_z = 0;
  top.eval();
  long cyc = 0, edges = 0;
  int lastAdc = 0;
  // UART to the board: a queue of levels, one per bit time
  std::deque<uint8_t> rxBits; long rxLeft = 0;
  // UART from the board
  int txState = -1; long txTimer = 0; int txByte = 0, txBit = 0;
  std::vector<uint8_t> out; out.reserve(4096);
  uint8_t buf[256];
  while (!stop && cyc < maxClocks) {
    if (rxLeft == 0 && !rxBits.empty()) { top.uart_in = rxBits.front(); rxBits.pop_front(); rxLeft = div; }
    if (rxLeft > 0) rxLeft--;
    top.clk = 1; top.eval();
    cyc++;
    if (cyc == 40) top.reset_btn = 0;
    int adc = top.adc_clk;
    bool edge = adc && !lastAdc;
    if (edge) {
      if (edges >= 7) {
        size_t s = (size_t)((edges - 7) % n);
        uint16_t a = u16(s, 0), b = u16(s, 2);
        top.sin_d = a & 0xFFF; top.sin_otr = (a >> 12) & 1; top.cos_d = b & 0xFFF; top.cos_otr = (b >> 12) & 1;
      }
      uint8_t e = stim[(size_t)(edges % n) * 5 + 4];
      top.enc_a = e & 1; top.enc_b = (e >> 1) & 1; top.enc_z = (e >> 2) & 1;
      edges++;
    }
    int level = top.uart_out;
    if (txState < 0) { if (!level) { txState = 0; txTimer = div / 2; } }
    else if (txTimer > 1) txTimer--;
    else {
      txTimer = div;
      if (txState == 0) { if (level) txState = -1; else { txState = 1; txByte = 0; txBit = 0; } }
      else if (txState == 1) { if (level) txByte |= 1 << txBit; if (++txBit == 8) txState = 2; }
      else { txState = -1; if (level) out.push_back((uint8_t)txByte); else std::fprintf(stderr, "board_loop: stop bit low at clock %ld\n", cyc); }
    }
    top.clk = 0; top.eval();
    lastAdc = top.adc_clk;
    if ((cyc & 255) == 0) {
      size_t at = 0;
      while (at < out.size()) {
        ssize_t w = write(fd, out.data() + at, out.size() - at);
        if (w > 0) at += (size_t)w; else usleep(200);
        if (stop) break;
      }
      out.clear();
      if (rxBits.size() < 64) {
        ssize_t r = read(fd, buf, sizeof buf);
        for (ssize_t k = 0; k < r; k++) {
          rxBits.push_back(0);
          for (int j = 0; j < 8; j++) rxBits.push_back((buf[k] >> j) & 1);
          rxBits.push_back(1);
        }
        // nothing to do for the board: let the host catch up instead of spinning
        if (r <= 0 && rxBits.empty() && txState < 0) usleep(20);
      }
    }
  }
  top.final();
  close(fd);
  std::fprintf(stderr, "board_loop: %ld clocks, %ld ADC edges\n", cyc, edges);
  return 0;
}
