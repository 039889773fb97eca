#include "regress.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <spawn.h>
#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <atomic>
#include <chrono>
#include <fstream>
#include <mutex>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "planner.h"
#include "scurve/cli/user_input.h"

extern char** environ;

namespace sc::regress {

namespace {

std::string num(double x) { return fmt::format("{:.17g}", x); }

// Deterministic on every platform (unlike std::uniform_real_distribution).
double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * double(rng() >> 11) * 0x1.0p-53;
}

double range_lo(const nlohmann::json& r, const char* key) { return r.at(key).at(0).get<double>(); }
double range_hi(const nlohmann::json& r, const char* key) { return r.at(key).at(1).get<double>(); }

}  // namespace

namespace {

// Planner draws a list may still make, of `total`.
struct DrawBudget {
  int64_t left, total;
};
// The move of a seed from ranges already checked (checked_ranges), drawn at
// most kDrawsPerSeed times and from the list's budget (both bound the
// planner work a list can ask for); `at` names the entry.
std::vector<std::string> random_move_from(uint64_t seed, const nlohmann::json& ranges, DrawBudget& draws,
                                          const std::string& at) {
  std::mt19937_64 rng(seed);
  const double max_clocks = ranges.at("max_clocks").get<double>();  // keep each run short
  for (int attempt = 0; attempt < kDrawsPerSeed; ++attempt) {
    if (draws.left-- <= 0) {
      throw input::Error(at, fmt::format("seed {}", seed),
                         fmt::format("the random entries need more than {} planner draws in all: fewer seeds, "
                                     "or ranges whose moves fit max_clocks more often", draws.total));
    }
    MoveRequest r;
    const double dist = uniform(rng, range_lo(ranges, "distance"), range_hi(ranges, "distance"));
    r.distance = int64_t(dist) * ((rng() & 1) ? 1 : -1);
    r.v_cruise = uniform(rng, range_lo(ranges, "v_cruise"), range_hi(ranges, "v_cruise"));
    r.v_start = (rng() & 1) ? 0.0 : uniform(rng, 0, 1.2 * r.v_cruise);
    r.v_end = (rng() & 1) ? 0.0 : uniform(rng, 0, 1.2 * r.v_cruise);
    r.a_max = uniform(rng, range_lo(ranges, "a_max"), range_hi(ranges, "a_max"));
    r.j_max = uniform(rng, range_lo(ranges, "j_max"), range_hi(ranges, "j_max"));
    r.kind = (rng() % 5 == 0) ? ProfileKind::Trapezoid : ProfileKind::SCurve;
    const PlanResult p = plan_move(r, PulseTiming{});
    const Plan* plan = std::get_if<Plan>(&p);
    if (!plan || double(plan->total_clocks) > max_clocks) continue;  // draw again
    return {"--distance", std::to_string(r.distance), "--v-start", num(r.v_start), "--v-cruise", num(r.v_cruise),
            "--v-end", num(r.v_end), "--a-max", num(r.a_max), "--j-max", num(r.j_max), "--profile",
            r.kind == ProfileKind::Trapezoid ? "trapezoid" : "scurve"};
  }
  throw input::Error(at + ".ranges", input::shown(ranges),
                     fmt::format("seed {}: no plannable move of at most max_clocks in {} draws: widen the ranges or "
                                 "raise max_clocks", seed, kDrawsPerSeed));
}

}  // namespace

std::vector<std::string> random_move_args(uint64_t seed, const nlohmann::json& ranges) {
  DrawBudget draws{kDrawsPerSeed, kDrawsPerSeed};
  return random_move_from(seed, checked_ranges("ranges", ranges), draws, "ranges");
}

