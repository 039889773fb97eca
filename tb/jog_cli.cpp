#include "jog_cli.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "jog_run.h"
#include "scurve/cli/user_input.h"
#include "scurve/reg_encode.h"

namespace sc {

using scurve::cli::bad_input;
using scurve::cli::int_flag;
using scurve::cli::real_flag;

void add_jog_command(CLI::App& app, JogCli& j) {
  CLI::App* c = app.add_subcommand(
      "jog", "velocity mode in simulation: ramp to each target velocity, hold it, end at rest or with a stop");
  j.cmd = c;
  c->add_option("--target", j.targets,
                "V[:T]: ramp to V pulses/s (signed) and hold it T seconds (default 0); repeat for a program "
                "(default 2000:0.05 -1000:0.05 0)")
      ->expected(1, 1000)
      ->take_all();
  real_flag(c, "--a-max", j.a_max, "acceleration limit, pulses/s^2 (default 20000)");
  real_flag(c, "--j-max", j.j_max, "jerk limit, pulses/s^3 (default 400000)");
  c->add_flag("--stop", j.stop, "end with CMD.STOP (the controlled stop) while the last target holds");
  real_flag(c, "--stop-jerk", j.stop_jerk, "STOP_JERK, pulses/s^3 (default --j-max)");
  real_flag(c, "--stop-acc", j.stop_acc, "STOP_ACC, pulses/s^2 (default --a-max)");
  int_flag(c, "--push-gap", j.push_gap, 0, 10'000'000,
           "clocks between two rows of one command: a slow host (default 0)");
  c->add_option("--engine", j.engine, "lockstep (default) | rtl | model | model-fast")
      ->check(CLI::IsMember(sim_engine_names()));
  scurve::cli::add_timing_flags(c, j.timing);
  scurve::cli::add_output_flags(c, j.timing);
}

namespace {

// "V" or "V:T", through the validation layer; the planner checks V against
// the step-rate limit.
JogCommand parse_target(size_t i, const std::string& text) {
  const std::string param = fmt::format("target[{}]", i);
  const size_t colon = text.find(':');
  JogCommand c;
  c.v_target = scurve::input::parse_real(param + ".velocity", text.substr(0, colon), -1e9, 1e9);
  if (colon != std::string::npos) {
    c.hold_s = scurve::input::parse_real(param + ".hold", std::string_view(text).substr(colon + 1), 0, 1000);
  }
  return c;
}

}  // namespace

int run_jog_cli(const JogCli& j) {
  JogRequest req;
  req.a_max = j.a_max;
  req.j_max = j.j_max;
  req.stop_at_end = j.stop;
  req.push_gap = j.push_gap;
  try {
    for (size_t i = 0; i < j.targets.size(); ++i) req.commands.push_back(parse_target(i, j.targets[i]));
  } catch (const scurve::input::Error& e) {
    return bad_input(e.what());
  }
  const PulseTiming timing = to_model(scurve::cli::to_timing(j.timing));
  auto planned = plan_jog(req, timing);
  if (const scurve::Error* e = std::get_if<scurve::Error>(&planned)) return bad_input(e->message);
  const auto codes = scurve::stop_limit_codes(j.stop_jerk > 0 ? j.stop_jerk : j.j_max,
                                              j.stop_acc > 0 ? j.stop_acc : j.a_max);
  if (const scurve::Error* e = std::get_if<scurve::Error>(&codes)) return bad_input(e->message);
  const SimEngine eng = sim_engine_from_name(j.engine);
  const bool tty = isatty(2);
  const JogRunResult r =
      run_jog(req, std::get<std::vector<scurve::VelocityPlan>>(planned), timing, eng,
              std::get<scurve::StopLimitCodes>(codes).jerk, std::get<scurve::StopLimitCodes>(codes).acc,
              [&](double x) {
                if (tty) std::fprintf(stderr, "\r[jog %3.0f%%]", 100 * std::min(1.0, x));
              });
  if (tty) std::fputs("\n", stderr);

  nlohmann::json out;
  out["engine"] = engine_name(r.engine);
  out["commands"] = nlohmann::json::array();
  for (const JogCommandReport& c : r.commands) {
    out["commands"].push_back({{"v_target", c.v_target}, {"v_held", c.v_held}, {"ramp_clocks", c.ramp_clocks},
                               {"queued_clock", c.queued_clock}, {"held", c.held}});
  }
  out["rows"] = r.rows;
  out["clocks"] = r.clocks;
  out["pulses"] = r.pulses;
  out["end_position"] = r.end_position;
  out["stopped"] = r.stopped;
  if (r.stopped) {
    out["stop_distance"] = r.stop_distance;
    out["stop_closed_form_distance"] = r.stop_closed_form;
  }
  out["mismatches"] = r.mismatches;
  out["matched_clocks"] = r.matched_clocks;
  out["wall_s"] = r.wall_s;
  out["clocks_per_s"] = r.clocks_per_s;
  out["failures"] = r.failures;
  out["pass"] = r.pass();
  if (j.timing.json) {
    std::cout << out.dump(2) << "\n";
  } else {
    std::string t = fmt::format("{:>3} {:>14} {:>16} {:>12} {:>14} {:>5}\n", "#", "target p/s", "held p/s (exact)",
                                "ramp clocks", "queued clock", "held");
    for (size_t i = 0; i < r.commands.size(); ++i) {
      const JogCommandReport& c = r.commands[i];
      t += fmt::format("{:>3} {:>14} {:>16.6f} {:>12} {:>14} {:>5}\n", i, c.v_target, c.v_held, c.ramp_clocks,
                       c.queued_clock, c.held ? "yes" : "NO");
    }
    t += fmt::format("engine {}: {} rows, {} clocks, {} pulses, end position {}\n", engine_name(r.engine), r.rows,
                     r.clocks, r.pulses, r.end_position);
    if (r.stopped) {
      t += fmt::format("controlled stop: {:.3f} pulses (closed form {:.3f})\n", r.stop_distance, r.stop_closed_form);
    }
    t += fmt::format("mismatches {} over {} clocks; {:.2f} s wall, {:.3g} clocks/s\n", r.mismatches,
                     r.matched_clocks, r.wall_s, r.clocks_per_s);
    for (const std::string& f : r.failures) t += "FAIL: " + f + "\n";
    t += r.pass() ? "PASS\n" : "FAIL\n";
    std::cout << t;
  }
  if (!scurve::cli::write_json_file(j.timing.json_out, out)) {
    return bad_input("--json-out: cannot write " + j.timing.json_out);
  }
  return r.pass() ? 0 : 1;
}

}  // namespace sc
