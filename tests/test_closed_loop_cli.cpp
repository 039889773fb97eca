// The closed-loop command line and scenario files: the plant and controller
// parameter tables (one range per setting, shared by the flags and the
// scenario keys, every number through the validation layer), and the ranges
// against what the register words can hold.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "closed_loop_cli.h"
#include "scurve/servo_config.h"

namespace sc {
namespace {

// Parses `args` as the closed-loop flags of a fresh command line; the
// error text of a refused command line, or "".
std::string parse_flags(const std::vector<std::string>& args, ClosedLoopCli& f) {
  CLI::App app;
  add_closed_loop_flags(&app, f);
  std::vector<std::string> argv_text = {"scurve"};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  try {
    app.parse(int(argv.size()), argv.data());
  } catch (const CLI::ParseError& e) {
    return e.what();
  }
  return {};
}

std::string decimal(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// A value well inside the range (integers: an integer).
double inside(const ControllerParam& p) {
  const double v = p.lo + 0.375 * (p.hi - p.lo);
  return p.integer ? std::floor(v) : v;
}

std::string scenario_with(const std::string& object, const std::string& key, const std::string& value) {
  return "{\"" + object + "\": {\"" + key + "\": " + value + "}}";
}

TEST(ClosedLoopCliParams, FlagAndScenarioKeySetTheSameControllerField) {
  for (const ControllerParam& p : controller_params()) {
    const double v = inside(p);
    ClosedLoopCli by_flag;
    ASSERT_EQ(parse_flags({std::string("--") + p.flag, decimal(v)}, by_flag), "") << p.flag;
    EXPECT_EQ(p.get(by_flag.ctl.values), v) << p.flag;
    ControllerInput by_key;
    PlantConfig plant;
    ASSERT_EQ(apply_scenario_json(scenario_with("controller", p.key, decimal(v)), by_key, plant), "") << p.key;
    EXPECT_EQ(p.get(by_key.values), v) << p.key;
  }
}

TEST(ClosedLoopCliParams, FlagAndScenarioKeySetTheSamePlantField) {
  for (const PlantParam& p : plant_params()) {
    const double v = p.integer ? std::floor(p.lo + 1) : p.lo + 0.375 * (p.hi - p.lo);
    ClosedLoopCli by_flag;
    ASSERT_EQ(parse_flags({std::string("--") + p.flag, decimal(v)}, by_flag), "") << p.flag;
    EXPECT_EQ(p.get(by_flag.plant), v) << p.flag;
    ControllerInput ctl;
    PlantConfig by_key;
    ASSERT_EQ(apply_scenario_json(scenario_with("plant", p.key, decimal(v)), ctl, by_key), "") << p.key;
    EXPECT_EQ(p.get(by_key), v) << p.key;
  }
}

// Refused text names the flag and the value as given; nothing is set.
TEST(ClosedLoopCliParams, ControllerFlagsRefuseNonDecimalNonFiniteAndOutOfRangeText) {
  for (const ControllerParam& p : controller_params()) {
    std::vector<std::string> bad = {"", "nan", "inf", "-inf", "0x10", "1e999", "ten", "1,5", decimal(p.hi * 2 + 1)};
    if (p.lo >= 0) bad.push_back("-1");
    if (p.integer) {
      for (const char* t : {"010", "1e1", "1.5", "+0x1"}) bad.push_back(t);
    }
    for (const std::string& text : bad) {
      ClosedLoopCli f;
      const double before = p.get(f.ctl.values);
      const std::string err = parse_flags({std::string("--") + p.flag, text}, f);
      EXPECT_NE(err.find(std::string(p.flag) + "=" + (text.empty() ? "''" : text)), std::string::npos)
          << p.flag << " " << text << ": " << err;
      EXPECT_EQ(p.get(f.ctl.values), before) << p.flag << " " << text;
    }
  }
}

TEST(ClosedLoopCliParams, RealControllerFlagsTakeDecimalExponents) {
  ClosedLoopCli f;
  ASSERT_EQ(parse_flags({"--k-p", "4e-3", "--ctl-rate", "2.5e4", "--v-lim", "5E3"}, f), "");
  EXPECT_EQ(f.ctl.values.k_p, 0.004);
  EXPECT_EQ(f.ctl.values.rate_hz, 25000);
  EXPECT_EQ(f.ctl.values.v_lim, 5000);
}

TEST(ClosedLoopCliParams, ScenarioControllerKeysRefuseWrongTypesAndRanges) {
  for (const ControllerParam& p : controller_params()) {
    std::vector<std::string> bad = {"\"1\"", "null", "true", "[1]", decimal(p.hi * 2 + 1)};
    if (p.lo >= 0) bad.push_back("-1");
    if (p.integer) bad.push_back("1.5");
    for (const std::string& v : bad) {
      ControllerInput c;
      PlantConfig plant;
      const std::string err = apply_scenario_json(scenario_with("controller", p.key, v), c, plant);
      EXPECT_NE(err.find(std::string("scenario.controller.") + p.key + "="), std::string::npos)
          << p.key << " " << v << ": " << err;
    }
  }
}

// Of repeated flags the last counts, and every one is checked: an earlier
// bad value is refused, not dropped.
TEST(ClosedLoopCliParams, RepeatedFlagsAreEachCheckedAndTheLastCounts) {
  ClosedLoopCli f;
  ASSERT_EQ(parse_flags({"--k-p", "0.002", "--k-p", "0.003", "--enc-filter", "1", "--enc-filter", "5"}, f), "");
  EXPECT_EQ(f.ctl.values.k_p, 0.003);
  EXPECT_EQ(f.ctl.values.enc_filt, 5);
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"--k-p", "nan", "--k-p", "0.004"}, {"--enc-filter", "010", "--enc-filter", "3"},
           {"--tail", "-1", "--tail", "0.1"}, {"--weights-csv", "", "--weights-csv", "w.csv"}}) {
    ClosedLoopCli g;
    const std::string err = parse_flags(args, g);
    EXPECT_NE(err.find(args[0].substr(2) + "=" + (args[1].empty() ? "''" : args[1])), std::string::npos)
        << args[0] << " " << args[1] << ": " << err;
  }
}