namespace {

// Names become file names under --out-dir: letters, digits, '_', '-', '.',
// not starting with '.', so no name reaches outside the directory.
void check_name(const std::string& param, const std::string& name) {
  static const std::regex ok("[A-Za-z0-9_][A-Za-z0-9_.-]{0,126}");
  if (!std::regex_match(name, ok)) {
    throw input::Error(param, "'" + name + "'",
                       "a test name is 1-127 of A-Z a-z 0-9 _ . - and does not start with '.'");
  }
}

// The move flags of sc_bench a list may set; output paths and test hooks
// stay under the runner's control.
const std::initializer_list<std::string_view> kMoveKeys = {
    "distance", "v-start", "v-cruise", "v-end", "a-max", "j-max", "profile",
    "pulse-high", "pulse-low", "dir-setup", "dir-hold"};

std::string move_value(const std::string& param, const std::string& key, const nlohmann::json& v) {
  if (key == "profile") {
    const std::string p = input::json_string(param, v);
    if (p != "scurve" && p != "trapezoid") throw input::Error(param, "'" + p + "'", "must be scurve or trapezoid");
    return p;
  }
  if (key == "distance") return std::to_string(input::json_int(param, v, -(int64_t(1) << 31), int64_t(1) << 31));
  if (key.rfind("pulse-", 0) == 0 || key.rfind("dir-", 0) == 0) {
    return std::to_string(input::json_int(param, v, 0, 65535));
  }
  return num(input::json_real(param, v, 0, 1e12));
}

// [lo, hi] of a random range, finite, lo <= hi, within [min, max].
std::pair<double, double> range_of(const std::string& param, const nlohmann::json& ranges, const char* key,
                                   double def_lo, double def_hi, double min, double max) {
  if (!ranges.contains(key)) return {def_lo, def_hi};
  const nlohmann::json& r = input::json_array(param + "." + key, ranges.at(key));
  if (r.size() != 2) throw input::Error(param + "." + key, input::shown(r), "must be [lo, hi]");
  const double lo = input::json_real(param + "." + key + "[0]", r[0], min, max);
  const double hi = input::json_real(param + "." + key + "[1]", r[1], min, max);
  if (lo > hi) throw input::Error(param + "." + key, input::shown(r), "lo must not exceed hi");
  return {lo, hi};
}

constexpr int64_t kMaxSeedsPerEntry = 10000;
constexpr int64_t kMaxSeed = int64_t(1) << 53;

}  // namespace

nlohmann::json checked_ranges(const std::string& param, const nlohmann::json& ranges) {
  input::json_known_keys(param, ranges, {"distance", "v_cruise", "a_max", "j_max", "max_clocks"});
  nlohmann::json out = nlohmann::json::object();
  const auto put = [&](const char* key, double lo, double hi, double min, double max) {
    const auto [a, b] = range_of(param, ranges, key, lo, hi, min, max);
    out[key] = {a, b};
  };
  put("distance", 20, 4000, 1, double(PlannerLimits::kMaxDistance));
  put("v_cruise", 500, 20000, PlannerLimits::kMinCruise, 1e7);
  put("a_max", 2000, 200000, PlannerLimits::kMinAccel, PlannerLimits::kMaxAccel);
  put("j_max", 20000, 5e6, PlannerLimits::kMinJerk, PlannerLimits::kMaxJerk);
  out["max_clocks"] =
      ranges.contains("max_clocks") ? input::json_real(param + ".max_clocks", ranges.at("max_clocks"), 1, 1e12) : 20e6;
  return out;
}

