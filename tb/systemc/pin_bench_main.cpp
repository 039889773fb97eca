// sc_bench_pin: the same bench with a pin-accurate DUT - the RTL verilated
// with --sc, clocked by an sc_clock, every port an sc_signal - to measure
// what per-clock SystemC scheduling costs next to the batched sc_bench
// (DESIGN.md: ~3.5 M clocks/s) and to cross-check the batched wiring.
//
//   PinSequencer (SC_THREAD on the falling edge) --sc_signals--> dut (Vsc_axis_core_pin)
//        drives inputs for the next rising edge, samples outputs settled after it;
//        --CoreIf--> model, --ScoreboardIf--> scoreboard, --PlantIf--> plant,
//        --TraceIf--> trace (the same modules as sc_bench)
#include <chrono>
#include <cstdio>
#include <systemc>

#include "Vsc_axis_core_pin.h"
#include "sc_modules.h"

using namespace sc::bench;
using sc::CoreInputs;
using sc::CoreOutputs;
using sc_core::sc_in;
using sc_core::sc_out;
using sc_core::sc_signal;

namespace {

// Port widths of sc_axis_core (rtl/sc_pkg.sv: VelW = 81, FracBits = 80).
constexpr int kVelW = 81;
constexpr int kFracW = 80;
using VelBv = sc_dt::sc_bv<kVelW>;
using FracBv = sc_dt::sc_bv<kFracW>;

template <int N>
sc_dt::sc_bv<N> to_bv(const uint32_t* w) {
  sc_dt::sc_bv<N> bv;
  for (int i = 0; i * 32 < N; ++i) bv.set_word(i, w[i]);
  return bv;
}
template <int N>
void from_bv(const sc_dt::sc_bv<N>& bv, uint32_t* w) {
  for (int i = 0; i * 32 < N; ++i) w[i] = bv.get_word(i);
}

class PinSequencer : public sc_core::sc_module {
 public:
  sc_in<bool> clk_i;
  sc_core::sc_port<CoreIf> model;
  sc_core::sc_port<ScoreboardIf> scoreboard;
  sc_core::sc_port<PlantIf> plant;
  sc_core::sc_port<TraceIf, 1, sc_core::SC_ZERO_OR_MORE_BOUND> trace;

  sc_out<bool> rst_no, enable_o, row_push_o, fifo_flush_o, start_o, abort_o, stop_o;
  sc_out<uint64_t> stop_jerk_o, stop_acc_o;
  sc_out<uint32_t> cfg_high_o, cfg_low_o, cfg_setup_o, cfg_hold_o;
  sc_out<uint32_t> row_flags_o, seg_phase_o, seg_clocks_o;
  sc_out<uint64_t> seg_jerk_o, seg_acc0_o;
  sc_out<VelBv> seg_vel0_o;
  sc_out<FracBv> pos_frac0_o;

  sc_in<bool> step_i, dir_i, en_i, busy_i, done_i, fault_table_i, fault_overrun_i;
  sc_in<bool> underrun_i, discont_i, move_done_i, fifo_full_i, stopping_i, overshoot_i, retarget_refused_i;
  sc_in<uint32_t> row_count_i;
  sc_in<uint32_t> phase_i, pulse_count_i, ref_pos_int_i, seg_idx_i, step_pending_i;
  sc_in<uint32_t> move_idx_i, boundary_pos_i, fifo_level_i;
  sc_in<uint64_t> ref_acc_i, ref_jerk_i;
  sc_in<FracBv> ref_pos_frac_i;
  sc_in<VelBv> ref_vel_i;

  PinSequencer(sc_core::sc_module_name name, const Stimulus& stim, PinCore& pins)
      : sc_module(name), stim_(stim), pins_(pins) {
    SC_HAS_PROCESS(PinSequencer);
    SC_THREAD(run);
    sensitive << clk_i.neg();
  }
  bool reached_done = false;
  uint64_t done_clock = 0, total_clocks = 0;

