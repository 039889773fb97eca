// The virtual board: the Verilated board top (sc_board_top, or with two
// axes sc_board_xy_top on the multi-axis map) with the plant of the
// testbench on its pins (per axis a stepper and an encoder with an index on
// STEP/DIR and A/B/Z, optionally a home switch and limit switches), its
// UART carried to a byte stream. `scurve virtual-board` puts that stream on
// a pseudo-terminal, so `scurve board --port` drives simulated hardware
// exactly as it drives the Arty.
#pragma once

#include <CLI/CLI.hpp>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "plant.h"
#include "scurve/board.h"
#include "rtl_axi_axis.h"
#include "rtl_axi_multi_axis.h"
#include "switch_plant.h"
#include "uart_line.h"

namespace sc {

struct VirtualBoardConfig {
  // 1: sc_board_top (UartClksPerBit clocks per bit, 1-byte frames); 2:
  // sc_board_xy_top (RtlBoardXY::kClksPerBit clocks per bit, 2-byte frames).
  size_t axes = 1;
  PlantConfig plant;              // per axis; default: the stepper, one count per pulse; index below
  // Switches, on every axis at the same positions:
  std::optional<int64_t> home_at; // a home switch, active at and beyond this pulse position toward home_dir
  int home_dir = -1;
  std::optional<int64_t> limit_neg_at, limit_pos_at;  // limit switches, active at and beyond
  uint32_t corrupt_every = 0;     // line noise: one bit of every N-th byte from the host flipped (0: none)
  uint64_t reset_after_bytes = 0; // the reset button pressed once this many bytes came from the host (0: never)
  uint64_t seed = 1;
};

class VirtualBoard {
 public:
  explicit VirtualBoard(const VirtualBoardConfig& cfg);
  // Bytes from the host, sent on the board's uart_rx in order.
  void receive_from_host(const uint8_t* data, size_t n);
  // Runs `clocks` system clocks; appends what the board sent to `to_host`.
  void run(uint64_t clocks, std::vector<uint8_t>& to_host);
  // Holds the reset button for a few clocks (the board restarts from reset).
  void press_reset();
  uint64_t clocks() const { return clocks_; }
  size_t axes() const { return axes_.size(); }
  int64_t position(size_t axis = 0) const { return axes_.at(axis).plant.commanded(); }  // net STEP pulses
  int64_t encoder(size_t axis = 0) const { return axes_.at(axis).plant.count(); }
  uint64_t corrupted() const { return corrupted_; }

 private:
  struct Axis {
    Plant plant;
    std::optional<SwitchPlant> home, lim_neg, lim_pos;
    uint8_t switches();  // limit -, limit +, home in bits 0-2 (the pins this clock)
  };
  void clock(bool reset_n);
  VirtualBoardConfig cfg_;
  std::unique_ptr<RtlBoard> rtl_;      // one axis
  std::unique_ptr<RtlBoardXY> rtl_xy_; // two axes
  std::vector<Axis> axes_;
  UartLine line_;
  uint64_t clocks_ = 0;
  uint64_t host_bytes_ = 0;
  uint64_t corrupted_ = 0;
  bool reset_pending_ = false;
};

// The virtual board as the host library's byte line, in process (the
// pseudo-terminal's stand-in for tests): what the host sends goes onto the
// board's UART; a receive runs the board until the bytes are there, the
// timeout counted in board time.
class VirtualBoardChannel : public scurve::ByteChannel {
 public:
  explicit VirtualBoardChannel(VirtualBoard& board) : b_(board) {}
  std::optional<scurve::Error> send(const std::vector<uint8_t>& bytes) override;
  std::optional<scurve::Error> receive(std::vector<uint8_t>& out, size_t n, double timeout) override;
  void discard_input() override { pending_.clear(); }

 private:
  VirtualBoard& b_;
  std::vector<uint8_t> pending_;  // sent by the board, not yet received
};

struct VirtualBoardCliOptions {
  std::string pty_link;  // a symlink to the pseudo-terminal (replaced if it is one already)
  double speed = 1.0;    // x real time; 0: as fast as the simulation runs
  double max_seconds = 0;  // wall seconds, then exit (0: until SIGINT / SIGTERM)
  VirtualBoardConfig board;
};

// Runs the virtual board on a new pseudo-terminal until SIGINT or SIGTERM
// (SIGUSR1 presses the reset button). Prints the terminal's path on stdout
// first. Exit 0, or 2 when the terminal cannot be made.
int run_virtual_board(const VirtualBoardCliOptions& opt);

// `scurve virtual-board`: its flags, then run_virtual_board().
struct VirtualBoardCli {
  CLI::App* cmd = nullptr;
  VirtualBoardCliOptions opt;
  int64_t home_at = 0, limit_neg_at = 0, limit_pos_at = 0;
  int64_t index_period = 4000;
};
void add_virtual_board_command(CLI::App& app, VirtualBoardCli& v);
int run_virtual_board_cli(VirtualBoardCli v);

}  // namespace sc
