// Bit-exact model of rtl/sc_axi_regs.sv (AXI4-Lite register file) and of
// rtl/sc_axi_axis.sv (register file + sc_axis_core). Same flops, same update
// order, one step() per clock; no Verilator or SystemC types.
#pragma once

#include <array>
#include <cstdint>

#include "axis_core.h"
#include "servo_axis.h"
#include "switch_filter.h"
#include "sync.h"

namespace sc {

// AXI4-Lite inputs of the slave for one clock (what the master drives).
struct AxiIn {
  uint16_t awaddr = 0;  // RegAddrW bits used
  bool awvalid = false;
  uint32_t wdata = 0;
  uint8_t wstrb = 0;
  bool wvalid = false;
  bool bready = false;
  uint16_t araddr = 0;
  bool arvalid = false;
  bool rready = false;
};

struct AxiOut {
  bool awready = false;
  bool wready = false;
  bool bvalid = false;
  uint8_t bresp = 0;
  bool arready = false;
  bool rvalid = false;
  uint32_t rdata = 0;
  uint8_t rresp = 0;
  bool operator==(const AxiOut&) const = default;
};

enum AxiResp : uint8_t { kOkay = 0, kSlvErr = 2, kDecErr = 3 };

// The register file's side inputs (synchronous).
struct RegsSide {
  bool estop = false;
  uint8_t enc_ab = 0;  // bit 0 = A, bit 1 = B
  int32_t enc_pos = 0;
  bool enc_z = false;    // encoder index: AxiServo's Z pin; for AxiAxis (and the register file) the level in step with enc_pos
  uint8_t sw_pins = 0;   // switch pins (bit SwLimNeg, SwLimPos, SwHome, SwProbe): AxiAxis / AxiServo filter them
  uint8_t sw_level = 0;  // the filter's outputs as the register file sees them (set by AxiAxis / AxiServo)
  uint8_t sw_edge = 0;
};

// Closed-loop inputs of the register file (sc_axi_servo): STATUS bits and
// the read-only words CL_STATUS .. CTL_W_V2 (cl_stat_i).
struct ServoStatus {
  bool in_pos = false;
  bool fault_ferr = false;
  std::array<uint32_t, ClStatWords> words{};
};

// The status words of an axis's loop (sc_pkg::cl_stat_words).
ServoStatus servo_status(const LoopOutputs& loop);

// The multi-axis inputs of the register file (group_i, start_ok_i of
// sc_axi_regs); one axis: both true.
struct RegsGroup {
  bool group = true;     // the write in flight reaches every axis (the group window)
  bool start_ok = true;  // every axis can take a START
};

class AxiRegs {
 public:
  struct State {
    bool aw_full = false;
    uint16_t awaddr = 0;
    bool w_full = false;
    uint32_t wdata = 0;
    uint8_t wstrb = 0;
    bool bvalid = false;
    uint8_t bresp = 0;
    bool rvalid = false;
    uint8_t rresp = 0;
    uint32_t rdata = 0;
    bool en = false;
    bool closed = false;                    // CTRL.CLOSED_LOOP
    std::array<uint32_t, ClCfgWords> cl{};  // controller settings (servo)
    uint8_t low_water = 0;
    uint8_t irq_en = 0;
    uint8_t irq_st = 0;
    bool irq = false;
    bool below = false, busy_prev = false, underrun_prev = false, fault_prev = false, discont_prev = false,
         guard_prev = false, reach_prev = false;
    PulseTiming cfg{};
    u128 frac0 = 0;
    uint8_t st_phase = 0;
    uint32_t st_clocks = 0;
    uint64_t st_jerk = 0;  // JerkW bits, unsigned view
    uint64_t st_acc0 = 0;
    u128 st_vel0 = 0;      // VelW bits, unsigned view
    bool push = false;
    bool replace = false;                   // ROW_PUSH.REPLACE with push
    uint32_t retarget_row = 0;              // RETARGET_ROW
    bool err_retarget = false;
    uint8_t push_flags = 0;
    bool flush = false;
    bool start = false;
    bool start_d1 = false;
    bool abort = false;
    bool stop = false;                      // CMD.STOP pulse
    uint64_t stop_jerk = StopJerkReset;     // STOP_JERK, JerkW bits
    uint64_t stop_acc = StopAccReset;       // STOP_ACC, AccW bits
    GuardLimits guard{};                    // GUARD_VEL / GUARD_ACC / GUARD_JERK (0 = no limit)
    bool err_reject = false;
    bool err_bad = false;
    bool err_estop = false;
    bool err_full = false;
    bool err_disc = false;
    bool err_under = false;
    bool err_lim_neg = false;
    bool err_lim_pos = false;
    bool err_guard = false;
    bool err_soft = false;
    uint8_t sw_invert = 0;                  // SW_CFG
    bool lim_en = true;
    bool lim_hard = false;
    bool soft_en = false;                   // SW_CFG.SOFT_EN, SOFT_MIN, SOFT_MAX
    int32_t soft_min = 0, soft_max = 0;
    uint16_t sw_debounce = uint16_t(RstDebounce);
    bool latch_rise = false, latch_fall = false;  // LATCH_CFG
    uint8_t latch_src = 0;                        // LATCH_CFG.SRC: LatchSrcHome / Probe / Index
    bool index = false;                           // the index level of the last clock: its edges
    bool latched = false;
    int32_t latch_pulse = 0, latch_enc = 0;
    bool operator==(const State&) const = default;
  };

