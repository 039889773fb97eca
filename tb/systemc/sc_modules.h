// SystemC structure of the bench (compiled as C++17, see components.h):
// one module per component, bound through sc_port/sc_export, plus signals
// for what other processes observe at synchronisation points.
//
// Temporal decoupling: BatchSequencer's SC_THREAD clocks DUT, model,
// scoreboard, plant and trace writer for a quantum of clocks (default
// 20,000 = 1 ms), then wait()s for that much simulated time. Inside a
// quantum it calls the components directly through pointers it obtained
// once through its ports (the idea of TLM-2.0's direct memory interface),
// so a clock costs a few virtual calls and no scheduler work. Quanta end on
// control-period boundaries and early at events (done, a stopping mismatch).
#pragma once

#include <cstdlib>
#include <functional>
#include <systemc>

#include "components.h"

namespace sc::bench {

// stdout carries the report (JSON for the regression runner): no banner, no
// "simulation stopped" info line.
inline void quiet_systemc() { sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING); }

// The benches' main(): libsystemc prints its banner before sc_main() runs,
// which would add four lines to every one-line error.
inline int run_systemc_main(int argc, char** argv) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  return sc_core::sc_elab_and_sim(argc, argv);
}

// ---- interfaces: each hands out its component for direct calls -------------------
struct CoreIf : virtual sc_core::sc_interface {
  virtual Core& core() = 0;
};
struct ScoreboardIf : virtual sc_core::sc_interface {
  virtual Checker& checker() = 0;
};
struct PlantIf : virtual sc_core::sc_interface {
  virtual Plant& plant() = 0;
};
struct TraceIf : virtual sc_core::sc_interface {
  virtual Tracer& tracer() = 0;
};

// ---- modules ---------------------------------------------------------------------
// A clocked core (the Verilated RTL or the model); publishes its pins and
// status at every synchronisation point.
class CoreModule : public sc_core::sc_module, public CoreIf {
 public:
  sc_core::sc_export<CoreIf> core_export;
  sc_core::sc_in<uint64_t> sync_clock_i;
  sc_core::sc_out<bool> done_o;
  sc_core::sc_out<uint32_t> phase_o;
  sc_core::sc_out<int32_t> pulse_count_o;
  CoreModule(sc_core::sc_module_name name, Core& core)
      : sc_module(name), sync_clock_i("sync_clock_i"), done_o("done_o"), phase_o("phase_o"),
        pulse_count_o("pulse_count_o"), core_(core) {
    core_export.bind(*this);
    SC_HAS_PROCESS(CoreModule);
    SC_METHOD(publish);
    sensitive << sync_clock_i;
    dont_initialize();
  }
  Core& core() override { return core_; }

 private:
  void publish() {
    done_o.write(core_.done());
    phase_o.write(core_.phase());
    pulse_count_o.write(core_.pulse_count());
  }
  Core& core_;
};

// Lockstep scoreboard; failed_o rises at the first synchronisation point
// after a mismatch.
class ScoreboardModule : public sc_core::sc_module, public ScoreboardIf {
 public:
  sc_core::sc_export<ScoreboardIf> sb_export;
  sc_core::sc_in<uint64_t> sync_clock_i;
  sc_core::sc_out<bool> failed_o;
  ScoreboardModule(sc_core::sc_module_name name, Checker& checker)
      : sc_module(name), sync_clock_i("sync_clock_i"), failed_o("failed_o"), checker_(checker) {
    sb_export.bind(*this);
    SC_HAS_PROCESS(ScoreboardModule);
    SC_METHOD(publish);
    sensitive << sync_clock_i;
    dont_initialize();
  }
  Checker& checker() override { return checker_; }

 private:
  void publish() { failed_o.write(checker_.mismatches() > 0); }
  Checker& checker_;
};

// The plant (open loop now: ideal stepper + pin checks; a closed-loop motor
// and encoder model plugs in here through the same Plant interface).
class PlantModule : public sc_core::sc_module, public PlantIf {
 public:
  sc_core::sc_export<PlantIf> plant_export;
  sc_core::sc_in<uint64_t> sync_clock_i;
  sc_core::sc_out<int32_t> position_o;
  PlantModule(sc_core::sc_module_name name, Plant& plant)
      : sc_module(name), sync_clock_i("sync_clock_i"), position_o("position_o"), plant_(plant) {
    plant_export.bind(*this);
    SC_HAS_PROCESS(PlantModule);
    SC_METHOD(publish);
    sensitive << sync_clock_i;
    dont_initialize();
  }
  Plant& plant() override { return plant_; }

 private:
  void publish() { position_o.write(plant_.position()); }
  Plant& plant_;
};

class TraceModule : public sc_core::sc_module, public TraceIf {
 public:
  sc_core::sc_export<TraceIf> trace_export;
  TraceModule(sc_core::sc_module_name name, Tracer& tracer) : sc_module(name), tracer_(tracer) {
    trace_export.bind(*this);
  }
  Tracer& tracer() override { return tracer_; }

