// UART bridge responses (the host end of the board's UART): any byte string
// is a response with a good sync, length and CRC, or an error; a good one
// is exactly what the board would send for its status and data.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fuzz_check.h"
#include "scurve/reg_encode.h"

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
  return 0;
}
