// `scurve diff` on FST waveforms: each file checked, then read by fstapi in
// a child process (fst_check.h), then compared signal by signal.
#include <errno.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "fst_check.h"
#include "fstapi.h"
#include "trace_diff.h"

namespace sc {

// ---- FST ------------------------------------------------------------------
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool ignored(const DiffOptions& opt, const std::string& name) {
  return std::find(opt.ignore.begin(), opt.ignore.end(), name) != opt.ignore.end();
}

// The child: fstapi reads the file and the signals go to fd as records
// (fst_check.h). Runs in a forked copy of the process: whatever the reader
// does with a damaged file stays there.
[[noreturn]] void read_fst_child(const std::string& path, int fd) {
  void* ctx = fstReaderOpen(path.c_str());
  if (!ctx) _exit(3);
  struct State {
    std::vector<std::string> names;
    std::unordered_map<fstHandle, size_t> by_handle;
    std::string buf;
    int fd;
    bool ok = true;
    void flush(size_t above) {
      if (buf.size() <= above) return;
      size_t off = 0;
      while (ok && off < buf.size()) {
        const ssize_t n = ::write(fd, buf.data() + off, buf.size() - off);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) ok = false;
        else off += size_t(n);
      }
      buf.clear();
    }
  } st;
  st.fd = fd;
  const uint64_t end_time = fstReaderGetEndTime(ctx);
  std::vector<std::string> scope;
  while (const fstHier* h = fstReaderIterateHier(ctx)) {
    switch (h->htyp) {
      case FST_HT_SCOPE: scope.emplace_back(h->u.scope.name); break;
      case FST_HT_UPSCOPE:
        if (!scope.empty()) scope.pop_back();
        break;
      case FST_HT_VAR: {
        std::string name;
        for (const std::string& p : scope) name += p + ".";
        name += h->u.var.name;
        // Aliases share a handle: keep the first name (the values are the same).
        if (!h->u.var.is_alias && !st.by_handle.count(h->u.var.handle)) {
          st.by_handle[h->u.var.handle] = st.names.size();
          st.names.push_back(name);
        }
        break;
      }
      default: break;
    }
  }
  st.buf = encode_fst_header(end_time, st.names);
  fstReaderSetFacProcessMaskAll(ctx);
  auto cb = [](void* user, uint64_t time, fstHandle handle, const unsigned char* value) {
    auto* s = static_cast<State*>(user);
    const auto it = s->by_handle.find(handle);
    if (it == s->by_handle.end()) return;
    append_fst_change(s->buf, it->second, time, reinterpret_cast<const char*>(value));
    s->flush(1 << 20);
  };
  fstReaderIterBlocks(ctx, cb, &st, nullptr);
  fstReaderClose(ctx);
  st.flush(0);
  _exit(st.ok ? 0 : 4);
}

FstSignals read_fst(const std::string& path) {
  if (const std::string why = fst_check_file(path); !why.empty()) {
    throw std::runtime_error(fmt::format("cannot read FST {}: {}", path, why));
  }
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(fmt::format("cannot read FST {}: pipe failed", path));
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(fmt::format("cannot read FST {}: fork failed", path));
  }
  if (pid == 0) {
    ::close(fds[0]);
    // fstapi prints its own complaints ("FSTAPI | ... exiting."): the parent
    // reports one line instead.
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) {
      ::dup2(null, 1);
      ::dup2(null, 2);
    }
    read_fst_child(path, fds[1]);
  }
  ::close(fds[1]);
  std::string bytes;
  char buf[1 << 16];
  while (true) {
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    bytes.append(buf, size_t(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error(fmt::format("cannot read FST {}: damaged file (the FST reader {})", path,
                                         WIFSIGNALED(status) ? fmt::format("died of signal {}", WTERMSIG(status))
                                                             : fmt::format("exited {}", WEXITSTATUS(status))));
  }
  try {
    return decode_fst_signals(bytes);
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("cannot read FST {}: {}", path, e.what()));
  }
}

}  // namespace

