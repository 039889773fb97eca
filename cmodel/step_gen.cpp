#include "step_gen.h"

namespace sc {

namespace {
inline uint16_t sat_inc(uint16_t v) { return v == StepGen::kCntMax ? v : uint16_t(v + 1); }
inline uint16_t sat_add(uint16_t v, uint64_t k) {
  const uint64_t s = uint64_t(v) + k;
  return s >= StepGen::kCntMax ? StepGen::kCntMax : uint16_t(s);
}
}  // namespace

static_assert(PulseTimeW == 16, "StepGen::State holds the timers in uint16_t");
static_assert(PendW <= 8, "StepGen::State holds the queue in int8_t");

void StepGen::step(const Inputs& in) {
  const bool have = q_.pend != 0;
  const bool want_fwd = q_.pend >= 0;
  const bool dir_ok = q_.dir == want_fwd;
  const bool rise = have && dir_ok && !q_.step && q_.low_cnt >= in.cfg.low &&
                    q_.since_dir >= in.cfg.setup;
  const bool flip = !q_.step && q_.since_rise >= in.cfg.hold &&
                    (have ? !dir_ok : (in.dir_hint_valid && in.dir_hint != q_.dir));

  // Updated in place (every right-hand side below reads a field before it is
  // written): copying the whole State per clock costs a store-forwarding
  // stall on the byte fields.
  const bool step_q = q_.step;
  const uint16_t high_left_q = q_.high_left;
  int pend = q_.pend;
  q_.since_dir = sat_inc(q_.since_dir);
  q_.since_rise = sat_inc(q_.since_rise);
  if (rise) {
    q_.step = true;
    q_.high_left = in.cfg.high;
    q_.since_rise = 1;
    pend += q_.dir ? -1 : 1;
    q_.count = add_wrap32(q_.count, q_.dir ? 1 : -1);
  } else if (step_q) {
    q_.high_left = uint16_t(high_left_q - 1);
    if (high_left_q <= 1) q_.step = false;
  }
  if (flip) {
    q_.dir = !q_.dir;
    q_.since_dir = 1;
  }
  if (in.step_req) {
    const bool blocked = in.step_fwd ? pend == kPendMax : pend == kPendMin;
    if (blocked) {
      q_.overrun = true;
    } else {
      pend += in.step_fwd ? 1 : -1;
    }
  }
  q_.pend = int8_t(pend);
  q_.low_cnt = q_.step ? 0 : sat_inc(q_.low_cnt);
  if (in.clear) {
    q_.overrun = false;
    q_.count = 0;
  }
}

void StepGen::jump_idle(uint64_t k) {
  q_.low_cnt = sat_add(q_.low_cnt, k);
  q_.since_rise = sat_add(q_.since_rise, k);
  q_.since_dir = sat_add(q_.since_dir, k);
}

}  // namespace sc
