#include "coverage_sink.h"

#include <fmt/format.h>
#include <unistd.h>
#include <verilated.h>
#include <verilated_cov.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <string>

namespace sc {
#if defined(VM_COVERAGE) && VM_COVERAGE
namespace {

// One process's counters by coverage point (the quoted key of a .dat line).
class CoverageTable {
 public:
  explicit CoverageTable(std::string dir) : dir_(std::move(dir)) {
    std::error_code ec;  // Verilator aborts the process on a file it cannot write
    std::filesystem::create_directories(dir_, ec);
  }
  ~CoverageTable() { write(); }
  CoverageTable(const CoverageTable&) = delete;
  CoverageTable& operator=(const CoverageTable&) = delete;

  void add(VerilatedContext& ctx) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::string tmp = fmt::format("{}/.part-{}-{}.dat", dir_, getpid(), parts_++);
    ctx.coveragep()->write(tmp.c_str());
    std::ifstream in(tmp, std::ios::binary);
    std::string line;
    // Lines are `C '<key>' <count>`; keys hold control characters, never `' `.
    while (std::getline(in, line)) {
      if (line.rfind("C '", 0) != 0) continue;
      const size_t end = line.rfind("' ");
      if (end == std::string::npos || end < 3) continue;
      counts_[line.substr(3, end - 3)] += std::strtoull(line.c_str() + end + 2, nullptr, 10);
    }
    std::remove(tmp.c_str());
  }

 private:
  void write() {
    if (counts_.empty()) return;
    const std::string path = fmt::format("{}/{}-{}.dat", dir_, program_invocation_short_name, getpid());
    std::ofstream out(path, std::ios::binary);
    out << "# SystemC::Coverage-3\n";
    for (const auto& [key, count] : counts_) out << "C '" << key << "' " << count << "\n";
  }

  std::string dir_;
  std::mutex mutex_;
  std::map<std::string, uint64_t> counts_;
  int parts_ = 0;
};

CoverageTable* table() {
  static const char* dir = std::getenv("SC_COVERAGE_DIR");
  if (dir == nullptr || *dir == '\0') return nullptr;
  static CoverageTable t(dir);
  return &t;
}

}  // namespace

void coverage_collect(VerilatedContext& ctx) {
  if (CoverageTable* t = table()) t->add(ctx);
}
#else
void coverage_collect(VerilatedContext& /*ctx*/) {}
#endif

}  // namespace sc
