// Register-level testbench for sc_axi_axis: an AXI4-Lite master driving the
// Verilated RTL and the bit-exact model (cmodel/axi_regs.h) in lockstep,
// compared every clock; the pin monitor checks the STEP/DIR pins (timing as
// programmed, step accounting) and counts the pulses. Also a UART
// host for the Verilated board top (frames on the uart_rx pin, responses
// decoded from uart_tx).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "axi_multi_axis.h"
#include "axi_regs.h"
#include "lockstep.h"
#include "pin_monitor.h"
#include "plant.h"
#include "reg_encode.h"
#include "rtl_axi_axis.h"
#include "rtl_axi_multi_axis.h"
#include "uart_line.h"

namespace sc {

SignalValues render_signals(const AxiAxisOutputs& o);
SignalValues render_signals(const AxiServoOutputs& o);
SignalValues render_signals(const AxiMultiAxisOutputs& o);

// AXI4-Lite master of the register-level benches: blocking transactions
// on top of the bench's tick().
class AxiMaster {
 public:
  explicit AxiMaster(uint32_t seed) : rng_(seed) {}
  virtual ~AxiMaster() = default;
  // One clock with the current bus and side inputs; compares RTL and model.
  virtual void tick() = 0;
  void idle(uint64_t n) {
    for (uint64_t i = 0; i < n && !failed(); ++i) tick();
  }

  // AXI4-Lite master transactions (blocking). With jitter on, AWVALID,
  // WVALID, BREADY, ARVALID and RREADY are raised after random delays
  // (AW before W, W before AW, late ready) from the seeded generator.
  uint8_t write(uint32_t addr, uint32_t data, uint8_t strb = 0xf);
  std::pair<uint32_t, uint8_t> read(uint32_t addr);
  void set_jitter(bool on) { jitter_ = on; }
  bool failed() const { return !error_.empty(); }
  const std::string& error() const { return error_; }

 protected:
  virtual AxiOut axi_out() const = 0;
  int delay();
  // The first lockstep mismatch or pin error fails the bench.
  void note(const LockstepLog& checker, const PinMonitor& pins);
  AxiIn in_;
  uint32_t addr_mask_ = (1u << RegAddrW) - 1;  // the bus's address wires
  bool jitter_ = false;
  std::mt19937 rng_;
  std::string error_;
};

// What both register-level benches hold: the Verilated top (optional), its
// model, the side inputs, the outputs of this clock, the lockstep checker
// and the pin monitor.
template <class Rtl, class Model, class Outputs>
class AxiLockstepBench : public AxiMaster {
 public:
  void reset() {
    if (rtl_) rtl_->reset(4);
    model_.reset();
    in_ = AxiIn{};
    out_ = model_.outputs();
  }

  RegsSide& side() { return side_; }
  const Outputs& out() const { return out_; }
  const Model& model() const { return model_; }
  uint64_t clock() const { return clock_; }
  int64_t net_steps() const { return pins_.net_steps(); }
  uint64_t matched() const { return checker_.matched(); }
  const PinMonitor& pins() const { return pins_; }

 protected:
  // with_rtl = false runs the model alone (for speed comparisons).
  AxiLockstepBench(bool with_rtl, uint32_t seed, StepAccounting accounting)
      : AxiMaster(seed), pins_{PinRules{PulseTiming{}, false, accounting}} {
    if (with_rtl) rtl_ = std::make_unique<Rtl>();
  }
  AxiOut axi_out() const override { return out_.axi; }
  std::unique_ptr<Rtl> rtl_;
  Model model_;
  RegsSide side_;
  Outputs out_;
  uint64_t clock_ = 0;
  Lockstep<Outputs> checker_{&render_signals};
  PinMonitor pins_;
};

// sc_axi_axis: Verilated RTL and AxiAxis in lockstep every clock. Open loop:
// the pins against the core's position (its step queue read from the model,
// as sc_axi_axis has no port for it).
class AxiBench : public AxiLockstepBench<RtlAxiAxis, AxiAxis, AxiAxisOutputs> {
 public:
  explicit AxiBench(bool with_rtl = true, uint32_t seed = 1);

  void reset();
  void tick() override;
  // Checker self-test: the model sees the encoder position off by `d`.
  void inject_model_enc_offset(int32_t d) { model_enc_offset_ = d; }
  // Switch pins driven every clock (also inside bus transactions) from the
  // pins' net step count: a switch model in the plant.
  void set_switch_pins(std::function<uint8_t(int64_t)> f) { switch_pins_ = std::move(f); }
  // The encoder inputs (ENC_POS, the index level) driven every clock from
  // the pins' net step count: an encoder on the plant's shaft.
  struct Encoder {
    int32_t count = 0;
    bool index = false;
  };
  void set_encoder(std::function<Encoder(int64_t)> f) { encoder_ = std::move(f); }

  // STEP rising edges, as clocks after the last START pulse to the core.
  const std::vector<uint64_t>& rise_times() const { return rise_times_; }