std::vector<TestCase> expand_list(const nlohmann::json& list, const std::vector<std::string>& only,
                                  const std::vector<std::string>& exclude, int64_t max_random_draws) {
  DrawBudget draws{max_random_draws, max_random_draws};
  input::json_known_keys("list", list, {"description", "defaults", "tests"});
  const nlohmann::json defaults = list.value("defaults", nlohmann::json::object());
  input::json_known_keys("defaults", defaults, {"bench", "timeout_s"});
  const std::string bench =
      defaults.contains("bench") ? input::json_string("defaults.bench", defaults.at("bench")) : "{bin}/sc_bench";
  const double default_timeout =
      defaults.contains("timeout_s") ? input::json_real("defaults.timeout_s", defaults.at("timeout_s"), 1, 7 * 86400)
                                     : 3600.0;
  if (!list.contains("tests")) throw input::Error("list.tests", "missing", "required: a non-empty array of tests");
  const nlohmann::json& tests = input::json_array("tests", list.at("tests"));
  if (tests.empty()) throw input::Error("tests", "[]", "the list holds no test");
  std::vector<TestCase> out;
  std::set<std::string> names, entries;
  for (size_t idx = 0; idx < tests.size(); ++idx) {
    const nlohmann::json& e = tests[idx];
    const std::string at = fmt::format("tests[{}]", idx);
    input::json_known_keys(at, e, {"name", "kind", "what", "labels", "timeout_s", "group", "move", "first_seed",
                                   "count", "seeds", "ranges", "argv"});
    TestCase base;
    if (!e.contains("name")) throw input::Error(at + ".name", "missing", "every test needs a name");
    base.entry = input::json_string(at + ".name", e.at("name"));
    check_name(at + ".name", base.entry);
    if (!entries.insert(base.entry).second) throw input::Error(at + ".name", base.entry, "used by an earlier test");
    base.name = base.entry;
    base.what = e.contains("what") ? input::json_string(at + ".what", e.at("what")) : "";
    if (!e.contains("kind")) throw input::Error(at + ".kind", "missing", "required: group, move, random or command");
    base.kind = input::json_string(at + ".kind", e.at("kind"));
    base.timeout_s = e.contains("timeout_s") ? input::json_real(at + ".timeout_s", e.at("timeout_s"), 1, 7 * 86400)
                                             : default_timeout;
    if (e.contains("labels")) {
      const nlohmann::json& l = input::json_array(at + ".labels", e.at("labels"));
      for (size_t k = 0; k < l.size(); ++k) base.labels.push_back(input::json_string(fmt::format("{}.labels[{}]", at, k), l[k]));
    }
    // Keys that belong to another kind are mistakes, not silently unused.
    const auto only_keys = [&](std::initializer_list<std::string_view> mine) {
      for (const char* k : {"group", "move", "first_seed", "count", "seeds", "ranges", "argv"}) {
        if (e.contains(k) && std::find(mine.begin(), mine.end(), k) == mine.end()) {
          throw input::Error(at + "." + k, input::shown(e.at(k)), "not a key of kind '" + base.kind + "'");
        }
      }
    };
    auto bench_cmd = [&](const std::string& name, std::vector<std::string> move) {
      std::vector<std::string> argv = {bench, "--json", "--name", name};
      argv.insert(argv.end(), move.begin(), move.end());
      return argv;
    };
    std::vector<TestCase> expanded;
    if (base.kind == "group") {
      only_keys({"group"});
      if (!e.contains("group")) throw input::Error(at + ".group", "missing", "required: 1, 2, 3 or 4");
      base.argv = bench_cmd(base.name, {"--group", std::to_string(input::json_int(at + ".group", e.at("group"), 1, 4))});
      expanded.push_back(base);
    } else if (base.kind == "move") {
      only_keys({"move"});
      if (!e.contains("move")) throw input::Error(at + ".move", "missing", "required: an object of move flags");
      input::json_known_keys(at + ".move", e.at("move"), kMoveKeys);
      if (!e.at("move").contains("distance")) throw input::Error(at + ".move.distance", "missing", "required");
      std::vector<std::string> move;
      for (const auto& [k, v] : e.at("move").items()) {
        move.push_back("--" + k);
        move.push_back(move_value(at + ".move." + k, k, v));
      }
      base.argv = bench_cmd(base.name, move);
      expanded.push_back(base);
    } else if (base.kind == "random") {
      only_keys({"first_seed", "count", "seeds", "ranges"});
      std::vector<uint64_t> seeds;
      if (e.contains("seeds")) {
        if (e.contains("first_seed") || e.contains("count")) {
          throw input::Error(at + ".seeds", input::shown(e.at("seeds")), "give seeds or first_seed/count, not both");
        }
        const nlohmann::json& s = input::json_array(at + ".seeds", e.at("seeds"));
        if (s.empty() || int64_t(s.size()) > kMaxSeedsPerEntry) {
          throw input::Error(at + ".seeds", input::shown(s), fmt::format("must hold 1 to {} seeds", kMaxSeedsPerEntry));
        }
        for (size_t k = 0; k < s.size(); ++k) {
          seeds.push_back(uint64_t(input::json_int(fmt::format("{}.seeds[{}]", at, k), s[k], 0, kMaxSeed)));
        }
      } else {
        const uint64_t first =
            e.contains("first_seed") ? uint64_t(input::json_int(at + ".first_seed", e.at("first_seed"), 0, kMaxSeed)) : 1;
        const int64_t count = e.contains("count") ? input::json_int(at + ".count", e.at("count"), 1, kMaxSeedsPerEntry) : 1;
        for (int64_t k = 0; k < count; ++k) seeds.push_back(first + uint64_t(k));
      }
      const nlohmann::json ranges =
          checked_ranges(at + ".ranges", e.contains("ranges") ? e.at("ranges") : nlohmann::json::object());
      for (uint64_t s : seeds) {
        TestCase t = base;
        t.seed = s;
        t.name = fmt::format("{}.s{}", base.entry, s);
        t.argv = bench_cmd(t.name, random_move_from(s, ranges, draws, at));  // ranges checked once above
        expanded.push_back(t);
      }
    } else if (base.kind == "command") {
      // Any program that exits 0 on pass (and may print a JSON object with
      // "pass", "clocks", "pulses", "final_error", "max_error", "rmse", ...).
      // A list is code: this entry runs whatever argv names (docs/verification.md).
      only_keys({"argv"});
      if (!e.contains("argv")) throw input::Error(at + ".argv", "missing", "required: the command and its arguments");
      const nlohmann::json& a = input::json_array(at + ".argv", e.at("argv"));
      if (a.empty()) throw input::Error(at + ".argv", "[]", "needs at least the program");
      for (size_t k = 0; k < a.size(); ++k) base.argv.push_back(input::json_string(fmt::format("{}.argv[{}]", at, k), a[k]));
      expanded.push_back(base);
    } else {
      throw input::Error(at + ".kind", "'" + base.kind + "'", "must be group, move, random or command");
    }
    for (const TestCase& t : expanded) {
      if (!names.insert(t.name).second) throw input::Error(at + ".name", t.name, "expands to a name already used");
    }
    auto has = [&](const std::string& l) {
      return std::find(base.labels.begin(), base.labels.end(), l) != base.labels.end();
    };
    if (!only.empty() && std::none_of(only.begin(), only.end(), has)) continue;
    if (std::any_of(exclude.begin(), exclude.end(), has)) continue;
    out.insert(out.end(), expanded.begin(), expanded.end());
  }
  return out;
}

