// Output digest and per-request timing of the host planner, to keep its
// output bit-identical while its speed changes:
//   plan_digest --write FILE     one hash line per request / stream move
//   plan_digest --check FILE     recompute and compare; exit 1 on a difference
//   plan_digest --slowest N      the N slowest plan() / plan_from() requests
//   plan_digest --combined       one hash over all lines
//   plan_digest --expect HEX     exit 1 unless the combined hash is HEX
//   plan_digest --durations FILE one line per request: its duration in clocks (or the error's
//                                parameter), per stream move its end clock from the stream's start,
//                                to compare the time-optimality of two planners
//   plan_digest --compare FILE   this planner's durations against FILE's: faster / equal / slower
//                                counts, accepted <-> refused and error parameter changes; exit 1 on
//                                a slower result or a changed outcome
// PLAN_DIGEST_N sets the number of random requests per clock rate (4000),
// PLAN_DIGEST_SHOW how many differences --compare lists (20).
// The set: random_request() requests (accepted or not) through plan(), the
// same requests through plan_from() from exact start states, and random
// streams through StreamPlanner. Each hash covers the whole result: every
// segment, pos_frac0, end_state, the figures, or the error text.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "../tests/random_moves.h"
#include "scurve/planner.h"
#include "scurve/stream_planner.h"

