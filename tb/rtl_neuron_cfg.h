// The controller settings (NeuronConfig, the generated sc::CtlCfg) on the
// ctl_cfg_i vector that sc_neuron_pi and sc_servo_axis share: packed by the
// generated ctl_cfg_pack(), written once for both adapters.
#pragma once

#include "neuron_pi.h"
#include "sc_layout.h"
#include "verilated_top.h"

namespace sc {

template <class V>
void bind_neuron_config(V& m, const NeuronConfig& n) {
  const auto v = ctl_cfg_pack(n);
  for (size_t i = 0; i < v.size(); ++i) m.ctl_cfg_i[i] = v[i];
}

}  // namespace sc
