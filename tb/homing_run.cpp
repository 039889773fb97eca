#include "homing_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "axi_bench.h"
#include "planner.h"
#include "scurve/hw/params.h"
#include "scurve/reg_encode.h"
#include "switch_plant.h"

namespace sc {

namespace {

// The host library's register port on the bench: transactions through the
// AXI master, time as clocks of the bench.
class BenchPort : public scurve::RegisterPort {
 public:
  explicit BenchPort(AxiBench& b) : b_(b) {}
  std::optional<scurve::Error> write(uint32_t addr, uint32_t data) override {
    const uint8_t resp = b_.write(addr, data);
    if (b_.failed()) return scurve::Error{"bench", b_.error()};
    if (resp != kOkay) {
      return scurve::Error{"board", fmt::format("write {} = 0x{:08x} answered {}", scurve::reg_name(addr), data,
                                                resp == kSlvErr ? "SLVERR" : "DECERR")};
    }
    return std::nullopt;
  }
  std::variant<uint32_t, scurve::Error> read(uint32_t addr) override {
    const auto [v, resp] = b_.read(addr);
    if (b_.failed()) return scurve::Error{"bench", b_.error()};
    if (resp != kOkay) {
      return scurve::Error{"board", fmt::format("read {} answered {}", scurve::reg_name(addr),
                                                resp == kSlvErr ? "SLVERR" : "DECERR")};
    }
    return v;
  }
  void wait(double seconds) override { b_.idle(uint64_t(std::llround(seconds * double(ClkHz)))); }

