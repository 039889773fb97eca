// The bench's components as plain C++ (no SystemC): clocked cores (RTL,
// model), the lockstep checker, the plant, the trace writer, the stimulus,
// and BenchRun, which builds them from the command line and reports.
//
// Why a separate layer: Debian's libsystemc is built for C++17 and its
// headers reference an API-check symbol that encodes the C++ standard, so
// every file that includes <systemc> is compiled as C++17, while the model
// and checker headers use C++20. This header is valid in both: model types
// appear only as forward-declared references. The SystemC modules
// (sc_modules.h) wrap these components.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "fst_output.h"

namespace sc {
struct CoreInputs;
struct CoreOutputs;
}  // namespace sc

namespace sc::bench {

// A clocked implementation of sc_axis_core: the Verilated RTL or the model.
class Core {
 public:
  virtual ~Core() = default;
  virtual void reset(int cycles) = 0;
  // One clock with these inputs; outputs() then holds the values after it.
  virtual void step(const CoreInputs& in) = 0;
  // One clock with the inputs of the last step() held (the cheap path for
  // the long stretches where the testbench drives nothing new).
  virtual void tick() = 0;
  virtual const CoreOutputs& outputs() const = 0;
  // The outputs the SystemC side publishes on signals.
  virtual bool done() const = 0;
  virtual uint32_t phase() const = 0;
  virtual int32_t pulse_count() const = 0;
  // Ends the run's output files (an FST waveform): each is whole at its path
  // or this throws input::Error naming its flag. Called outside SystemC.
  virtual void close_outputs() {}
};

// The lockstep scoreboard: every output of the RTL compared every clock with
// the reference model it was built with (BenchRun binds the two), which it
// reads in place rather than through a copy of its outputs.
class Checker {
 public:
  virtual ~Checker() = default;
  virtual bool compare(uint64_t clock, const CoreOutputs& rtl) = 0;
  virtual bool should_stop() const = 0;
  virtual uint64_t mismatches() const = 0;
};

// What the plant feeds back into the core for the next clock. The open-loop
// core has no feedback inputs; a closed-loop plant (motor + encoder) fills
// the encoder lines and the sequencer applies them.
struct PlantFeedback {
  bool enc_a = false;
  bool enc_b = false;
};

// The plant consumes the STEP/DIR/EN pins every clock.
class Plant {
 public:
  virtual ~Plant() = default;
  virtual PlantFeedback on_clock(uint64_t clock, const CoreOutputs& pins) = 0;
  virtual void finish(uint64_t clock) = 0;
  virtual int32_t position() const = 0;  // pulses
};

// Kinematics traces of both sides (written on change / decimated).
class Tracer {
 public:
  virtual ~Tracer() = default;
  virtual void on_clock(uint64_t clock, const CoreOutputs& rtl, const CoreOutputs& model) = 0;
  // Each file whole at its path, or input::Error naming its flag (the bench
  // calls this after sc_start returns, never from inside a process).
  virtual void close(uint64_t end_clock) = 0;
};

// The move as a sequence of per-clock inputs: table rows, start, then idle.
class Stimulus {
 public:
  virtual ~Stimulus() = default;
  virtual size_t rows() const = 0;
  virtual const CoreInputs& row_write(size_t i) const = 0;
  virtual const CoreInputs& start() const = 0;
  virtual const CoreInputs& run() const = 0;  // held after start
  virtual uint64_t max_move_clocks() const = 0;  // hang limit after start
  virtual uint64_t tail_clocks() const = 0;      // quiet clocks after done
  virtual uint64_t planned_clocks() const = 0;
};

// Pin-level view of the core's ports for the --sc DUT (plain words, so the
// SystemC side needs no model types). Wide values: little-endian 32-bit words.
struct PinInputs {
  bool enable = false, row_push = false, fifo_flush = false, start = false, abort = false, stop = false;
  uint64_t stop_jerk = 0, stop_acc = 0;
  uint32_t cfg_high = 0, cfg_low = 0, cfg_setup = 0, cfg_hold = 0;
  uint32_t row_flags = 0, seg_phase = 0, seg_clocks = 0;
  uint64_t seg_jerk = 0, seg_acc0 = 0;
  uint32_t seg_vel0[3] = {}, pos_frac0[3] = {};
};
struct PinOutputs {
  bool step = false, dir = false, en = false, busy = false, done = false;
  bool fault_table = false, fault_overrun = false;
  bool underrun = false, discont = false, move_done = false, fifo_full = false;
  bool stopping = false, overshoot = false, retarget_refused = false;
  uint32_t row_count = 0;
  uint32_t phase = 0, pulse_count = 0, ref_pos_int = 0, seg_idx = 0, step_pending = 0;
  uint32_t move_idx = 0, boundary_pos = 0, fifo_level = 0;
  uint64_t ref_acc = 0, ref_jerk = 0;
  uint32_t ref_pos_frac[3] = {}, ref_vel[3] = {};
};
// A Core whose outputs are latched from the pins of a DUT clocked elsewhere.
class PinCore : public Core {
 public:
  static void encode(const CoreInputs& in, PinInputs* pins);
  virtual void latch(const PinOutputs& pins) = 0;
};

// The Verilated --cc RTL (tb/rtl_core.h) with an optional FST window.
std::unique_ptr<Core> make_rtl_cc_core(const std::string& fst_path, uint64_t fst_from, uint64_t fst_to);
std::unique_ptr<PinCore> make_pin_core();

// One bench run: options from the command line, the components, the report.
struct BenchOptions {
  std::string name;
  bool json = false;
  uint64_t quantum = 20000;     // clocks per SystemC wait()
  uint64_t sync_period = 2000;  // control period: quanta end on its multiples
  std::string fst_path;
  uint64_t fst_from = 0, fst_to = kDefaultFstWindow;
  std::string fst_model_path;  // the model's outputs as FST, same window and port names
  std::string trace_rtl, trace_model;
  uint64_t trace_decimate = 20000;
  size_t max_mismatches = 1;
  uint64_t inject_model_fault = UINT64_MAX;
};

struct RunStats {
  std::string bench;  // "systemc-batched" or "systemc-pin"
  double wall_s = 0;
  uint64_t done_clock = 0, total_clocks = 0, syncs = 0;
  bool reached_done = false;
  const CoreOutputs* last_rtl = nullptr;
};

class BenchRun {
 public:
  // Parses argv (move, timing, bench options). On --help or bad input
  // returns null with *exit_code set (0 help, 2 bad input).
  static std::unique_ptr<BenchRun> from_args(int argc, char** argv, bool batched, int* exit_code);
  virtual ~BenchRun() = default;
  virtual const BenchOptions& options() const = 0;
  virtual Core& model() = 0;
  virtual Checker& checker() = 0;
  virtual Plant& plant() = 0;
  virtual Tracer* tracer() = 0;  // null: no traces requested
  virtual const Stimulus& stimulus() const = 0;
  // Judges the run, prints the table or JSON; returns the exit code (0/1).
  virtual int report(const RunStats& stats) = 0;
  // Closes the output files (traces, waveforms) of the run and of `rtl` (if
  // any) after sc_start returned; 0, or 2 with one line on stderr when one
  // of them could not be written whole.
  virtual int close_outputs(uint64_t end_clock, Core* rtl) = 0;
};

}  // namespace sc::bench
