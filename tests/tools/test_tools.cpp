// Kinematics traces, `scurve diff` and the regression list/shard logic, plus
// end-to-end runs of the SystemC bench with an injected model fault.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <nlohmann/json.hpp>
#include <chrono>
#include <csignal>
#include <map>
#include <set>
#include <thread>

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <regex>
#include <tuple>
#include <string>

#include "axis_core.h"
#include "kin_trace.h"
#include "regress.h"
#include "trace_diff.h"

using namespace sc;
#if defined(__has_feature)
#define SC_HAS_FEATURE_ASAN __has_feature(address_sanitizer)
#else
#define SC_HAS_FEATURE_ASAN 0
#endif

namespace fs = std::filesystem;

namespace {

// A scratch directory removed with everything in it when the test ends.
class TempDir {
 public:
  explicit TempDir(const std::string& name)
      : path_(fs::temp_directory_path() / ("scurve_tools_" + name + "_" + std::to_string(getpid()))) {
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  fs::path operator/(const std::string& f) const { return path_ / f; }
  std::string string() const { return path_.string(); }

 private:
  fs::path path_;
};

// A synthetic run: a pulse every 1000 clocks (high for 50), the velocity
// changing every clock. `tweak` may corrupt the outputs of one clock.
template <typename Tweak>
void write_synthetic(const fs::path& path, const char* source, uint64_t clocks, Tweak tweak) {
  KinTraceWriter w(path.string(), source, 5000);
  CoreOutputs o;
  o.en = o.busy = true;
  o.dir = true;
  o.phase = 4;
  for (uint64_t c = 0; c < clocks; ++c) {
    const uint64_t k = c % 1000;
    o.step = k < 50;
    if (k == 0) ++o.pulse_count;
    o.ref_vel = i128(c) * 1000;
    o.ref_pos_int = int32_t(c / 1000);
    CoreOutputs out = o;
    tweak(c, out);
    w.on_clock(c, out);
  }
  w.close(clocks);
}

void no_tweak(uint64_t, CoreOutputs&) {}

int run(const std::string& cmd) {
  const int rc = std::system((cmd + " >/dev/null 2>&1").c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

}  // namespace

TEST(KinTrace, WritesOnChangeAndDecimatedAndReadsBack) {
  const TempDir d("rw");
  write_synthetic(d / "a.csv", "rtl", 100000, no_tweak);
  const KinTrace t = read_kin_trace((d / "a.csv").string());
  EXPECT_EQ(t.meta.at("source"), "rtl");
  EXPECT_EQ(t.end_clock, 100000u);
  // Two rows per pulse (rise, fall) + one per 5000 clocks, not one per clock.
  EXPECT_LE(t.clocks.size(), 100u * 2 + 100000u / 5000 + 2);
  EXPECT_GE(t.clocks.size(), 100u * 2);
  ASSERT_EQ(t.columns.size(), kin_trace_columns().size());
  EXPECT_TRUE(t.held[0]);   // step
  EXPECT_FALSE(t.held.back());  // ref_jerk is sampled
}

TEST(TraceDiff, IdenticalTracesReportNothing) {
  const TempDir d("same");
  write_synthetic(d / "a.csv", "rtl", 50000, no_tweak);
  write_synthetic(d / "b.csv", "model", 50000, no_tweak);
  const DiffReport r = diff_traces((d / "a.csv").string(), (d / "b.csv").string());
  EXPECT_TRUE(r.identical()) << r.to_text();
  EXPECT_EQ(r.compared_signals, kin_trace_columns().size());
  EXPECT_EQ(r.compared_clocks, 50000u);
}

TEST(TraceDiff, FindsInjectedHeldDivergenceAtItsClock) {
  const TempDir d("held");
  write_synthetic(d / "a.csv", "rtl", 50000, no_tweak);
  // From clock 23456 on, B counts one pulse more.
  write_synthetic(d / "b.csv", "model", 50000, [](uint64_t c, CoreOutputs& o) {
    if (c >= 23456) o.pulse_count += 1;
  });
  const DiffReport r = diff_traces((d / "a.csv").string(), (d / "b.csv").string());
  ASSERT_FALSE(r.identical());
  ASSERT_EQ(r.signals.size(), 1u) << r.to_text();
  EXPECT_EQ(r.signals[0].signal, "pulse_count");
  EXPECT_EQ(r.signals[0].first_clock, 23456u);
  EXPECT_EQ(r.signals[0].differing_clocks, 50000u - 23456u);  // held to the end
  EXPECT_EQ(r.differing_clocks, 50000u - 23456u);
  const std::string text = r.to_text();
  EXPECT_NE(text.find("first divergence: clock 23456 signal pulse_count"), std::string::npos) << text;
  EXPECT_NE(text.find("context"), std::string::npos);
}

TEST(TraceDiff, FindsSampledDivergenceAndLengthDifference) {
  const TempDir d("sampled");
  write_synthetic(d / "a.csv", "rtl", 50000, no_tweak);
  // Velocity off at one clock that is a sample row (multiple of 5000).
  write_synthetic(d / "b.csv", "model", 40000, [](uint64_t c, CoreOutputs& o) {
    if (c == 15000) o.ref_vel += 1;
  });
  const DiffReport r = diff_traces((d / "a.csv").string(), (d / "b.csv").string());
  ASSERT_EQ(r.signals.size(), 1u) << r.to_text();
  EXPECT_EQ(r.signals[0].signal, "ref_vel");
  EXPECT_EQ(r.signals[0].first_clock, 15000u);
  EXPECT_TRUE(r.length_differs);
  EXPECT_EQ(r.a_last_clock, 49999u);
  EXPECT_EQ(r.b_last_clock, 39999u);
}

TEST(TraceDiff, RejectsMalformedTraces) {
  const TempDir d("bad");
  std::ofstream(d / "bad.csv") << "clock,step\n5,1\n3,0\n";
  write_synthetic(d / "a.csv", "rtl", 1000, no_tweak);
  EXPECT_THROW(diff_traces((d / "bad.csv").string(), (d / "a.csv").string()), std::runtime_error);
  EXPECT_THROW(diff_traces((d / "a.csv").string(), (d / "x.fst").string()), std::runtime_error);
}

// ---- end to end through the SystemC bench --------------------------------------------
const std::string kShortMove =
    " --distance 300 --v-start 0 --v-cruise 3000 --v-end 0 --a-max 50000 --j-max 500000";

TEST(ScBench, ModelAndRtlTracesOfACleanRunAreIdentical) {
  const TempDir d("clean");
  const std::string rtl = (d / "rtl.csv").string(), model = (d / "model.csv").string();
  ASSERT_EQ(run(std::string(SC_BENCH) + kShortMove + " --trace-rtl " + rtl + " --trace-model " + model), 0);
  const DiffReport r = diff_traces(rtl, model);
  EXPECT_TRUE(r.identical()) << r.to_text();
  EXPECT_GT(r.compared_clocks, 100000u);
  EXPECT_EQ(run(std::string(SCURVE) + " diff " + rtl + " " + model), 0);
}

TEST(ScBench, InjectedModelFaultIsFoundAtItsClockByScoreboardAndDiff) {
  const TempDir d("inject");
  const std::string rtl = (d / "rtl.csv").string(), model = (d / "model.csv").string();
  const std::string json = (d / "run.json").string();
  const uint64_t k = 123457;
  const int rc = std::system((std::string(SC_BENCH) + kShortMove + " --json --inject-model-fault " +
                              std::to_string(k) + " --trace-rtl " + rtl + " --trace-model " + model + " > " + json +
                              " 2>/dev/null")
                                 .c_str());
  EXPECT_EQ(WEXITSTATUS(rc), 1);
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_FALSE(j.at("pass").get<bool>());
  EXPECT_EQ(j.at("first_mismatch").get<std::string>().rfind("clock " + std::to_string(k) + " signal pulse_count_o", 0),
            0u)
      << j.at("first_mismatch");
  const DiffReport r = diff_traces(rtl, model);
  ASSERT_FALSE(r.signals.empty()) << r.to_text();
  EXPECT_EQ(r.signals.front().signal, "pulse_count");
  EXPECT_EQ(r.signals.front().first_clock, k);
  EXPECT_EQ(r.signals.front().a, "0");
  EXPECT_EQ(r.signals.front().b, "1");
  EXPECT_EQ(run(std::string(SCURVE) + " diff " + rtl + " " + model), 1);
}

TEST(ScBench, FstWindowsOfTwoIdenticalRunsAreIdenticalAndADifferentWindowIsNot) {
  const TempDir d("fst");
  const std::string a = (d / "a.fst").string(), b = (d / "b.fst").string(), c = (d / "c.fst").string();
  const std::string win = " --fst-from 100000 --fst-to 104000";
  ASSERT_EQ(run(std::string(SC_BENCH) + kShortMove + " --fst " + a + win), 0);
  ASSERT_EQ(run(std::string(SC_BENCH) + kShortMove + " --fst " + b + win), 0);
  ASSERT_EQ(run(std::string(SC_BENCH) + kShortMove + " --fst " + c + " --fst-from 100000 --fst-to 103000"), 0);
  const DiffReport same = diff_traces(a, b);
  EXPECT_TRUE(same.identical()) << same.to_text();
  EXPECT_GT(same.compared_signals, 20u);
  const DiffReport shorter = diff_traces(a, c);
  EXPECT_FALSE(shorter.identical());
  EXPECT_TRUE(shorter.length_differs);
  EXPECT_EQ(shorter.b_last_clock, 102999u);
}

// ---- regression list ---------------------------------------------------------------------
nlohmann::json default_list() {
  std::ifstream in(std::string(SOURCE_DIR) + "/tests/regress_list.json");
  return nlohmann::json::parse(in);
}

TEST(Regress, RandomMovesAreReproducibleFromTheSeed) {
  const auto a = regress::random_move_args(42, nlohmann::json::object());
  const auto b = regress::random_move_args(42, nlohmann::json::object());
  const auto c = regress::random_move_args(43, nlohmann::json::object());
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  const auto l1 = regress::expand_list(default_list(), {}, {});
  const auto l2 = regress::expand_list(default_list(), {}, {});
  ASSERT_EQ(l1.size(), l2.size());
  for (size_t i = 0; i < l1.size(); ++i) EXPECT_EQ(l1[i].argv, l2[i].argv);
}

TEST(Regress, DefaultListHasTheFourPaperGroupsRandomSeedsAndCorners) {
  const auto tests = regress::expand_list(default_list(), {}, {});
  std::set<std::string> kinds, names;
  for (const auto& t : tests) {
    kinds.insert(t.kind);
    EXPECT_TRUE(names.insert(t.name).second) << "duplicate test name " << t.name;
  }
  for (int g = 1; g <= 4; ++g) EXPECT_TRUE(names.count("paper_group" + std::to_string(g)));
  EXPECT_TRUE(kinds.count("random"));
  EXPECT_TRUE(kinds.count("move"));
  EXPECT_TRUE(kinds.count("command"));  // closed-loop scenarios through scurve sim --closed-loop
  const auto quick = regress::expand_list(default_list(), {}, {"long"});
  EXPECT_EQ(quick.size(), tests.size() - 4);
}

TEST(Regress, ShardsPartitionTheList) {
  const auto all = regress::expand_list(default_list(), {}, {});
  for (int n : {1, 2, 3, 7}) {
    std::multiset<std::string> seen;
    for (int i = 1; i <= n; ++i) {
      for (const auto& t : regress::select_shard(all, i, n)) seen.insert(t.name);
    }
    std::multiset<std::string> want;
    for (const auto& t : all) want.insert(t.name);
    EXPECT_EQ(seen, want) << "n=" << n;
  }
  EXPECT_EQ(regress::parse_shard("2/3"), std::make_pair(2, 3));
  EXPECT_THROW(regress::parse_shard("0/2"), std::invalid_argument);
  EXPECT_THROW(regress::parse_shard("3/2"), std::invalid_argument);
  EXPECT_THROW(regress::parse_shard("1-2"), std::invalid_argument);
  EXPECT_THROW(regress::parse_shard("01/2"), std::invalid_argument);  // decimal only
  EXPECT_THROW(regress::parse_shard("1/0x2"), std::invalid_argument);
}

TEST(Regress, CommandEntriesAreExtensible) {
  const nlohmann::json list = {
      {"tests",
       {{{"name", "closed_loop_g1"}, {"kind", "command"}, {"argv", {"{bin}/scurve", "sim", "--closed-loop"}}},
        {{"name", "bad"}, {"kind", "nonsense"}}}}};
  EXPECT_THROW(regress::expand_list(list, {}, {}), std::invalid_argument);
  const nlohmann::json ok = {{"tests", {list["tests"][0]}}};
  const auto t = regress::expand_list(ok, {}, {});
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].argv.front(), "{bin}/scurve");
}

TEST(ScBench, ModelFstMatchesRtlFstAndAnInjectedFaultIsFoundAtItsClock) {
  const TempDir d("fst_model");
  const std::string rtl = (d / "rtl.fst").string(), model = (d / "model.fst").string();
  const std::string waves = " --fst " + rtl + " --fst-model " + model + " --fst-from 100000 --fst-to 130000";
  ASSERT_EQ(run(std::string(SC_BENCH) + kShortMove + waves), 0);
  const DiffReport clean = diff_traces(rtl, model);
  EXPECT_TRUE(clean.identical()) << clean.to_text();
  EXPECT_EQ(clean.compared_signals, 16u);  // every output port of sc_axis_core

  const uint64_t k = 123457;
  EXPECT_EQ(run(std::string(SC_BENCH) + kShortMove + waves + " --max-mismatches 1000000 --inject-model-fault " +
                std::to_string(k)),
            1);
  const DiffReport r = diff_traces(rtl, model);
  ASSERT_EQ(r.signals.size(), 1u) << r.to_text();
  EXPECT_EQ(r.signals[0].signal, "sc_axis_core.pulse_count_o [31:0]");
  EXPECT_EQ(r.signals[0].first_clock, k);
  EXPECT_EQ(r.signals[0].differing_clocks, 130000 - k);
}

TEST(Cli, BadInputExitsWithTwo) {
  const TempDir d("cli");
  write_synthetic(d / "a.csv", "rtl", 1000, no_tweak);
  const std::string scurve = SCURVE;
  EXPECT_EQ(run(scurve + " diff " + (d / "a.csv").string() + " " + (d / "missing.csv").string()), 2);
  EXPECT_EQ(run(scurve + " regress --list " + (d / "missing.json").string() + " --out-dir " + d.string()), 2);
  EXPECT_EQ(run(scurve + " regress --shard 3/2 --list-only --out-dir " + d.string()), 2);
  EXPECT_EQ(run(std::string(SC_BENCH) + " --group 5"), 2);
  EXPECT_EQ(run(std::string(SC_BENCH) + " --group 1 --distance 5"), 2);  // a group or a move, not both
  EXPECT_EQ(run(std::string(SC_BENCH) + " --distance 100 --v-cruise 1000 --a-max 0 --j-max 100"), 2);
}

TEST(Regress, CommandResultsWithRunsAreSummarised) {
  regress::TestResult r;
  r.test.name = "cl";
  r.test.entry = "cl";
  r.test.kind = "command";
  r.pass = true;
  r.result = nlohmann::json::parse(R"({"runs": [
      {"clocks": 10, "pulses": 5, "final_error": 0, "max_tracking_error": 1.5, "rmse": 0.3, "mismatches": 0},
      {"clocks": 20, "pulses": 7, "final_error": -2, "max_tracking_error": 2.5, "rmse": 0.2, "mismatches": 1}],
      "pass": true})");
  const std::string table = regress::summary_table({r});
  EXPECT_NE(table.find("30"), std::string::npos) << table;      // clocks summed
  EXPECT_NE(table.find("2.500"), std::string::npos) << table;   // worst max error
  EXPECT_NE(table.find("-2"), std::string::npos) << table;      // worst final error
}