std::pair<int, int> parse_shard(const std::string& s) {
  const size_t slash = s.find('/');
  if (slash == std::string::npos) throw input::Error("shard", s, "expected i/n with 1 <= i <= n");
  const int n = int(input::parse_int("shard", std::string_view(s).substr(slash + 1), 1, 1 << 20));
  const int i = int(input::parse_int("shard", std::string_view(s).substr(0, slash), 1, n));
  return {i, n};
}

std::vector<TestCase> select_shard(const std::vector<TestCase>& tests, int index, int count) {
  std::vector<TestCase> out;
  for (size_t k = 0; k < tests.size(); ++k) {
    if (int(k % size_t(count)) == index - 1) out.push_back(tests[k]);
  }
  return out;
}

// ---- running --------------------------------------------------------------------
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

volatile std::sig_atomic_t g_signal = 0;
void on_signal(int sig) { g_signal = sig; }

// The fields the runner reads from a test's JSON, with the types it needs.
std::string result_shape_error(const nlohmann::json& j) {
  if (!j.is_object()) return "printed JSON that is not an object";
  if (j.contains("pass") && !j["pass"].is_boolean()) return "printed \"pass\": " + input::shown(j["pass"]) + ", not true/false";
  const auto numeric = [](const nlohmann::json& o) -> std::string {
    for (const char* k : {"clocks", "pulses", "final_error", "max_error", "max_tracking_error", "rmse", "mismatches"}) {
      if (o.contains(k) && !o[k].is_null() && !o[k].is_number()) {
        return fmt::format("printed \"{}\": {}, not a number", k, input::shown(o[k]));
      }
    }
    return "";
  };
  if (std::string e = numeric(j); !e.empty()) return e;
  if (j.contains("runs")) {
    if (!j["runs"].is_array()) return "printed \"runs\" that is not an array";
    for (const auto& run : j["runs"]) {
      if (!run.is_object()) return "printed a run that is not an object";
      if (std::string e = numeric(run); !e.empty()) return e;
    }
  }
  return "";
}