  // servo = true: the closed-loop words of sc_axi_servo (Servo = 1).
  explicit AxiRegs(bool servo = false) : servo_(servo) { reset(); }
  void reset();
  // One clock. `core` = the core's outputs during this clock.
  void step(const AxiIn& in, const RegsSide& side, const CoreOutputs& core, const ServoStatus& st = ServoStatus{},
            const RegsGroup& g = RegsGroup{});
  // Implemented bits and reset value of controller-settings word i.
  static uint32_t cl_mask(int i);
  static uint32_t cl_reset(int i);

  AxiOut axi_outputs() const;
  // The core's inputs from the register file; the limit inputs from the
  // filtered levels `sw_level` (bit SwLimNeg, SwLimPos) and SW_CFG.
  // ref_pos: the core's REF_POS this clock (the soft limits compare it).
  CoreInputs core_inputs(uint32_t sw_level = 0, int32_t ref_pos = 0) const;
  // The soft limits' sides: active beyond SOFT_MAX / SOFT_MIN.
  bool soft_fwd(int32_t ref_pos) const { return q_.soft_en && ref_pos > q_.soft_max; }
  bool soft_rev(int32_t ref_pos) const { return q_.soft_en && ref_pos < q_.soft_min; }
  // STATUS.BUSY: the core is busy or an accepted START has not reached it yet.
  bool busy(const CoreOutputs& core) const { return core.busy || q_.start || q_.start_d1; }
  // start_able_o: enabled, idle and not e-stopped.
  bool start_able(const CoreOutputs& core) const { return !busy(core) && !q_.err_estop && q_.en; }
  const State& state() const { return q_; }

 private:
  uint32_t read_word(uint16_t addr, const RegsSide& side, const CoreOutputs& core, const ServoStatus& st,
                     uint8_t& resp) const;
  int cfg_index(uint16_t addr) const;   // -1: not a controller-settings word
  int stat_index(uint16_t addr) const;  // -1: not a closed-loop status word
  uint32_t sw_cfg_word() const;         // SW_CFG as read
  bool servo_;
  State q_;
};

// Outputs of sc_axi_axis compared by the lockstep checker.
struct AxiAxisOutputs {
  AxiOut axi;
  bool step = false, dir = false, en = false;
  bool busy = false, done = false, fault = false;
  uint8_t phase = 0;
  int32_t pulse_count = 0;
  int32_t ref_pos = 0;
  bool irq = false;
  bool operator==(const AxiAxisOutputs&) const = default;
};

class AxiAxis {
 public:
  AxiAxis() { reset(); }
  void reset() {
    regs_.reset();
    core_.reset();
    sw_.reset();
  }
  void step(const AxiIn& in, const RegsSide& side) {
    const CoreInputs ci = regs_.core_inputs(sw_.level(), core_.outputs().ref_pos_int);
    RegsSide rs = side;
    rs.sw_level = uint8_t(sw_.level());
    rs.sw_edge = uint8_t(sw_.edge());
    const AxiRegs::State& q = regs_.state();
    const uint32_t invert = q.sw_invert, debounce = q.sw_debounce;
    regs_.step(in, rs, core_.outputs());
    core_.step(ci);
    sw_.step(side.sw_pins, invert, debounce);
  }
  AxiAxisOutputs outputs() const;
  const AxiRegs& regs() const { return regs_; }
  const AxisCore& core() const { return core_; }
  const SwitchFilter& switches() const { return sw_; }

 private:
  AxiRegs regs_;
  AxisCore core_;
  SwitchFilter sw_;  // u_sw
};

// Outputs of sc_axi_servo compared by the lockstep checker.
struct AxiServoOutputs {
  AxiOut axi;
  bool step = false, dir = false, en = false;
  bool busy = false, done = false, fault = false;
  uint8_t phase = 0;
  int32_t pulse_count = 0;
  int32_t ref_pos = 0;
  int32_t enc_pos = 0;
  bool in_pos = false, fault_ferr = false;
  bool irq = false;
  bool operator==(const AxiServoOutputs&) const = default;
};

// Model of rtl/sc_axi_servo.sv: AxiRegs(servo) + ServoAxis. The encoder
// inputs are side.enc_ab (bit 0 = A, bit 1 = B) at this clock's edge;
// side.enc_pos is not used (ENC_POS reads the decoder).
class AxiServo {
 public:
  AxiServo() : regs_(true) { reset(); }
  void reset() {
    regs_.reset();
    servo_.reset();
    enc_sync_.reset();
    sw_.reset();
  }
  void step(const AxiIn& in, const RegsSide& side);
  AxiServoOutputs outputs() const;
  const AxiRegs& regs() const { return regs_; }
  const ServoAxis& servo() const { return servo_; }
  const SwitchFilter& switches() const { return sw_; }
  ServoAxis& mutable_servo() { return servo_; }
  // The sc_servo_axis inputs the register file drives (encoder pins aside).
  ServoInputs servo_inputs() const;
  // Controller settings words -> sc_servo_axis configuration.
  static ServoConfig decode_config(bool enable, bool closed, const PulseTiming& t,
                                   const std::array<uint32_t, ClCfgWords>& w);

 private:
  AxiRegs regs_;
  ServoAxis servo_;
  Sync enc_sync_{2, false};  // u_sync_enc: STATUS.ENC_AB
  SwitchFilter sw_;          // u_sw
};

}  // namespace sc
