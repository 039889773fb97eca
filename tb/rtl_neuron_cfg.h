// The controller settings (NeuronConfig) on the cfg_* ports that
// sc_neuron_pi and sc_servo_axis share, written once for both adapters.
// The encoder shift port has a different name in each top: the caller
// binds it.
#pragma once

#include "neuron_pi.h"
#include "verilated_top.h"

namespace sc {

template <class V>
void bind_neuron_config(V& m, const NeuronConfig& n) {
  m.cfg_div_i = n.div;
  m.cfg_ff_en_i = n.ff_en;
  m.cfg_learn_shift_i = port_bits(n.learn_shift, LearnShW);
  m.cfg_learn_dz_p_i = n.learn_dz_p;
  m.cfg_learn_dz_v_i = n.learn_dz_v;
  m.cfg_k_p_i = port_bits(n.k_p, CoefW);
  m.cfg_k_v_i = port_bits(n.k_v, CoefW);
  m.cfg_kb_i = port_bits(n.kb, CoefW);
  m.cfg_eta_p1_i = port_bits(n.eta_p1, CoefW);
  m.cfg_eta_p2_i = port_bits(n.eta_p2, CoefW);
  m.cfg_eta_v1_i = port_bits(n.eta_v1, CoefW);
  m.cfg_eta_v2_i = port_bits(n.eta_v2, CoefW);
  m.cfg_w_p1_i = port_bits(n.w_p1, WgtW);
  m.cfg_w_p2_i = port_bits(n.w_p2, WgtW);
  m.cfg_w_v1_i = port_bits(n.w_v1, WgtW);
  m.cfg_w_v2_i = port_bits(n.w_v2, WgtW);
  m.cfg_w_min_i = port_bits(n.w_min, WgtW);
  m.cfg_w_p1_max_i = port_bits(n.w_p1_max, WgtW);
  m.cfg_w_p2_max_i = port_bits(n.w_p2_max, WgtW);
  m.cfg_w_v1_max_i = port_bits(n.w_v1_max, WgtW);
  m.cfg_w_v2_max_i = port_bits(n.w_v2_max, WgtW);
  m.cfg_v_lim_i = n.v_lim;
  m.cfg_u_lim_i = n.u_lim;
  m.cfg_ferr_lim_i = n.ferr_lim;
  m.cfg_inpos_win_i = n.inpos_win;
  m.cfg_inpos_hold_i = n.inpos_hold;
  m.cfg_settle_rate_i = n.settle_rate;
}

}  // namespace sc
