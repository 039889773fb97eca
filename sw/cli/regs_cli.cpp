#include "scurve/cli/regs_cli.h"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <optional>
#include <nlohmann/json.hpp>

#include "scurve/cli/move_flags.h"

#include "scurve/reg_encode.h"
#include "scurve/servo_config.h"

namespace scurve::cli {

using namespace hw;

void add_regs_flags(CLI::App* cmd, RegsCliFlags& f) {
  cmd->add_flag("--uart", f.uart, "print the UART bridge frames (hex bytes, CRC-8) instead of address = data");
  cmd->add_flag("--no-start", f.no_start, "leave out the final CMD.START write");
  cmd->add_flag("--closed-loop", f.closed_loop,
                "closed-loop axis (board top): write the controller settings (the closed-loop runner's "
                "defaults for this pulse timing) and CTRL.CLOSED_LOOP before the table");
  cmd->add_flag("--guard", f.guard,
                "write the row guards GUARD_VEL / GUARD_ACC / GUARD_JERK from the move's own limits (its largest "
                "speed, --a-max and its jerk limit) after the stop limits");
  add_stop_flags(cmd, f.stop);
  add_retarget_flags(cmd, f.retarget);
}

std::variant<nlohmann::json, Error> regs_to_json(const RegsCliFlags& f, const MoveRequest& request, const Plan& plan,
                                                 const PulseTiming& timing) {
  const auto stop = resolve_stop_flags(f.stop, request, plan);
  if (const std::string* e = std::get_if<std::string>(&stop)) return Error{"stop", *e};
  const StopRequest& sr = std::get<StopRequest>(stop);
  if (sr.at_clock && f.no_start) return Error{"stop_at", "--stop-at: stops a started move; it cannot go with --no-start"};
  const auto rt = resolve_retarget_flags(f.retarget, request, plan, timing);
  if (const std::string* e = std::get_if<std::string>(&rt)) return Error{"retarget", *e};
  const std::optional<RetargetPlan>& retarget = std::get<std::optional<RetargetPlan>>(rt);
  if (retarget && (f.no_start || sr.at_clock)) {
    return Error{"retarget_at", "--retarget-at: redirects a started move; it cannot go with --no-start or --stop-at"};
  }
  std::vector<RegWrite> writes = encode_move(plan, timing, !f.no_start);
  // The stop limits after the pulse timing, before the table: the move's own
  // unless given, so CMD.STOP, an underrun or a discontinuity stop it as planned.
  const std::vector<RegWrite> limits =
      std::get<std::vector<RegWrite>>(encode_stop_limits(sr.limits.jerk, sr.limits.acc, plan.clock));
  const auto after_timing = std::find_if(writes.begin(), writes.end(),
                                         [](const RegWrite& w) { return w.addr == uint32_t(RegDirTime); });
  std::vector<RegWrite> config = limits;
  if (f.guard) {
    const GuardLimitCodesResult g = move_guard_codes(request, plan.clock);
    if (const Error* err = std::get_if<Error>(&g)) return Error{err->parameter, "--guard: " + err->message};
    const std::vector<RegWrite> gw = encode_guard_codes(std::get<GuardLimitCodes>(g));
    config.insert(config.end(), gw.begin(), gw.end());
  }
  // A travel window (--soft-min / --soft-max): also the hardware's soft
  // limits, so a table that would leave it stops at its edge.
  if (request.soft_limits) {
    const SoftLimitWritesResult s = encode_soft_limits(*request.soft_limits);
    if (const Error* err = std::get_if<Error>(&s)) return *err;
    const std::vector<RegWrite>& sw = std::get<std::vector<RegWrite>>(s);
    config.insert(config.end(), sw.begin(), sw.end());
  }
  writes.insert(after_timing + 1, config.begin(), config.end());
  // Writes due at a time after START: the index of the first and the clock.
  std::optional<std::pair<size_t, uint64_t>> due;
  if (sr.at_clock) {
    due = {writes.size(), *sr.at_clock};
    writes.push_back(stop_command());
  }
  if (retarget) {
    due = {writes.size(), uint64_t(std::llround(f.retarget.at * plan.clock.hz))};
    const std::vector<RowFlags> flags = move_row_flags(retarget->plan.segments, true, retarget->acceleration);
    const std::vector<RegWrite> rw = encode_retarget(retarget->row, retarget->plan.segments, flags);
    writes.insert(writes.end(), rw.begin(), rw.end());
  }
  if (f.closed_loop) {
    const double counts_per_step = 1.0;  // the closed-loop runner's default encoder
    const ServoConfigResult r = to_servo_config(ControllerParams{}, counts_per_step, timing, plan.clock);
    if (const Error* err = std::get_if<Error>(&r)) return Error{err->parameter, "--closed-loop: " + err->message};
    std::vector<RegWrite> cl = encode_servo_config(std::get<ServoConfig>(r));
    cl.insert(cl.begin(), RegWrite{uint32_t(RegCtrl), (1u << CtrlEnableBit) | (1u << CtrlClosedBit)});
    writes.erase(writes.begin());  // CTRL = enable: replaced by the closed-loop CTRL write
    writes.insert(writes.begin(), cl.begin(), cl.end());
    if (due) due->first += cl.size() - 1;
  }
  nlohmann::json out = nlohmann::json::array();
  for (size_t i = 0; i < writes.size(); ++i) {
    const RegWrite& w = writes[i];
    nlohmann::json j = {{"addr", w.addr}, {"reg", reg_name(w.addr)}, {"data", w.data}};
    if (due && i == due->first) {
      j["at_clock"] = due->second;  // clocks after the START write takes effect
      j["at_s"] = double(due->second) / plan.clock.hz;
    }
    if (f.uart) {
      // The UART frame (word address in the frame), checked by the encoder.
      FrameResult fr = uart_write_frame(w.addr, w.data);
      if (const Error* err = std::get_if<Error>(&fr)) {
        return Error{err->parameter, "--uart: " + reg_name(w.addr) + ": " + err->message};
      }
      std::string hex;
      for (uint8_t b : std::get<std::vector<uint8_t>>(fr)) hex += fmt::format("{:02X}", b);
      j["frame"] = hex;
    }
    out.push_back(j);
  }
  return out;
}

int run_regs_cli(const RegsCliFlags& f, const MoveRequest& request, const Plan& plan, const PulseTiming& timing,
                 bool json, const std::string& json_out) {
  const auto r = regs_to_json(f, request, plan, timing);
  if (const Error* e = std::get_if<Error>(&r)) return bad_input(e->message);
  const nlohmann::json& out = std::get<nlohmann::json>(r);
  if (!write_json_file(json_out, out)) return bad_input("--json-out: cannot write " + json_out);
  if (json) {
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  for (const nlohmann::json& j : out) {
    const auto addr = j["addr"].get<uint32_t>();
    const auto data = j["data"].get<uint32_t>();
    const std::string reg = j["reg"].get<std::string>();
    if (j.contains("at_clock")) {
      std::cout << fmt::format("# {} s ({} clocks) after START:\n", j["at_s"].get<double>(), j["at_clock"].get<uint64_t>());
    }
    if (f.uart) {
      // The frame holds the word address; the comment names the byte address.
      const std::string hex = j["frame"].get<std::string>();
      std::string spaced;
      for (size_t i = 0; i < hex.size(); i += 2) spaced += hex.substr(i, 2) + " ";
      std::cout << fmt::format("{} # {} (0x{:03X}) = 0x{:08X}\n", spaced, reg, addr, data);
    } else {
      std::cout << fmt::format("0x{:03X} {:<12} 0x{:08X}\n", addr, reg, data);
    }
  }
  return 0;
}

}  // namespace scurve::cli