TestResult run_one(const TestCase& t, const RunOptions& opt) {
  TestResult r;
  r.test = t;
  std::vector<std::string> argv = t.argv;
  const std::string bin = "{bin}";
  for (std::string& a : argv) {
    const auto p = a.find(bin);
    if (p != std::string::npos) a.replace(p, bin.size(), opt.bin_dir);
  }
  r.command = shell_command(argv);
  const std::string out_path = fmt::format("{}/{}.json", opt.out_dir, t.name);
  r.log_path = fmt::format("{}/{}.log", opt.out_dir, t.name);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, r.log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> cargv;
  for (std::string& a : argv) cargv.push_back(a.data());
  cargv.push_back(nullptr);
  // The child's environment: ours, without SystemC's banner.
  std::vector<std::string> env_store;
  for (char** e = environ; *e; ++e) env_store.emplace_back(*e);
  env_store.emplace_back("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1");
  std::vector<char*> cenv;
  for (std::string& e : env_store) cenv.push_back(e.data());
  cenv.push_back(nullptr);

  // Its own process group, so a timeout or a signal reaches the bench's
  // children too.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attr, 0);

  const auto t0 = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, cargv[0], &fa, &attr, cargv.data(), cenv.data());
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&attr);
  if (rc != 0) {
    r.failure = fmt::format("cannot start {}: {}", argv[0], std::strerror(rc));
    return r;
  }
  int status = 0;
  while (true) {
    const pid_t w = waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (el > t.timeout_s && !r.timed_out) {
      r.timed_out = true;
      kill(-pid, SIGKILL);
    }
    if (g_signal != 0 && !r.interrupted) {
      r.interrupted = true;
      kill(-pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  if (!r.timed_out) kill(-pid, SIGKILL);  // anything the test left running in its group
  // stdout is empty or one JSON object whose known fields have their types;
  // anything else is a failed test, never a crash of the runner.
  std::string bad_output;
  const std::string out = read_file(out_path);
  if (out.find_first_not_of(" \t\r\n") != std::string::npos) {
    try {
      r.result = nlohmann::json::parse(out);
      bad_output = result_shape_error(r.result);
    } catch (const nlohmann::json::exception&) {
      bad_output = "printed output that is not one JSON object";
    }
    if (!bad_output.empty()) r.result = nullptr;
  }
  const bool json_pass = !r.result.is_object() || r.result.value("pass", true);
  r.pass = !r.timed_out && !r.interrupted && r.exit_code == 0 && json_pass && bad_output.empty();
  if (!r.pass) {
    if (r.interrupted) {
      r.failure = fmt::format("interrupted by signal {}", int(g_signal));
    } else if (!bad_output.empty()) {
      r.failure = fmt::format("{} (stdout: {})", bad_output, out_path);
    } else if (r.timed_out) {
      r.failure = fmt::format("timeout after {:.0f} s", t.timeout_s);
    } else if (r.result.is_object() && r.result.contains("failures") && !r.result["failures"].empty()) {
      // First line only: the mismatch context stays in the JSON and JUnit output.
      const std::string f = r.result["failures"][0].is_string() ? r.result["failures"][0].get<std::string>()
                                                                  : r.result["failures"][0].dump();
      r.failure = f.substr(0, f.find('\n'));
    } else {
      r.failure = fmt::format("exit code {} (log: {})", r.exit_code, r.log_path);
    }
  }
  return r;
}

}  // namespace

std::vector<TestResult> run_tests(const std::vector<TestCase>& tests, const RunOptions& opt) {
  std::vector<TestResult> results(tests.size());
  g_signal = 0;
  struct sigaction sa{}, old_int{}, old_term{};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);
  std::atomic<size_t> next{0};
  std::mutex m;
  size_t done = 0, failed = 0;
  std::vector<std::string> running;
  const bool tty = opt.progress && isatty(2);
  auto show = [&](const std::string& finished_line) {
    // Called with m held.
    if (tty) {
      std::string names;
      for (const std::string& n : running) names += (names.empty() ? "" : " ") + n;
      if (names.size() > 60) names = names.substr(0, 57) + "...";
      if (!finished_line.empty()) std::fprintf(stderr, "\r\033[K%s\n", finished_line.c_str());
      std::fprintf(stderr, "\r\033[K[%zu/%zu] %zu failed  running: %s", done, tests.size(), failed, names.c_str());
    } else if (opt.progress && !finished_line.empty()) {
      std::fprintf(stderr, "[%zu/%zu] %s\n", done, tests.size(), finished_line.c_str());
    }
    std::fflush(stderr);
  };
  auto worker = [&]() {
    for (size_t i = next++; i < tests.size(); i = next++) {
      if (g_signal != 0) {
        results[i].test = tests[i];
        results[i].interrupted = true;
        results[i].failure = fmt::format("not run: interrupted by signal {}", int(g_signal));
        results[i].command = shell_command(tests[i].argv);
        continue;
      }
      {
        std::lock_guard<std::mutex> g(m);
        running.push_back(tests[i].name);
        show("");
      }
      results[i] = run_one(tests[i], opt);
      std::lock_guard<std::mutex> g(m);
      running.erase(std::find(running.begin(), running.end(), tests[i].name));
      ++done;
      if (!results[i].pass) ++failed;
      show(fmt::format("{} {} ({:.1f} s){}", results[i].pass ? "PASS" : "FAIL", tests[i].name, results[i].wall_s,
                       results[i].pass ? "" : ": " + results[i].failure));
    }
  };
  std::vector<std::thread> pool;
  for (unsigned k = 0; k < std::max(1u, std::min<unsigned>(opt.jobs, unsigned(tests.size()))); ++k) {
    pool.emplace_back(worker);
  }
  for (auto& t : pool) t.join();
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
  if (tty) std::fprintf(stderr, "\r\033[K");
  return results;
}