// ---- hostile lists and results: exit 2 with one line naming the field --------------------
namespace {

struct Outcome {
  int rc = -1;
  std::vector<std::string> err_lines;
};

Outcome run_capture(const std::string& cmd, const std::string& err_file) {
  const int rc = std::system((cmd + " >/dev/null 2>" + err_file).c_str());
  Outcome o;
  o.rc = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  std::ifstream in(err_file);
  for (std::string line; std::getline(in, line);) o.err_lines.push_back(line);
  return o;
}

}  // namespace

// A damaged FST is unreadable (exit 2, one line) or read (exit 0 or 1),
// never a crash: the block chain is checked first, fstapi reads in a child.
TEST(ScBench, DamagedFstFilesAreRefusedWithOneLineNeverACrash) {
  const TempDir d("fst_damaged");
  const std::string good = (d / "good.fst").string();
  ASSERT_EQ(run(std::string(SC_BENCH) + kShortMove + " --fst " + good + " --fst-from 100000 --fst-to 101000"), 0);
  std::string bytes;
  {
    std::ifstream in(good, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ASSERT_GT(bytes.size(), 400u);
  std::mt19937_64 rng(7);
  for (int k = 0; k < 40; ++k) {
    std::string bad = bytes;
    if (k == 0) {
      bad.resize(bad.size() / 2);  // truncated
    } else if (k == 1) {
      bad[bad.size() - 20] = char(0xff);  // inside the last block
    } else {
      // Bytes past the header flipped: lengths and payloads alike.
      for (int f = 0; f < 1 + k / 4; ++f) bad[330 + rng() % (bad.size() - 330)] ^= char(1 + rng() % 255);
    }
    const std::string path = (d / ("bad" + std::to_string(k) + ".fst")).string();
    std::ofstream(path, std::ios::binary) << bad;
    const Outcome o = run_capture(std::string(SCURVE) + " diff " + good + " " + path, (d / "err.txt").string());
    EXPECT_TRUE(o.rc == 0 || o.rc == 1 || o.rc == 2) << "case " << k << ": exit " << o.rc;
    if (o.rc == 2) {
      EXPECT_EQ(o.err_lines.size(), 1u) << "case " << k;
      if (!o.err_lines.empty()) EXPECT_NE(o.err_lines[0].find(path), std::string::npos) << o.err_lines[0];
    }
    if (k == 0) EXPECT_EQ(o.rc, 2);
  }
}

TEST(Regress, HostileListsAreRefusedAtLoadTimeNamingTheField) {
  const TempDir d("hostile");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"tests":[{"name":"r","kind":"random","count":-5}]})", "tests[0].count=-5"},
      {R"({"tests":[{"name":"r","kind":"random","count":1e8}]})", "tests[0].count=100000000.0"},
      {R"({"tests":[{"name":"r","kind":"random","seeds":[1.5]}]})", "tests[0].seeds[0]=1.5"},
      {R"({"tests":[{"name":"../../../../tmp/x","kind":"group","group":1}]})", "tests[0].name='../../../../tmp/x'"},
      {R"({"tests":[{"name":"a/b","kind":"group","group":1}]})", "tests[0].name='a/b'"},
      {R"({"tests":[{"name":"m","kind":"move","move":{"distance":5,"trace-rtl":"x.csv"}}]})", "tests[0].move.trace-rtl"},
      {R"({"tests":[{"name":"m","kind":"move","move":{"distance":"5; rm"}}]})", "tests[0].move.distance"},
      {R"({"tests":[{"name":"g"}]})", "tests[0].kind=missing"},
      {R"({"tests":{}})", "tests={}"},
      {R"({"tests":[]})", "tests=[]"},
      {R"({"tests":[{"name":"r","kind":"random","ranges":{"distance":[5000,10]}}]})", "tests[0].ranges.distance"},
      {R"({"tests":[{"name":"r","kind":"random","ranges":{"distanse":[1,10]}}]})", "tests[0].ranges.distanse"},
      {R"({"tests":[{"name":"g","kind":"group","group":1,"timeout_s":-1}]})", "tests[0].timeout_s=-1"},
      {R"({"tests":[{"name":"g","kind":"group","group":9}]})", "tests[0].group=9"},
      {R"({"tests":[{"name":"g","kind":"group","group":1},{"name":"g","kind":"group","group":2}]})", "tests[1].name=g"},
      {R"({"testz":[]})", "list.testz"},
      {R"([])", "list=[]"},
      {R"({not json)", "not JSON"},
  };
  for (size_t k = 0; k < cases.size(); ++k) {
    const std::string list = (d / fmt::format("l{}.json", k)).string();
    std::ofstream(list) << cases[k].first;
    const std::string out = (d / fmt::format("out{}", k)).string();
    const Outcome o = run_capture(std::string(SCURVE) + " regress --list " + list + " --out-dir " + out,
                                  (d / "err.txt").string());
    EXPECT_EQ(o.rc, 2) << cases[k].first;
    ASSERT_EQ(o.err_lines.size(), 1u) << cases[k].first;
    EXPECT_NE(o.err_lines[0].find(cases[k].second), std::string::npos) << o.err_lines[0];
    EXPECT_FALSE(fs::exists(out)) << "nothing written for a refused list: " << cases[k].first;
  }
  const Outcome dir = run_capture(std::string(SCURVE) + " regress --list-only --list " + d.string(), (d / "err.txt").string());
  EXPECT_EQ(dir.rc, 2);
  ASSERT_EQ(dir.err_lines.size(), 1u);
  EXPECT_NE(dir.err_lines[0].find("not a readable file"), std::string::npos) << dir.err_lines[0];
}