// Switches are given or not: a value after them would be read as a
// double negation ("--no-ff=false").
TEST(ClosedLoopCliParams, SwitchesTakeNoValue) {
  for (const char* sw : {"--no-ff=false", "--fixed-gain=0", "--open-loop=no", "--missed-steps=false",
                         "--closed-loop=false", "--compare=0", "--ferr-stop=1"}) {
    ClosedLoopCli f;
    EXPECT_NE(parse_flags({sw}, f), "") << sw;
  }
  ClosedLoopCli f;
  ASSERT_EQ(parse_flags({"--no-ff", "--fixed-gain", "--open-loop", "--ferr-stop"}, f), "");
  EXPECT_TRUE(f.ctl.values.ferr_stop);
  EXPECT_FALSE(f.ctl.values.ff);
  EXPECT_FALSE(f.ctl.values.adaptive);
  EXPECT_FALSE(f.ctl.values.closed_loop);
}

// The switches' scenario keys take JSON booleans only; the flag and the key
// set the same field.
TEST(ClosedLoopCliParams, ScenarioSwitchKeysAreBooleans) {
  for (const char* key : {"ff", "adaptive", "ferr_stop"}) {
    for (const char* bad : {"1", "\"true\"", "null", "[]"}) {
      ControllerInput c;
      PlantConfig plant;
      const std::string err = apply_scenario_json(fmt::format(R"({{"controller": {{"{}": {}}}}})", key, bad), c, plant);
      EXPECT_NE(err.find(std::string("scenario.controller.") + key), std::string::npos) << key << "=" << bad << ": " << err;
    }
  }
  ControllerInput c;
  PlantConfig plant;
  ASSERT_EQ(apply_scenario_json(R"({"controller": {"ferr_stop": true}})", c, plant), "");
  EXPECT_TRUE(c.values.ferr_stop);
}

