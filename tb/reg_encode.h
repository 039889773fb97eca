// The hardware model's view of the host library's register/UART encoding
// (scurve/reg_encode.h) and controller-settings conversion: model rows,
// plans and configurations converted to the host types.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "neuron_pi.h"
#include "planner.h"
#include "scurve/reg_encode.h"
#include "scurve/servo_config.h"
#include "servo_axis.h"

namespace sc {

using scurve::crc8;
using scurve::FrameResult;
using scurve::parse_uart_response;
using scurve::reg_name;
using scurve::RegWrite;
using scurve::uart_read_frame;
using scurve::uart_write_frame;
using scurve::UartResponse;

static_assert(scurve::kMinControlDiv == NeuronPi::kMinDiv, "host and model disagree on the shortest control period");

// The host's and the model's controller configurations are the same
// generated struct (scripts/gen_layout.py) in two namespaces: converted
// through the register words, so no field list is written here.
inline NeuronConfig to_model(const scurve::NeuronConfig& h) {
  const auto w = scurve::hw::ctl_cfg_to_words(h);
  std::array<uint32_t, ClCfgWords> words{};
  std::copy(w.begin(), w.end(), words.begin());
  return ctl_cfg_from_words(words);
}

inline scurve::NeuronConfig to_host(const NeuronConfig& n) {
  const auto w = ctl_cfg_to_words(n);
  std::array<uint32_t, scurve::hw::ClCfgWords> words{};
  std::copy(w.begin(), w.end(), words.begin());
  return scurve::hw::ctl_cfg_from_words(words);
}

inline ServoConfig to_model(const scurve::ServoConfig& h) {
  ServoConfig c;
  c.enable = h.enable;
  c.closed_loop = h.closed_loop;
  c.timing = to_model(h.timing);
  c.ctl = to_model(h.ctl);
  return c;
}

inline scurve::ServoConfig to_host(const ServoConfig& c) {
  scurve::ServoConfig h;
  h.enable = c.enable;
  h.closed_loop = c.closed_loop;
  h.timing = to_host(c.timing);
  h.ctl = to_host(c.ctl);
  return h;
}

inline std::vector<RegWrite> encode_move(const Plan& plan, const PulseTiming& timing, bool start = true) {
  return scurve::encode_move(to_host(plan), to_host(timing), start);
}
inline std::vector<RegWrite> encode_servo_config(const ServoConfig& c) {
  return scurve::encode_servo_config(to_host(c));
}
inline std::vector<RegWrite> encode_row(const Segment& s, scurve::RowFlags flags = {}) {
  return scurve::encode_row(to_host(s), flags);
}

}  // namespace sc
