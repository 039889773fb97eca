#include "row_reach.h"

namespace sc {

namespace {

constexpr int kW = RowReach::kW;
constexpr i128 wrapw(i128 x) { return wrap_signed(x, kW); }
constexpr bool neg_w(i128 x) { return x < 0; }  // x is kept sign-extended from bit kW-1

// The RTL's SixUnit: 6 * 2^(DivSh + QuoW - 1) in kW bits.
constexpr i128 kSixUnit = i128(6) << (RowReach::kDivSh + RowReach::kQuoW - 1);

// x fits `bits` bits signed (the RTL's range compares on the datapath).
constexpr bool fits(i128 x, int bits) {
  return x >= -(i128(1) << (bits - 1)) && x < (i128(1) << (bits - 1));
}

}  // namespace

void RowReach::step(const Inputs& in) {
  using St = RowReach::St;
  using Ph = RowReach::Ph;
  using Goal = RowReach::Goal;
  using Op = RowReach::Op;
  const State& q = q_;
  State d = q;

  const i128 a_x = q.a, j_x = q.j, v_x = q.v;
  const bool cls0 = q.v < 0;
  const uint32_t n_m1 = q.n - 1, n_m2 = q.n - 2, m_m1 = q.m - 1, m_m2 = q.m - 2;

  // The adder: acc + mcd (Mul), acc - mcd (Div, Sub).
  const i128 sum = wrapw(q.op == Op::Mul ? q.acc + q.mcd : q.acc - q.mcd);
  // 2 v_m within the velocity range, a_(N-2) within the acceleration range
  const bool v_in_range = fits(q.acc, VelW + 1);
  const bool a_in_range = fits(q.acc, AccW);
  const uint64_t quo = q.mlr & ((uint64_t(1) << kQuoW) - 1);
  const bool rem_nz = q.acc != 0;
  const int64_t cand_up = q.neg ? -int64_t(quo) : int64_t(quo) + (rem_nz ? 1 : 0);
  const int64_t cand_dn = q.neg ? -int64_t(quo) - (rem_nz ? 1 : 0) : int64_t(quo);

  switch (q.st) {
    case St::Idle:
      if (in.start) {
        d.st = St::Dec;
        d.ph = Ph::Start;
        d.n = in.clocks;
        d.j = in.jerk;
        d.a = in.acc0;
        d.v = in.vel0;
        d.bad = false;
        d.fwd = 0;
        d.rev = 0;
      }
      break;

    case St::Op:
      d.cnt = uint8_t(q.cnt + 1);
      switch (q.op) {
        case Op::Mul:
          if (q.mlr & 1) d.acc = sum;
          d.mcd = wrapw(q.mcd << 1);
          d.mlr = q.mlr >> 1;
          break;
        case Op::Div:
          if (!neg_w(sum)) d.acc = sum;
          d.mcd = q.mcd >> 1;
          d.mlr = (q.mlr << 1) | (neg_w(sum) ? 0 : 1);
          break;
        case Op::Sub:
          d.acc = sum;
          break;
      }
      if (q.cnt == uint8_t(q.len - 1)) d.st = St::Dec;
      break;

    case St::Dec: {
      bool after_acc_end = false, after_k = false, after_vk = false, after_vn = false;
      bool after_sn = false, after_st1 = false, after_search = false;
      bool go_v = false, go_s = false, go_sat = false;
      uint32_t go_m = 0;
      Goal go_goal = Goal::Vk;
      bool op_go = false;
      Op op_kind = Op::Mul;
      uint8_t op_len = 32;
      i128 op_acc = 0, op_mcd = 0;
      uint64_t op_mlr = 0;
      Ph op_ph = Ph::Start;
      auto launch = [&](i128 acc, i128 mcd, uint64_t mlr, Ph ph) {
        op_go = true;
        op_acc = acc;
        op_mcd = mcd;
        op_mlr = mlr;
        op_ph = ph;
      };

      switch (q.ph) {
        case Ph::Start:
          if (q.n == 0) {
            d.st = St::Done;
          } else if (q.n >= 2 && q.j != 0) {
            launch(a_x, j_x, n_m2, Ph::AccEnd);  // a_(N-2) = a + (N-2) j
          } else {
            after_acc_end = true;
          }
          break;
        case Ph::AccEnd:
          if (!a_in_range) d.bad = true;
          after_acc_end = true;
          break;
        case Ph::NegK:
          op_kind = Op::Div;
          op_len = 64;
          if (q.a < 0) launch(q.acc, wrapw(j_x << 63), 0, Ph::DivK);
          else         launch(a_x, q.acc, 0, Ph::DivK);
          break;
        case Ph::DivK:
          if (q.mlr >= uint64_t(n_m1)) d.k = n_m1;
          else                         d.k = uint32_t(q.mlr) + (rem_nz ? 1 : 0);
          after_k = true;
          break;
        case Ph::V1:
          launch(wrapw(v_x << 1), q.acc, q.m, Ph::V2);
          break;
        case Ph::V2:
          if (!v_in_range) d.bad = true;
          switch (q.goal) {
            case Goal::Vk:
              d.clsk = neg_w(q.acc);
              after_vk = true;
              break;
            case Goal::Vn:
              d.clsn = neg_w(q.acc);
              after_vn = true;
              break;
            default:
              if (neg_w(q.acc) == q.cls_ref) d.lo = q.m;
              else                           d.hi = q.m;
              after_search = true;
              break;
          }
          break;
        case Ph::S0:
          launch(q.acc, j_x, m_m2, Ph::S1);
          break;
        case Ph::S1:
          launch(wrapw(v_x << 1), q.acc, m_m1, Ph::S2);
          break;
        case Ph::S2:
          op_len = 1;
          launch(q.acc, wrapw(v_x << 2), 1, Ph::S2b);
          break;
        case Ph::S2b:
          launch(0, q.acc, q.m, Ph::S3);
          break;
        case Ph::S3:
        case Ph::NegS:
          if (q.ph == Ph::S3 && neg_w(q.acc)) {
            d.neg = true;
            op_kind = Op::Sub;
            op_len = 1;
            launch(0, q.acc, 0, Ph::NegS);
          } else {
            if (q.ph == Ph::S3) d.neg = false;
            op_kind = Op::Div;
            op_len = kQuoW;
            launch(q.acc, kSixUnit, 0, Ph::DivS);
          }
          break;
        case Ph::DivS:
          if (cand_up > q.fwd) d.fwd = cand_up;
          if (cand_dn < q.rev) d.rev = cand_dn;
          switch (q.goal) {
            case Goal::Sn: after_sn = true; break;
            case Goal::St1: after_st1 = true; break;
            default: d.st = St::Done; break;
          }
          break;
      }

      // The sequence, in order; each step may fall through to the next.
      if (after_acc_end) {
        if (d.bad) {
          go_sat = true;
        } else if (q.j != 0 && q.a != 0 && (q.a < 0) != (q.j < 0)) {
          op_kind = Op::Sub;
          op_len = 1;
          launch(0, q.a < 0 ? a_x : wrapw(j_x << 63), 0, Ph::NegK);
        } else {
          d.k = 0;
          after_k = true;
        }
      }
      if (after_k) {
        if (d.k != 0) {
          go_v = true;
          go_m = d.k;
          go_goal = Goal::Vk;
        } else {
          d.clsk = cls0;
          after_vk = true;
        }
      }
      if (after_vk) {
        if (n_m1 > d.k) {
          go_v = true;
          go_m = n_m1;
          go_goal = Goal::Vn;
        } else {
          d.clsn = d.clsk;
          after_vn = true;
        }
      }
      if (after_vn) {
        if (d.bad) {
          go_sat = true;
        } else {
          go_s = true;
          go_m = q.n;
          go_goal = Goal::Sn;
        }
      }
      if (after_sn) {
        if (d.clsk != cls0) {
          d.lo = 0;
          d.hi = d.k;
          d.cls_ref = cls0;
          d.srch2 = false;
          after_search = true;
        } else {
          after_st1 = true;
        }
      }
      if (after_st1) {
        if (d.clsn != d.clsk) {
          d.lo = d.k;
          d.hi = n_m1;
          d.cls_ref = d.clsk;
          d.srch2 = true;
          after_search = true;
        } else {
          d.st = St::Done;
        }
      }
      if (after_search) {
        if (uint32_t(d.hi - d.lo) > 1) {
          go_v = true;
          go_m = d.lo + (uint32_t(d.hi - d.lo) >> 1);
          go_goal = Goal::Search;
        } else {
          go_s = true;
          go_m = d.hi;
          go_goal = d.srch2 ? Goal::St2 : Goal::St1;
        }
      }

      // 2 v_m: 2a + (m-1) j first; 6 S(m): 3a = a + 2a first
      if (go_v || go_s) {
        d.m = go_m;
        d.goal = go_goal;
        op_kind = Op::Mul;
        op_len = go_v ? 32 : 1;
        launch(go_v ? wrapw(a_x << 1) : a_x, go_v ? j_x : wrapw(a_x << 1),
               go_v ? uint64_t(uint32_t(go_m - 1)) : 1, go_v ? Ph::V1 : Ph::S0);
      }
      if (go_sat) {
        d.fwd = kReachMax;
        d.rev = kReachMin;
        d.st = St::Done;
      }
      if (op_go) {
        d.st = St::Op;
        d.op = op_kind;
        d.len = op_len;
        d.cnt = 0;
        d.acc = op_acc;
        d.mcd = op_mcd;
        d.mlr = op_mlr;
        d.ph = op_ph;
      }
      break;
    }

    case St::Done:
      d.st = St::Idle;
      break;
  }

  if (in.abort) d.st = St::Idle;
  q_ = d;
}

}  // namespace sc
