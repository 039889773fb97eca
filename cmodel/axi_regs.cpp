#include "axi_regs.h"

namespace sc {

namespace {

constexpr uint32_t bit(int b) { return uint32_t(1) << b; }
constexpr uint32_t field(uint32_t v, int lsb, int w) { return (v >> lsb) & ((w >= 32) ? ~0u : ((1u << w) - 1)); }
uint32_t strb_mask(uint8_t strb) {
  uint32_t m = 0;
  for (int b = 0; b < 4; ++b)
    if (strb & (1 << b)) m |= 0xffu << (8 * b);
  return m;
}
uint32_t wmerge(uint32_t old_v, uint32_t new_v, uint32_t mask) { return (old_v & ~mask) | (new_v & mask); }
// Replace 32 bits at `lsb` of a wide value (only the bits below `width` kept).
u128 put_word(u128 v, int lsb, uint32_t w, int width) {
  const u128 m = u128(0xffffffffu) << lsb;
  return mask_bits((v & ~m) | (u128(w) << lsb), width);
}
uint32_t get_word(u128 v, int lsb) { return uint32_t(v >> lsb); }
// The RegAddrW-bit address arithmetic of the RTL (wraps at the window).
constexpr uint16_t kAddrMask = uint16_t((1u << RegAddrW) - 1);
static_assert(RegAddrW <= 16, "AxiIn addresses are 16 bits");
bool locked_addr(uint16_t a) {
  switch (a) {
    case RegPulseTime: case RegDirTime:
    case RegPosFrac0: case RegPosFrac0 + 4: case RegPosFrac0 + 8:
    case RegStopJerk: case RegStopJerk + 4: case RegStopAcc: case RegStopAcc + 4:
    case RegSwCfg:
    case RegGuardVel: case RegGuardVel + 4: case RegGuardVel + 8:
    case RegGuardAcc: case RegGuardAcc + 4: case RegGuardJerk: case RegGuardJerk + 4:
    case RegSoftMin: case RegSoftMax:
      return true;
    default:
      return false;
  }
}

}  // namespace

uint32_t AxiRegs::cl_mask(int i) { return kClCfgMask[i]; }

uint32_t AxiRegs::cl_reset(int i) { return kClCfgReset[i]; }

void AxiRegs::reset() {
  q_ = State{};
  q_.cfg = PulseTiming{uint16_t(RstPulseHigh), uint16_t(RstPulseLow), uint16_t(RstDirSetup), uint16_t(RstDirHold)};
  q_.low_water = uint8_t(RstFifoLow);
  for (int i = 0; i < ClCfgWords; ++i) q_.cl[size_t(i)] = cl_reset(i);
}

int AxiRegs::cfg_index(uint16_t a) const {
  const uint16_t off = uint16_t((a - RegClFirst) & kAddrMask);
  return (servo_ && (off & 3) == 0 && (off >> 2) < ClCfgWords) ? (off >> 2) : -1;
}

int AxiRegs::stat_index(uint16_t a) const {
  const uint16_t off = uint16_t((a - RegClStat) & kAddrMask);
  return (servo_ && (off & 3) == 0 && (off >> 2) < ClStatWords) ? (off >> 2) : -1;
}

uint32_t AxiRegs::read_word(uint16_t a, const RegsSide& side, const CoreOutputs& core, const ServoStatus& st,
                            uint8_t& resp) const {
  resp = kOkay;
  const bool busy_eff = busy(core);
  switch (a) {
    case RegId: return (uint32_t(RegIdMagic) << 16) | uint32_t(RegMapVersion);
    case RegCtrl: return (q_.en ? bit(CtrlEnableBit) : 0) | (q_.closed ? bit(CtrlClosedBit) : 0);
    case RegCmd: return 0;
    case RegStatus: {
      uint32_t s = uint32_t(core.phase & ((1u << PhaseW) - 1)) << StatusPhaseLsb;
      if (busy_eff) s |= bit(StatusBusyBit);
      if (core.done && !busy_eff) s |= bit(StatusDoneBit);
      if (core.en) s |= bit(StatusEnBit);
      if (core.fault_table) s |= bit(StatusFaultTableBit);
      if (core.fault_overrun) s |= bit(StatusFaultOverrunBit);
      if (q_.err_estop) s |= bit(StatusEstopBit);
      if (q_.err_reject || q_.err_bad || q_.err_estop || q_.err_lim_neg || q_.err_lim_pos || q_.err_guard ||
          q_.err_soft || q_.err_retarget) {
        s |= bit(StatusErrBit);
      }
      if (st.fault_ferr) s |= bit(StatusFaultFerrBit);
      if (st.in_pos) s |= bit(StatusInPosBit);
      s |= uint32_t(side.enc_ab & 3) << StatusEncALsb;
      s |= uint32_t(core.seg_idx & ((1u << SegIdxW) - 1)) << StatusSegIdxLsb;
      if (core.underrun) s |= bit(StatusUnderrunBit);
      if (core.discont) s |= bit(StatusDiscontBit);
      if (core.stopping) s |= bit(StatusStoppingBit);
      if (core.overshoot) s |= bit(StatusOvershootBit);
      s |= uint32_t(side.sw_level & ((1u << SwW) - 1)) << StatusSwLevelLsb;
      if (q_.latched) s |= bit(StatusLatchedBit);
      if (core.guard) s |= bit(StatusGuardBit);
      if (core.reach) s |= bit(StatusReachBit);
      return s;
    }
    case RegErr:
      return (q_.err_reject ? bit(ErrRejectBit) : 0) | (q_.err_bad ? bit(ErrBadAddrBit) : 0) |
             (q_.err_estop ? bit(ErrEstopBit) : 0) | (q_.err_full ? bit(ErrFifoFullBit) : 0) |
             (q_.err_disc ? bit(ErrDiscontBit) : 0) | (q_.err_under ? bit(ErrUnderrunBit) : 0) |
             (q_.err_lim_neg ? bit(ErrLimNegBit) : 0) | (q_.err_lim_pos ? bit(ErrLimPosBit) : 0) |
             (q_.err_guard ? bit(ErrGuardBit) : 0) | (q_.err_soft ? bit(ErrSoftLimBit) : 0) |
             (q_.err_retarget ? bit(ErrRetargetBit) : 0);
    case RegSwCfg: return sw_cfg_word();
    case RegLatchCfg:
      return (q_.latch_rise ? bit(LatchRiseBit) : 0) | (q_.latch_fall ? bit(LatchFallBit) : 0) |
             (uint32_t(q_.latch_src) << LatchSrcLsb);
    case RegLatchPulse: return uint32_t(q_.latch_pulse);
    case RegSoftMin: return uint32_t(q_.soft_min);
    case RegSoftMax: return uint32_t(q_.soft_max);
    case RegRowCount: return core.row_count;
    case RegRetargetRow: return q_.retarget_row;
    case RegLatchEnc: return uint32_t(q_.latch_enc);
    case RegPulseCount: return uint32_t(core.pulse_count);
    case RegRefPos: return uint32_t(core.ref_pos_int);
    case RegEncPos: return uint32_t(side.enc_pos);
    case RegFollowErr: return uint32_t(core.ref_pos_int) - uint32_t(side.enc_pos);
    case RegFifoStatus:
      return (uint32_t(core.fifo_level) << FifoLevelLsb) | (core.fifo_full ? bit(FifoFullBit) : 0) |
             (core.fifo_level < q_.low_water ? bit(FifoLowBit) : 0);
    case RegFifoLow: return uint32_t(q_.low_water) << FifoLowLsb;
    case RegMoveIndex: return core.move_idx;
    case RegBoundaryPos: return uint32_t(core.boundary_pos);
    case RegIrqStatus: return q_.irq_st;
    case RegIrqEnable: return uint32_t(q_.irq_en) << IrqEnableLsb;
    case RegPulseTime: return (uint32_t(q_.cfg.high) << PulseHighLsb) | (uint32_t(q_.cfg.low) << PulseLowLsb);
    case RegDirTime: return (uint32_t(q_.cfg.setup) << DirSetupLsb) | (uint32_t(q_.cfg.hold) << DirHoldLsb);
    case RegPosFrac0: return get_word(q_.frac0, 0);
    case RegPosFrac0 + 4: return get_word(q_.frac0, 32);
    case RegPosFrac0 + 8: return get_word(q_.frac0, 64);
    case RegSegPhase: return uint32_t(q_.st_phase) << SegPhaseLsb;
    case RegSegClocks: return q_.st_clocks;
    case RegSegJerk: return uint32_t(q_.st_jerk);
    case RegSegJerk + 4: return uint32_t(q_.st_jerk >> 32);
    case RegStopJerk: return uint32_t(q_.stop_jerk);
    case RegStopJerk + 4: return uint32_t(q_.stop_jerk >> 32);
    case RegStopAcc: return uint32_t(q_.stop_acc);
    case RegStopAcc + 4: return uint32_t(q_.stop_acc >> 32);
    case RegGuardVel: return get_word(q_.guard.vel, 0);
    case RegGuardVel + 4: return get_word(q_.guard.vel, 32);
    case RegGuardVel + 8: return get_word(q_.guard.vel, 64);
    case RegGuardAcc: return uint32_t(q_.guard.acc);
    case RegGuardAcc + 4: return uint32_t(q_.guard.acc >> 32);
    case RegGuardJerk: return uint32_t(q_.guard.jerk);
    case RegGuardJerk + 4: return uint32_t(q_.guard.jerk >> 32);
    case RegSegAcc0: return uint32_t(q_.st_acc0);
    case RegSegAcc0 + 4: return uint32_t(q_.st_acc0 >> 32);
    case RegSegVel0: return get_word(q_.st_vel0, 0);
    case RegSegVel0 + 4: return get_word(q_.st_vel0, 32);
    case RegSegVel0 + 8: return get_word(q_.st_vel0, 64);
    case RegRowPush: return 0;
    default:
      if (const int i = cfg_index(a); i >= 0) return q_.cl[size_t(i)];
      if (const int i = stat_index(a); i >= 0) return st.words[size_t(i)];
      resp = kDecErr;
      return 0;
  }
}

void AxiRegs::step(const AxiIn& in, const RegsSide& side, const CoreOutputs& core, const ServoStatus& st,
                   const RegsGroup& g) {
  const State q = q_;
  State d = q;
  d.push = false;
  d.replace = false;
  d.flush = false;
  d.start = false;
  d.abort = false;
  d.stop = false;
  bool set_reject = false, set_bad = false;
  const bool busy_eff = busy(core);
  const bool do_write = q.aw_full && q.w_full && !q.bvalid;
  const bool do_read = in.arvalid && !q.rvalid;
  const uint32_t wmask = strb_mask(q.wstrb);
  const uint32_t wd = q.wdata;

  if (in.awvalid && !q.aw_full) {
    d.aw_full = true;
    d.awaddr = uint16_t(in.awaddr & kAddrMask);
  }
  if (in.wvalid && !q.w_full) {
    d.w_full = true;
    d.wdata = in.wdata;
    d.wstrb = in.wstrb & 0xf;
  }
  if (q.bvalid && in.bready) d.bvalid = false;
  if (q.rvalid && in.rready) d.rvalid = false;

  if (do_write) {
    d.aw_full = false;
    d.w_full = false;
    d.bvalid = true;
    d.bresp = kOkay;
    const uint16_t a = q.awaddr;
    const bool closed_change = a == RegCtrl && (q.wstrb & 1) && (((wd >> CtrlClosedBit) & 1) != uint32_t(q.closed));
    // The shared row clocks, row push, retarget and START / FLUSH act on every
    // axis: refused in one axis's window of a multi-axis map.
    const bool cmd_group = a == RegCmd && (q.wstrb & 1) && !(wd & bit(CmdEstopBit)) && !(wd & bit(CmdStopBit)) &&
                           (wd & (bit(CmdStartBit) | bit(CmdFlushBit)));
    const bool group_only = a == RegRowPush || a == RegSegClocks || a == RegRetargetRow || cmd_group;
    if ((busy_eff && (locked_addr(a) || cfg_index(a) >= 0 || closed_change)) || (!g.group && group_only)) {
      d.bresp = kSlvErr;
      set_reject = true;
    } else {
      switch (a) {
        case RegId: case RegStatus: case RegPulseCount: case RegRefPos: case RegEncPos: case RegFollowErr:
        case RegFifoStatus: case RegMoveIndex: case RegBoundaryPos: case RegLatchPulse: case RegLatchEnc:
        case RegRowCount:
          d.bresp = kSlvErr;
          set_bad = true;
          break;
        case RegCtrl:
          if (q.wstrb & 1) {
            d.en = (wd >> CtrlEnableBit) & 1;
            d.closed = (wd >> CtrlClosedBit) & 1;
          }
          break;
        case RegCmd:
          if (q.wstrb & 1) {
            if (wd & bit(CmdEstopBit)) {
              d.abort = true;
              d.en = false;
              d.err_estop = true;
            } else if (wd & bit(CmdStopBit)) {
              d.stop = true;
            } else if (wd & bit(CmdStartBit)) {
              if (busy_eff || q.err_estop || !q.en || !g.start_ok) {
                d.bresp = kSlvErr;
                set_reject = true;
              } else {
                d.start = true;
              }
            } else if (wd & bit(CmdFlushBit)) {
              if (busy_eff) {
                d.bresp = kSlvErr;
                set_reject = true;
              } else {
                d.flush = true;
              }
            }
          }
          break;
        case RegErr:
          if (q.wstrb & 1) {
            if (wd & bit(ErrRejectBit)) d.err_reject = false;
            if (wd & bit(ErrBadAddrBit)) d.err_bad = false;
            if (wd & bit(ErrEstopBit)) d.err_estop = false;
            if (wd & bit(ErrFifoFullBit)) d.err_full = false;
            if (wd & bit(ErrDiscontBit)) d.err_disc = false;
            if (wd & bit(ErrUnderrunBit)) d.err_under = false;
            if (wd & bit(ErrLimNegBit)) d.err_lim_neg = false;
            if (wd & bit(ErrLimPosBit)) d.err_lim_pos = false;
            if (wd & bit(ErrGuardBit)) d.err_guard = false;
            if (wd & bit(ErrSoftLimBit)) d.err_soft = false;
            if (wd & bit(ErrRetargetBit)) d.err_retarget = false;
          }
          break;
        case RegIrqStatus:
          if (q.wstrb & 1) d.irq_st = uint8_t(q.irq_st & ~wd & ((1u << IrqW) - 1));
          break;
        case RegIrqEnable:
          d.irq_en = uint8_t(field(wmerge(uint32_t(q.irq_en) << IrqEnableLsb, wd, wmask), IrqEnableLsb, IrqW));
          break;
        case RegSwCfg: {
          const uint32_t w = wmerge(sw_cfg_word(), wd, wmask);
          d.sw_invert = uint8_t(field(w, SwInvertLsb, SwW));
          d.lim_en = (w >> SwLimEnBit) & 1;
          d.lim_hard = (w >> SwLimHardBit) & 1;
          d.soft_en = (w >> SwSoftEnBit) & 1;
          d.sw_debounce = uint16_t(field(w, SwDebounceLsb, DebounceW));
          break;
        }
        case RegLatchCfg:
          if (q.wstrb & 1) {
            if (field(wd, LatchSrcLsb, LatchSrcW) > uint32_t(LatchSrcIndex)) {
              d.bresp = kSlvErr;  // no such input: nothing changes
              set_reject = true;
            } else {
              d.latch_rise = (wd >> LatchRiseBit) & 1;
              d.latch_fall = (wd >> LatchFallBit) & 1;
              d.latch_src = uint8_t(field(wd, LatchSrcLsb, LatchSrcW));
              d.latched = false;
            }
          }
          break;
        case RegFifoLow:
          d.low_water = uint8_t(field(wmerge(uint32_t(q.low_water) << FifoLowLsb, wd, wmask), FifoLowLsb, RowLevelW));
          break;
        case RegPulseTime: {
          const uint32_t old_w = (uint32_t(q.cfg.high) << PulseHighLsb) | (uint32_t(q.cfg.low) << PulseLowLsb);
          const uint32_t w = wmerge(old_w, wd, wmask);
          const uint16_t high = uint16_t(field(w, PulseHighLsb, PulseTimeW));
          const uint16_t low = uint16_t(field(w, PulseLowLsb, PulseTimeW));
          if (high == 0 || low == 0) {
            d.bresp = kSlvErr;  // a pulse time of 0 clocks: nothing changes
            set_reject = true;
          } else {
            d.cfg.high = high;
            d.cfg.low = low;
          }
          break;
        }
        case RegDirTime:
          d.cfg.setup = uint16_t(field(wmerge(uint32_t(q.cfg.setup) << DirSetupLsb, wd, wmask), DirSetupLsb, PulseTimeW));
          d.cfg.hold = uint16_t(field(wmerge(uint32_t(q.cfg.hold) << DirHoldLsb, wd, wmask), DirHoldLsb, PulseTimeW));
          break;
        case RegPosFrac0: d.frac0 = put_word(q.frac0, 0, wmerge(get_word(q.frac0, 0), wd, wmask), FracBits); break;
        case RegPosFrac0 + 4: d.frac0 = put_word(q.frac0, 32, wmerge(get_word(q.frac0, 32), wd, wmask), FracBits); break;
        case RegPosFrac0 + 8: d.frac0 = put_word(q.frac0, 64, wmerge(get_word(q.frac0, 64), wd, wmask), FracBits); break;
        case RegSegPhase:
          d.st_phase = uint8_t(field(wmerge(uint32_t(q.st_phase) << SegPhaseLsb, wd, wmask), SegPhaseLsb, PhaseW));
          break;
        case RegSegClocks: d.st_clocks = wmerge(q.st_clocks, wd, wmask); break;
        case RegSegJerk:
          d.st_jerk = uint64_t(put_word(q.st_jerk, 0, wmerge(uint32_t(q.st_jerk), wd, wmask), JerkW));
          break;
        case RegSegJerk + 4:
          d.st_jerk = uint64_t(put_word(q.st_jerk, 32, wmerge(uint32_t(q.st_jerk >> 32), wd, wmask), JerkW));
          break;
        case RegStopJerk:
          d.stop_jerk = uint64_t(put_word(q.stop_jerk, 0, wmerge(uint32_t(q.stop_jerk), wd, wmask), JerkW));
          break;
        case RegStopJerk + 4:
          d.stop_jerk = uint64_t(put_word(q.stop_jerk, 32, wmerge(uint32_t(q.stop_jerk >> 32), wd, wmask), JerkW));
          break;
        case RegStopAcc:
          d.stop_acc = uint64_t(put_word(q.stop_acc, 0, wmerge(uint32_t(q.stop_acc), wd, wmask), AccW));
          break;
        case RegStopAcc + 4:
          d.stop_acc = uint64_t(put_word(q.stop_acc, 32, wmerge(uint32_t(q.stop_acc >> 32), wd, wmask), AccW));
          break;
        case RegGuardVel: d.guard.vel = put_word(q.guard.vel, 0, wmerge(get_word(q.guard.vel, 0), wd, wmask), VelW); break;
        case RegGuardVel + 4:
          d.guard.vel = put_word(q.guard.vel, 32, wmerge(get_word(q.guard.vel, 32), wd, wmask), VelW);
          break;
        case RegGuardVel + 8:
          d.guard.vel = put_word(q.guard.vel, 64, wmerge(get_word(q.guard.vel, 64), wd, wmask), VelW);
          break;
        case RegGuardAcc:
          d.guard.acc = uint64_t(put_word(q.guard.acc, 0, wmerge(uint32_t(q.guard.acc), wd, wmask), AccW));
          break;
        case RegGuardAcc + 4:
          d.guard.acc = uint64_t(put_word(q.guard.acc, 32, wmerge(uint32_t(q.guard.acc >> 32), wd, wmask), AccW));
          break;
        case RegGuardJerk:
          d.guard.jerk = uint64_t(put_word(q.guard.jerk, 0, wmerge(uint32_t(q.guard.jerk), wd, wmask), JerkW));
          break;
        case RegGuardJerk + 4:
          d.guard.jerk = uint64_t(put_word(q.guard.jerk, 32, wmerge(uint32_t(q.guard.jerk >> 32), wd, wmask), JerkW));
          break;
        case RegSoftMin: d.soft_min = int32_t(wmerge(uint32_t(q.soft_min), wd, wmask)); break;
        case RegSoftMax: d.soft_max = int32_t(wmerge(uint32_t(q.soft_max), wd, wmask)); break;
        case RegRetargetRow: d.retarget_row = wmerge(q.retarget_row, wd, wmask); break;
        case RegSegAcc0:
          d.st_acc0 = uint64_t(put_word(q.st_acc0, 0, wmerge(uint32_t(q.st_acc0), wd, wmask), AccW));
          break;
        case RegSegAcc0 + 4:
          d.st_acc0 = uint64_t(put_word(q.st_acc0, 32, wmerge(uint32_t(q.st_acc0 >> 32), wd, wmask), AccW));
          break;
        case RegSegVel0: d.st_vel0 = put_word(q.st_vel0, 0, wmerge(get_word(q.st_vel0, 0), wd, wmask), VelW); break;
        case RegSegVel0 + 4: d.st_vel0 = put_word(q.st_vel0, 32, wmerge(get_word(q.st_vel0, 32), wd, wmask), VelW); break;
        case RegSegVel0 + 8: d.st_vel0 = put_word(q.st_vel0, 64, wmerge(get_word(q.st_vel0, 64), wd, wmask), VelW); break;
        case RegRowPush:
          if (q.wstrb & 1) {
            // A replace drops queued rows: the executor decides, not the level.
            if (core.fifo_full && !((wd >> RowPushReplaceBit) & 1)) {
              d.bresp = kSlvErr;
              d.err_full = true;
            } else {
              d.push = true;
              d.replace = (wd >> RowPushReplaceBit) & 1;
              d.push_flags = uint8_t(((wd >> RowPushMoveEndBit) & 1) << RowFlagMoveEnd |
                                     ((wd >> RowPushStreamEndBit) & 1) << RowFlagStreamEnd |
                                     ((wd >> RowPushAccStepBit) & 1) << RowFlagAccStep |
                                     ((wd >> RowPushHoldBit) & 1) << RowFlagHold);
            }
          }
          break;
        default:
          if (const int i = cfg_index(a); i >= 0) {
            d.cl[size_t(i)] = wmerge(q.cl[size_t(i)], wd, wmask) & cl_mask(i);
          } else if (stat_index(a) >= 0) {
            d.bresp = kSlvErr;
            set_bad = true;
          } else {
            d.bresp = kDecErr;
            set_bad = true;
          }
          break;
      }
    }
  }

  if (do_read) {
    uint8_t resp = kOkay;
    d.rvalid = true;
    d.rdata = read_word(uint16_t(in.araddr & kAddrMask), side, core, st, resp);
    d.rresp = resp;
    if (resp != kOkay) set_bad = true;
  }

  if (side.estop) {
    d.abort = true;
    d.en = false;
    d.start = false;
    d.err_estop = true;
  }
  if (set_reject) d.err_reject = true;
  if (set_bad) d.err_bad = true;
  // interrupt causes: events of the core's status
  const bool below = core.fifo_level < q.low_water;
  const bool lim_trip = core.lim_trip_fwd || core.lim_trip_rev;
  const bool fault_any = core.fault_table || core.fault_overrun || st.fault_ferr || q.err_estop || lim_trip;
  if (core.discont && !q.discont_prev) d.err_disc = true;
  if (core.underrun && !q.underrun_prev) d.err_under = true;
  if (core.lim_trip_rev) d.err_lim_neg = true;
  if (core.lim_trip_fwd) d.err_lim_pos = true;
  if (core.guard && !q.guard_prev) d.err_guard = true;
  if (core.retarget_refused) d.err_retarget = true;
  if ((core.lim_trip_fwd && soft_fwd(core.ref_pos_int)) || (core.lim_trip_rev && soft_rev(core.ref_pos_int))) {
    d.err_soft = true;
  }
  if (core.reach && !q.reach_prev) d.err_soft = true;
  if (side.sw_edge != 0) d.irq_st |= uint8_t(bit(IrqSwitchBit));
  // position latch: an edge of the filtered home, probe or index level,
  // armed; a capture wins over a re-arm in the same clock
  bool src_edge = false, src_level = false;
  if (q.latch_src == LatchSrcIndex) {
    src_edge = side.enc_z != q.index;
    src_level = side.enc_z;
  } else {
    const int src = q.latch_src == LatchSrcProbe ? SwProbe : SwHome;
    src_edge = (side.sw_edge >> src) & 1;
    src_level = (side.sw_level >> src) & 1;
  }
  d.index = side.enc_z;
  if (!q.latched && src_edge && (src_level ? q.latch_rise : q.latch_fall)) {
    d.latched = true;
    d.latch_pulse = core.pulse_count;
    d.latch_enc = side.enc_pos;
    d.irq_st |= uint8_t(bit(IrqLatchBit));
  }
  if (below && !q.below) d.irq_st |= uint8_t(bit(IrqLowWaterBit));
  if (core.move_done) d.irq_st |= uint8_t(bit(IrqMoveDoneBit));
  if (q.busy_prev && !busy_eff) d.irq_st |= uint8_t(bit(IrqIdleBit));
  if (core.underrun && !q.underrun_prev) d.irq_st |= uint8_t(bit(IrqUnderrunBit));
  if ((fault_any && !q.fault_prev) || (core.discont && !q.discont_prev) || (core.guard && !q.guard_prev) ||
      (core.reach && !q.reach_prev)) {
    d.irq_st |= uint8_t(bit(IrqFaultBit));
  }
  d.irq = (d.irq_st & d.irq_en) != 0;
  d.below = below;
  d.busy_prev = busy_eff;
  d.underrun_prev = core.underrun;
  d.fault_prev = fault_any;
  d.discont_prev = core.discont;
  d.guard_prev = core.guard;
  d.reach_prev = core.reach;
  d.start_d1 = q.start;
  q_ = d;
}

AxiOut AxiRegs::axi_outputs() const {
  AxiOut o;
  o.awready = !q_.aw_full;
  o.wready = !q_.w_full;
  o.bvalid = q_.bvalid;
  o.bresp = q_.bresp;
  o.arready = !q_.rvalid;
  o.rvalid = q_.rvalid;
  o.rdata = q_.rdata;
  o.rresp = q_.rresp;
  return o;
}

uint32_t AxiRegs::sw_cfg_word() const {
  return (uint32_t(q_.sw_invert) << SwInvertLsb) | (q_.lim_en ? bit(SwLimEnBit) : 0) |
         (q_.lim_hard ? bit(SwLimHardBit) : 0) | (q_.soft_en ? bit(SwSoftEnBit) : 0) |
         (uint32_t(q_.sw_debounce) << SwDebounceLsb);
}

CoreInputs AxiRegs::core_inputs(uint32_t sw_level, int32_t ref_pos) const {
  CoreInputs c;
  c.lim_fwd = (q_.lim_en && ((sw_level >> SwLimPos) & 1)) || soft_fwd(ref_pos);
  c.lim_rev = (q_.lim_en && ((sw_level >> SwLimNeg) & 1)) || soft_rev(ref_pos);
  c.lim_hard = q_.lim_hard;
  c.enable = q_.en;
  c.cfg = q_.cfg;
  c.row_push = q_.push;
  c.row_replace = q_.replace;
  c.retarget_row = q_.retarget_row;
  c.row.flags = q_.push_flags;
  c.row.seg.phase = Phase(q_.st_phase);
  c.row.seg.clocks = q_.st_clocks;
  c.row.seg.jerk = wrap_signed64(int64_t(q_.st_jerk), JerkW);
  c.row.seg.acc0 = wrap_signed64(int64_t(q_.st_acc0), AccW);
  c.row.seg.vel0 = wrap_signed(i128(q_.st_vel0), VelW);
  c.fifo_flush = q_.flush;
  c.pos_frac0 = q_.frac0;
  c.start = q_.start;
  c.abort = q_.abort;
  c.stop = q_.stop;
  c.stop_jerk = q_.stop_jerk;
  c.stop_acc = q_.stop_acc;
  c.guard = q_.guard;
  c.soft = {q_.soft_en, q_.soft_min, q_.soft_max};
  return c;
}

AxiAxisOutputs AxiAxis::outputs() const {
  const CoreOutputs c = core_.outputs();
  AxiAxisOutputs o;
  o.axi = regs_.axi_outputs();
  o.step = c.step;
  o.dir = c.dir;
  o.en = c.en;
  o.busy = regs_.busy(c);
  o.done = c.done && !o.busy;
  o.fault = c.fault_table || c.fault_overrun;
  o.phase = c.phase;
  o.pulse_count = c.pulse_count;
  o.ref_pos = c.ref_pos_int;
  o.irq = regs_.state().irq;
  return o;
}

// ---- sc_axi_servo ----------------------------------------------------------------

ServoStatus servo_status(const LoopOutputs& l) {
  ServoStatus st;
  st.in_pos = l.in_pos;
  st.fault_ferr = l.fault_ferr;
  st.words[0] = (l.in_pos ? bit(ClStInPosBit) : 0) | (l.fault_ferr ? bit(ClStFerrBit) : 0) |
                (l.ctl_active ? bit(ClStActiveBit) : 0) | (uint32_t(l.ctl_state & ((1u << CtlStW) - 1)) << ClStStateLsb) |
                (uint32_t(l.enc_illegal) << ClStIllLsb);
  st.words[1] = uint32_t(l.u);
  st.words[2] = uint32_t(l.v_cmd);
  st.words[3] = uint32_t(l.e_p);
  st.words[4] = uint32_t(l.e_v);
  st.words[5] = uint32_t(l.w_p1);
  st.words[6] = uint32_t(l.w_p2);
  st.words[7] = uint32_t(l.w_v1);
  st.words[8] = uint32_t(l.w_v2);
  return st;
}

ServoConfig AxiServo::decode_config(bool enable, bool closed, const PulseTiming& t,
                                    const std::array<uint32_t, ClCfgWords>& w) {
  ServoConfig c;
  c.enable = enable;
  c.closed_loop = closed;
  c.timing = t;
  c.ctl = ctl_cfg_from_words(w);
  return c;
}

ServoInputs AxiServo::servo_inputs() const {
  const CoreInputs ci = regs_.core_inputs(sw_.level(), servo_.outputs().ref_pos_int);
  const AxiRegs::State& q = regs_.state();
  ServoInputs si;
  si.cfg = decode_config(ci.enable, q.closed, ci.cfg, q.cl);
  si.row_push = ci.row_push;
  si.row_replace = ci.row_replace;
  si.retarget_row = ci.retarget_row;
  si.row = ci.row;
  si.fifo_flush = ci.fifo_flush;
  si.pos_frac0 = ci.pos_frac0;
  si.start = ci.start;
  si.abort = ci.abort;
  si.stop = ci.stop;
  si.stop_jerk = ci.stop_jerk;
  si.stop_acc = ci.stop_acc;
  si.guard = ci.guard;
  si.lim_fwd = ci.lim_fwd;
  si.lim_rev = ci.lim_rev;
  si.lim_hard = ci.lim_hard;
  return si;
}

void AxiServo::step(const AxiIn& in, const RegsSide& side) {
  const ServoOutputs so = servo_.outputs();
  CoreOutputs co;
  co.en = so.en;
  co.busy = so.busy;
  co.done = so.done;
  co.phase = so.phase;
  co.fault_table = so.fault_table;
  co.fault_overrun = so.fault_overrun;
  co.pulse_count = so.pulse_count;
  co.ref_pos_int = so.ref_pos_int;
  co.seg_idx = 0;
  co.underrun = so.underrun;
  co.discont = so.discont;
  co.guard = so.guard;
  co.stopping = so.stopping;
  co.overshoot = so.overshoot;
  co.move_done = so.move_done;
  co.move_idx = so.move_idx;
  co.boundary_pos = so.boundary_pos;
  co.fifo_level = so.fifo_level;
  co.fifo_full = so.fifo_full;
  co.row_count = so.row_count;
  co.retarget_refused = so.retarget_refused;
  co.lim_trip_fwd = so.lim_trip_fwd;
  co.lim_trip_rev = so.lim_trip_rev;
  LoopOutputs loop;
  servo_.read_loop_outputs(loop);
  const ServoStatus st = servo_status(loop);
  ServoInputs si = servo_inputs();
  si.enc_a = side.enc_ab & 1;
  si.enc_b = (side.enc_ab >> 1) & 1;
  si.enc_z = side.enc_z;
  RegsSide rs = side;
  rs.enc_ab = uint8_t(enc_sync_.q());
  rs.enc_pos = so.enc_pos;
  rs.enc_z = so.enc_index;
  rs.sw_level = uint8_t(sw_.level());
  rs.sw_edge = uint8_t(sw_.edge());
  const uint32_t invert = regs_.state().sw_invert, debounce = regs_.state().sw_debounce;
  regs_.step(in, rs, co, st);
  servo_.step(si);
  enc_sync_.step(side.enc_ab & 3u);
  sw_.step(side.sw_pins, invert, debounce);
}

AxiServoOutputs AxiServo::outputs() const {
  const ServoOutputs s = servo_.outputs();
  AxiServoOutputs o;
  o.axi = regs_.axi_outputs();
  o.step = s.step;
  o.dir = s.dir;
  o.en = s.en;
  CoreOutputs co;
  co.busy = s.busy;
  o.busy = regs_.busy(co);
  o.done = s.done && !o.busy;
  o.fault = s.fault_table || s.fault_overrun || s.fault_ferr;
  o.phase = s.phase;
  o.pulse_count = s.pulse_count;
  o.ref_pos = s.ref_pos_int;
  o.enc_pos = s.enc_pos;
  o.in_pos = s.in_pos;
  o.fault_ferr = s.fault_ferr;
  o.irq = regs_.state().irq;
  return o;
}

}  // namespace sc
