// Homing as host primitives over the register interface: the sequence runs
// on the host, the parts that must be exact to the clock run in hardware.
//
//   1. seek: a move toward the home switch at the seek speed, with the
//      position latch armed on the switch becoming active (LATCH_CFG.RISE);
//      when STATUS.LATCHED shows the switch was reached, CMD.STOP (the
//      jerk-limited controlled stop with STOP_JERK / STOP_ACC);
//   2. back-off: a move away at the slow latch speed with the latch armed on
//      the release (LATCH_CFG.FALL); when it has captured, CMD.STOP;
//   3. zero: the release point, in REF_POS coordinates, is the back-off's
//      start plus LATCH_PULSE (PULSE_COUNT restarts at each START); the
//      machine position is REF_POS - home_ref + offset;
//   4. optionally (max_index_travel > 0) on to the encoder index: a move on
//      at the latch speed with the latch armed on the index rising
//      (LATCH_CFG.SRC = index); the zero is then the index point, whose
//      position does not depend on the switch's repeatability (the classic
//      switch-plus-index home of a servo axis).
//
// Why on the host: the timing-critical part (the capture of the count in
// the clock the filtered edge arrives) is the hardware latch; what is left
// (speeds, distances, which switch, retries, offsets) differs per machine
// and costs no FPGA area on the host. The seek's stop happens a poll period
// later than a hardware stop would, which only moves the seek's overtravel
// (place the switch accordingly); the zero does not depend on it.
//
// Repeatability: the release is crossed at the constant latch speed, and
// the capture comes DEBOUNCE + 2 clocks (plus any contact bounce) after the
// pin. While the step interval at the latch speed is longer than that, no
// step falls between the crossing and the capture, so LATCH_PULSE is the
// crossing step itself and the zero is the same pulse every run:
// exact_latch_speed() is that bound.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "scurve/planner.h"
#include "scurve/register_port.h"

namespace scurve {

struct HomingRequest {
  int direction = -1;          // where the home switch lies: -1 negative, +1 positive
  double seek_speed = 0;       // pulses/s, toward the switch
  double latch_speed = 0;      // pulses/s, off the switch (<= seek_speed)
  double a_max = 0;            // pulses/s^2 of both moves
  double j_max = 0;            // pulses/s^3 of both moves
  int64_t max_travel = 0;      // pulses the seek may run without reaching the switch
  int64_t max_backoff = 0;     // pulses the back-off may run without the switch releasing
  int64_t offset = 0;          // machine position of the zero point (the release, or the index)
  int64_t max_index_travel = 0;  // 0: the zero is the release; > 0: pulses the axis may creep on to the index
  double poll_period = 1e-3;   // s between STATUS reads while a move runs
};

struct HomingResult {
  int64_t home_ref = 0;        // REF_POS of the zero point: the release or, with the index, the index point
  int64_t seek_stop = 0;       // REF_POS where the seek came to rest
  int64_t backoff_stop = 0;    // REF_POS where the back-off came to rest
  int64_t latch_pulse = 0;     // LATCH_PULSE as read (pulses since the back-off's START)
  bool seek_skipped = false;   // the switch was already active: no seek
  bool on_index = false;       // home_ref is the encoder index point (step 4)
  int64_t release_ref = 0;     // REF_POS of the release point
  int64_t index_enc = 0;       // LATCH_ENC at the index (the encoder's count there)
  int64_t offset = 0;
  // Machine position of a REF_POS value.
  int64_t machine_position(int64_t ref_pos) const { return ref_pos - home_ref + offset; }
};

using HomingOutcome = std::variant<HomingResult, Error>;

// The largest latch speed (pulses/s) at which the zero is exact to the
// pulse for a switch filter of `debounce` clocks and contact bounce up to
// `bounce` clocks (see above).
double exact_latch_speed(uint32_t debounce, uint32_t bounce, Clock clock = Clock{});

// Checks the request (the one place its values are validated): an Error
// naming the field, the value and the bound, or nothing.
std::optional<Error> check_homing_request(const HomingRequest& req, const PulseTiming& timing,
                                          Clock clock = Clock{});

// Runs the sequence. The axis must be idle; CTRL.ENABLE is written with
// every move, CTRL.CLOSED_LOOP kept as it is (the closed-loop axis homes in
// its mode); the limits, switch polarity and debounce (SW_CFG) and the stop
// limits are the board's configuration. Leaves the latch holding the
// release's capture and the axis at rest past the release point.
HomingOutcome home(RegisterPort& port, const HomingRequest& req, const PulseTiming& timing, Clock clock = Clock{});

}  // namespace scurve
