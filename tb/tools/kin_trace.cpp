#include "kin_trace.h"
#include "scurve/cli/user_input.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
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
    : path_(path), part_path_(path + ".part"), decimate_(decimate ? decimate : 1) {
  f_ = std::fopen(part_path_.c_str(), "w");
  if (!f_) throw std::runtime_error(fmt::format("cannot write trace {}: {}", path, std::strerror(errno)));
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
  if (f_) {  // never closed: an aborted run leaves no trace that looks complete
    std::fclose(f_);
    std::remove(part_path_.c_str());
  }
}

void KinTraceWriter::close(uint64_t end_clock) {
  if (!f_) return;
  const std::string trailer = fmt::format("# end_clock={} rows={}\n", end_clock, rows_);
  std::fwrite(trailer.data(), 1, trailer.size(), f_);
  const bool ok = std::fflush(f_) == 0 && !std::ferror(f_);
  const int err = errno;
  const bool closed = std::fclose(f_) == 0;
  f_ = nullptr;
  if (!ok || !closed || std::rename(part_path_.c_str(), path_.c_str()) != 0) {
    const std::string why = std::strerror(ok && closed ? errno : err);
    std::remove(part_path_.c_str());
    throw std::runtime_error(fmt::format("cannot write trace {}: {}", path_, why));
  }
}

void KinTraceWriter::write_row(uint64_t clock, const CoreOutputs& o) {
  // Formatted in memory and written with fwrite, which does not throw: a
  // failed write (a full disk) is found and reported by close(), outside
  // whatever loop (a SystemC process) is running the clocks.
  fmt::memory_buffer row;
  fmt::format_to(std::back_inserter(row), "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", clock, int(o.step), int(o.dir), int(o.en),
             int(o.busy), int(o.done), int(o.phase), int(o.seg_idx), o.pulse_count, int(o.step_pending),
             o.ref_pos_int, to_string_i128(i128(o.ref_pos_frac)), to_string_i128(o.ref_vel), o.ref_acc, o.ref_jerk);
  std::fwrite(row.data(), 1, row.size(), f_);
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

KinTraceReader::KinTraceReader(const std::string& path) : path_(path) {
  if (!std::filesystem::is_regular_file(path)) throw std::runtime_error(fmt::format("{}: not a readable file", path));
  file_.open(path);
  if (!file_) throw std::runtime_error(fmt::format("{}: cannot read", path));
  read_header();
}

KinTraceReader::KinTraceReader(std::istream& in, const std::string& name) : in_(&in), path_(name) { read_header(); }

void KinTraceReader::read_header() {
  const std::string& path = path_;
  // Header: "# scurve-kin-trace v1 ..." then the column line.
  while (columns_.empty() && std::getline(*in_, line_)) {
    ++lineno_;
    if (line_.empty()) continue;
    if (line_[0] == '#') {
      parse_meta(line_);
      continue;
    }
    std::vector<std::string> f = split(line_, ',');
    if (f.empty() || f[0] != "clock") throw std::runtime_error(fmt::format("{}:{}: no header line", path, lineno_));
    if (!meta_.count("scurve-kin-trace")) {
      throw std::runtime_error(fmt::format("{}:{}: not a kinematics trace (no '# scurve-kin-trace v1' line)", path, lineno_));
    }
    columns_.assign(f.begin() + 1, f.end());
    if (columns_.empty()) throw std::runtime_error(fmt::format("{}:{}: no columns", path, lineno_));
    std::vector<std::string> sorted = columns_;
    std::sort(sorted.begin(), sorted.end());
    for (size_t i = 0; i < sorted.size(); ++i) {
      if (sorted[i].empty() || (i > 0 && sorted[i] == sorted[i - 1])) {
        throw std::runtime_error(
            fmt::format("{}:{}: column '{}' empty or repeated", path, lineno_, input::printable(sorted[i])));
      }
    }
    const std::vector<std::string> held_names = split(meta_.count("held") ? meta_.at("held") : "", ';');
    for (const std::string& c : columns_) {
      held_.push_back(std::find(held_names.begin(), held_names.end(), c) != held_names.end());
    }
  }
  if (columns_.empty()) throw std::runtime_error(fmt::format("{}: empty trace (no header)", path));
}

void KinTraceReader::parse_meta(const std::string& line) {
  for (const std::string& kv : split(line.substr(1), ' ')) {
    if (kv.empty()) continue;
    const auto eq = kv.find('=');
    const std::string key = kv.substr(0, eq);
    const std::string value = eq == std::string::npos ? "" : kv.substr(eq + 1);
    const std::string where = fmt::format("{}:{}: {}", path_, lineno_, key);
    if (key == "scurve-kin-trace") {
      meta_[key] = "";
    } else if (key == "v1") {
      meta_["version"] = "1";
    } else if (key == "decimate") {
      input::parse_int(where, value, 1, int64_t(1) << 40);
    } else if (key == "clk_hz") {
      input::parse_int(where, value, 1000, 10'000'000'000);
    } else if (key == "frac_bits") {
      input::parse_int(where, value, 1, 127);
    } else if (key == "end_clock") {
      trailer_end_ = uint64_t(input::parse_int(where, value, 0, INT64_MAX));
    } else if (key == "rows") {
      input::parse_int(where, value, 0, INT64_MAX);
    }
    if (eq != std::string::npos) meta_[key] = value;
  }
}

bool KinTraceReader::next(uint64_t& clock, std::vector<std::string>& row) {
  while (std::getline(*in_, line_)) {
    ++lineno_;
    if (line_.empty()) continue;
    if (line_[0] == '#') {
      parse_meta(line_);
      continue;
    }
    row = split(line_, ',');
    if (row.size() != columns_.size() + 1) {
      throw std::runtime_error(
          fmt::format("{}:{}: {} fields, header has {}", path_, lineno_, row.size(), columns_.size() + 1));
    }
    const int64_t clk = input::parse_int(fmt::format("{}:{}: clock", path_, lineno_), row[0], 0, INT64_MAX - 1);
    if (have_row_ && uint64_t(clk) <= last_clock_) {
      throw std::runtime_error(fmt::format("{}:{}: clock {} not after {}", path_, lineno_, clk, last_clock_));
    }
    for (size_t i = 1; i < row.size(); ++i) {
      if (!input::is_decimal_integer(row[i])) {
        throw std::runtime_error(fmt::format("{}:{}: {}='{}': not a decimal integer", path_, lineno_,
                                             input::printable(columns_[i - 1]), input::printable(row[i].substr(0, 40))));
      }
    }
    row.erase(row.begin());
    clock = last_clock_ = uint64_t(clk);
    have_row_ = true;
    return true;
  }
  if (in_->bad()) throw std::runtime_error(fmt::format("{}: read error", path_));
  return false;
}

uint64_t KinTraceReader::end_clock() const {
  return std::max(have_row_ ? last_clock_ + 1 : 0, trailer_end_);
}

KinTrace read_kin_trace(const std::string& path) {
  KinTraceReader r(path);
  KinTrace t;
  t.columns = r.columns();
  t.held = r.held();
  uint64_t c = 0;
  std::vector<std::string> row;
  while (r.next(c, row)) {
    t.clocks.push_back(c);
    t.rows.push_back(row);
  }
  t.meta = r.meta();
  t.end_clock = r.end_clock();
  return t;
}

}  // namespace sc