TEST(Regress, CommandOutputThatIsNotAResultFailsTheTestNotTheRunner) {
  const TempDir d("badout");
  const std::string list = (d / "l.json").string();
  std::ofstream(list) << R"({"tests":[
    {"name":"not_json","kind":"command","argv":["sh","-c","echo '{not json'"]},
    {"name":"pass_text","kind":"command","argv":["sh","-c","echo '{\"pass\":\"yes\"}'"]},
    {"name":"clocks_text","kind":"command","argv":["sh","-c","echo '{\"clocks\":\"many\"}'"]},
    {"name":"good","kind":"command","argv":["sh","-c","echo '{\"pass\":true,\"clocks\":5}'"]}]})";
  const std::string out = (d / "out").string();
  const Outcome o = run_capture(std::string(SCURVE) + " regress --jobs 2 --list " + list + " --out-dir " + out,
                                (d / "err.txt").string());
  EXPECT_EQ(o.rc, 1);
  std::ifstream in(out + "/results.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& r : j.at("results")) by_name[r.at("name")] = r;
  EXPECT_FALSE(by_name.at("not_json").at("pass").get<bool>());
  EXPECT_FALSE(by_name.at("pass_text").at("pass").get<bool>());
  EXPECT_FALSE(by_name.at("clocks_text").at("pass").get<bool>());
  EXPECT_TRUE(by_name.at("good").at("pass").get<bool>());
  EXPECT_NE(by_name.at("pass_text").at("failure").get<std::string>().find("\"pass\""), std::string::npos);
  EXPECT_TRUE(fs::exists(out + "/junit.xml"));
  // The same results merged back, and merged twice.
  const Outcome merged = run_capture(std::string(SCURVE) + " regress --merge " + out + "/results.json --out-dir " +
                                         (d / "m1").string(), (d / "err.txt").string());
  EXPECT_EQ(merged.rc, 1);  // the failing tests stay failing
  const Outcome twice = run_capture(std::string(SCURVE) + " regress --merge " + out + "/results.json " + out +
                                        "/results.json --out-dir " + (d / "m2").string(), (d / "err.txt").string());
  EXPECT_EQ(twice.rc, 2);
  ASSERT_EQ(twice.err_lines.size(), 1u);
  EXPECT_NE(twice.err_lines[0].find("already in"), std::string::npos) << twice.err_lines[0];
  const std::string bad = (d / "bad.json").string();
  std::ofstream(bad) << R"({"results":[{"name":"x","pass":"yes"}]})";
  const Outcome typed = run_capture(std::string(SCURVE) + " regress --merge " + bad + " --out-dir " +
                                        (d / "m3").string(), (d / "err.txt").string());
  EXPECT_EQ(typed.rc, 2);
  ASSERT_EQ(typed.err_lines.size(), 1u);
  EXPECT_NE(typed.err_lines[0].find("results[0].pass"), std::string::npos) << typed.err_lines[0];
}