int interrupted() { return int(g_signal); }

std::string shell_command(const std::vector<std::string>& argv) {
  std::string s;
  for (const std::string& a : argv) {
    const bool plain = !a.empty() && a.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                         "0123456789_-+=./:,@%") == std::string::npos;
    std::string q = a;
    if (!plain) {
      q = "'";
      for (char c : a) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
      q += "'";
    }
    s += (s.empty() ? "" : " ") + q;
  }
  return s;
}

// ---- reports ----------------------------------------------------------------------
namespace {

// The table's figures from a bench's JSON. Accepts sc_bench's object and
// `{"runs": [...]}` (scurve sim, closed loop: summed clocks/pulses/mismatches,
// worst errors) and the closed loop's name "max_tracking_error".
nlohmann::json table_metrics(const nlohmann::json& j) {
  if (!j.is_object()) return nullptr;
  auto one = [](const nlohmann::json& r) {
    nlohmann::json m = r;
    if (!m.contains("max_error") && m.contains("max_tracking_error")) m["max_error"] = m["max_tracking_error"];
    return m;
  };
  if (!j.contains("runs") || !j["runs"].is_array()) return one(j);
  nlohmann::json m = nlohmann::json::object();
  for (const auto& raw : j["runs"]) {
    const nlohmann::json r = one(raw);
    for (const char* k : {"clocks", "pulses", "mismatches"}) {
      if (r.contains(k) && r[k].is_number()) m[k] = m.value(k, int64_t(0)) + r[k].get<int64_t>();
    }
    if (r.contains("final_error") && r["final_error"].is_number()) {
      const int64_t e = r["final_error"].get<int64_t>();
      if (!m.contains("final_error") || std::abs(e) > std::abs(m["final_error"].get<int64_t>())) m["final_error"] = e;
    }
    for (const char* k : {"max_error", "rmse"}) {
      if (r.contains(k) && r[k].is_number()) m[k] = std::max(m.value(k, 0.0), r[k].get<double>());
    }
  }
  return m;
}

template <typename T>
std::string field(const nlohmann::json& r, const char* key, const char* fmt_spec) {
  if (!r.is_object() || !r.contains(key) || !r[key].is_number()) return "-";
  return fmt::format(fmt::runtime(fmt_spec), r[key].get<T>());
}

std::string xml_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      case '\'': o += "&apos;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') {
          o += ' ';  // not allowed in XML 1.0
        } else {
          o += c;
        }
    }
  }
  return o;
}


}  // namespace

