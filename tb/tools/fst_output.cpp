#include "fst_output.h"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <climits>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>

#include "scurve/cli/user_input.h"

namespace sc {

namespace {

// What the SIGBUS handler needs, prepared beforehand: it may only call
// async-signal-safe functions (write, unlink, _exit).
struct Slot {
  std::atomic<bool> used{false};
  char message[1024];
  char part[PATH_MAX];
  char hier[PATH_MAX + 8];  // the writer's "<part>.hier" scratch file
};
std::array<Slot, 4> g_slots;
std::mutex g_slots_mutex;

extern "C" void on_write_fault(int) {
  for (Slot& s : g_slots) {
    if (!s.used.load()) continue;
    ::unlink(s.part);
    ::unlink(s.hier);
  }
  for (Slot& s : g_slots) {
    if (s.used.load()) {
      [[maybe_unused]] const ssize_t n = ::write(2, s.message, std::strlen(s.message));
      break;  // one line: the first open waveform
    }
  }
  ::_exit(2);
}

int claim_slot(const std::string& param, const std::string& path, const std::string& part) {
  std::lock_guard<std::mutex> g(g_slots_mutex);
  for (size_t i = 0; i < g_slots.size(); ++i) {
    Slot& s = g_slots[i];
    if (s.used.load()) continue;
    if (part.size() + 6 >= sizeof s.part) throw input::Error(param, path, "path too long");
    std::snprintf(s.message, sizeof s.message,
                  "error: %s=%s: writing the waveform failed (no space left or a file-size limit)\n", param.c_str(),
                  path.c_str());
    std::snprintf(s.part, sizeof s.part, "%s", part.c_str());
    std::snprintf(s.hier, sizeof s.hier, "%s.hier", part.c_str());
    s.used.store(true);
    struct sigaction sa {};
    sa.sa_handler = on_write_fault;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGBUS, &sa, nullptr);
    return int(i);
  }
  throw input::Error(param, path, "too many waveforms open at once");
}

void release_slot(int i) {
  if (i < 0) return;
  std::lock_guard<std::mutex> g(g_slots_mutex);
  g_slots[size_t(i)].used.store(false);
}

uint64_t be64(const unsigned char* p) {
  uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v = (v << 8) | p[i];
  return v;
}

}  // namespace

FstOutput::FstOutput(std::string param, std::string path)
    : param_(std::move(param)), path_(std::move(path)), part_(path_ + ".part") {
  input::output_path(param_, path_);
  slot_ = claim_slot(param_, path_, part_);
}

FstOutput::~FstOutput() {
  if (!committed_) {
    std::remove(part_.c_str());
    std::remove((part_ + ".hier").c_str());
  }
  release_slot(slot_);
}

void FstOutput::creation_failed() const { throw input::Error(param_, path_, "cannot create " + part_); }

void FstOutput::commit() {
  const std::string why = fst_incomplete_reason(part_);
  if (!why.empty()) {
    std::remove(part_.c_str());
    throw input::Error(param_, path_, "writing the waveform failed (" + why + ")");
  }
  if (std::rename(part_.c_str(), path_.c_str()) != 0) {
    std::remove(part_.c_str());
    throw input::Error(param_, path_, std::string("cannot rename ") + part_ + ": " + std::strerror(errno));
  }
  committed_ = true;
}

std::string fst_incomplete_reason(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "no file";
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return "unreadable";
  // Block types of the FST format (gtkwave fstapi.h).
  constexpr unsigned char kHdr = 0, kGeom = 3, kHier = 4, kHierLz4 = 6, kHierLz4Duo = 7, kSkip = 255;
  const auto* p = reinterpret_cast<const unsigned char*>(data.data());
  const size_t size = data.size();
  bool geometry = false, hierarchy = false;
  size_t pos = 0;
  while (pos < size) {
    const unsigned char type = p[pos];
    if (pos == 0 && type != kHdr) return "no FST header";
    if (type == kSkip) return "a block left unfinished";
    if (pos + 9 > size) return "truncated";
    const uint64_t len = be64(p + pos + 1);  // counts its own 8 bytes
    if (len < 8 || len > size - pos - 1) return "truncated";
    geometry = geometry || type == kGeom;
    hierarchy = hierarchy || type == kHier || type == kHierLz4 || type == kHierLz4Duo;
    pos += 1 + len;
  }
  if (size == 0) return "empty";
  if (!geometry || !hierarchy) return "truncated: no geometry or hierarchy block";
  return "";
}

}  // namespace sc