TEST(ClosedLoopCliParams, EmptyFilePathsAreRefused) {
  for (const char* flag : {"--weights-csv", "--scenario"}) {
    ClosedLoopCli f;
    const std::string err = parse_flags({flag, ""}, f);
    EXPECT_NE(err.find(std::string(flag + 2) + "=''"), std::string::npos) << err;
  }
}

// Gains not given follow the control rate; given ones (flag or scenario)
// are used as given.
TEST(ClosedLoopCliParams, UngivenGainsTakeTheDefaultsForTheControlRate) {
  ClosedLoopCli f;
  ASSERT_EQ(parse_flags({"--ctl-rate", "40000"}, f), "");
  const ControllerParams r = f.ctl.resolve();
  const ControllerParams want = scurve::controller_defaults(40000);
  for (const ControllerParam& p : controller_params()) EXPECT_EQ(p.get(r), p.get(want)) << p.key;
  EXPECT_EQ(r.k_v, 0.005);

  ClosedLoopCli g;
  ASSERT_EQ(parse_flags({"--ctl-rate", "40000", "--k-v", "0.02"}, g), "");
  EXPECT_EQ(g.ctl.resolve().k_v, 0.02);
  EXPECT_EQ(g.ctl.resolve().w_p1_max, want.w_p1_max);

  ControllerInput s;
  PlantConfig plant;
  ASSERT_EQ(apply_scenario_json(R"({"controller": {"rate_hz": 20000, "w_p1_max": 0.5}})", s, plant), "");
  EXPECT_EQ(s.resolve().k_v, 0.01);
  EXPECT_EQ(s.resolve().w_p1_max, 0.5);
  EXPECT_EQ(ClosedLoopCli{}.ctl.resolve().k_v, ControllerParams{}.k_v);
}

// Settings that keep the cross-checks of to_servo_config satisfied while
// one setting sits at a bound of its range.
ControllerParams with_value(const ControllerParam& p, double v) {
  ControllerParams c;
  const std::string key = p.key;
  if (key.find("_max") != std::string::npos) c.w_min = -scurve::kMaxWeight;  // bounds must not cross w_min
  if (key == "w_min") c.w_p1_max = c.w_p2_max = c.w_v1_max = c.w_v2_max = scurve::kMaxWeight;
  p.set(c, v);
  return c;
}

// Every value the table accepts, at both ends of every range, is one the
// register words can hold (no clamping) at the default pulse timing, except
// u_lim, which needs the fastest timing to reach its top.
TEST(ClosedLoopCliParams, ControllerRangeEndsAreEncodable) {
  for (const ControllerParam& p : controller_params()) {
    for (const double v : {p.lo, p.hi}) {
      PulseTiming t;
      if (std::string(p.key) == "u_lim") t.high = t.low = 1;
      ServoConfig out;
      EXPECT_EQ(to_servo_config(with_value(p, v), PlantConfig{}, t, out), "") << p.flag << "=" << decimal(v);
    }
  }
}

// The shipped scenario names every controller and plant key of the tables,
// and applies cleanly: the tables and the documented file agree.
TEST(ClosedLoopCliParams, ShippedScenarioNamesEveryTableKey) {
  std::ifstream in(std::string(SOURCE_DIR) + "/tb/scenarios/nema23_1000line.json");
  ASSERT_TRUE(in);
  std::stringstream text;
  text << in.rdbuf();
  ControllerInput c;
  PlantConfig plant;
  ASSERT_EQ(apply_scenario_json(text.str(), c, plant), "");
  const nlohmann::json j = nlohmann::json::parse(text.str());
  for (const ControllerParam& p : controller_params()) EXPECT_TRUE(j["controller"].contains(p.key)) << p.key;
  for (const PlantParam& p : plant_params()) {
    if (std::string(p.key) == "tau") continue;  // the first-order plant's only setting
    EXPECT_TRUE(j["plant"].contains(p.key)) << p.key;
  }
}

}  // namespace
}  // namespace sc
