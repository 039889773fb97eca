#include "scurve/homing.h"

#include <fmt/format.h>

#include <cmath>

#include "scurve/hw/params.h"
#include "scurve/reg_encode.h"

namespace scurve {

namespace {

constexpr uint32_t bit(int b) { return uint32_t(1) << b; }
constexpr double kMaxPollPeriod = 10.0;  // s
// How long a move may outlast its plan (the controlled stop after it) before
// the board is taken as not answering.
constexpr double kStopAllowance = 10.0;  // s

Error port_error(const Error& e, const std::string& during) {
  return Error{e.parameter, fmt::format("{} during {}", e.message, during)};
}

MoveRequest move_of(const HomingRequest& r, int64_t distance, double speed) {
  MoveRequest m;
  m.distance = distance;
  m.v_cruise = speed;
  m.a_max = r.a_max;
  m.j_max = r.j_max;
  return m;
}

enum class Leg { Seek, Backoff, Index };

std::variant<Plan, Error> plan_leg(const HomingRequest& r, Leg leg, const PulseTiming& timing, Clock clock) {
  const int64_t d = leg == Leg::Seek      ? r.direction * r.max_travel
                    : leg == Leg::Backoff ? -r.direction * r.max_backoff
                                          : -r.direction * r.max_index_travel;
  const PlanResult p = Planner{clock}.plan(move_of(r, d, leg == Leg::Seek ? r.seek_speed : r.latch_speed), timing);
  if (const Error* e = std::get_if<Error>(&p)) {
    const char* name = leg == Leg::Seek ? "seek" : leg == Leg::Backoff ? "back-off" : "index";
    return Error{e->parameter, fmt::format("{} move: {}", name, e->message)};
  }
  return std::get<Plan>(p);
}

class Session {
 public:
  Session(RegisterPort& port, const HomingRequest& req) : port_(port), req_(req) {}
  // CTRL bits the moves keep (CLOSED_LOOP: the servo axis homes in its mode).
  uint32_t ctrl_keep = 0;

  std::optional<Error> write(uint32_t addr, uint32_t data, const char* during) {
    if (auto e = port_.write(addr, data)) return port_error(*e, during);
    return std::nullopt;
  }
  std::variant<uint32_t, Error> read(uint32_t addr, const char* during) {
    auto r = port_.read(addr);
    if (const Error* e = std::get_if<Error>(&r)) return port_error(*e, during);
    return r;
  }

  // Loads and starts `plan`; polls until the latch has captured (then
  // CMD.STOP) and the axis is at rest. Returns whether the latch captured,
  // or an Error.
  std::variant<bool, Error> run_until_latched(const Plan& plan, const PulseTiming& timing, const char* leg) {
    if (auto e = write(hw::RegCmd, bit(hw::CmdFlushBit), leg)) return *e;
    for (const RegWrite& w : encode_move(plan, timing, true)) {
      const uint32_t data = w.addr == uint32_t(hw::RegCtrl) ? (w.data | ctrl_keep) : w.data;
      if (auto e = write(w.addr, data, leg)) return *e;
    }
    bool stop_sent = false;
    bool ever_busy = false;
    const double budget = plan.duration_s + kStopAllowance;
    for (double t = 0; t <= budget; t += req_.poll_period) {
      port_.wait(req_.poll_period);
      auto s = read(hw::RegStatus, leg);
      if (const Error* e = std::get_if<Error>(&s)) return *e;
      const uint32_t status = std::get<uint32_t>(s);
      const bool latched = status & bit(hw::StatusLatchedBit);
      const bool busy = status & bit(hw::StatusBusyBit);
      ever_busy = ever_busy || busy;
      if (latched && busy && !stop_sent) {
        if (auto e = write(hw::RegCmd, bit(hw::CmdStopBit), leg)) return *e;
        stop_sent = true;
      }
      if (!busy) {
        if (latched) return true;
        if (status & bit(hw::StatusDoneBit)) return false;
        auto er = read(hw::RegErr, leg);
        const uint32_t err = std::holds_alternative<uint32_t>(er) ? std::get<uint32_t>(er) : 0;
        return Error{"board", fmt::format("the {} move {} before the latch captured: STATUS=0x{:08x} ERR=0x{:08x} "
                                          "(disabled, e-stopped, a limit or a fault)",
                                          leg, ever_busy ? "stopped" : "was refused", status, err)};
      }
    }
    return Error{"board", fmt::format("the axis is still busy {:.1f} s into the {} move (planned {:.3f} s)", budget,
                                      leg, plan.duration_s)};
  }

