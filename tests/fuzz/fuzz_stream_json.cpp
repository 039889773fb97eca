// Stream files (`scurve stream FILE`): any bytes are refused with one line
// naming the place, or read into moves the stream planner either refuses
// (one line naming the move and the bound) or plans with every move ending
// exactly on the running sum of the distances.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.h"
#include "scurve/cli/stream_file.h"
#include "scurve/cli/user_input.h"
#include "scurve/stream_planner.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  scurve::cli::StreamRequest req;
  try {
    req = scurve::cli::parse_stream_json(text);
  } catch (const scurve::input::Error& e) {
    fuzz::one_line_message(e.what());
    return 0;
  }
  fuzz::require(!req.moves.empty(), "accepted a stream without moves", text);
  // Long accepted streams cost planning time, not coverage: the first moves.
  if (req.moves.size() > 64) req.moves.resize(64);
  scurve::StreamPlanner sp(scurve::Clock{}, scurve::PulseTiming{}, req.limits);
  int64_t sum = 0;
  size_t planned = 0;
  auto take = [&] {
    for (const scurve::StreamedMove& m : sp.take_ready()) {
      sum += m.distance;
      fuzz::require(m.end_position == sum, "end position off the running sum", std::to_string(m.index));
      ++planned;
    }
  };
  for (const scurve::StreamMove& m : req.moves) {
    if (auto e = sp.append(m)) {
      fuzz::one_line_message(e->message);
      return 0;
    }
    take();
  }
  if (auto e = sp.flush()) {
    fuzz::one_line_message(e->message);
    return 0;
  }
  take();
  fuzz::require(planned == req.moves.size(), "a move was not planned", std::to_string(planned));
  return 0;
}
