// The open-loop core (sc_axis_core) with a planned move's rows loaded and
// not started, RTL and model in lockstep every clock; shared by the stop and
// the directed core tests.
#pragma once

#include <cstdint>
#include <variant>

#include "lockstep.h"
#include "planner.h"
#include "rtl_core.h"
#include "stop_harness.h"

namespace sc::stoptest {

inline uint64_t jerk_lsb(ld j) { return uint64_t(j * kLsb / (kF * kF * kF)); }
inline uint64_t acc_lsb(ld a) { return uint64_t(a * kLsb / (kF * kF)); }

struct LoadedCore {
  RtlCore rtl;
  AxisCore model;
  LockstepChecker chk;
  CoreInputs in;
  uint64_t clock = 0;
  Plan plan;
  // A move of `distance` pulses at 40,000 pulses/s with these limits, which
  // are also the stop limits.
  explicit LoadedCore(int64_t distance, double a_max = 4e6, double j_max = 4e9) {
    rtl.reset();
    MoveRequest req;
    req.distance = distance;
    req.v_cruise = 40000;
    req.a_max = a_max;
    req.j_max = j_max;
    plan = std::get<Plan>(plan_move(req, PulseTiming{}));
    in.enable = true;
    in.cfg = PulseTiming{};
    in.pos_frac0 = plan.pos_frac0;
    in.stop_jerk = jerk_lsb(j_max);
    in.stop_acc = acc_lsb(a_max);
    for (const Row& r : move_rows(plan.segments)) {
      CoreInputs w = in;
      w.row_push = true;
      w.row = r;
      tick(w);
    }
  }
  void tick(const CoreInputs& ci) {
    rtl.step(ci);
    model.step(ci);
    chk.compare(clock++, rtl.outputs(), model.outputs());
  }
  void tick() { tick(in); }
  CoreOutputs out() const { return rtl.outputs(); }
  // START, then the clock after it.
  void start() {
    CoreInputs s = in;
    s.start = true;
    tick(s);
    tick();
  }
};

}  // namespace sc::stoptest
