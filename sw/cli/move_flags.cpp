#include "scurve/cli/move_flags.h"
#include "scurve/cli/user_input.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

namespace scurve::cli {

// Ranges of the move itself are the planner's, checked there.
using input::kAnyReal;

CLI::Option* real_flag(CLI::App* app, const char* flag, double& target, const std::string& what, double lo,
                       double hi) {
  return app->add_option_function<std::string>(
      flag,
      [&target, flag, lo, hi](const std::string& v) {
        try {
          target = input::parse_real(flag + 2, v, lo, hi);
        } catch (const input::Error& e) {
          throw CLI::ValidationError(e.what());
        }
      },
      what)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

CLI::Option* output_file_flag(CLI::App* app, const char* flag, std::string& target, const std::string& what) {
  return app->add_option_function<std::string>(
      flag,
      [&target, flag](const std::string& v) {
        try {
          input::output_path(flag + 2, v);
        } catch (const input::Error& e) {
          throw CLI::ValidationError(e.what());
        }
        target = v;
      },
      what)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

void add_move_flags(CLI::App* app, MoveFlags& f, std::vector<CLI::Option*>* move_opts) {
  std::vector<CLI::Option*> opts;
  const int64_t max_distance = PlannerLimits::kMaxDistance;
  opts.push_back(int_flag(app, "--distance", f.distance, -max_distance, max_distance,
                          "move length in pulses (sign = direction)"));
  opts.back()->each([&f](const std::string&) { f.distance_given = true; });
  opts.push_back(real_flag(app, "--v-start", f.v_start, "start speed, pulses/s"));
  opts.push_back(real_flag(app, "--v-cruise", f.v_cruise, "cruise speed, pulses/s"));
  opts.push_back(real_flag(app, "--v-end", f.v_end, "end speed, pulses/s"));
  opts.push_back(real_flag(app, "--a-max", f.a_max, "acceleration limit, pulses/s^2"));
  opts.push_back(real_flag(app, "--j-max", f.j_max, "jerk limit, pulses/s^3 (scurve)"));
  opts.push_back(app->add_option("--profile", f.profile, "scurve | trapezoid")
                     ->check(CLI::IsMember({"scurve", "trapezoid"})));
  opts.push_back(app->add_option_function<std::vector<std::string>>(
                        "--jerks",
                        [&f](const std::vector<std::string>& v) {
                          f.jerks.clear();
                          try {
                            for (const std::string& x : v) f.jerks.push_back(input::parse_real("jerks", x, -kAnyReal, kAnyReal));
                          } catch (const input::Error& e) {
                            throw CLI::ValidationError(e.what());
                          }
                        },
                        "asymmetric jerks Ts1 Ts2 Te1 Te2 (paper 002), pulses/s^3")
                     ->expected(4));
  opts.push_back(app->add_flag("--adjust-end-speed", f.adjust_end_speed,
                               "use the closest reachable end speed instead of failing"));
  const int64_t max_pos = PlannerLimits::kMaxPosition;
  opts.push_back(int_flag(app, "--start-pos", f.start_pos, -max_pos, max_pos,
                          "position the move starts at, pulses (default 0; the window's reference)"));
  opts.push_back(int_flag(app, "--soft-min", f.soft_min, -max_pos, max_pos,
                          "soft limit: lowest position the move may reach, pulses (default: unbounded)"));
  opts.push_back(int_flag(app, "--soft-max", f.soft_max, -max_pos, max_pos,
                          "soft limit: highest position the move may reach, pulses (default: unbounded)"));
  opts.push_back(app->add_option_function<std::string>(
                        "--axis",
                        [&f](const std::string& v) {
                          try {
                            f.axis = input::parse_name("axis", v, SoftLimits::kMaxAxisName);
                          } catch (const input::Error& e) {
                            throw CLI::ValidationError(e.what());
                          }
                        },
                        "axis name in soft-limit errors (default x)")
                     ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast));
  if (move_opts) move_opts->insert(move_opts->end(), opts.begin(), opts.end());
  add_timing_flags(app, f);
}

void add_timing_flags(CLI::App* app, MoveFlags& f) {
  int_flag(app, "--pulse-high", f.pulse_high, 1, 65535, "STEP high time, clocks (1..65535)");
  int_flag(app, "--pulse-low", f.pulse_low, 1, 65535, "minimum STEP low time, clocks (1..65535)");
  int_flag(app, "--dir-setup", f.dir_setup, 0, 65535, "DIR setup before STEP rise, clocks (0..65535)");
  int_flag(app, "--dir-hold", f.dir_hold, 0, 65535, "DIR hold after STEP rise, clocks (0..65535)");
}

void add_clock_flag(CLI::App* app, MoveFlags& f) {
  real_flag(app, "--clock-hz", f.clock_hz,
            fmt::format("system clock of the board, Hz ({:.0f}..{:.0f}; default {:.0f})", Clock::kMinHz, Clock::kMaxHz,
                        Clock::kDefaultHz),
            Clock::kMinHz, Clock::kMaxHz);
}

void add_output_flags(CLI::App* app, MoveFlags& f) {
  app->add_flag("--json", f.json, "print one JSON object");
  output_file_flag(app, "--json-out", f.json_out, "also write the JSON object to this file");
}

void add_stop_flags(CLI::App* app, StopFlags& f) {
  real_flag(app, "--stop-at", f.at, "controlled stop (CMD.STOP) this many seconds after START", 0)
      ->each([&f](const std::string&) { f.at_given = true; });
  real_flag(app, "--stop-jerk", f.jerk, "stop jerk limit STOP_JERK, pulses/s^3 (default: the move's jerk limit)")
      ->each([&f](const std::string&) { f.jerk_given = true; });
  real_flag(app, "--stop-acc", f.acc, "stop deceleration limit STOP_ACC, pulses/s^2 (default: the move's a_max)")
      ->each([&f](const std::string&) { f.acc_given = true; });
}

void add_retarget_flags(CLI::App* app, RetargetFlags& f) {
  real_flag(app, "--retarget-at", f.at, "retarget the move: decide this many seconds after START", 0)
      ->each([&f](const std::string&) { f.at_given = true; });
  int_flag(app, "--retarget-distance", f.distance, -PlannerLimits::kMaxDistance, PlannerLimits::kMaxDistance,
           "the move's new distance from its start, pulses (ahead of the axis at the retarget)")
      ->each([&f](const std::string&) { f.distance_given = true; });
}

std::variant<std::optional<RetargetPlan>, std::string> resolve_retarget_flags(const RetargetFlags& f,
                                                                             const MoveRequest& request,
                                                                             const Plan& plan,
                                                                             const PulseTiming& timing) {
  if (!f.at_given && !f.distance_given) return std::optional<RetargetPlan>{};
  if (f.at_given != f.distance_given) {
    return std::string(f.at_given ? "--retarget-at: needs --retarget-distance (the new distance)"
                                  : "--retarget-distance: needs --retarget-at (when to retarget)");
  }
  const RetargetResult r = plan_retarget(Planner{plan.clock}, plan, request, {f.at, f.distance}, timing);
  if (const Error* e = std::get_if<Error>(&r)) {
    return fmt::format("--{}: {}", e->parameter == "retarget_at" ? "retarget-at" : "retarget-distance", e->message);
  }
  return std::optional<RetargetPlan>{std::get<RetargetPlan>(r)};
}

std::variant<StopRequest, std::string> resolve_stop_flags(const StopFlags& f, const MoveRequest& request,
                                                          const Plan& plan) {
  StopRequest s;
  s.limits = move_stop_limits(request, plan.clock);
  if (f.jerk_given) s.limits.jerk = f.jerk;
  if (f.acc_given) s.limits.acc = f.acc;
  const StopLimitCodesResult codes = stop_limit_codes(s.limits.jerk, s.limits.acc, plan.clock);
  if (const Error* e = std::get_if<Error>(&codes)) {
    const bool jerk = e->parameter == "stop_jerk";
    const bool given = jerk ? f.jerk_given : f.acc_given;
    return fmt::format("--{}: {}{}", jerk ? "stop-jerk" : "stop-acc", e->message,
                       given ? "" : " (the move's own limit, the default)");
  }
  s.codes = std::get<StopLimitCodes>(codes);
  if (f.at_given) {
    // The stop must come while the move runs (a STOP in its last clock, or
    // after it, stops nothing).
    const double duration = double(plan.total_clocks) / plan.clock.hz;
    const double clocks = std::round(f.at * plan.clock.hz);
    if (!(clocks + 1 < double(plan.total_clocks))) {
      return fmt::format("--stop-at={}: must be below the move's duration, {} s ({} clocks at {} Hz)", f.at,
                         duration, plan.total_clocks, plan.clock.hz);
    }
    s.at_clock = uint64_t(clocks);
  }
  return s;
}

MoveRequest to_request(const MoveFlags& f) {
  MoveRequest r;
  r.distance = f.distance;
  r.v_start = f.v_start;
  r.v_cruise = f.v_cruise;
  r.v_end = f.v_end;
  r.a_max = f.a_max;
  r.j_max = f.j_max;
  r.kind = f.profile == "trapezoid" ? ProfileKind::Trapezoid : ProfileKind::SCurve;
  if (f.jerks.size() == 4) r.jerks = std::array<double, 4>{f.jerks[0], f.jerks[1], f.jerks[2], f.jerks[3]};
  r.adjust_end_speed = f.adjust_end_speed;
  r.start_position = f.start_pos;
  if (f.soft_min || f.soft_max) r.soft_limits = SoftLimits{f.axis, f.soft_min, f.soft_max};
  return r;
}

PulseTiming to_timing(const MoveFlags& f) {
  PulseTiming t;
  t.high = uint16_t(f.pulse_high);
  t.low = uint16_t(f.pulse_low);
  t.setup = uint16_t(f.dir_setup);
  t.hold = uint16_t(f.dir_hold);
  return t;
}

Clock to_clock(const MoveFlags& f) { return Clock{f.clock_hz}; }

std::string check_move_flags(const MoveFlags& f) {
  if (!f.distance_given) return "--distance: required (the move length in pulses, sign = direction)";
  if (!f.jerks.empty() && f.profile != "scurve") {
    return fmt::format("--jerks: the four jerks shape an S-curve; --profile={} has none", f.profile);
  }
  if (f.soft_min && f.soft_max && *f.soft_min > *f.soft_max) {
    return input::Error("soft-min", std::to_string(*f.soft_min),
                        fmt::format("must be <= soft-max={} (the window is [soft-min, soft-max])", *f.soft_max))
        .what();
  }
  return {};
}

std::string check_clock_flag(double hz) {
  if (!std::isfinite(hz) || !(hz > 0)) {
    return fmt::format("--clock-hz={}: must be a positive, finite number within {:.0f}..{:.0f} Hz", hz, Clock::kMinHz,
                       Clock::kMaxHz);
  }
  if (hz < Clock::kMinHz || hz > Clock::kMaxHz) {
    return fmt::format("--clock-hz={}: outside the accepted range {:.0f}..{:.0f} Hz", hz, Clock::kMinHz,
                       Clock::kMaxHz);
  }
  return {};
}

int bad_input(const std::string& msg) {
  // One line whatever the message quotes (file text, a JSON parser's view).
  std::fprintf(stderr, "error: %s\n", input::printable(msg).c_str());
  return 2;
}

namespace {

// The option named "--name" on the app or any of its subcommands.
const CLI::Option* find_long_option(const CLI::App& app, const std::string& name) {
  if (const CLI::Option* o = app.get_option_no_throw(name)) return o;
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (const CLI::Option* o = find_long_option(*sub, name)) return o;
  }
  return nullptr;
}

// "--name=value" forms CLI11 gets wrong, settled before it parses: a switch
// given a value is refused naming the value (CLI11 says only "was given a
// disallowed flag override"), and "--name=" becomes "--name" "" (CLI11
// would take the next argument as the value, or report the value missing),
// so an empty value is checked and reported like any other. Returns an
// error line, or "" with args rewritten.
std::string settle_equals_forms(const CLI::App& app, std::vector<std::string>& args) {
  std::vector<std::string> out;
  bool options = true;
  for (const std::string& a : args) {
    if (a == "--") options = false;
    const size_t eq = a.find('=');
    if (!options || a.rfind("--", 0) != 0 || eq == std::string::npos || eq < 3) {
      out.push_back(a);
      continue;
    }
    const std::string name = a.substr(0, eq), value = a.substr(eq + 1);
    const CLI::Option* o = find_long_option(app, name);
    if (o && o->get_items_expected_max() == 0) {
      return input::Error(name.substr(2), value.empty() ? "''" : value, "a switch takes no value").what();
    }
    if (o && value.empty()) {
      out.push_back(name);
      out.emplace_back();
      continue;
    }
    out.push_back(a);
  }
  args = std::move(out);
  return "";
}

}  // namespace

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  // A file-size limit makes a write fail (EFBIG) instead of killing the
  // program, so it reports the failure and removes its partial files.
  std::signal(SIGXFSZ, SIG_IGN);
  std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
  if (const std::string e = settle_equals_forms(app, args); !e.empty()) return bad_input(e);
  std::vector<char*> settled = {argc > 0 ? argv[0] : nullptr};
  for (std::string& a : args) settled.push_back(a.data());
  settled.push_back(nullptr);
  try {
    app.parse(int(settled.size() - 1), settled.data());
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // "scurve frob": name the word and the commands there are, not only
    // that one is required.
    if (app.get_require_subcommand_min() > 0 && app.get_subcommands().empty() && !args.empty() && args[0][0] != '-') {
      std::string known;
      for (const CLI::App* sub : app.get_subcommands({})) known += (known.empty() ? "" : ", ") + sub->get_name();
      return bad_input(fmt::format("{}: unknown command (commands: {})", args[0], known));
    }
    return bad_input(e.what());
  }
  return std::nullopt;
}

