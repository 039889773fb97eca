#include "tool_commands.h"

#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <thread>

#include "regress.h"
#include "scurve/cli/move_flags.h"
#include "trace_diff.h"

namespace sc {

struct ToolCommands {
  CLI::App* diff = nullptr;
  std::string diff_a, diff_b;
  DiffOptions diff_opt;
  bool diff_json = false;

  CLI::App* regress = nullptr;
  std::string list;
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  std::string out_dir = "regress-out";
  std::string shard;
  std::vector<std::string> labels, exclude_labels;
  std::string bin_dir;
  bool list_only = false;
  bool rerun_with_waves = false;
  std::vector<std::string> merge;
  std::string suite = "scurve-regress";
};

std::shared_ptr<ToolCommands> add_tool_commands(CLI::App& app) {
  auto t = std::make_shared<ToolCommands>();
  t->diff = app.add_subcommand("diff", "compare two traces (kinematics CSV or FST); exit 0 identical, 1 different");
  t->diff->add_option("a", t->diff_a, "first trace (.csv from --trace-rtl/--trace-model, or .fst)")->required();
  t->diff->add_option("b", t->diff_b, "second trace")->required();
  t->diff->add_option("--ignore", t->diff_opt.ignore, "signal to leave out (repeatable)");
  scurve::cli::int_flag(t->diff, "--context", t->diff_opt.context_rows, 0, 1000000,
                        "rows/changes of context each side (default 3)");
  scurve::cli::int_flag(t->diff, "--fst-ticks-per-clock", t->diff_opt.fst_ticks_per_clock, 1, int64_t(1) << 40,
                        "FST time units per clock (the benches write 50: ns at 20 MHz)");
  t->diff->add_flag("--json", t->diff_json, "print the report as JSON");

  t->regress = app.add_subcommand("regress", "run a regression list in parallel; JUnit XML + JSON");
  // The last of repeated flags wins, so scripts/regress.sh's defaults can be overridden.
  const auto last = CLI::MultiOptionPolicy::TakeLast;
  t->regress->add_option("--list", t->list, "test list (default: the installed default list, share/scurve/regress_list.json next to bin/)")->multi_option_policy(last);
  scurve::cli::int_flag(t->regress, "--jobs", t->jobs, 1, 256, "parallel runs (default: cores)");
  t->regress->add_option("--out-dir", t->out_dir, "results, logs, junit.xml, results.json")
      ->multi_option_policy(last);
  t->regress->add_option("--shard", t->shard, "run part i of n (i/n): tests k with k % n == i-1");
  t->regress->add_option("--label", t->labels, "only tests with this label (repeatable)");
  t->regress->add_option("--exclude-label", t->exclude_labels, "skip tests with this label (repeatable)");
  t->regress->add_option("--bin-dir", t->bin_dir, "where sc_bench and scurve are (default: next to scurve)");
  t->regress->add_flag("--list-only", t->list_only, "print the selected tests and their commands, run nothing");
  t->regress->add_flag("--rerun-failing-with-waves", t->rerun_with_waves,
                       "re-run each failing bench test with an FST window and kinematics traces");
  t->regress->add_option("--merge", t->merge, "combine results.json files of shards instead of running")
      ->expected(1, -1);
  t->regress->add_option("--suite", t->suite, "JUnit suite name");
  return t;
}

namespace {

using scurve::cli::bad_input;

int run_diff(const ToolCommands& t) {
  DiffReport rep;
  try {
    rep = diff_traces(t.diff_a, t.diff_b, t.diff_opt);
  } catch (const std::exception& e) {
    return bad_input(e.what());
  }
  if (t.diff_json) {
    nlohmann::json sig = nlohmann::json::array();
    for (const SignalDiff& d : rep.signals) {
      sig.push_back({{"signal", d.signal}, {"first_clock", d.first_clock}, {"a", d.a}, {"b", d.b},
                     {"differing_clocks", d.differing_clocks}});
    }
    nlohmann::json j = {{"format", rep.format},
                        {"a", rep.a_name},
                        {"b", rep.b_name},
                        {"identical", rep.identical()},
                        {"compared_signals", rep.compared_signals},
                        {"compared_clocks", rep.compared_clocks},
                        {"differing_signals", rep.signals.size()},
                        {"differing_clocks", rep.differing_clocks},
                        {"length_differs", rep.length_differs},
                        {"a_last_clock", rep.a_last_clock},
                        {"b_last_clock", rep.b_last_clock},
                        {"only_in_a", rep.only_in_a},
                        {"only_in_b", rep.only_in_b},
                        {"signals", sig},
                        {"context", rep.context}};
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << rep.to_text();
  }
  return rep.identical() ? 0 : 1;
}

std::string self_dir() {
  std::error_code ec;
  const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string(".") : p.parent_path().string();
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path);
}

// A waveform window around the first reported clock of the failure.
std::pair<uint64_t, uint64_t> wave_window(const regress::TestResult& r) {
  std::string text = r.failure;
  if (r.result.is_object()) text = r.result.value("first_mismatch", "") + " " + text;
  std::smatch m;
  if (std::regex_search(text, m, std::regex("clock (\\d+)"))) {
    const uint64_t c = std::stoull(m[1]);
    return {c > 20000 ? c - 20000 : 0, c + 2000};
  }
  return {0, 2000000};  // no clock named: the start of the run
}

int run_regress(const ToolCommands& t) {
  namespace fs = std::filesystem;
  using namespace regress;

  std::vector<TestResult> results;
  std::string shard_text = "1/1";
  if (!t.merge.empty()) {
    std::map<std::string, std::string> seen;  // test name -> the file it came from
    for (const std::string& f : t.merge) {
      if (!fs::is_regular_file(f)) return bad_input(fmt::format("--merge={}: not a readable file", f));
      std::ifstream in(f);
      if (!in) return bad_input(fmt::format("--merge={}: cannot read", f));
      try {
        const auto part = results_from_json(nlohmann::json::parse(in));
        for (const TestResult& r : part) {
          const auto [it, fresh] = seen.emplace(r.test.name, f);
          if (!fresh) {
            return bad_input(fmt::format("--merge={}: test {} is already in {} (a shard merged twice?)", f,
                                         r.test.name, it->second));
          }
        }
        results.insert(results.end(), part.begin(), part.end());
      } catch (const std::exception& e) {
        return bad_input(fmt::format("--merge={}: {}", f, input::printable(e.what())));
      }
    }
    shard_text = "merged";
  } else {
    std::string list = t.list;
    if (list.empty()) {
      // Installed (and in the build tree) next to bin/: share/scurve/.
      list = (fs::path(self_dir()).parent_path() / "share/scurve/regress_list.json").string();
    }
    if (!fs::is_regular_file(list)) return bad_input(fmt::format("--list={}: not a readable file", list));
    std::ifstream in(list);
    if (!in) return bad_input(fmt::format("--list={}: cannot read", list));
    std::vector<TestCase> tests;
    try {
      nlohmann::json parsed;
      try {
        parsed = nlohmann::json::parse(in);
      } catch (const nlohmann::json::exception& e) {
        return bad_input(fmt::format("--list={}: not JSON ({})", list, input::printable(e.what())));
      }
      tests = expand_list(parsed, t.labels, t.exclude_labels);
      if (!t.shard.empty()) {
        const auto [i, n] = parse_shard(t.shard);
        tests = select_shard(tests, i, n);
        shard_text = t.shard;
      }
    } catch (const std::exception& e) {
      return bad_input(e.what());
    }
    if (t.list_only) {
      for (const TestCase& tc : tests) std::cout << tc.name << "\t" << shell_command(tc.argv) << "\n";
      return 0;
    }
    RunOptions ro;
    ro.jobs = t.jobs;
    std::error_code ec;
    fs::create_directories(t.out_dir, ec);
    if (ec) return bad_input(fmt::format("--out-dir {}: {}", t.out_dir, ec.message()));
    ro.bin_dir = t.bin_dir.empty() ? self_dir() : t.bin_dir;
    ro.out_dir = t.out_dir;
    results = run_tests(tests, ro);

    if (t.rerun_with_waves) {
      for (TestResult& r : results) {
        if (r.pass) continue;
        if (r.test.kind == "command") {
          std::cout << fmt::format("{}: command test, no waves option known; rerun by hand\n", r.test.name);
          continue;
        }
        const auto [from, to] = wave_window(r);
        TestCase w = r.test;
        const std::string base = fmt::format("{}/{}", t.out_dir, r.test.name);
        w.name = r.test.name + ".waves";
        for (const std::string& a : {std::string("--fst"), base + ".fst", std::string("--fst-from"),
                                     std::to_string(from), std::string("--fst-to"), std::to_string(to),
                                     std::string("--trace-rtl"), base + ".rtl.csv", std::string("--trace-model"),
                                     base + ".model.csv"}) {
          w.argv.push_back(a);
        }
        RunOptions one = ro;
        one.jobs = 1;
        run_tests({w}, one);
        std::cout << fmt::format("{}: waves {}.fst (clocks {}..{}), traces {}.rtl.csv / {}.model.csv\n"
                                 "  compare: scurve diff {}.rtl.csv {}.model.csv\n",
                                 r.test.name, base, from, to, base, base, base, base);
      }
    }
  }
  std::cout << summary_table(results);
  try {
    fs::create_directories(t.out_dir);
    write_file(t.out_dir + "/junit.xml", junit_xml(results, t.suite));
    write_file(t.out_dir + "/results.json", results_json(results, shard_text).dump(2) + "\n");
  } catch (const std::exception& e) {
    return bad_input(e.what());
  }
  std::cout << fmt::format("wrote {0}/results.json and {0}/junit.xml\n", t.out_dir);
  if (const int sig = interrupted(); sig != 0) {
    std::fprintf(stderr, "error: interrupted by signal %d: running tests killed, results written\n", sig);
    return 128 + sig;
  }
  for (const TestResult& r : results) {
    if (!r.pass) return 1;
  }
  return 0;
}

}  // namespace

bool run_tool_command(const ToolCommands& t, int* exit_code) {
  if (t.diff->parsed()) {
    *exit_code = run_diff(t);
    return true;
  }
  if (t.regress->parsed()) {
    *exit_code = run_regress(t);
    return true;
  }
  return false;
}

}  // namespace sc