 private:
  void drive(const CoreInputs& in) {
    PinInputs p;
    PinCore::encode(in, &p);
    enable_o.write(p.enable);
    cfg_high_o.write(p.cfg_high);
    cfg_low_o.write(p.cfg_low);
    cfg_setup_o.write(p.cfg_setup);
    cfg_hold_o.write(p.cfg_hold);
    row_push_o.write(p.row_push);
    fifo_flush_o.write(p.fifo_flush);
    row_flags_o.write(p.row_flags);
    seg_phase_o.write(p.seg_phase);
    seg_clocks_o.write(p.seg_clocks);
    seg_jerk_o.write(p.seg_jerk);
    seg_acc0_o.write(p.seg_acc0);
    seg_vel0_o.write(to_bv<kVelW>(p.seg_vel0));
    pos_frac0_o.write(to_bv<kFracW>(p.pos_frac0));
    start_o.write(p.start);
    abort_o.write(p.abort);
    stop_o.write(p.stop);
    stop_jerk_o.write(p.stop_jerk);
    stop_acc_o.write(p.stop_acc);
  }
  void sample() {
    PinOutputs p;
    p.step = step_i.read();
    p.dir = dir_i.read();
    p.en = en_i.read();
    p.busy = busy_i.read();
    p.done = done_i.read();
    p.fault_table = fault_table_i.read();
    p.fault_overrun = fault_overrun_i.read();
    p.underrun = underrun_i.read();
    p.discont = discont_i.read();
    p.stopping = stopping_i.read();
    p.overshoot = overshoot_i.read();
    p.move_done = move_done_i.read();
    p.fifo_full = fifo_full_i.read();
    p.row_count = row_count_i.read();
    p.retarget_refused = retarget_refused_i.read();
    p.move_idx = move_idx_i.read();
    p.boundary_pos = boundary_pos_i.read();
    p.fifo_level = fifo_level_i.read();
    p.phase = phase_i.read();
    p.pulse_count = pulse_count_i.read();
    p.ref_pos_int = ref_pos_int_i.read();
    p.seg_idx = seg_idx_i.read();
    p.step_pending = step_pending_i.read();
    p.ref_acc = ref_acc_i.read();
    p.ref_jerk = ref_jerk_i.read();
    from_bv<kFracW>(ref_pos_frac_i.read(), p.ref_pos_frac);
    from_bv<kVelW>(ref_vel_i.read(), p.ref_vel);
    pins_.latch(p);
  }
  // One clock: drive `in` for the coming rising edge and step the model with
  // it; at the falling edge after it, sample the DUT and compare.
  void clock(const CoreInputs& in) {
    drive(in);
    model_->step(in);
    wait();
    sample();
    const CoreOutputs& r = pins_.outputs();
    if (!sb_->compare(clock_, r) && sb_->should_stop()) stop_ = true;
    plant_->on_clock(clock_, r);
    if (trace_) trace_->on_clock(clock_, r, model_->outputs());
    ++clock_;
  }
  void run() {
    model_ = &model->core();
    sb_ = &scoreboard->checker();
    plant_ = &plant->plant();
    trace_ = trace.size() ? &trace->tracer() : nullptr;
    rst_no.write(false);
    for (int i = 0; i < 4; ++i) wait();
    rst_no.write(true);
    model_->reset(4);
    for (size_t i = 0; i < stim_.rows() && !stop_; ++i) clock(stim_.row_write(i));
    if (!stop_) clock(stim_.start());
    const CoreInputs& in = stim_.run();
    const uint64_t limit = clock_ + stim_.max_move_clocks();
    while (!stop_ && clock_ < limit && !pins_.done()) clock(in);
    reached_done = pins_.done();
    done_clock = clock_;
    const uint64_t tail_end = clock_ + stim_.tail_clocks();
    while (!stop_ && clock_ < tail_end) clock(in);
    total_clocks = clock_;
    plant_->finish(clock_);
    sc_core::sc_stop();
  }

  const Stimulus& stim_;
  PinCore& pins_;
  Core* model_ = nullptr;
  Checker* sb_ = nullptr;
  Plant* plant_ = nullptr;
  Tracer* trace_ = nullptr;
  uint64_t clock_ = 0;
  bool stop_ = false;
};

}  // namespace