 private:
  bool last_step_ = false;
  int32_t model_enc_offset_ = 0;
  std::function<uint8_t(int64_t)> switch_pins_;
  std::function<Encoder(int64_t)> encoder_;
  uint64_t start_clock_ = 0;
  std::vector<uint64_t> rise_times_;
};

// The same for sc_axi_servo (closed-loop axis): Verilated RTL and AxiServo
// in lockstep every clock. With a plant attached, the STEP/DIR pins drive
// the plant and its encoder A/B go back to the DUT (as tb/closed_loop_run);
// without one, side().enc_ab drives the encoder inputs. Both modes: the pins
// against the step generator's counter.
class AxiServoBench : public AxiLockstepBench<RtlAxiServo, AxiServo, AxiServoOutputs> {
 public:
  explicit AxiServoBench(bool with_rtl = true, uint32_t seed = 1);
  void tick() override;
  void attach_plant(const PlantConfig& cfg) { plant_ = std::make_unique<Plant>(cfg, double(ClkHz)); }
  const Plant* plant() const { return plant_.get(); }
  // Checker self-test: from now on the model sees encoder A inverted.
  void inject_model_fault() { inject_ = true; }

 private:
  std::unique_ptr<Plant> plant_;
  bool inject_ = false;
};

// sc_axi_multi_axis (2 closed-loop capable axes, the multi-axis map):
// Verilated RTL and AxiMultiAxis in lockstep every clock; one pin monitor
// per axis (the pins against its step counter, PULSE_COUNT, with the pulse
// timing its register file programs); every axis's BUSY rises on one clock.
class AxiMultiBench : public AxiMaster {
 public:
  explicit AxiMultiBench(bool with_rtl = true, uint32_t seed = 1);
  void reset();
  void tick() override;
  bool estop = false;
  std::array<MultiAxisPins, MaxAxes>& pins_in() { return pins_in_; }
  const AxiMultiAxisOutputs& out() const { return out_; }
  const AxiMultiAxis& model() const { return model_; }
  const PinMonitor& pins(size_t a) const { return monitors_.at(a); }
  uint64_t clock() const { return clock_; }
  uint64_t matched() const { return checker_.matched(); }
  // A stepper plant per axis: the axis's STEP/DIR pins drive it, its
  // encoder A/B/Z go back to the axis's encoder inputs (the closed loop).
  void attach_plants(const PlantConfig& cfg);
  const Plant* plant(size_t a) const { return a < plants_.size() ? plants_[a].get() : nullptr; }

 protected:
  AxiOut axi_out() const override { return out_.axi; }

 private:
  std::vector<std::unique_ptr<Plant>> plants_;
  std::unique_ptr<RtlAxiMultiAxis> rtl_;
  AxiMultiAxis model_;
  std::array<MultiAxisPins, MaxAxes> pins_in_{};
  AxiMultiAxisOutputs out_;
  uint64_t clock_ = 0;
  Lockstep<AxiMultiAxisOutputs> checker_{&render_signals};
  std::vector<PinMonitor> monitors_;
  std::array<bool, MaxAxes> busy_{};  // STATUS.BUSY of the last clock
};

// Host end of the UART bridge of a Verilated board top: 8N1 at
// clks_per_bit system clocks (x5 pin clocks through the clock stand-in),
// frames for a register map of addr_bits byte address bits. The board's
// pins are the subclass's (tick()).
class BoardUartHost {
 public:
  BoardUartHost(int clks_per_bit, int addr_bits) : bit100_(5 * clks_per_bit), addr_bits_(addr_bits), line_(bit100_) {}
  virtual ~BoardUartHost() = default;
  // Send raw bytes, then collect response bytes until `expect` arrived or
  // `timeout_bits` bit times passed with no byte.
  std::vector<uint8_t> transact(const std::vector<uint8_t>& frame, size_t expect, int timeout_bits = 60);
  // Register access through the bridge at a byte address (the frame carries
  // addr / 4); an address the encoder refuses comes back as !ok with its error.
  UartResponse write(uint32_t addr, uint32_t data);
  UartResponse read(uint32_t addr);
  // Keep the clock running with the line idle.
  void idle(uint64_t clocks100);
  // The PC's line, to queue line faults before a transact() (pin clocks).
  UartLine& line() { return line_; }
  int pin_clocks_per_bit() const { return bit100_; }

 protected:
  // One 100 MHz pin clock of the board with the line's level.
  virtual void tick() = 0;
  int bit100_;  // pin clocks per bit
  int addr_bits_;
  UartLine line_;
};

// The one-axis board top (sc_board_top).
class UartHost : public BoardUartHost {
 public:
  explicit UartHost(RtlBoard& board, int clks_per_bit);
  bool estop = false;
  uint8_t enc_ab = 0;  // encoder pins: bit 0 = A, bit 1 = B
  bool enc_z = false;  // encoder index pin
  int64_t net_steps() const { return pins_.net_steps(); }
  uint64_t pulses() const { return pins_.rising_edges(); }
  // The STEP/DIR pins checked against the pulse timing the host programs
  // (system clocks; the monitor counts pin clocks, 5 per system clock).
  void set_timing(const PulseTiming& t);
  const PinMonitor& pins() const { return pins_; }

 private:
  void tick() override;
  RtlBoard& b_;
  PinMonitor pins_{PinRules{PulseTiming{}, false, StepAccounting::None}};
};

// The two-axis board top (sc_board_xy_top, the multi-axis map): both
// axes' STEP/DIR pins on a pin monitor each (pulse timing at its reset
// value, in pin clocks).
class UartHostXY : public BoardUartHost {
 public:
  explicit UartHostXY(RtlBoardXY& board, int clks_per_bit);
  const PinMonitor& pins(size_t axis) const { return pins_.at(axis); }

 private:
  void tick() override;
  RtlBoardXY& b_;
  std::vector<PinMonitor> pins_;
};

}  // namespace sc
