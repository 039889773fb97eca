#include "trace_diff.h"

#include <fmt/format.h>

#include <algorithm>
#include <deque>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "kin_trace.h"

namespace sc {

std::string DiffReport::to_text() const {
  std::string s = fmt::format("diff ({}): A={}  B={}\n", format, a_name, b_name);
  s += fmt::format("compared {} signals over {} clocks", compared_signals, compared_clocks);
  if (!only_in_a.empty()) s += fmt::format("; {} only in A", only_in_a.size());
  if (!only_in_b.empty()) s += fmt::format("; {} only in B", only_in_b.size());
  s += "\n";
  if (identical()) return s + "identical: no divergence\n";
  if (!signals.empty()) {
    const SignalDiff& f = signals.front();
    s += fmt::format("first divergence: clock {} signal {}: A={} B={}\n", f.first_clock, f.signal, f.a, f.b);
    if (!context.empty()) s += context;
    s += fmt::format("summary: {} of {} signals differ, on {} clocks\n", signals.size(), compared_signals,
                     differing_clocks);
    for (const SignalDiff& d : signals) {
      s += fmt::format("  {:<16} first at clock {:>11}  differs on {} clocks\n", d.signal, d.first_clock,
                       d.differing_clocks);
    }
  }
  if (length_differs) {
    s += fmt::format("length differs: A ends at clock {}, B at clock {}\n", a_last_clock, b_last_clock);
  }
  return s;
}

namespace {

std::string with_source(const std::string& path, const std::map<std::string, std::string>& meta) {
  const auto it = meta.find("source");
  return it == meta.end() ? path : fmt::format("{} ({})", path, it->second);
}

bool ignored(const DiffOptions& opt, const std::string& name) {
  return std::find(opt.ignore.begin(), opt.ignore.end(), name) != opt.ignore.end();
}

}  // namespace

// CSV: held columns are exact between rows (sample and hold); sampled
// columns are compared only at clocks where both traces have a row. Both
// traces are streamed: memory holds the current and the next row of each and
// a few rows of context, whatever the length.
namespace {

// One trace as a sequence of rows with one row of look-ahead.
struct Stream {
  explicit Stream(const std::string& path) : r(path) { more = r.next(next_clock, next_row); }
  Stream(std::istream& in, const std::string& name) : r(in, name) { more = r.next(next_clock, next_row); }
  // The next row becomes the current one.
  void advance() {
    cur_clock = next_clock;
    cur_row.swap(next_row);
    has_cur = true;
    more = r.next(next_clock, next_row);
  }
  KinTraceReader r;
  bool has_cur = false, more = false;
  uint64_t cur_clock = 0, next_clock = 0;
  std::vector<std::string> cur_row, next_row;
};

struct ContextRows {
  std::deque<std::pair<uint64_t, std::vector<std::string>>> before;  // rows before the first divergence
  std::vector<std::pair<uint64_t, std::vector<std::string>>> after;  // the first row at or after it, and more
};

}  // namespace

namespace {

DiffReport diff_kin(Stream& a, const std::string& a_path, Stream& b, const std::string& b_path,
                    const DiffOptions& opt) {
  DiffReport rep;
  rep.format = "csv";

  struct Col {
    std::string name;
    size_t ia, ib;
    bool held;
  };
  const std::vector<std::string>& ac = a.r.columns();
  const std::vector<std::string>& bc = b.r.columns();
  std::vector<Col> cols;
  for (size_t i = 0; i < ac.size(); ++i) {
    if (ignored(opt, ac[i])) continue;
    const auto it = std::find(bc.begin(), bc.end(), ac[i]);
    if (it == bc.end()) {
      rep.only_in_a.push_back(ac[i]);
      continue;
    }
    const size_t ib = size_t(it - bc.begin());
    cols.push_back({ac[i], i, ib, a.r.held()[i] && b.r.held()[ib]});
  }
  for (const std::string& c : bc) {
    if (!ignored(opt, c) && std::find(ac.begin(), ac.end(), c) == ac.end()) rep.only_in_b.push_back(c);
  }
  rep.compared_signals = cols.size();

  std::map<std::string, size_t> index;  // signal -> position in rep.signals
  bool diverged = false;
  uint64_t c0 = 0;
  ContextRows ctx_a, ctx_b;
  const size_t keep = opt.context_rows;
  auto remember = [&](Stream& s, ContextRows& ctx) {
    if (!diverged) {
      ctx.before.emplace_back(s.cur_clock, s.cur_row);
      if (ctx.before.size() > keep + 1) ctx.before.pop_front();
    } else if (ctx.after.size() < keep + 1) {
      ctx.after.emplace_back(s.cur_clock, s.cur_row);
    }
  };
  while (a.more || b.more) {
    const uint64_t ca = a.more ? a.next_clock : UINT64_MAX;
    const uint64_t cb = b.more ? b.next_clock : UINT64_MAX;
    const uint64_t c = std::min(ca, cb);
    const bool row_a = ca == c, row_b = cb == c;
    if (row_a) {
      a.advance();
      remember(a, ctx_a);
    }
    if (row_b) {
      b.advance();
      remember(b, ctx_b);
    }
    if (!a.has_cur || !b.has_cur) continue;  // one trace has not started yet
    // The end of the shorter trace, known once its file is read to the end
    // (before that the look-ahead rows bound every span).
    const uint64_t a_end = a.more ? UINT64_MAX : a.r.end_clock();
    const uint64_t b_end = b.more ? UINT64_MAX : b.r.end_clock();
    const uint64_t common_end = std::min(a_end, b_end);
    if (c >= common_end) continue;  // past the shorter trace
    const uint64_t next_a = a.more ? a.next_clock : common_end;
    const uint64_t next_b = b.more ? b.next_clock : common_end;
    const uint64_t span = std::max<uint64_t>(1, std::min({next_a, next_b, common_end}) - c);  // clocks this value holds
    bool any = false;
    uint64_t any_span = 0;
    for (const Col& col : cols) {
      if (!col.held && !(row_a && row_b)) continue;
      const std::string& va = a.cur_row[col.ia];
      const std::string& vb = b.cur_row[col.ib];
      if (va == vb) continue;  // canonical decimal: equal text is an equal number
      const uint64_t n = col.held ? span : 1;
      any = true;
      any_span = std::max(any_span, n);
      auto it = index.find(col.name);
      if (it == index.end()) {
        index[col.name] = rep.signals.size();
        rep.signals.push_back({col.name, c, va, vb, n});
      } else {
        rep.signals[it->second].differing_clocks += n;
      }
    }
    if (any) {
      rep.differing_clocks += any_span;
      if (!diverged) {
        diverged = true;
        c0 = c;
        // Rows at c0 are the first "after" rows; the rest stay "before".
        for (auto* ctx : {&ctx_a, &ctx_b}) {
          if (!ctx->before.empty() && ctx->before.back().first == c0) {
            ctx->after.push_back(std::move(ctx->before.back()));
            ctx->before.pop_back();
          }
          while (ctx->before.size() > keep) ctx->before.pop_front();
        }
      }
    }
  }
  rep.a_name = with_source(a_path, a.r.meta());
  rep.b_name = with_source(b_path, b.r.meta());
  rep.a_last_clock = a.r.end_clock() ? a.r.end_clock() - 1 : 0;
  rep.b_last_clock = b.r.end_clock() ? b.r.end_clock() - 1 : 0;
  rep.length_differs = rep.a_last_clock != rep.b_last_clock;
  rep.compared_clocks = std::min(a.r.end_clock(), b.r.end_clock());
  std::stable_sort(rep.signals.begin(), rep.signals.end(),
                   [](const SignalDiff& x, const SignalDiff& y) { return x.first_clock < y.first_clock; });

  if (diverged) {
    // Context: the rows of both traces around the first divergence.
    std::vector<std::string> names;
    for (const SignalDiff& d : rep.signals) names.push_back(d.signal);
    for (const Col& col : cols) {
      if (names.size() >= 6) break;
      if (std::find(names.begin(), names.end(), col.name) == names.end() && col.held) names.push_back(col.name);
    }
    auto render = [&](const ContextRows& ctx, const std::vector<std::string>& columns, const char* tag) {
      std::string s;
      auto line = [&](const std::pair<uint64_t, std::vector<std::string>>& r) {
        std::string l = fmt::format("  {} clock {:>11}{}", tag, r.first, r.first == c0 ? " >" : "  ");
        for (const std::string& n : names) {
          const auto it = std::find(columns.begin(), columns.end(), n);
          if (it != columns.end()) l += fmt::format(" {}={}", n, r.second[size_t(it - columns.begin())]);
        }
        s += l + "\n";
      };
      for (const auto& r : ctx.before) line(r);
      for (const auto& r : ctx.after) line(r);
      return s;
    };
    rep.context = "context (rows of each trace around the first divergence):\n" + render(ctx_a, ac, "A") +
                  render(ctx_b, bc, "B");
  }
  return rep;
}

}  // namespace

DiffReport diff_kin_traces(const std::string& a_path, const std::string& b_path, const DiffOptions& opt) {
  Stream a(a_path), b(b_path);
  return diff_kin(a, a_path, b, b_path, opt);
}

DiffReport diff_kin_streams(std::istream& a_in, const std::string& a_name, std::istream& b_in,
                            const std::string& b_name, const DiffOptions& opt) {
  Stream a(a_in, a_name), b(b_in, b_name);
  return diff_kin(a, a_name, b, b_name, opt);
}

}  // namespace sc