// A marker in the grandchild's command line tells whether it survived.
bool process_running(const std::string& marker) {
  // "[s]leep" matches "sleep" but not the command line of this pgrep's shell.
  return std::system(("pgrep -f '[" + marker.substr(0, 1) + "]" + marker.substr(1) + "' >/dev/null").c_str()) == 0;
}

TEST(Regress, TimeoutAndSigtermKillTheWholeProcessGroup) {
  const TempDir d("pgroup");
  const std::string marker = fmt::format("sleep 97{}", getpid() % 1000);
  const std::string list = (d / "l.json").string();
  std::ofstream(list) << R"({"tests":[{"name":"slow","kind":"command","timeout_s":1,"argv":["sh","-c",")" << marker
                      << " & " << marker << R"("]}]})";
  const Outcome o = run_capture(std::string(SCURVE) + " regress --list " + list + " --out-dir " + (d / "o1").string(),
                                (d / "err.txt").string());
  EXPECT_EQ(o.rc, 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_FALSE(process_running(marker)) << "a grandchild outlived the timeout";

  const std::string list2 = (d / "l2.json").string();
  std::ofstream(list2) << R"({"tests":[{"name":"slow","kind":"command","argv":["sh","-c",")" << marker << " & "
                       << marker << R"("]}]})";
  const std::string cmd = std::string(SCURVE) + " regress --list " + list2 + " --out-dir " + (d / "o2").string() +
                          " >/dev/null 2>&1 & p=$!; sleep 1; kill -TERM $p; wait $p";
  const int rc = std::system(("bash -c '" + cmd + "'").c_str());
  EXPECT_EQ(WEXITSTATUS(rc), 128 + SIGTERM);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_FALSE(process_running(marker)) << "SIGTERM to the runner left a test running";
  EXPECT_TRUE(fs::exists(d / "o2" / "results.json"));
}