namespace {

using namespace scurve;
using test::RandomRequest;

struct Hash {
  uint64_t h = 1469598103934665603ull;  // FNV-1a
  void bytes(const void* p, size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
  template <class T>
  void val(const T& v) {
    bytes(&v, sizeof v);
  }
  void str(const std::string& s) {
    val(s.size());
    bytes(s.data(), s.size());
  }
  void seg(const Segment& s) {
    val(int(s.phase));
    val(s.clocks);
    val(s.jerk);
    val(s.acc0);
    val(s.vel0);
  }
};

uint64_t digest(const PlanResult& r) {
  Hash h;
  if (const auto* e = std::get_if<Error>(&r)) {
    h.val(1);
    h.str(e->parameter);
    h.str(e->message);
    return h.h;
  }
  const Plan& p = std::get<Plan>(r);
  h.val(0);
  h.val(p.segments.size());
  for (const Segment& s : p.segments) h.seg(s);
  h.val(p.pos_frac0);
  h.val(p.distance);
  h.val(p.total_clocks);
  for (double d : {p.duration_s, p.peak_velocity, p.peak_acceleration, p.peak_jerk, p.v_plateau, p.v_end_actual,
                   p.v_end_used}) {
    h.val(d);
  }
  h.val(p.end_speed_adjusted);
  h.val(p.end_state.velocity);
  h.val(p.end_state.frac);
  return h.h;
}

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

struct Timed {
  double us;
  std::string what;
};

std::string describe(const RandomRequest& rr) {
  const MoveRequest& r = rr.req;
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "d=%lld vs=%.17g vc=%.17g ve=%.17g a=%.17g j=%.17g %s%s adj=%d hi=%u lo=%u",
                (long long)r.distance, r.v_start, r.v_cruise, r.v_end, r.a_max, r.j_max,
                r.kind == ProfileKind::Trapezoid ? "trap" : "scurve", r.jerks ? " jerks" : "", int(r.adjust_end_speed),
                unsigned(rr.timing.high), unsigned(rr.timing.low));
  std::string s = buf;
  if (r.jerks) {
    std::snprintf(buf, sizeof buf, " [%.17g %.17g %.17g %.17g]", (*r.jerks)[0], (*r.jerks)[1], (*r.jerks)[2],
                  (*r.jerks)[3]);
    s += buf;
  }
  return s;
}

std::vector<StreamMove> random_stream(std::mt19937_64& g, size_t n, double v_max, bool short_only) {
  std::uniform_int_distribution<int64_t> dist(1, 100000);
  std::uniform_int_distribution<int> coin(0, 99);
  std::uniform_real_distribution<double> frac(0.0, 1.0);
  std::vector<StreamMove> moves(n);
  int dir = 1;
  for (StreamMove& m : moves) {
    if (coin(g) < 20) dir = -dir;
    const int64_t d = short_only || coin(g) < 60 ? 1 + int64_t(std::pow(frac(g), 3) * 2000) : dist(g);
    m.distance = dir * d;
    m.v_cruise = std::max(1.0, v_max * std::pow(frac(g), 2));
    m.v_junction_max = coin(g) < 10 ? 0.0 : v_max * frac(g);
  }
  return moves;
}

uint64_t digest(const StreamedMove& m) {
  Hash h;
  h.val(m.index);
  h.val(m.distance);
  h.val(m.segments.size());
  for (const Segment& s : m.segments) h.seg(s);
  h.val(m.v_in);
  h.val(m.v_out);
  h.val(m.start.velocity);
  h.val(m.start.frac);
  h.val(m.end.velocity);
  h.val(m.end.frac);
  h.val(m.start_clock);
  h.val(m.end_clock);
  h.val(m.end_position);
  return h.h;
}

// "<kind> <hz> <i> ok <clocks> v_end=<v_end_actual>" or "<kind> <hz> <i> err <parameter>".
std::string duration_line(const char* kind, double hz, int i, const PlanResult& r) {
  char buf[256];
  if (const auto* e = std::get_if<Error>(&r)) {
    std::snprintf(buf, sizeof buf, "%s %g %d err %s", kind, hz, i, e->parameter.c_str());
  } else {
    const Plan& p = std::get<Plan>(r);
    std::snprintf(buf, sizeof buf, "%s %g %d ok %llu v_end=%.17g", kind, hz, i, (unsigned long long)p.total_clocks,
                  p.v_end_actual);
  }
  return buf;
}

// Compares duration lines (same requests, same order) of FILE (before) and `now`.
int compare_durations(const std::string& file, const std::vector<std::string>& now,
                      const std::vector<std::string>& what) {
  std::ifstream f(file);
  std::string l;
  size_t k = 0, faster = 0, equal = 0, slower = 0, changed = 0, shown = 0;
  long long saved = 0;
  const char* show_env = std::getenv("PLAN_DIGEST_SHOW");  // how many differences to list (20)
  const size_t show = show_env ? size_t(std::atoll(show_env)) : 20;
  const auto split = [](const std::string& s) {
    std::vector<std::string> w;
    size_t i = 0;
    while (i < s.size()) {
      const size_t j = std::min(s.find(' ', i), s.size());
      w.push_back(s.substr(i, j - i));
      i = j + 1;
    }
    return w;
  };
  while (std::getline(f, l) && k < now.size()) {
    const auto a = split(l), b = split(now[k]);
    const bool ok_a = a.size() > 4 && a[3] == "ok", ok_b = b.size() > 4 && b[3] == "ok";
    const bool is_end = a.size() > 2 && a[2] == "end";
    if (is_end || !ok_a || !ok_b) {
      if (l != now[k]) {
        ++changed;
        if (shown++ < show) std::printf("CHANGED: %s -> %s  %s\n", l.c_str(), now[k].c_str(), what[k].c_str());
      }
    } else {
      const long long ca = std::atoll(a[4].c_str()), cb = std::atoll(b[4].c_str());
      if (cb < ca) ++faster;
      if (cb == ca) ++equal;
      if (cb > ca) {
        ++slower;
        if (shown++ < show) std::printf("SLOWER: %s -> %s  %s\n", l.c_str(), now[k].c_str(), what[k].c_str());
      }
      saved += ca - cb;
    }
    ++k;
  }
  if (k != now.size()) ++changed;
  std::printf("%zu results: %zu faster (%lld clocks in all), %zu equal, %zu slower, %zu outcome changes\n", k,
              faster, saved, equal, slower, changed);
  return slower || changed ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string mode = argc > 1 ? argv[1] : "--slowest";
  const std::string file = argc > 2 ? argv[2] : "";
  const int n_slow = mode == "--slowest" && argc > 2 ? std::atoi(argv[2]) : 20;
  const char* n_env = std::getenv("PLAN_DIGEST_N");  // requests per clock rate
  const int n_requests = n_env ? std::atoi(n_env) : 4000;

  std::vector<std::string> lines, what;  // what: the request of each line
  std::vector<std::string> durations;     // --durations: one per line of `lines`
  std::vector<Timed> times;
  char buf[128];

  // plan() and plan_from() at two clock rates.
  for (const double hz : {20e6, 25e6}) {
    const Clock clock{hz};
    const Planner planner{clock};
    std::mt19937_64 g(hz == 20e6 ? 101 : 202);
    for (int i = 0; i < n_requests; ++i) {
      const RandomRequest rr = test::random_request(g, clock);
      double t0 = cpu_seconds();
      const PlanResult r = planner.plan(rr.req, rr.timing);
      double t1 = cpu_seconds();
      std::snprintf(buf, sizeof buf, "plan %g %d %016llx", hz, i, (unsigned long long)digest(r));
      lines.push_back(buf);
      durations.push_back(duration_line("plan", hz, i, r));
      what.push_back(describe(rr));
      times.push_back({(t1 - t0) * 1e6, std::string("plan ") + (std::holds_alternative<Plan>(r) ? "ok  " : "err ") +
                                            describe(rr)});
      // From an exact state: the request's start speed (in the move's
      // direction), a random fraction; a quarter at a random speed.
      const int dir = rr.req.distance < 0 ? -1 : 1;
      JunctionState st;
      const double v = (g() % 4 == 0) ? std::uniform_real_distribution<double>(0, 1)(g) * rr.req.v_cruise
                                      : rr.req.v_start;
      st.velocity = dir * i128(std::floor(v * vel_lsb_per_unit(clock)));
      st.frac = (u128(g()) << 16) & (kOne - 1);
      t0 = cpu_seconds();
      const PlanResult rf = planner.plan_from(st, rr.req, rr.timing);
      t1 = cpu_seconds();
      std::snprintf(buf, sizeof buf, "from %g %d %016llx", hz, i, (unsigned long long)digest(rf));
      lines.push_back(buf);
      durations.push_back(duration_line("from", hz, i, rf));
      std::snprintf(buf, sizeof buf, " v0=%.17g frac=%s", v, to_hex_u128(st.frac, 80).c_str());
      what.push_back(describe(rr) + buf);
      times.push_back({(t1 - t0) * 1e6, std::string("from ") + (std::holds_alternative<Plan>(rf) ? "ok  " : "err ") +
                                            describe(rr) + buf});
    }
  }

  // Streams: the benchmark's limits and two others, mixed and short moves.
  const StreamLimits stream_limits[] = {{2000, 20000, 20000}, {500, 2500, 3000}, {1e5, 1e7, 100000}};
  int run = 0;
  for (const StreamLimits& l : stream_limits) {
    for (const bool short_only : {false, true}) {
      std::mt19937_64 g(1000 + run);
      const auto moves = random_stream(g, 2000, l.v_max, short_only);
      StreamPlanner sp(Clock{}, PulseTiming{}, l);
      std::vector<StreamedMove> out;
      std::string err;
      for (const StreamMove& m : moves) {
        if (auto e = sp.append(m)) err += e->message + ";";
        for (StreamedMove& s : sp.take_ready()) out.push_back(std::move(s));
      }
      if (auto e = sp.flush()) err += e->message + ";";
      for (StreamedMove& s : sp.take_ready()) out.push_back(std::move(s));
      for (size_t k = 0; k < out.size(); ++k) {
        std::snprintf(buf, sizeof buf, "stream %d %zu %016llx", run, k, (unsigned long long)digest(out[k]));
        lines.push_back(buf);
        // A streamed move's end clock from the stream's start: its own duration
        // depends on the fraction where the previous move ended.
        std::snprintf(buf, sizeof buf, "stream %d %zu ok %llu v_out=%.17g", run, k,
                      (unsigned long long)out[k].end_clock, out[k].v_out);
        durations.push_back(buf);
        what.push_back("stream move");
      }
      Hash h;
      h.str(err);
      std::snprintf(buf, sizeof buf, "stream %d end %zu %016llx", run, out.size(), (unsigned long long)h.h);
      lines.push_back(buf);
      std::snprintf(buf, sizeof buf, "stream %d end %zu", run, out.size());
      durations.push_back(buf + (err.empty() ? std::string() : " err " + err));
      what.push_back("stream end");
      ++run;
    }
  }

  if (mode == "--combined" || mode == "--expect") {
    Hash h;
    for (const auto& l : lines) h.str(l);
    std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)h.h);
    std::printf("%zu hashes, combined %s\n", lines.size(), buf);
    if (mode == "--expect" && file != buf) {
      std::printf("expected %s: the planner's output changed (if on purpose, update the expected hash)\n",
                  file.c_str());
      return 1;
    }
    return 0;
  }
  if (mode == "--durations") {
    std::ofstream f(file);
    for (const auto& l : durations) f << l << "\n";
    std::printf("wrote %zu durations to %s\n", durations.size(), file.c_str());
    return 0;
  }
  if (mode == "--compare") return compare_durations(file, durations, what);
  if (mode == "--write") {
    std::ofstream f(file);
    for (const auto& l : lines) f << l << "\n";
    std::printf("wrote %zu hashes to %s\n", lines.size(), file.c_str());
    return 0;
  }
  if (mode == "--check") {
    std::ifstream f(file);
    std::string l;
    size_t k = 0, bad = 0;
    while (std::getline(f, l)) {
      if (k >= lines.size() || lines[k] != l) {
        if (bad < 20) {
          std::printf("DIFF: want %s got %s  %s\n", l.c_str(), k < lines.size() ? lines[k].c_str() : "-",
                      k < what.size() ? what[k].c_str() : "");
        }
        ++bad;
      }
      ++k;
    }
    if (k != lines.size()) ++bad;
    std::printf("%zu hashes, %zu differ\n", lines.size(), bad);
    return bad ? 1 : 0;
  }
  std::sort(times.begin(), times.end(), [](const Timed& a, const Timed& b) { return a.us > b.us; });
  double total = 0;
  for (const auto& t : times) total += t.us;
  std::printf("%zu requests, total %.0f us, mean %.1f us\n", times.size(), total, total / double(times.size()));
  for (int i = 0; i < n_slow && i < int(times.size()); ++i) std::printf("%9.1f us  %s\n", times[i].us, times[i].what.c_str());
  return 0;
}