int sc_main(int argc, char** argv) {
  quiet_systemc();
  int exit_code = 0;
  std::unique_ptr<BenchRun> run = BenchRun::from_args(argc, argv, false, &exit_code);
  if (!run) return exit_code;
  RunStats stats;
  stats.bench = "systemc-pin";
  std::unique_ptr<PinCore> pins = make_pin_core();

  sc_core::sc_clock clk("clk", sc_core::sc_time(50, sc_core::SC_NS));
  sc_signal<bool> rst_n("rst_n"), enable("enable"), row_push("row_push"), fifo_flush("fifo_flush"), start("start"),
      abort_sig("abort"), stop_sig("stop");
  sc_signal<uint64_t> stop_jerk("stop_jerk"), stop_acc("stop_acc");
  sc_signal<uint32_t> cfg_high("cfg_high"), cfg_low("cfg_low"), cfg_setup("cfg_setup"), cfg_hold("cfg_hold");
  sc_signal<uint32_t> row_flags("row_flags"), seg_phase("seg_phase"), seg_clocks("seg_clocks");
  sc_signal<uint64_t> seg_jerk("seg_jerk"), seg_acc0("seg_acc0");
  sc_signal<VelBv> seg_vel0("seg_vel0");
  sc_signal<FracBv> pos_frac0("pos_frac0");
  sc_signal<bool> step("step"), dir("dir"), en("en"), busy("busy"), done("done"), fault_table("fault_table"),
      fault_overrun("fault_overrun"), underrun("underrun"), discont("discont"), move_done("move_done"),
      fifo_full("fifo_full"), stopping("stopping"), overshoot("overshoot");
  sc_signal<uint32_t> phase("phase"), pulse_count("pulse_count"), ref_pos_int("ref_pos_int"), seg_idx("seg_idx"),
      step_pending("step_pending"), move_idx("move_idx"), boundary_pos("boundary_pos"), fifo_level("fifo_level");
  sc_signal<uint64_t> ref_acc("ref_acc"), ref_jerk("ref_jerk");
  // Retarget ports: this bench runs single moves, no replace.
  sc_signal<bool> row_replace("row_replace"), retarget_refused("retarget_refused");
  sc_signal<uint32_t> retarget_row("retarget_row"), row_count("row_count");
  sc_signal<FracBv> ref_pos_frac("ref_pos_frac");
  sc_signal<VelBv> ref_vel("ref_vel");
  // Nothing drives clock_count here: every clock is already a SystemC
  // synchronisation point, so the modules' publish methods stay idle.
  sc_signal<uint64_t> clock_count("clock_count");
  sc_signal<bool> model_done("model_done"), failed("failed");
  sc_signal<uint32_t> model_phase("model_phase");
  sc_signal<int32_t> model_pulses("model_pulses"), position("position");

  Vsc_axis_core_pin dut("dut");
  dut.clk_i(clk);
  dut.rst_ni(rst_n);
  dut.enable_i(enable);
  dut.cfg_high_i(cfg_high);
  dut.cfg_low_i(cfg_low);
  dut.cfg_setup_i(cfg_setup);
  dut.cfg_hold_i(cfg_hold);
  dut.row_push_i(row_push);
  dut.row_replace_i(row_replace);
  dut.retarget_row_i(retarget_row);
  dut.row_flags_i(row_flags);
  dut.row_phase_i(seg_phase);
  dut.row_clocks_i(seg_clocks);
  dut.row_jerk_i(seg_jerk);
  dut.row_acc0_i(seg_acc0);
  dut.row_vel0_i(seg_vel0);
  dut.fifo_flush_i(fifo_flush);
  dut.pos_frac0_i(pos_frac0);
  dut.start_i(start);
  dut.abort_i(abort_sig);
  dut.stop_i(stop_sig);
  dut.stop_jerk_i(stop_jerk);
  dut.stop_acc_i(stop_acc);
  // No external step source on the plain core (ExtStep = 0): one constant
  // low signal for every ext_* input (and the limit inputs); the extra
  // outputs are not observed.
  sc_signal<bool> ext_off("ext_off");
  sc_signal<bool> exec_start("exec_start"), abort_q("abort_q"), ref_done("ref_done"), ref_running("ref_running"),
      step_busy("step_busy");
  sc_signal<bool> start_able("start_able"), arm_ready("arm_ready"), arm_drop("arm_drop"), fault_abort("fault_abort"),
      arming("arming");
  dut.ext_sel_i(ext_off);
  dut.ext_req_i(ext_off);
  dut.ext_fwd_i(ext_off);
  dut.ext_hint_valid_i(ext_off);
  dut.ext_hint_i(ext_off);
  dut.ext_busy_i(ext_off);
  dut.ext_abort_i(ext_off);
  dut.ext_done_i(ext_off);
  dut.sync_start_ok_i(ext_off);  // one axis: no start synchronisation
  dut.sync_go_i(ext_off);
  dut.sync_drop_i(ext_off);
  dut.sync_reach_veto_i(ext_off);
  sc_signal<bool> reach_bad("reach_bad");
  dut.reach_bad_o(reach_bad);
  // No limit switches, no guard limits (0 = none) and no soft limits on this bench.
  sc_signal<VelBv> guard_vel("guard_vel");
  sc_signal<uint64_t> guard_acc("guard_acc"), guard_jerk("guard_jerk");
  sc_signal<bool> guard("guard");
  dut.guard_vel_i(guard_vel);
  dut.guard_acc_i(guard_acc);
  dut.guard_jerk_i(guard_jerk);
  dut.guard_o(guard);
  // no soft-limit window
  sc_signal<uint32_t> soft_min("soft_min"), soft_max("soft_max");
  sc_signal<bool> reach("reach");
  dut.soft_en_i(ext_off);
  dut.soft_min_i(soft_min);
  dut.soft_max_i(soft_max);
  dut.reach_o(reach);
  // the core's own row reach evaluator (OwnReach): its outside ports unused
  sc_signal<bool> rc_start("rc_start"), rc_abort("rc_abort");
  sc_signal<uint32_t> rc_clocks("rc_clocks");
  sc_signal<uint64_t> rc_jerk("rc_jerk"), rc_acc0("rc_acc0"), rc_fwd("rc_fwd"), rc_rev("rc_rev");
  sc_signal<VelBv> rc_vel0("rc_vel0");
  dut.rc_start_o(rc_start);
  dut.rc_abort_o(rc_abort);
  dut.rc_clocks_o(rc_clocks);
  dut.rc_jerk_o(rc_jerk);
  dut.rc_acc0_o(rc_acc0);
  dut.rc_vel0_o(rc_vel0);
  dut.rc_busy_i(ext_off);
  dut.rc_done_i(ext_off);
  dut.rc_fwd_i(rc_fwd);
  dut.rc_rev_i(rc_rev);
  dut.lim_fwd_i(ext_off);
  dut.lim_rev_i(ext_off);
  dut.lim_hard_i(ext_off);
  sc_signal<bool> lim_trip_fwd("lim_trip_fwd"), lim_trip_rev("lim_trip_rev");
  dut.lim_trip_fwd_o(lim_trip_fwd);
  dut.lim_trip_rev_o(lim_trip_rev);
  dut.exec_start_o(exec_start);
  dut.start_able_o(start_able);
  dut.arm_ready_o(arm_ready);
  dut.arm_drop_o(arm_drop);
  dut.fault_abort_o(fault_abort);
  dut.arming_o(arming);
  dut.abort_o(abort_q);
  dut.ref_done_o(ref_done);
  dut.ref_running_o(ref_running);
  dut.step_busy_o(step_busy);
  dut.step_o(step);
  dut.dir_o(dir);
  dut.en_o(en);
  dut.busy_o(busy);
  dut.done_o(done);
  dut.phase_o(phase);
  dut.fault_table_o(fault_table);
  dut.fault_overrun_o(fault_overrun);
  dut.underrun_o(underrun);
  dut.discont_o(discont);
  dut.stopping_o(stopping);
  dut.overshoot_o(overshoot);
  dut.move_done_o(move_done);
  dut.move_idx_o(move_idx);
  dut.boundary_pos_o(boundary_pos);
  dut.fifo_level_o(fifo_level);
  dut.fifo_full_o(fifo_full);
  dut.row_count_o(row_count);
  dut.retarget_refused_o(retarget_refused);
  dut.pulse_count_o(pulse_count);
  dut.ref_pos_int_o(ref_pos_int);
  dut.ref_pos_frac_o(ref_pos_frac);
  dut.ref_vel_o(ref_vel);
  dut.ref_acc_o(ref_acc);
  dut.ref_jerk_o(ref_jerk);
  dut.seg_idx_o(seg_idx);
  dut.step_pending_o(step_pending);

  CoreModule model("model", run->model());
  ScoreboardModule scoreboard("scoreboard", run->checker());
  PlantModule plant("plant", run->plant());
  PinSequencer seq("sequencer", run->stimulus(), *pins);
  std::unique_ptr<TraceModule> trace;
  if (run->tracer()) {
    trace = std::make_unique<TraceModule>("trace", *run->tracer());
    seq.trace(trace->trace_export);
  }
  seq.clk_i(clk);
  seq.model(model.core_export);
  seq.scoreboard(scoreboard.sb_export);
  seq.plant(plant.plant_export);
  seq.rst_no(rst_n);
  seq.enable_o(enable);
  seq.row_push_o(row_push);
  seq.fifo_flush_o(fifo_flush);
  seq.start_o(start);
  seq.abort_o(abort_sig);
  seq.stop_o(stop_sig);
  seq.stop_jerk_o(stop_jerk);
  seq.stop_acc_o(stop_acc);
  seq.cfg_high_o(cfg_high);
  seq.cfg_low_o(cfg_low);
  seq.cfg_setup_o(cfg_setup);
  seq.cfg_hold_o(cfg_hold);
  seq.row_flags_o(row_flags);
  seq.seg_phase_o(seg_phase);
  seq.seg_clocks_o(seg_clocks);
  seq.seg_jerk_o(seg_jerk);
  seq.seg_acc0_o(seg_acc0);
  seq.seg_vel0_o(seg_vel0);
  seq.pos_frac0_o(pos_frac0);
  seq.step_i(step);
  seq.dir_i(dir);
  seq.en_i(en);
  seq.busy_i(busy);
  seq.done_i(done);
  seq.fault_table_i(fault_table);
  seq.fault_overrun_i(fault_overrun);
  seq.underrun_i(underrun);
  seq.discont_i(discont);
  seq.stopping_i(stopping);
  seq.overshoot_i(overshoot);
  seq.move_done_i(move_done);
  seq.fifo_full_i(fifo_full);
  seq.row_count_i(row_count);
  seq.retarget_refused_i(retarget_refused);
  seq.move_idx_i(move_idx);
  seq.boundary_pos_i(boundary_pos);
  seq.fifo_level_i(fifo_level);
  seq.phase_i(phase);
  seq.pulse_count_i(pulse_count);
  seq.ref_pos_int_i(ref_pos_int);
  seq.seg_idx_i(seg_idx);
  seq.step_pending_i(step_pending);
  seq.ref_acc_i(ref_acc);
  seq.ref_jerk_i(ref_jerk);
  seq.ref_pos_frac_i(ref_pos_frac);
  seq.ref_vel_i(ref_vel);
  model.sync_clock_i(clock_count);
  model.done_o(model_done);
  model.phase_o(model_phase);
  model.pulse_count_o(model_pulses);
  scoreboard.sync_clock_i(clock_count);
  scoreboard.failed_o(failed);
  plant.sync_clock_i(clock_count);
  plant.position_o(position);

  const auto t0 = std::chrono::steady_clock::now();
  sc_core::sc_start();
  stats.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  stats.done_clock = seq.done_clock;
  stats.total_clocks = seq.total_clocks;
  stats.syncs = seq.total_clocks;
  stats.reached_done = seq.reached_done;
  stats.last_rtl = &pins->outputs();
  if (const int rc = run->close_outputs(stats.total_clocks, nullptr)) return rc;
  return run->report(stats);
}

int main(int argc, char** argv) { return run_systemc_main(argc, argv); }