TEST(Regress, RerunLinesAreShellQuotedToTheSameArgv) {
  const std::vector<std::string> argv = {"printf", "%s|", "a b", "it's", "$(touch x)", "", ";rm", "{bin}/x"};
  const TempDir d("quote");
  const std::string out = (d / "o.txt").string();
  ASSERT_EQ(std::system(("cd " + d.string() + " && " + regress::shell_command(argv) + " > " + out).c_str()), 0);
  std::ifstream in(out);
  std::string got;
  std::getline(in, got);
  EXPECT_EQ(got, "a b|it's|$(touch x)||;rm|{bin}/x|");
  EXPECT_FALSE(fs::exists(d / "x"));
}

// ---- trace diff: unreadable input is exit 2, and traces are streamed ------------------
namespace {

void write_trace(const fs::path& p, const std::string& header, uint64_t rows, uint64_t bad_row, const std::string& bad) {
  std::ofstream f(p);
  f << header << "\n";
  f << "clock,step,dir,en,busy,done,phase,seg_idx,pulse_count,step_pending,ref_pos_int,ref_pos_frac,ref_vel,ref_acc,"
       "ref_jerk\n";
  for (uint64_t c = 0; c < rows; ++c) {
    f << c * 3 << ",1,1,1,0,4,0," << c << ",0," << c << ",123456789012345678901,"
      << (c == bad_row ? bad : std::to_string(c)) << ",1,0,0\n";
  }
  f << "# end_clock=" << rows * 3 << " rows=" << rows << "\n";
}

const std::string kHeader =
    "# scurve-kin-trace v1 source=rtl decimate=5000 clk_hz=20000000 frac_bits=64 "
    "held=step;dir;en;busy;done;phase;seg_idx;pulse_count;step_pending";

}  // namespace

