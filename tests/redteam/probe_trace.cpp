// Print STEP rising edges (clock, interval, phase, pending, velocity) of one
// planned move run on the model; args: the move as in probe output.
#include "rt_util.h"
#include "sim_run.h"

using namespace sc;

int main(int argc, char** argv) {
  MoveRequest r; PulseTiming t;
  r.distance = 63; r.v_start = 187.01773354147682; r.v_cruise = 2222222.222222222; r.v_end = 0;
  r.a_max = 21341866.432203829; r.j_max = 1e11;
  r.jerks = std::array<double, 4>{154725430.95915189, 100000000000, 9300259659.4784851, 100000000000};
  t = PulseTiming{7, 2, 1, 59509};
  const Plan p = std::get<Plan>(plan_move(r, t));
  for (auto& s : p.segments) std::printf("row %-14s clocks %u jerk %lld acc0 %lld vel0 %.3f p/s\n", phase_name(s.phase), s.clocks, (long long)s.jerk, (long long)s.acc0, vel_to_phys(s.vel0));
  AxisCore m;
  CoreInputs in; in.enable = true; in.cfg = t;
  for (const CoreInputs& ci : load_sequence(p.segments, p.pos_frac0, in)) { m.step(ci); in = ci; }
  in.start = false;
  bool last = false; uint64_t lr = 0;
  for (uint64_t c = 0; c < p.total_clocks + 50; ++c) {
    m.step(in);
    const CoreOutputs o = m.outputs();
    if (o.step && !last) {
      std::printf("rise %6llu iv %4llu phase %-14s pend %d v %.1f\n", (unsigned long long)c, (unsigned long long)(c - lr), phase_name(Phase(o.phase)), int(o.step_pending), vel_to_phys(o.ref_vel));
      lr = c;
    }
    last = o.step;
  }
}
