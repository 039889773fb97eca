// UART bridge responses (the host end of the board's UART): any byte string
// is a response with a good sync, length and CRC, or an error; a good one
// is exactly what the board would send for its status and data. The first
// bytes as a register byte address also drive the request encoder: it
// refuses (one line, parameter "addr") or frames the word address addr / 4.
#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "fuzz_check.h"
#include "scurve/reg_encode.h"

namespace {

void check_request(uint32_t addr, uint32_t data) {
  for (bool is_read : {false, true}) {
    const scurve::FrameResult r = is_read ? scurve::uart_read_frame(addr) : scurve::uart_write_frame(addr, data);
    if (const auto* e = std::get_if<scurve::Error>(&r)) {
      fuzz::one_line_message(e->message);
      fuzz::require(e->parameter == "addr", "refusal names another parameter", e->parameter);
      fuzz::require(addr % 4 != 0 || addr >= (1u << scurve::hw::RegAddrW), "refused a window address",
                    std::to_string(addr));
      continue;
    }
    const std::vector<uint8_t>& f = std::get<std::vector<uint8_t>>(r);
    fuzz::require(f.size() == (is_read ? 4u : 8u), "request length", std::to_string(f.size()));
    fuzz::require(uint32_t(f[2]) * 4 == addr, "address byte is not addr / 4", std::to_string(addr));
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
  check_request(addr, wdata);
  check_request(addr & ((1u << scurve::hw::RegAddrW) - 1), wdata);  // mostly inside the window
  return 0;
}