std::string summary_table(const std::vector<TestResult>& results) {
  std::string s = fmt::format("{:<24} {:>6} {:>11} {:>7} {:>6} {:>7} {:>7} {:>5} {:>8} {}\n", "test", "seed", "clocks",
                              "pulses", "f.err", "max_e", "rmse", "mism", "wall_s", "result");
  size_t pass = 0;
  for (const TestResult& r : results) {
    const nlohmann::json j = table_metrics(r.result);
    s += fmt::format("{:<24} {:>6} {:>11} {:>7} {:>6} {:>7} {:>7} {:>5} {:>8.2f} {}\n", r.test.name,
                     r.test.kind == "random" ? std::to_string(r.test.seed) : "-", field<uint64_t>(j, "clocks", "{}"),
                     field<int64_t>(j, "pulses", "{}"), field<int64_t>(j, "final_error", "{}"),
                     field<double>(j, "max_error", "{:.3f}"), field<double>(j, "rmse", "{:.3f}"),
                     field<uint64_t>(j, "mismatches", "{}"), r.wall_s, r.pass ? "PASS" : "FAIL");
    pass += r.pass;
  }
  // Pass rate per list entry (OpenTitan-style test plan view).
  std::vector<std::string> entries;
  for (const TestResult& r : results) {
    if (std::find(entries.begin(), entries.end(), r.test.entry) == entries.end()) entries.push_back(r.test.entry);
  }
  s += "\nper entry:\n";
  for (const std::string& e : entries) {
    size_t n = 0, p = 0;
    for (const TestResult& r : results) {
      if (r.test.entry == e) {
        ++n;
        p += r.pass;
      }
    }
    s += fmt::format("  {:<24} {:>3}/{:<3} pass\n", e, p, n);
  }
  s += fmt::format("\n{} of {} tests passed\n", pass, results.size());
  for (const TestResult& r : results) {
    if (!r.pass) {
      s += fmt::format("FAIL {}: {}\n  rerun: {}\n", r.test.name, r.failure,
                       r.command.empty() ? shell_command(r.test.argv) : r.command);
    }
  }
  return s;
}

std::string junit_xml(const std::vector<TestResult>& results, const std::string& suite) {
  size_t failures = 0;
  double time = 0;
  for (const TestResult& r : results) {
    failures += !r.pass;
    time += r.wall_s;
  }
  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += fmt::format("<testsuites name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{:.3f}\">\n",
                   xml_escape(suite), results.size(), failures, time);
  s += fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" skipped=\"0\" time=\"{:.3f}\">\n",
                   xml_escape(suite), results.size(), failures, time);
  for (const TestResult& r : results) {
    s += fmt::format("    <testcase classname=\"{}.{}\" name=\"{}\" time=\"{:.3f}\">\n", xml_escape(suite),
                     xml_escape(r.test.entry), xml_escape(r.test.name), r.wall_s);
    if (!r.pass) {
      s += fmt::format("      <failure message=\"{}\">{}</failure>\n", xml_escape(r.failure),
                       xml_escape(r.result.is_object() ? r.result.dump(2) : r.failure));
    }
    s += fmt::format("      <system-out>{}</system-out>\n",
                     xml_escape(r.command.empty() ? shell_command(r.test.argv) : r.command));
    s += "    </testcase>\n";
  }
  s += "  </testsuite>\n</testsuites>\n";
  return s;
}

