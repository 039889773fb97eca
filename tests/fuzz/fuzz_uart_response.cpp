// UART bridge responses (the host end of the board's UART): any byte string
// is a response with a good sync, length and CRC, or an error; a good one
// is exactly what the board would send for its status and data. The first
// bytes as a register byte address also drive the request encoder, for the
// one-axis and the multi-axis map: it refuses (one line, parameter "addr")
// or frames the word address addr / 4 in the map's address bytes.
#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "fuzz_check.h"
#include "scurve/reg_encode.h"

namespace {

// A request in a map of addr_bits byte address bits (one axis, or the
// multi-axis map with its 2-byte word addresses).
void check_request(uint32_t addr, uint32_t data, int addr_bits) {
  const size_t addr_bytes = size_t(scurve::uart_addr_bytes(addr_bits));
  for (bool is_read : {false, true}) {
    const scurve::FrameResult r =
        is_read ? scurve::uart_read_frame(addr, addr_bits) : scurve::uart_write_frame(addr, data, addr_bits);
    if (const auto* e = std::get_if<scurve::Error>(&r)) {
      fuzz::one_line_message(e->message);
      fuzz::require(e->parameter == "addr", "refusal names another parameter", e->parameter);
      fuzz::require(addr % 4 != 0 || addr >= (1u << addr_bits), "refused a map address", std::to_string(addr));
      continue;
    }
    const std::vector<uint8_t>& f = std::get<std::vector<uint8_t>>(r);
    fuzz::require(f.size() == (is_read ? 3u : 7u) + addr_bytes, "request length", std::to_string(f.size()));
    uint32_t word = 0;
    for (size_t i = 0; i < addr_bytes; ++i) word |= uint32_t(f[2 + i]) << (8 * i);
    fuzz::require(word * 4 == addr, "address bytes are not addr / 4", std::to_string(addr));
    fuzz::require(scurve::crc8(f.data() + 1, f.size() - 2) == f.back(), "request CRC", "");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<uint8_t> b(data, data + size);
  for (bool is_read : {false, true}) {
    const scurve::UartResponse r = scurve::parse_uart_response(b, is_read);
    if (!r.ok) {
      fuzz::one_line_message(r.error);
      continue;
    }
    fuzz::require(size == 3 || size == 7, "accepted length", std::to_string(size));
    fuzz::require(scurve::crc8(data + 1, size - 2) == data[size - 1], "accepted a bad CRC", "");
  }
  uint32_t addr = 0, wdata = 0;
  for (size_t i = 0; i < size && i < 8; ++i) (i < 4 ? addr : wdata) |= uint32_t(data[i]) << (8 * (i % 4));
  for (const int bits : {scurve::hw::RegAddrW, scurve::hw::MultiRegAddrW}) {
    check_request(addr, wdata, bits);
    check_request(addr & ((1u << bits) - 1), wdata, bits);  // mostly inside the map
  }
  return 0;
}