 private:
  AxiBench& b_;
};

}  // namespace

HomingSimResult run_homing_sim(const HomingSimConfig& c) {
  HomingSimResult out;
  out.switch_at = c.switch_at;
  out.bounce = c.bounce;
  const int dir = c.request.direction;
  AxiBench b(c.lockstep, uint32_t(c.seed));
  b.reset();
  SwitchPlant plant(c.switch_at, dir, int(c.bounce), false, c.seed);
  plant.set_noise(c.noise_rate, int(c.noise_clocks));
  out.release_point = plant.release_point();
  b.set_switch_pins([&plant](int64_t pos) { return uint8_t(plant.pin(pos) ? 1u << scurve::hw::SwHome : 0u); });
  const int64_t index_at = c.index_at ? *c.index_at : out.release_point - dir * (c.index_period / 2);
  auto is_index = [&c, index_at](int64_t pos) {
    return c.index_period > 0 && (pos - index_at) % c.index_period == 0;
  };
  if (c.index_period > 0) {
    b.set_encoder([&is_index](int64_t pos) { return AxiBench::Encoder{int32_t(pos), is_index(pos)}; });
  }
  b.idle(4);

  BenchPort port(b);
  auto setup = [&]() -> std::optional<scurve::Error> {
    const uint32_t sw_cfg = (uint32_t(1) << scurve::hw::SwLimEnBit) | (c.debounce << scurve::hw::SwDebounceLsb);
    if (auto e = port.write(scurve::hw::RegSwCfg, sw_cfg)) return e;
    const auto w = scurve::encode_stop_limits(c.stop_jerk, c.stop_acc);
    if (const scurve::Error* e = std::get_if<scurve::Error>(&w)) return *e;
    for (const scurve::RegWrite& r : std::get<std::vector<scurve::RegWrite>>(w)) {
      if (auto e = port.write(r.addr, r.data)) return e;
    }
    if (auto e = port.write(scurve::hw::RegCtrl, uint32_t(1) << scurve::hw::CtrlEnableBit)) return e;
    port.wait(double(c.debounce + c.bounce + 10) / double(ClkHz));  // the filter has seen the pins
    return std::nullopt;
  };
  if (auto e = setup()) {
    out.error = e->message;
  } else {
    const scurve::HomingOutcome r = scurve::home(port, c.request, c.timing);
    if (const scurve::Error* e = std::get_if<scurve::Error>(&r)) {
      out.error = fmt::format("{}: {}", e->parameter, e->message);
    } else {
      out.homed = true;
      out.result = std::get<scurve::HomingResult>(r);
      out.zero_point = out.release_point;
      if (out.result.on_index) {
        // Z rises on entering an index count: the first one past where the
        // back-off came to rest, in the creep's direction.
        int64_t p = out.result.backoff_stop - dir;
        while (!is_index(p) && std::abs(p - out.result.backoff_stop) <= c.index_period) p -= dir;
        out.index_point = p;
        out.zero_point = p;
        if (out.result.index_enc != p) {
          out.error = fmt::format("LATCH_ENC {} at the index, the encoder's index count is {}", out.result.index_enc, p);
        }
      }
      out.zero_error = out.result.home_ref - out.zero_point;
      // At rest the pins and the reference agree (no step lost or invented).
      port.wait(double(c.timing.high + c.timing.low + c.timing.setup + c.timing.hold) / double(ClkHz));
      auto ref = port.read(scurve::hw::RegRefPos);
      if (const scurve::Error* e = std::get_if<scurve::Error>(&ref)) {
        out.error = e->message;
      } else {
        out.ref_pos = int32_t(std::get<uint32_t>(ref));
      }
    }
  }
  if (b.failed() && out.error.empty()) out.error = b.error();
  out.pins = b.net_steps();
  out.clocks = b.clock();
  out.glitches = plant.glitches();
  out.matched_clocks = b.matched();
  return out;
}

HomingSummary summarize(const std::vector<HomingSimResult>& runs) {
  HomingSummary s;
  bool first = true;
  for (const HomingSimResult& r : runs) {
    ++s.runs;
    if (!r.pass()) continue;
    ++s.passed;
    s.zero_min = first ? r.zero_error : std::min(s.zero_min, r.zero_error);
    s.zero_max = first ? r.zero_error : std::max(s.zero_max, r.zero_error);
    first = false;
  }
  return s;
}

std::string homing_table(const std::vector<HomingSimResult>& runs) {
  std::string t = fmt::format("{:>4} {:>9} {:>7} {:>10} {:>10} {:>10} {:>9} {:>8} {:>11}  {}\n", "run", "switch",
                              "bounce", "seek stop", "home ref", "zero at", "zero err", "glitches", "clocks",
                              "result");
  for (size_t i = 0; i < runs.size(); ++i) {
    const HomingSimResult& r = runs[i];
    t += fmt::format("{:>4} {:>9} {:>7} {:>10} {:>10} {:>10} {:>9} {:>8} {:>11}  {}\n", i + 1, r.switch_at, r.bounce,
                     r.homed ? std::to_string(r.result.seek_stop) : "-",
                     r.homed ? std::to_string(r.result.home_ref) : "-", r.homed ? r.zero_point : r.release_point,
                     r.homed ? std::to_string(r.zero_error) : "-", r.glitches, r.clocks,
                     r.pass() ? "ok" : (r.error.empty() ? "pins != REF_POS" : r.error));
  }
  const HomingSummary s = summarize(runs);
  t += fmt::format("homed {}/{}; zero error {} .. {} pulses (spread {})\n", s.passed, s.runs, s.zero_min, s.zero_max,
                   s.spread());
  return t;
}

nlohmann::json homing_to_json(const std::vector<HomingSimResult>& runs, bool lockstep) {
  nlohmann::json j;
  j["engine"] = lockstep ? "lockstep" : "model";
  j["runs"] = nlohmann::json::array();
  for (const HomingSimResult& r : runs) {
    nlohmann::json x;
    x["switch_at"] = r.switch_at;
    x["release_point"] = r.release_point;
    x["bounce_clocks"] = r.bounce;
    x["homed"] = r.homed;
    if (!r.error.empty()) x["error"] = r.error;
    if (r.homed) {
      x["seek_stop"] = r.result.seek_stop;
      x["seek_skipped"] = r.result.seek_skipped;
      x["backoff_stop"] = r.result.backoff_stop;
      x["latch_pulse"] = r.result.latch_pulse;
      x["release_ref"] = r.result.release_ref;
      x["home_ref"] = r.result.home_ref;
      x["zero_point"] = r.zero_point;
      if (r.result.on_index) {
        x["index_point"] = r.index_point;
        x["index_enc"] = r.result.index_enc;
      }
      x["zero_error"] = r.zero_error;
      x["machine_position_at_rest"] = r.result.machine_position(r.ref_pos);
    }
    x["pins"] = r.pins;
    x["ref_pos"] = r.ref_pos;
    x["glitches"] = r.glitches;
    x["clocks"] = r.clocks;
    x["matched_clocks"] = r.matched_clocks;
    x["pass"] = r.pass();
    j["runs"].push_back(x);
  }
  const HomingSummary s = summarize(runs);
  j["homed"] = s.passed;
  j["zero_error_min"] = s.zero_min;
  j["zero_error_max"] = s.zero_max;
  j["spread"] = s.spread();
  j["pass"] = s.passed == s.runs;
  return j;
}

}  // namespace sc
