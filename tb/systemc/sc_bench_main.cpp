// sc_bench: the SystemC co-verification bench, temporally decoupled.
//
//   BatchSequencer --CoreIf--> dut   (Verilated --cc RTL, optional FST window)
//                  --CoreIf--> model (bit-exact C++ model)
//                  --ScoreboardIf--> scoreboard (lockstep compare, peaks)
//                  --PlantIf--> plant (open loop: ideal stepper + pin checks)
//                  --TraceIf--> trace (kinematics CSV of RTL and model)
//   signals: sync_clock (sequencer -> dut, model, scoreboard, plant),
//            rtl_done (dut -> sequencer), failed (scoreboard -> sequencer),
//            phase, pulse_count, position (published at each sync)
//
//   sc_bench --group 1 [--json] [--fst w.fst --fst-from N --fst-to M]
//            [--trace-rtl rtl.csv --trace-model model.csv --trace-decimate N]
// Exit codes: 0 pass, 1 a check failed, 2 bad input.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <systemc>

#include "sc_modules.h"

using namespace sc::bench;

int sc_main(int argc, char** argv) {
  quiet_systemc();
  int exit_code = 0;
  std::unique_ptr<BenchRun> run = BenchRun::from_args(argc, argv, true, &exit_code);
  if (!run) return exit_code;
  const BenchOptions& opt = run->options();
  RunStats stats;
  stats.bench = "systemc-batched";
  std::unique_ptr<Core> rtl = make_rtl_cc_core(opt.fst_path, opt.fst_from, opt.fst_to);

  SequencerConfig seq_cfg;
  seq_cfg.quantum = opt.quantum;
  seq_cfg.sync_period = opt.sync_period;
  const bool show_progress = isatty(2) && !opt.json;
  if (show_progress) {
    seq_cfg.progress = [](double f) { std::fprintf(stderr, "\r%5.1f%%", 100 * (f < 1 ? f : 1.0)); };
  }

  sc_core::sc_signal<uint64_t> sync_clock("sync_clock");
  sc_core::sc_signal<bool> rtl_done("rtl_done"), model_done("model_done"), failed("failed");
  sc_core::sc_signal<uint32_t> rtl_phase("rtl_phase"), model_phase("model_phase");
  sc_core::sc_signal<int32_t> rtl_pulses("rtl_pulses"), model_pulses("model_pulses"), position("position");

  CoreModule dut("dut", *rtl);
  CoreModule model("model", run->model());
  ScoreboardModule scoreboard("scoreboard", run->checker());
  PlantModule plant("plant", run->plant());
  BatchSequencer sequencer("sequencer", run->stimulus(), seq_cfg);
  std::unique_ptr<TraceModule> trace;
  if (run->tracer()) {
    trace = std::make_unique<TraceModule>("trace", *run->tracer());
    sequencer.trace(trace->trace_export);
  }
  sequencer.rtl(dut.core_export);
  sequencer.model(model.core_export);
  sequencer.scoreboard(scoreboard.sb_export);
  sequencer.plant(plant.plant_export);
  sequencer.sync_clock_o(sync_clock);
  sequencer.rtl_done_i(rtl_done);
  sequencer.failed_i(failed);
  dut.sync_clock_i(sync_clock);
  dut.done_o(rtl_done);
  dut.phase_o(rtl_phase);
  dut.pulse_count_o(rtl_pulses);
  model.sync_clock_i(sync_clock);
  model.done_o(model_done);
  model.phase_o(model_phase);
  model.pulse_count_o(model_pulses);
  scoreboard.sync_clock_i(sync_clock);
  scoreboard.failed_o(failed);
  plant.sync_clock_i(sync_clock);
  plant.position_o(position);

  const auto t0 = std::chrono::steady_clock::now();
  sc_core::sc_start();
  stats.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (show_progress) std::fputc('\n', stderr);
  stats.done_clock = sequencer.done_clock();
  stats.total_clocks = sequencer.total_clocks();
  stats.syncs = sequencer.syncs();
  stats.reached_done = sequencer.reached_done();
  stats.last_rtl = &rtl->outputs();
  if (const int rc = run->close_outputs(stats.total_clocks, rtl.get())) return rc;
  return run->report(stats);
}

int main(int argc, char** argv) { return run_systemc_main(argc, argv); }