std::string parse_flags(CLI::App& app, std::vector<std::string> args) {
  if (std::string e = settle_equals_forms(app, args); !e.empty()) return e;
  std::reverse(args.begin(), args.end());  // CLI11 takes the vector last argument first
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    return e.what();
  }
  return {};
}

std::variant<Plan, Error> plan_flags(const MoveFlags& f) {
  if (std::string e = check_move_flags(f); !e.empty()) return Error{"", e};
  if (std::string e = check_clock_flag(f.clock_hz); !e.empty()) return Error{"", e};
  PlanResult r = Planner(to_clock(f)).plan(to_request(f), to_timing(f));
  if (auto* e = std::get_if<Error>(&r)) return std::move(*e);
  return std::move(std::get<Plan>(r));
}

bool write_json_file(const std::string& path, const nlohmann::json& j) {
  if (path.empty()) return true;
  // Written whole to "<path>.part", then renamed: a failed write (a full
  // disk, a file-size limit) leaves no truncated file behind.
  const std::string part = path + ".part";
  std::FILE* f = std::fopen(part.c_str(), "w");
  if (!f) return false;
  const std::string s = j.dump(2) + "\n";
  const bool written = std::fwrite(s.data(), 1, s.size(), f) == s.size() && std::fflush(f) == 0;
  const bool closed = std::fclose(f) == 0;
  if (!written || !closed || std::rename(part.c_str(), path.c_str()) != 0) {
    std::remove(part.c_str());
    return false;
  }
  return true;
}

}  // namespace scurve::cli
