#include "kin_trace.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sc {

const std::vector<std::string>& kin_trace_columns() {
  static const std::vector<std::string> cols = {
      // held: written on every change, so their value between rows is exact
      "step", "dir", "en", "busy", "done", "phase", "seg_idx", "pulse_count", "step_pending",
      // sampled: every `decimate` clocks and on the rows above
      "ref_pos_int", "ref_pos_frac", "ref_vel", "ref_acc", "ref_jerk"};
  return cols;
}

KinTraceWriter::KinTraceWriter(const std::string& path, const std::string& source, uint64_t decimate)
    : decimate_(decimate ? decimate : 1) {
  f_ = std::fopen(path.c_str(), "w");
  if (!f_) throw std::runtime_error(fmt::format("cannot write trace {}", path));
  // Big buffer: rows come in bursts around each pulse.
  std::setvbuf(f_, nullptr, _IOFBF, 1 << 20);
  std::string held, all = "clock";
  const auto& cols = kin_trace_columns();
  for (size_t i = 0; i < cols.size(); ++i) {
    if (i < kHeldColumns) held += (held.empty() ? "" : ";") + cols[i];
    all += "," + cols[i];
  }
  fmt::print(f_, "# scurve-kin-trace v1 source={} decimate={} clk_hz={} frac_bits={} held={}\n", source, decimate_,
             ClkHz, FracBits, held);
  fmt::print(f_, "{}\n", all);
}

KinTraceWriter::~KinTraceWriter() {
  if (f_) std::fclose(f_);
}

void KinTraceWriter::close(uint64_t end_clock) {
  if (f_) {
    fmt::print(f_, "# end_clock={} rows={}\n", end_clock, rows_);
    std::fclose(f_);
    f_ = nullptr;
  }
}

void KinTraceWriter::write_row(uint64_t clock, const CoreOutputs& o) {
  fmt::print(f_, "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", clock, int(o.step), int(o.dir), int(o.en),
             int(o.busy), int(o.done), int(o.phase), int(o.seg_idx), o.pulse_count, int(o.step_pending),
             o.ref_pos_int, to_string_i128(i128(o.ref_pos_frac)), to_string_i128(o.ref_vel), o.ref_acc, o.ref_jerk);
  ++rows_;
  last_ = o;
  have_last_ = true;
  next_sample_ = (clock / decimate_ + 1) * decimate_;
}

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream is(s);
  while (std::getline(is, cur, sep)) out.push_back(cur);
  if (!s.empty() && s.back() == sep) out.emplace_back();
  return out;
}

}  // namespace

KinTrace read_kin_trace(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(fmt::format("cannot read trace {}", path));
  KinTrace t;
  std::string line;
  size_t lineno = 0;
  std::vector<std::string> held_names;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty()) continue;
    if (line[0] == '#') {
      for (const std::string& kv : split(line.substr(1), ' ')) {
        const auto eq = kv.find('=');
        if (eq != std::string::npos) t.meta[kv.substr(0, eq)] = kv.substr(eq + 1);
      }
      continue;
    }
    std::vector<std::string> f = split(line, ',');
    if (t.columns.empty() && !f.empty() && f[0] == "clock") {
      t.columns.assign(f.begin() + 1, f.end());
      held_names = split(t.meta.count("held") ? t.meta["held"] : "", ';');
      for (const std::string& c : t.columns) {
        bool h = false;
        for (const std::string& n : held_names) h = h || n == c;
        t.held.push_back(h);
      }
      continue;
    }
    if (t.columns.empty()) throw std::runtime_error(fmt::format("{}:{}: no header line", path, lineno));
    if (f.size() != t.columns.size() + 1) {
      throw std::runtime_error(
          fmt::format("{}:{}: {} fields, header has {}", path, lineno, f.size(), t.columns.size() + 1));
    }
    uint64_t clk = 0;
    try {
      clk = std::stoull(f[0]);
    } catch (const std::exception&) {
      throw std::runtime_error(fmt::format("{}:{}: bad clock '{}'", path, lineno, f[0]));
    }
    if (!t.clocks.empty() && clk <= t.clocks.back()) {
      throw std::runtime_error(fmt::format("{}:{}: clock {} not increasing", path, lineno, clk));
    }
    t.clocks.push_back(clk);
    f.erase(f.begin());
    t.rows.push_back(std::move(f));
  }
  if (t.columns.empty()) throw std::runtime_error(fmt::format("{}: empty trace (no header)", path));
  t.end_clock = t.clocks.empty() ? 0 : t.clocks.back() + 1;
  if (t.meta.count("end_clock")) t.end_clock = std::max(t.end_clock, uint64_t(std::stoull(t.meta["end_clock"])));
  return t;
}

}  // namespace sc
