// Homing (scurve::home, the host library's sequence) run against the
// register-level axis (sc_axi_axis: RTL and model in lockstep, or the model
// alone) with a home switch in the plant (tb/switch_plant.h): bounce, noise,
// a debounce filter. What is checked does not come from the sequence: the
// zero against the switch's true release point, the pins against REF_POS.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scurve/homing.h"

namespace sc {

struct HomingSimConfig {
  scurve::HomingRequest request;
  scurve::PulseTiming timing;
  int64_t switch_at = 0;       // the switch's edge, pulses from the start (its sign is request.direction)
  uint32_t debounce = 2000;    // SW_CFG.DEBOUNCE, clocks
  uint32_t bounce = 0;         // contact bounce on every change, clocks
  double noise_rate = 0;       // glitches per clock
  uint32_t noise_clocks = 0;   // length of one glitch, clocks
  double stop_jerk = 0, stop_acc = 0;  // STOP_JERK / STOP_ACC, pulses/s^3, pulses/s^2
  // An encoder on the shaft, one count per pulse, its index high at the
  // counts index_at + k index_period (request.max_index_travel > 0 homes on
  // it); index_at by default half a revolution past the release point.
  int64_t index_period = 0;
  std::optional<int64_t> index_at;
  bool lockstep = true;        // false: the model alone
  uint64_t seed = 1;
};

struct HomingSimResult {
  int64_t switch_at = 0;
  int64_t release_point = 0;   // the plant's first position off the switch
  int64_t index_point = 0;     // with the index: the plant's first index position past the back-off's stop
  int64_t zero_point = 0;      // what the zero must be: index_point with the index, else release_point
  uint32_t bounce = 0;
  bool homed = false;
  std::string error;           // the sequence's error, or the bench's
  scurve::HomingResult result;
  int64_t zero_error = 0;      // result.home_ref - zero_point, pulses
  int64_t pins = 0;            // net STEP pulses on the pins at the end
  int64_t ref_pos = 0;         // REF_POS at the end
  uint64_t clocks = 0;
  uint64_t glitches = 0;
  uint64_t matched_clocks = 0;
  bool pass() const { return homed && error.empty() && pins == ref_pos; }
};

HomingSimResult run_homing_sim(const HomingSimConfig& c);

// Summary of several runs: spread of the zero (max - min of zero_error).
struct HomingSummary {
  size_t runs = 0, passed = 0;
  int64_t zero_min = 0, zero_max = 0;
  int64_t spread() const { return zero_max - zero_min; }
};
HomingSummary summarize(const std::vector<HomingSimResult>& runs);
std::string homing_table(const std::vector<HomingSimResult>& runs);
nlohmann::json homing_to_json(const std::vector<HomingSimResult>& runs, bool lockstep);

}  // namespace sc
