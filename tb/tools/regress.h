// `scurve regress`: runs a JSON test list (paper groups, seeded random
// moves, corner cases, arbitrary commands such as closed-loop scenarios)
// as separate bench processes in parallel, shows progress, prints a summary
// table and writes JUnit XML and JSON. `--shard i/n` runs every n-th test
// so several machines can split a list; `--merge` combines their JSON.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sc::regress {

struct TestCase {
  std::string name;    // unique: entry name, plus ".s<seed>" for random entries
  std::string entry;   // the list entry it came from
  std::string what;    // what the entry proves
  std::string kind;    // group | move | random | command
  uint64_t seed = 0;   // random entries only
  std::vector<std::string> argv;  // bench command (argv[0] may use {bin})
  double timeout_s = 3600;
  std::vector<std::string> labels;
};

struct TestResult {
  TestCase test;
  bool pass = false;
  int exit_code = -1;
  bool timed_out = false;
  bool interrupted = false;  // by SIGINT/SIGTERM to the runner
  double wall_s = 0;
  nlohmann::json result;  // the bench's JSON (null if it printed none)
  std::string failure;    // one line when failing
  std::string log_path;   // stderr of the run
  std::string command;    // argv as run ({bin} resolved), for a rerun by hand
};

// A random entry's seed draws a move at most kDrawsPerSeed times (until one
// plans within its max_clocks); a list's random entries draw at most
// max_random_draws times in all. Either bound exceeded: the list is refused.
constexpr int kDrawsPerSeed = 100;
constexpr int64_t kMaxRandomDraws = 200000;
// Expands a list (see tests/regress_list.json) into test cases. Labels:
// keep a test when it has any of `only` (if given) and none of `exclude`.
std::vector<TestCase> expand_list(const nlohmann::json& list, const std::vector<std::string>& only,
                                  const std::vector<std::string>& exclude,
                                  int64_t max_random_draws = kMaxRandomDraws);
// Test k (0-based, in list order) belongs to shard i (1-based) of n when k % n == i - 1.
std::vector<TestCase> select_shard(const std::vector<TestCase>& tests, int index, int count);
// Parses "i/n"; throws std::invalid_argument naming the flag.
std::pair<int, int> parse_shard(const std::string& s);

// A random entry's "ranges" checked (known keys, [lo, hi] within the
// planner's limits) with the defaults filled in; throws input::Error.
nlohmann::json checked_ranges(const std::string& param, const nlohmann::json& ranges);

// The random move of a seed: bench flags of an accepted (plannable) request.
std::vector<std::string> random_move_args(uint64_t seed, const nlohmann::json& ranges);

struct RunOptions {
  unsigned jobs = 1;
  std::string bin_dir;   // replaces {bin} in argv[0]
  std::string out_dir;   // per-test JSON/log, results.json, junit.xml
  bool progress = true;  // a live line on a terminal
};
// Runs each test in its own process group; a timeout kills the whole group.
// SIGINT/SIGTERM during the run kill every running group, start nothing
// more, and leave interrupted() set (the tests not run are marked so).
std::vector<TestResult> run_tests(const std::vector<TestCase>& tests, const RunOptions& opt);
// The signal that interrupted the last run_tests(), or 0.
int interrupted();

// argv as one line a POSIX shell runs as the same argv.
std::string shell_command(const std::vector<std::string>& argv);

std::string summary_table(const std::vector<TestResult>& results);
std::string junit_xml(const std::vector<TestResult>& results, const std::string& suite);
nlohmann::json results_json(const std::vector<TestResult>& results, const std::string& shard);
// Reads a results.json back (for --merge); throws input::Error on a wrong
// shape or type, naming the field.
std::vector<TestResult> results_from_json(const nlohmann::json& j);

}  // namespace sc::regress
