#include "fst_check.h"

#include "scurve/cli/user_input.h"

#include <fmt/format.h>

#include <cstdio>
#include <cstring>
#include <functional>
#include <stdexcept>

namespace sc {

namespace {

uint64_t be64(const uint8_t* p) {
  uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v = v << 8 | p[i];
  return v;
}

// Header block layout (fstapi.c FST_HDR_OFFS_*): tag, section length, start
// and end time, endianness test double, memory used, scope count, var count,
// max handle, section count, timescale, version, date, file type, time zero.
constexpr size_t kHdrLength = 330;
constexpr size_t kOffsEndian = 1 + 8 + 8 + 8;
constexpr size_t kOffsNumScopes = kOffsEndian + 8 + 8;
constexpr size_t kOffsNumVars = kOffsNumScopes + 8;
constexpr size_t kOffsMaxHandle = kOffsNumVars + 8;

enum : uint8_t {
  kBlHdr = 0,
  kBlVcdata = 1,
  kBlBlackout = 2,
  kBlGeom = 3,
  kBlHier = 4,
  kBlVcdataDynAlias = 5,
  kBlHierLz4 = 6,
  kBlHierLz4Duo = 7,
  kBlVcdataDynAlias2 = 8,
};

}  // namespace

namespace {

// read(pos, n, buf): n bytes at pos of a file of `size` bytes (pos + n <= size).
std::string check_blocks(size_t size, const std::function<void(size_t, size_t, uint8_t*)>& read) {
  if (size < kHdrLength) return fmt::format("{} bytes, shorter than an FST header", size);
  uint8_t hdr[kHdrLength];
  read(0, kHdrLength, hdr);
  const uint8_t* data = hdr;
  if (data[0] != kBlHdr || be64(data + 1) != kHdrLength - 1) return "no FST header block";
  // The writer stores e as a native double; accept either byte order.
  double e = 0;
  std::memcpy(&e, data + kOffsEndian, 8);
  uint8_t swapped[8];
  for (int i = 0; i < 8; ++i) swapped[i] = data[kOffsEndian + 7 - i];
  double e_swapped = 0;
  std::memcpy(&e_swapped, swapped, 8);
  constexpr double kE = 2.7182818284590452354;
  if (e != kE && e_swapped != kE) return "FST header: endianness test value wrong";
  const uint64_t scopes = be64(data + kOffsNumScopes), vars = be64(data + kOffsNumVars);
  const uint64_t handles = be64(data + kOffsMaxHandle);
  if (scopes > kFstMaxScopes) return fmt::format("FST header: {} scopes (at most {})", scopes, kFstMaxScopes);
  if (handles > kFstMaxHandles) return fmt::format("FST header: {} signals (at most {})", handles, kFstMaxHandles);
  if (vars > kFstMaxHandles * 4) return fmt::format("FST header: {} variables (at most {})", vars, kFstMaxHandles * 4);
  bool hier = false, geom = false;
  size_t pos = kHdrLength;
  while (pos < size) {
    if (size - pos < 9) return fmt::format("block at byte {}: truncated", pos);
    uint8_t head[9];
    read(pos, 9, head);
    const uint8_t type = head[0];
    const uint64_t len = be64(head + 1);
    if (len < 8 || len > size - pos - 1) {
      return fmt::format("block at byte {}: length {} does not fit the file", pos, len);
    }
    switch (type) {
      case kBlVcdata:
      case kBlVcdataDynAlias:
      case kBlVcdataDynAlias2:
      case kBlBlackout: break;
      case kBlGeom: geom = true; break;
      case kBlHier:
      case kBlHierLz4:
      case kBlHierLz4Duo: hier = true; break;
      case 255: return fmt::format("block at byte {}: unfinished (the writer did not close the file)", pos);
      default: return fmt::format("block at byte {}: type {} not supported", pos, int(type));
    }
    pos += 1 + size_t(len);
  }
  if (!hier) return "no hierarchy block";
  if (!geom) return "no geometry block";
  return "";
}

}  // namespace

std::string fst_check(const uint8_t* data, size_t size) {
  return check_blocks(size, [data](size_t pos, size_t n, uint8_t* buf) { std::memcpy(buf, data + pos, n); });
}

std::string fst_check_file(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return "cannot open";
  std::string why;
  if (std::fseek(f, 0, SEEK_END) != 0) why = "cannot seek";
  const long end = why.empty() ? std::ftell(f) : -1;
  if (end < 0 && why.empty()) why = "cannot seek";
  bool io_error = false;
  if (why.empty()) {
    why = check_blocks(size_t(end), [&](size_t pos, size_t n, uint8_t* buf) {
      if (std::fseek(f, long(pos), SEEK_SET) != 0 || std::fread(buf, 1, n, f) != n) {
        io_error = true;
        std::memset(buf, 0xff, n);
      }
    });
  }
  std::fclose(f);
  return io_error ? "read error" : why;
}

namespace {

constexpr char kMagic[] = "SCFST1\n";
constexpr size_t kMagicLen = sizeof(kMagic) - 1;

void put64(std::string& out, uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(char(uint8_t(v >> (8 * i))));
}

struct Reader {
  const std::string& b;
  size_t pos = 0;
  size_t left() const { return b.size() - pos; }
  uint64_t u64(const char* what) {
    if (left() < 8) throw std::runtime_error(fmt::format("FST records: truncated {}", what));
    uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= uint64_t(uint8_t(b[pos + size_t(i)])) << (8 * i);
    pos += 8;
    return v;
  }
  std::string bytes(const char* what) {
    const uint64_t n = u64(what);
    if (n > left()) throw std::runtime_error(fmt::format("FST records: {} of {} bytes past the end", what, n));
    std::string s = b.substr(pos, size_t(n));
    pos += size_t(n);
    return s;
  }
};

}  // namespace

std::string encode_fst_header(uint64_t end_time, const std::vector<std::string>& names) {
  std::string out(kMagic, kMagicLen);
  put64(out, end_time);
  put64(out, names.size());
  for (const std::string& n : names) {
    put64(out, n.size());
    out += n;
  }
  return out;
}

void append_fst_change(std::string& out, uint64_t index, uint64_t time, const std::string& value) {
  put64(out, index);
  put64(out, time);
  put64(out, value.size());
  out += value;
}

FstSignals decode_fst_signals(const std::string& bytes) {
  if (bytes.compare(0, kMagicLen, kMagic, kMagicLen) != 0) throw std::runtime_error("FST records: no header");
  Reader r{bytes, kMagicLen};
  FstSignals s;
  s.end_time = r.u64("end time");
  const uint64_t n = r.u64("signal count");
  if (n > kFstMaxHandles || n > r.left() / 8) throw std::runtime_error(fmt::format("FST records: {} signals", n));
  s.names.reserve(size_t(n));
  for (uint64_t i = 0; i < n; ++i) s.names.push_back(r.bytes("signal name"));
  s.changes.resize(size_t(n));
  while (r.left() > 0) {
    const uint64_t index = r.u64("signal index");
    const uint64_t time = r.u64("time");
    std::string v = r.bytes("value");
    if (index >= n) throw std::runtime_error(fmt::format("FST records: signal {} of {}", index, n));
    auto& ch = s.changes[size_t(index)];
    if (!ch.empty() && ch.back().first > time) {
      throw std::runtime_error(fmt::format("FST records: {} time {} after {}", input::printable(s.names[size_t(index)]),
                                           time, ch.back().first));
    }
    if (!ch.empty() && ch.back().first == time) {
      ch.back().second = std::move(v);  // last write of a time step wins
    } else {
      ch.emplace_back(time, std::move(v));
    }
  }
  return s;
}

}  // namespace sc