DiffReport diff_fst(const std::string& a_path, const std::string& b_path, const DiffOptions& opt) {
  const FstSignals a = read_fst(a_path);
  const FstSignals b = read_fst(b_path);
  DiffReport rep;
  rep.format = "fst";
  rep.a_name = a_path;
  rep.b_name = b_path;
  const uint64_t ticks = std::max<uint64_t>(1, opt.fst_ticks_per_clock);
  auto to_clock = [&](uint64_t t) { return t / ticks; };
  rep.a_last_clock = to_clock(a.end_time);
  rep.b_last_clock = to_clock(b.end_time);
  rep.length_differs = a.end_time != b.end_time;
  const uint64_t end = std::min(a.end_time, b.end_time);
  rep.compared_clocks = to_clock(end) + 1;

  std::map<std::string, size_t> b_index;
  for (size_t i = 0; i < b.names.size(); ++i) b_index[b.names[i]] = i;
  std::map<std::string, bool> in_a;
  // Clock intervals where some signal differs, merged afterwards.
  std::vector<std::pair<uint64_t, uint64_t>> bad;
  struct First {
    size_t ia, ib;
    uint64_t time;
  };
  std::vector<First> firsts;
  for (size_t i = 0; i < a.names.size(); ++i) {
    const std::string& name = a.names[i];
    in_a[name] = true;
    if (ignored(opt, name)) continue;
    const auto it = b_index.find(name);
    if (it == b_index.end()) {
      rep.only_in_a.push_back(name);
      continue;
    }
    ++rep.compared_signals;
    const auto& ca = a.changes[i];
    const auto& cb = b.changes[it->second];
    // Walk both change lists: the value holds until the next change.
    size_t pa = 0, pb = 0;
    const std::string none = "x";
    const std::string* va = &none;
    const std::string* vb = &none;
    bool differing = false;
    uint64_t diff_from = 0, t = 0, total = 0;
    SignalDiff sd;
    bool seen = false;
    while (true) {
      const uint64_t ta = pa < ca.size() ? ca[pa].first : UINT64_MAX;
      const uint64_t tb = pb < cb.size() ? cb[pb].first : UINT64_MAX;
      t = std::min(ta, tb);
      if (t > end) t = end + 1;
      // close the interval [diff_from, t)
      if (differing && t > diff_from) {
        bad.emplace_back(to_clock(diff_from), to_clock(t - 1) + 1);
        total += to_clock(t - 1) + 1 - to_clock(diff_from);
      }
      if (t > end) break;
      while (pa < ca.size() && ca[pa].first == t) va = &ca[pa++].second;
      while (pb < cb.size() && cb[pb].first == t) vb = &cb[pb++].second;
      differing = *va != *vb;
      diff_from = t;
      if (differing && !seen) {
        seen = true;
        sd = {name, to_clock(t), *va, *vb, 0};
        firsts.push_back({i, it->second, t});
      }
    }
    if (seen) {
      sd.differing_clocks = std::max<uint64_t>(1, total);
      rep.signals.push_back(sd);
    }
  }
  for (const std::string& n : b.names) {
    if (!in_a.count(n) && !ignored(opt, n)) rep.only_in_b.push_back(n);
  }
  std::stable_sort(rep.signals.begin(), rep.signals.end(),
                   [](const SignalDiff& x, const SignalDiff& y) { return x.first_clock < y.first_clock; });
  std::sort(bad.begin(), bad.end());
  uint64_t covered_to = 0;
  for (const auto& [from, to] : bad) {
    const uint64_t f = std::max(from, covered_to);
    if (to > f) rep.differing_clocks += to - f;
    covered_to = std::max(covered_to, to);
  }
  if (!firsts.empty()) {
    const First f = *std::min_element(firsts.begin(), firsts.end(),
                                      [](const First& x, const First& y) { return x.time < y.time; });
    auto render = [&](const FstSignals& s, size_t idx, const char* tag) {
      const auto& ch = s.changes[idx];
      const auto pos = size_t(std::lower_bound(ch.begin(), ch.end(), std::make_pair(f.time, std::string())) -
                              ch.begin());
      const size_t from = pos > opt.context_rows ? pos - opt.context_rows : 0;
      const size_t to = std::min(ch.size(), pos + opt.context_rows + 1);
      std::string out;
      for (size_t r = from; r < to; ++r) {
        out += fmt::format("  {} clock {:>11} (t={}){} {}={}\n", tag, to_clock(ch[r].first), ch[r].first,
                           ch[r].first == f.time ? " >" : "  ", s.names[idx], ch[r].second);
      }
      return out;
    };
    rep.context = "context (value changes of that signal around the first divergence):\n" +
                  render(a, f.ia, "A") + render(b, f.ib, "B");
  }
  return rep;
}

DiffReport diff_traces(const std::string& a, const std::string& b, const DiffOptions& opt) {
  if (ends_with(a, ".fst") != ends_with(b, ".fst")) {
    throw std::runtime_error("diff: both traces must be of the same kind (two .fst or two kinematics CSV)");
  }
  return ends_with(a, ".fst") ? diff_fst(a, b, opt) : diff_kin_traces(a, b, opt);
}

}  // namespace sc