TEST(TraceDiff, NonNumericValuesAndBadHeadersAreUnreadableNotDifferent) {
  const TempDir d("unreadable");
  write_trace(d / "a.csv", kHeader, 2000, UINT64_MAX, "");
  const std::vector<std::tuple<std::string, uint64_t, std::string, std::string>> cases = {
      {kHeader, 1000, "x", "ref_pos_frac='x'"},
      {kHeader, 1000, "0100", "ref_pos_frac='0100'"},
      {kHeader, 1000, "-0", "ref_pos_frac='-0'"},
      {kHeader, 1000, "+5", "ref_pos_frac='+5'"},
      {std::regex_replace(kHeader, std::regex("clk_hz=20000000"), "clk_hz=0"), UINT64_MAX, "", "clk_hz=0"},
      {std::regex_replace(kHeader, std::regex("frac_bits=64"), "frac_bits=99999999999"), UINT64_MAX, "",
       "frac_bits=99999999999"},
      {"# some other csv", UINT64_MAX, "", "not a kinematics trace"},
  };
  for (const auto& [header, row, bad, expect] : cases) {
    write_trace(d / "b.csv", header, 2000, row, bad);
    const Outcome o = run_capture(std::string(SCURVE) + " diff " + (d / "a.csv").string() + " " +
                                      (d / "b.csv").string(), (d / "err.txt").string());
    EXPECT_EQ(o.rc, 2) << expect;
    ASSERT_EQ(o.err_lines.size(), 1u) << expect;
    EXPECT_NE(o.err_lines[0].find(expect), std::string::npos) << o.err_lines[0];
  }
}