 private:
  RegisterPort& port_;
  const HomingRequest& req_;
};

}  // namespace

double exact_latch_speed(uint32_t debounce, uint32_t bounce, Clock clock) {
  // One step interval longer than the latency from the pin to the capture
  // (bounce + debounce + the synchroniser and filter clocks), with margin
  // for the speed's rounding to LSBs.
  return clock.hz / (double(debounce) + double(bounce) + 8.0) * 0.95;
}

std::optional<Error> check_homing_request(const HomingRequest& r, const PulseTiming& timing, Clock clock) {
  if (std::string e = check_clock(clock); !e.empty()) return Error{"clock_hz", e};
  if (r.direction != -1 && r.direction != 1) {
    return Error{"direction", fmt::format("direction={}: needs -1 (home at the negative end) or +1", r.direction)};
  }
  const double rate = step_rate_limit(timing, clock);
  if (!std::isfinite(r.seek_speed) || r.seek_speed <= 0 || r.seek_speed > rate) {
    return Error{"seek_speed", fmt::format("seek_speed={} pulses/s: needs > 0 and <= {} (the step rate the pulse "
                                           "timing allows)",
                                           r.seek_speed, rate)};
  }
  if (!std::isfinite(r.latch_speed) || r.latch_speed <= 0 || r.latch_speed > r.seek_speed) {
    return Error{"latch_speed", fmt::format("latch_speed={} pulses/s: needs > 0 and <= seek_speed={}", r.latch_speed,
                                            r.seek_speed)};
  }
  if (r.max_travel < 1 || r.max_travel > PlannerLimits::kMaxDistance) {
    return Error{"max_travel",
                 fmt::format("max_travel={} pulses: needs 1 .. {}", r.max_travel, PlannerLimits::kMaxDistance)};
  }
  if (r.max_backoff < 1 || r.max_backoff > PlannerLimits::kMaxDistance) {
    return Error{"max_backoff",
                 fmt::format("max_backoff={} pulses: needs 1 .. {}", r.max_backoff, PlannerLimits::kMaxDistance)};
  }
  if (r.max_index_travel < 0 || r.max_index_travel > PlannerLimits::kMaxDistance) {
    return Error{"max_index_travel", fmt::format("max_index_travel={} pulses: needs 0 (no index) .. {}",
                                                 r.max_index_travel, PlannerLimits::kMaxDistance)};
  }
  if (r.offset < -PlannerLimits::kMaxPosition || r.offset > PlannerLimits::kMaxPosition) {
    return Error{"offset", fmt::format("offset={} pulses: needs -{} .. {}", r.offset, PlannerLimits::kMaxPosition,
                                       PlannerLimits::kMaxPosition)};
  }
  if (!std::isfinite(r.poll_period) || r.poll_period <= 0 || r.poll_period > kMaxPollPeriod) {
    return Error{"poll_period", fmt::format("poll_period={} s: needs > 0 and <= {}", r.poll_period, kMaxPollPeriod)};
  }
  for (Leg leg : {Leg::Seek, Leg::Backoff, Leg::Index}) {
    if (leg == Leg::Index && r.max_index_travel == 0) continue;
    auto p = plan_leg(r, leg, timing, clock);
    if (Error* e = std::get_if<Error>(&p)) return *e;
  }
  return std::nullopt;
}

HomingOutcome home(RegisterPort& port, const HomingRequest& req, const PulseTiming& timing, Clock clock) {
  if (auto e = check_homing_request(req, timing, clock)) return *e;
  const Plan seek = std::get<Plan>(plan_leg(req, Leg::Seek, timing, clock));
  const Plan backoff = std::get<Plan>(plan_leg(req, Leg::Backoff, timing, clock));
  Session s(port, req);
  HomingResult out;
  out.offset = req.offset;
  const uint32_t home_level = bit(hw::StatusSwLevelLsb + hw::SwHome);

  auto st = s.read(hw::RegStatus, "the first status read");
  if (const Error* e = std::get_if<Error>(&st)) return *e;
  if (std::get<uint32_t>(st) & bit(hw::StatusBusyBit)) {
    return Error{"board", "the axis is busy: homing starts from rest (CMD.STOP first)"};
  }
  auto ctrl = s.read(hw::RegCtrl, "the first status read");
  if (const Error* e = std::get_if<Error>(&ctrl)) return *e;
  s.ctrl_keep = std::get<uint32_t>(ctrl) & bit(hw::CtrlClosedBit);

  // 1. seek, unless already on the switch
  if (std::get<uint32_t>(st) & home_level) {
    out.seek_skipped = true;
  } else {
    if (auto e = s.write(hw::RegLatchCfg, bit(hw::LatchRiseBit), "the seek")) return *e;
    auto r = s.run_until_latched(seek, timing, "seek");
    if (const Error* e = std::get_if<Error>(&r)) return *e;
    if (!std::get<bool>(r)) {
      return Error{"max_travel", fmt::format("max_travel={} pulses: the seek found no home switch", req.max_travel)};
    }
  }
  auto ref = s.read(hw::RegRefPos, "the seek");
  if (const Error* e = std::get_if<Error>(&ref)) return *e;
  out.seek_stop = int32_t(std::get<uint32_t>(ref));
  st = s.read(hw::RegStatus, "the seek");
  if (const Error* e = std::get_if<Error>(&st)) return *e;
  if (!(std::get<uint32_t>(st) & home_level)) {
    return Error{"seek_speed", fmt::format("seek_speed={} pulses/s: the seek stopped past the home switch (it is "
                                           "inactive at {}); seek slower or stop sooner",
                                           req.seek_speed, out.seek_stop)};
  }

  // 2. back off until the release, latched
  if (auto e = s.write(hw::RegLatchCfg, bit(hw::LatchFallBit), "the back-off")) return *e;
  auto r = s.run_until_latched(backoff, timing, "back-off");
  if (const Error* e = std::get_if<Error>(&r)) return *e;
  if (!std::get<bool>(r)) {
    return Error{"max_backoff",
                 fmt::format("max_backoff={} pulses: the home switch did not release", req.max_backoff)};
  }

  // 3. the zero
  auto lp = s.read(hw::RegLatchPulse, "the zero");
  if (const Error* e = std::get_if<Error>(&lp)) return *e;
  out.latch_pulse = int32_t(std::get<uint32_t>(lp));
  out.release_ref = out.seek_stop + out.latch_pulse;
  out.home_ref = out.release_ref;
  ref = s.read(hw::RegRefPos, "the zero");
  if (const Error* e = std::get_if<Error>(&ref)) return *e;
  out.backoff_stop = int32_t(std::get<uint32_t>(ref));
  if (req.max_index_travel == 0) return out;

  // 4. on to the encoder index, latched on Z rising
  const Plan creep = std::get<Plan>(plan_leg(req, Leg::Index, timing, clock));
  const uint32_t index_rise = bit(hw::LatchRiseBit) | (uint32_t(hw::LatchSrcIndex) << hw::LatchSrcLsb);
  if (auto e = s.write(hw::RegLatchCfg, index_rise, "the index move")) return *e;
  r = s.run_until_latched(creep, timing, "index");
  if (const Error* e = std::get_if<Error>(&r)) return *e;
  if (!std::get<bool>(r)) {
    return Error{"max_index_travel",
                 fmt::format("max_index_travel={} pulses: no encoder index pulse past the release", req.max_index_travel)};
  }
  lp = s.read(hw::RegLatchPulse, "the index move");
  if (const Error* e = std::get_if<Error>(&lp)) return *e;
  auto le = s.read(hw::RegLatchEnc, "the index move");
  if (const Error* e = std::get_if<Error>(&le)) return *e;
  out.on_index = true;
  out.home_ref = out.backoff_stop + int32_t(std::get<uint32_t>(lp));
  out.index_enc = int32_t(std::get<uint32_t>(le));
  return out;
}

}  // namespace scurve