 private:
  Tracer& tracer_;
};

// ---- the temporally decoupled sequencer -----------------------------------------------
struct SequencerConfig {
  uint64_t quantum = 20000;
  uint64_t sync_period = 2000;
  std::function<void(double)> progress;  // fraction of the planned move, at syncs
};

class BatchSequencer : public sc_core::sc_module {
 public:
  sc_core::sc_port<CoreIf> rtl;
  sc_core::sc_port<CoreIf> model;
  sc_core::sc_port<ScoreboardIf> scoreboard;
  sc_core::sc_port<PlantIf> plant;
  sc_core::sc_port<TraceIf, 1, sc_core::SC_ZERO_OR_MORE_BOUND> trace;
  sc_core::sc_out<uint64_t> sync_clock_o;  // clocks simulated so far
  sc_core::sc_in<bool> rtl_done_i;
  sc_core::sc_in<bool> failed_i;

  BatchSequencer(sc_core::sc_module_name name, const Stimulus& stim, const SequencerConfig& cfg)
      : sc_module(name), sync_clock_o("sync_clock_o"), rtl_done_i("rtl_done_i"), failed_i("failed_i"),
        stim_(stim), cfg_(cfg) {
    SC_HAS_PROCESS(BatchSequencer);
    SC_THREAD(run);
  }
  bool reached_done() const { return reached_done_; }
  uint64_t done_clock() const { return done_clock_; }
  uint64_t total_clocks() const { return clock_; }
  uint64_t syncs() const { return syncs_; }

 private:
  // One clock: `in` is driven, or (held) the previous inputs stay.
  void tick(const CoreInputs* in) {
    if (in) {
      rtl_->step(*in);
      model_->step(*in);
    } else {
      rtl_->tick();
      model_->tick();
    }
    const CoreOutputs& r = rtl_->outputs();
    if (!sb_->compare(clock_, r) && sb_->should_stop()) stop_ = true;
    plant_->on_clock(clock_, r);  // open loop: no feedback inputs on this core yet
    if (trace_) trace_->on_clock(clock_, r, model_->outputs());
    ++clock_;
  }
  // Held inputs for clocks [clock_, end), or until done (an event boundary).
  void run_quantum(uint64_t end, bool until_done) {
    while (clock_ < end && !stop_) {
      tick(nullptr);
      if (until_done && rtl_->done()) break;
    }
  }
  uint64_t quantum_end(uint64_t cap) const {
    uint64_t end = (clock_ + cfg_.quantum) / cfg_.sync_period * cfg_.sync_period;
    if (end <= clock_) end = clock_ + cfg_.sync_period;
    return end < cap ? end : cap;
  }
  void sync() {
    if (clock_ == synced_clock_) return;  // a zero-time wait would race the published signals
    sync_clock_o.write(clock_);
    // SystemC time follows the simulated clock exactly (50 ns per clock).
    wait(sc_core::sc_time(double(clock_ - synced_clock_) * 50.0, sc_core::SC_NS));
    synced_clock_ = clock_;
    ++syncs_;
  }
  void run() {
    rtl_ = &rtl->core();
    model_ = &model->core();
    sb_ = &scoreboard->checker();
    plant_ = &plant->plant();
    trace_ = trace.size() ? &trace->tracer() : nullptr;

    rtl_->reset(4);
    model_->reset(4);
    for (size_t i = 0; i < stim_.rows() && !stop_; ++i) tick(&stim_.row_write(i));
    if (!stop_) tick(&stim_.start());
    if (!stop_) tick(&stim_.run());  // drops start; the inputs stay as they are from here on
    const uint64_t start_clock = clock_;
    sync();
    const uint64_t limit = start_clock + stim_.max_move_clocks();
    const double planned = double(stim_.planned_clocks()) + 1.0;
    // Decisions use the published signals only, at synchronisation points.
    while (!stop_ && clock_ < limit && !rtl_done_i.read()) {
      run_quantum(quantum_end(limit), true);
      sync();
      if (failed_i.read() && sb_->should_stop()) break;
      if (cfg_.progress) cfg_.progress(double(clock_ - start_clock) / planned);
    }
    reached_done_ = rtl_done_i.read();
    done_clock_ = clock_;
    // Quiet tail: nothing may move after done.
    const uint64_t tail_end = clock_ + stim_.tail_clocks();
    while (!stop_ && clock_ < tail_end) {
      run_quantum(quantum_end(tail_end), false);
      sync();
    }
    plant_->finish(clock_);
    sc_core::sc_stop();
  }

  const Stimulus& stim_;
  const SequencerConfig cfg_;
  Core* rtl_ = nullptr;
  Core* model_ = nullptr;
  Checker* sb_ = nullptr;
  Plant* plant_ = nullptr;
  Tracer* trace_ = nullptr;
  uint64_t clock_ = 0, synced_clock_ = 0, syncs_ = 0, done_clock_ = 0;
  bool stop_ = false, reached_done_ = false;
};

}  // namespace sc::bench
