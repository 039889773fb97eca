// The hardware model's view of the host library's register/UART encoding
// (scurve/reg_encode.h) and controller-settings conversion: model rows,
// plans and configurations converted to the host types.
#pragma once

#include <string>
#include <vector>

#include "neuron_pi.h"
#include "planner.h"
#include "scurve/reg_encode.h"
#include "scurve/servo_config.h"
#include "servo_axis.h"

namespace sc {

using scurve::crc8;
using scurve::parse_uart_response;
using scurve::reg_name;
using scurve::RegWrite;
using scurve::uart_read_frame;
using scurve::uart_write_frame;
using scurve::UartResponse;

static_assert(scurve::kMinControlDiv == NeuronPi::kMinDiv, "host and model disagree on the shortest control period");

inline NeuronConfig to_model(const scurve::NeuronConfig& h) {
  NeuronConfig n;
  n.div = h.div;
  n.shift = h.shift;
  n.ff_en = h.ff_en;
  n.learn_shift = h.learn_shift;
  n.learn_dz_p = h.learn_dz_p;
  n.learn_dz_v = h.learn_dz_v;
  n.k_p = h.k_p;
  n.k_v = h.k_v;
  n.kb = h.kb;
  n.eta_p1 = h.eta_p1;
  n.eta_p2 = h.eta_p2;
  n.eta_v1 = h.eta_v1;
  n.eta_v2 = h.eta_v2;
  n.w_p1 = h.w_p1;
  n.w_p2 = h.w_p2;
  n.w_v1 = h.w_v1;
  n.w_v2 = h.w_v2;
  n.w_min = h.w_min;
  n.w_p1_max = h.w_p1_max;
  n.w_p2_max = h.w_p2_max;
  n.w_v1_max = h.w_v1_max;
  n.w_v2_max = h.w_v2_max;
  n.v_lim = h.v_lim;
  n.u_lim = h.u_lim;
  n.ferr_lim = h.ferr_lim;
  n.inpos_win = h.inpos_win;
  n.inpos_hold = h.inpos_hold;
  n.settle_rate = h.settle_rate;
  return n;
}

inline scurve::NeuronConfig to_host(const NeuronConfig& n) {
  scurve::NeuronConfig h;
  h.div = n.div;
  h.shift = n.shift;
  h.ff_en = n.ff_en;
  h.learn_shift = n.learn_shift;
  h.learn_dz_p = n.learn_dz_p;
  h.learn_dz_v = n.learn_dz_v;
  h.k_p = n.k_p;
  h.k_v = n.k_v;
  h.kb = n.kb;
  h.eta_p1 = n.eta_p1;
  h.eta_p2 = n.eta_p2;
  h.eta_v1 = n.eta_v1;
  h.eta_v2 = n.eta_v2;
  h.w_p1 = n.w_p1;
  h.w_p2 = n.w_p2;
  h.w_v1 = n.w_v1;
  h.w_v2 = n.w_v2;
  h.w_min = n.w_min;
  h.w_p1_max = n.w_p1_max;
  h.w_p2_max = n.w_p2_max;
  h.w_v1_max = n.w_v1_max;
  h.w_v2_max = n.w_v2_max;
  h.v_lim = n.v_lim;
  h.u_lim = n.u_lim;
  h.ferr_lim = n.ferr_lim;
  h.inpos_win = n.inpos_win;
  h.inpos_hold = n.inpos_hold;
  h.settle_rate = n.settle_rate;
  return h;
}

inline ServoConfig to_model(const scurve::ServoConfig& h) {
  ServoConfig c;
  c.enable = h.enable;
  c.closed_loop = h.closed_loop;
  c.timing = to_model(h.timing);
  c.enc_filt = h.enc_filt;
  c.ctl = to_model(h.ctl);
  return c;
}

inline scurve::ServoConfig to_host(const ServoConfig& c) {
  scurve::ServoConfig h;
  h.enable = c.enable;
  h.closed_loop = c.closed_loop;
  h.timing = to_host(c.timing);
  h.enc_filt = c.enc_filt;
  h.ctl = to_host(c.ctl);
  return h;
}

inline std::vector<RegWrite> encode_move(const Plan& plan, const PulseTiming& timing, bool start = true) {
  return scurve::encode_move(to_host(plan), to_host(timing), start);
}
inline std::vector<RegWrite> encode_servo_config(const ServoConfig& c) {
  return scurve::encode_servo_config(to_host(c));
}
inline std::vector<RegWrite> encode_row(const Segment& s, unsigned row) { return scurve::encode_row(to_host(s), row); }

}  // namespace sc
