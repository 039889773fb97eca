// Reading FST files a user gives `scurve diff`, robustly. The FST reader
// (gtkwave's fstapi, shipped with Verilator) trusts its input: a damaged
// file can crash it or make it allocate without bound. So a file is first
// checked here (the block chain: a 330-byte header, then blocks of known
// types whose lengths add up to exactly the file size, at least one
// hierarchy and one geometry block, bounded signal counts), then read by
// fstapi in a child process that sends the signals back through a pipe in
// the format below; the parent decodes that with every length checked. A
// file the child cannot read is an error naming the file, never a crash.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace sc {

struct FstSignals {
  std::vector<std::string> names;                                      // one per handle we keep
  std::unordered_map<uint32_t, size_t> by_handle;                      // fstHandle -> index (child side)
  std::vector<std::vector<std::pair<uint64_t, std::string>>> changes;  // per signal, time ordered
  uint64_t end_time = 0;
};

// Upper bounds the check enforces (far above any trace the benches write).
inline constexpr uint64_t kFstMaxHandles = uint64_t(1) << 20;
inline constexpr uint64_t kFstMaxScopes = uint64_t(1) << 20;

// "" when the bytes have the shape of a finished FST file, else why not.
std::string fst_check(const uint8_t* data, size_t size);
// The same on a file (reads the header and the block heads only).
std::string fst_check_file(const std::string& path);

// The child's record stream: "SCFST1\n", end_time (u64), the signal count
// (u64), each name (u64 length + bytes), then change records (u64 signal
// index, u64 time, u64 length + value bytes), all little-endian.
std::string encode_fst_header(uint64_t end_time, const std::vector<std::string>& names);
void append_fst_change(std::string& out, uint64_t index, uint64_t time, const std::string& value);
// Decodes a record stream; throws std::runtime_error on any inconsistency.
// Values of one signal at one time: the last one wins; times must not
// decrease per signal.
FstSignals decode_fst_signals(const std::string& bytes);

}  // namespace sc