nlohmann::json results_json(const std::vector<TestResult>& results, const std::string& shard) {
  nlohmann::json arr = nlohmann::json::array();
  size_t pass = 0;
  for (const TestResult& r : results) {
    pass += r.pass;
    arr.push_back({{"name", r.test.name},
                   {"entry", r.test.entry},
                   {"what", r.test.what},
                   {"kind", r.test.kind},
                   {"seed", r.test.seed},
                   {"argv", r.test.argv},
                   {"labels", r.test.labels},
                   {"timeout_s", r.test.timeout_s},
                   {"pass", r.pass},
                   {"exit_code", r.exit_code},
                   {"timed_out", r.timed_out},
                   {"wall_s", r.wall_s},
                   {"failure", r.failure},
                   {"log", r.log_path},
                   {"command", r.command},
                   {"result", r.result}});
  }
  return {{"shard", shard}, {"tests", results.size()}, {"passed", pass}, {"pass", pass == results.size()},
          {"results", arr}};
}

std::vector<TestResult> results_from_json(const nlohmann::json& j) {
  using namespace input;
  json_object("results file", j);
  if (!j.contains("results")) throw Error("results", "missing", "required: the array of test results");
  const nlohmann::json& arr = json_array("results", j.at("results"));
  std::vector<TestResult> out;
  for (size_t k = 0; k < arr.size(); ++k) {
    const std::string at = fmt::format("results[{}]", k);
    const nlohmann::json& e = json_object(at, arr[k]);
    const auto str = [&](const char* key, const std::string& def) {
      return e.contains(key) ? json_string(at + "." + key, e.at(key)) : def;
    };
    const auto strings = [&](const char* key) {
      std::vector<std::string> v;
      if (!e.contains(key)) return v;
      const nlohmann::json& a = json_array(at + "." + key, e.at(key));
      for (size_t i = 0; i < a.size(); ++i) v.push_back(json_string(fmt::format("{}.{}[{}]", at, key, i), a[i]));
      return v;
    };
    TestResult r;
    if (!e.contains("name")) throw Error(at + ".name", "missing", "required");
    r.test.name = json_string(at + ".name", e.at("name"));
    check_name(at + ".name", r.test.name);
    r.test.entry = str("entry", r.test.name);
    r.test.what = str("what", "");
    r.test.kind = str("kind", "");
    r.test.seed = e.contains("seed") ? uint64_t(json_int(at + ".seed", e.at("seed"), 0, kMaxSeed)) : 0;
    r.test.argv = strings("argv");
    r.test.labels = strings("labels");
    r.test.timeout_s = e.contains("timeout_s") ? json_real(at + ".timeout_s", e.at("timeout_s"), 0, 7 * 86400) : 3600.0;
    if (!e.contains("pass")) throw Error(at + ".pass", "missing", "required: true or false");
    r.pass = json_bool(at + ".pass", e.at("pass"));
    r.exit_code = e.contains("exit_code") ? int(json_int(at + ".exit_code", e.at("exit_code"), -1, 255 + 128)) : -1;
    r.timed_out = e.contains("timed_out") ? json_bool(at + ".timed_out", e.at("timed_out")) : false;
    r.wall_s = e.contains("wall_s") ? json_real(at + ".wall_s", e.at("wall_s"), 0, 1e9) : 0.0;
    r.failure = str("failure", "");
    r.log_path = str("log", "");
    r.command = str("command", "");
    r.result = e.value("result", nlohmann::json());
    if (!r.result.is_null()) {
      if (const std::string bad = result_shape_error(r.result); !bad.empty()) throw Error(at + ".result", shown(r.result), bad);
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace sc::regress