TEST(TraceDiff, LongTracesAreStreamedInBoundedMemory) {
  const TempDir d("stream");
#if !defined(__SANITIZE_ADDRESS__) && !SC_HAS_FEATURE_ASAN
  // ~73 MB each: loaded whole (as rows of strings) this took over 1 GB.
  constexpr uint64_t kRows = 1'000'000, kBadRow = 777'777;
  constexpr bool kCheckRss = true;
#else
  // Under ASan its shadow memory and quarantine are part of the RSS: the
  // bound is checked in the default build, the diff itself here, shorter.
  constexpr uint64_t kRows = 100'000, kBadRow = 77'777;
  constexpr bool kCheckRss = false;
#endif
  write_trace(d / "a.csv", kHeader, kRows, UINT64_MAX, "");
  write_trace(d / "b.csv", kHeader, kRows, kBadRow, "1");
  const Outcome o = run_capture(std::string(SCURVE) + " diff " + (d / "a.csv").string() + " " +
                                    (d / "b.csv").string(), (d / "err.txt").string());
  EXPECT_EQ(o.rc, 1);
  if (kCheckRss) {
    rusage ru{};
    getrusage(RUSAGE_CHILDREN, &ru);
    EXPECT_LT(ru.ru_maxrss, 64 * 1024) << "max RSS of a child, KiB";
  }
  const DiffReport r = diff_traces((d / "a.csv").string(), (d / "b.csv").string());
  ASSERT_EQ(r.signals.size(), 1u) << r.to_text();
  EXPECT_EQ(r.signals[0].signal, "ref_pos_frac");
  EXPECT_EQ(r.signals[0].first_clock, kBadRow * 3);
  EXPECT_TRUE(std::regex_search(r.context, std::regex("A clock +" + std::to_string(kBadRow * 3) + " >"))) << r.context;
}
