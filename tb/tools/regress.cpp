#include "regress.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <atomic>
#include <chrono>
#include <fstream>
#include <mutex>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "planner.h"

extern char** environ;

namespace sc::regress {

namespace {

std::vector<std::string> strings_of(const nlohmann::json& j, const char* key) {
  std::vector<std::string> v;
  if (j.contains(key)) {
    for (const auto& s : j.at(key)) v.push_back(s.get<std::string>());
  }
  return v;
}

std::string num(double x) { return fmt::format("{:.17g}", x); }

// Deterministic on every platform (unlike std::uniform_real_distribution).
double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * double(rng() >> 11) * 0x1.0p-53;
}

double range_lo(const nlohmann::json& r, const char* key, double def) {
  return r.contains(key) ? r.at(key).at(0).get<double>() : def;
}
double range_hi(const nlohmann::json& r, const char* key, double def) {
  return r.contains(key) ? r.at(key).at(1).get<double>() : def;
}

}  // namespace

std::vector<std::string> random_move_args(uint64_t seed, const nlohmann::json& ranges) {
  std::mt19937_64 rng(seed);
  const double max_clocks = ranges.value("max_clocks", 20e6);  // keep each run short
  for (int attempt = 0; attempt < 1000; ++attempt) {
    MoveRequest r;
    const double dist = uniform(rng, range_lo(ranges, "distance", 20), range_hi(ranges, "distance", 4000));
    r.distance = int64_t(dist) * ((rng() & 1) ? 1 : -1);
    r.v_cruise = uniform(rng, range_lo(ranges, "v_cruise", 500), range_hi(ranges, "v_cruise", 20000));
    r.v_start = (rng() & 1) ? 0.0 : uniform(rng, 0, 1.2 * r.v_cruise);
    r.v_end = (rng() & 1) ? 0.0 : uniform(rng, 0, 1.2 * r.v_cruise);
    r.a_max = uniform(rng, range_lo(ranges, "a_max", 2000), range_hi(ranges, "a_max", 200000));
    r.j_max = uniform(rng, range_lo(ranges, "j_max", 20000), range_hi(ranges, "j_max", 5e6));
    r.kind = (rng() % 5 == 0) ? ProfileKind::Trapezoid : ProfileKind::SCurve;
    const PlanResult p = plan_move(r, PulseTiming{});
    const Plan* plan = std::get_if<Plan>(&p);
    if (!plan || double(plan->total_clocks) > max_clocks) continue;  // draw again
    return {"--distance", std::to_string(r.distance), "--v-start", num(r.v_start), "--v-cruise", num(r.v_cruise),
            "--v-end", num(r.v_end), "--a-max", num(r.a_max), "--j-max", num(r.j_max), "--profile",
            r.kind == ProfileKind::Trapezoid ? "trapezoid" : "scurve"};
  }
  throw std::runtime_error(fmt::format("seed {}: no plannable random move in 1000 draws", seed));
}

std::vector<TestCase> expand_list(const nlohmann::json& list, const std::vector<std::string>& only,
                                  const std::vector<std::string>& exclude) {
  const nlohmann::json defaults = list.value("defaults", nlohmann::json::object());
  const std::string bench = defaults.value("bench", "{bin}/sc_bench");
  std::vector<TestCase> out;
  for (const auto& e : list.at("tests")) {
    TestCase base;
    base.entry = e.at("name").get<std::string>();
    base.name = base.entry;
    base.what = e.value("what", "");
    base.kind = e.value("kind", "group");
    base.timeout_s = e.value("timeout_s", defaults.value("timeout_s", 3600.0));
    base.labels = strings_of(e, "labels");
    auto has = [&](const std::string& l) {
      return std::find(base.labels.begin(), base.labels.end(), l) != base.labels.end();
    };
    if (!only.empty() && std::none_of(only.begin(), only.end(), has)) continue;
    if (std::any_of(exclude.begin(), exclude.end(), has)) continue;
    const std::vector<std::string> extra = strings_of(e, "args");
    auto bench_cmd = [&](const std::string& name, std::vector<std::string> move) {
      std::vector<std::string> argv = {bench, "--json", "--name", name};
      argv.insert(argv.end(), move.begin(), move.end());
      argv.insert(argv.end(), extra.begin(), extra.end());
      return argv;
    };
    if (base.kind == "group") {
      base.argv = bench_cmd(base.name, {"--group", std::to_string(e.at("group").get<int>())});
      out.push_back(base);
    } else if (base.kind == "move") {
      std::vector<std::string> move;
      for (const auto& [k, v] : e.at("move").items()) {
        move.push_back("--" + k);
        move.push_back(v.is_string() ? v.get<std::string>() : v.dump());
      }
      base.argv = bench_cmd(base.name, move);
      out.push_back(base);
    } else if (base.kind == "random") {
      std::vector<uint64_t> seeds;
      if (e.contains("seeds")) {
        for (const auto& s : e.at("seeds")) seeds.push_back(s.get<uint64_t>());
      } else {
        const uint64_t first = e.value("first_seed", uint64_t(1));
        for (uint64_t k = 0; k < e.value("count", uint64_t(1)); ++k) seeds.push_back(first + k);
      }
      const nlohmann::json ranges = e.value("ranges", nlohmann::json::object());
      for (uint64_t s : seeds) {
        TestCase t = base;
        t.seed = s;
        t.name = fmt::format("{}.s{}", base.entry, s);
        t.argv = bench_cmd(t.name, random_move_args(s, ranges));
        out.push_back(t);
      }
    } else if (base.kind == "command") {
      // Any program that exits 0 on pass (and may print a JSON object with
      // "pass", "clocks", "pulses", "final_error", "max_error", "rmse", ...).
      base.argv = strings_of(e, "argv");
      if (base.argv.empty()) throw std::invalid_argument(fmt::format("test {}: command needs argv", base.entry));
      out.push_back(base);
    } else {
      throw std::invalid_argument(fmt::format("test {}: unknown kind '{}'", base.entry, base.kind));
    }
  }
  return out;
}

std::pair<int, int> parse_shard(const std::string& s) {
  int i = 0, n = 0;
  char slash = 0;
  std::istringstream is(s);
  if (!(is >> i >> slash >> n) || slash != '/' || n < 1 || i < 1 || i > n || !is.eof()) {
    throw std::invalid_argument(fmt::format("--shard {}: expected i/n with 1 <= i <= n", s));
  }
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

TestResult run_one(const TestCase& t, const RunOptions& opt) {
  TestResult r;
  r.test = t;
  std::vector<std::string> argv = t.argv;
  const std::string bin = "{bin}";
  for (std::string& a : argv) {
    const auto p = a.find(bin);
    if (p != std::string::npos) a.replace(p, bin.size(), opt.bin_dir);
  }
  for (const std::string& a : argv) r.command += (r.command.empty() ? "" : " ") + a;
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

  const auto t0 = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, cargv[0], &fa, nullptr, cargv.data(), cenv.data());
  posix_spawn_file_actions_destroy(&fa);
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
      kill(pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  const std::string out = read_file(out_path);
  const auto brace = out.find('{');
  if (brace != std::string::npos) {
    try {
      r.result = nlohmann::json::parse(out.substr(brace));
    } catch (const std::exception&) {
      r.result = nullptr;
    }
  }
  const bool json_pass = !r.result.is_object() || r.result.value("pass", true);
  r.pass = !r.timed_out && r.exit_code == 0 && json_pass;
  if (!r.pass) {
    if (r.timed_out) {
      r.failure = fmt::format("timeout after {:.0f} s", t.timeout_s);
    } else if (r.result.is_object() && r.result.contains("failures") && !r.result["failures"].empty()) {
      // First line only: the mismatch context stays in the JSON and JUnit output.
      const std::string f = r.result["failures"][0].get<std::string>();
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
  if (tty) std::fprintf(stderr, "\r\033[K");
  return results;
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
  if (!r.is_object() || !r.contains(key) || r[key].is_null()) return "-";
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

std::string command_line(const std::vector<std::string>& argv) {
  std::string s;
  for (const std::string& a : argv) s += (s.empty() ? "" : " ") + a;
  return s;
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
                       r.command.empty() ? command_line(r.test.argv) : r.command);
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
                     xml_escape(r.command.empty() ? command_line(r.test.argv) : r.command));
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
  std::vector<TestResult> out;
  for (const auto& e : j.at("results")) {
    TestResult r;
    r.test.name = e.at("name").get<std::string>();
    r.test.entry = e.value("entry", r.test.name);
    r.test.what = e.value("what", "");
    r.test.kind = e.value("kind", "");
    r.test.seed = e.value("seed", uint64_t(0));
    r.test.argv = e.value("argv", std::vector<std::string>{});
    r.test.labels = e.value("labels", std::vector<std::string>{});
    r.test.timeout_s = e.value("timeout_s", 3600.0);
    r.pass = e.at("pass").get<bool>();
    r.exit_code = e.value("exit_code", -1);
    r.timed_out = e.value("timed_out", false);
    r.wall_s = e.value("wall_s", 0.0);
    r.failure = e.value("failure", "");
    r.log_path = e.value("log", "");
    r.command = e.value("command", "");
    r.result = e.value("result", nlohmann::json());
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace sc::regress
