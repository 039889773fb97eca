#include "row_reach.h"

namespace sc {

namespace {

constexpr int kW = RowReach::kW;
constexpr i128 wrapw(i128 x) { return wrap_signed(x, kW); }
constexpr bool neg_w(i128 x) { return x < 0; }  // x is kept sign-extended from bit kW-1
constexpr uint64_t kMlrMask = (uint64_t(1) << ReachW) - 1;
constexpr int64_t sx_reach(uint64_t x) { return wrap_signed64(int64_t(x & kMlrMask), ReachW); }

// x fits `bits` bits signed (the RTL's range compares on the datapath).
constexpr bool fits(i128 x, int bits) {
  return x >= -(i128(1) << (bits - 1)) && x < (i128(1) << (bits - 1));
}

// The RTL's micro-program ROM.
enum class Kind : uint8_t { Mul, DivK, Div3 };
enum class Src : uint8_t { A, J, V, Acc };
struct Uop {
  Kind kind = Kind::Mul;
  Src src = Src::J;
  bool clr = false, usem = false, sub = false, last = false;
  uint8_t c = 1;
  uint8_t len = 0;  // iterations - 1
};
constexpr uint8_t kDiv3Len = uint8_t(kW - RowReach::kDivSh - 3);
constexpr uint8_t kPcA = 0, kPcK = 3, kPcV = 6, kPcSn = 11, kPcS = 20;

Uop uop(uint8_t pc) {
  Uop u;
  auto mul_m = [&](Src s) { u.src = s; u.clr = true; u.usem = true; u.len = 31; };
  auto div3 = [&] { u.kind = Kind::Div3; u.src = Src::Acc; u.len = kDiv3Len; u.last = true; };
  switch (pc) {
    // a_(N-2) = (N-1) j + a - j
    case 0: mul_m(Src::J); break;
    case 1: u.src = Src::A; break;
    case 2: u.sub = true; u.last = true; break;
    // k: (a - j) / (j 2^31 .. j)
    case 3: u.src = Src::A; u.clr = true; break;
    case 4: u.sub = true; u.len = 30; break;
    case 5: u.kind = Kind::DivK; u.c = 0; u.len = 31; u.last = true; break;
    // 2 v_M
    case 6: mul_m(Src::J); break;
    case 7: u.src = Src::A; u.c = 2; u.len = 1; break;
    case 8: u.sub = true; break;
    case 9: mul_m(Src::Acc); break;
    case 10: u.src = Src::V; u.c = 2; u.len = 1; u.last = true; break;
    // 6 S(M+1)
    case 11: mul_m(Src::J); break;
    case 12: u.src = Src::A; u.c = 3; u.len = 1; break;
    case 13: mul_m(Src::Acc); break;
    case 14: u.src = Src::V; u.c = 6; u.len = 2; break;
    case 15: u.src = Src::A; u.c = 3; u.len = 1; break;
    case 16: u.sub = true; break;
    case 17: mul_m(Src::Acc); break;
    case 18: u.src = Src::V; u.c = 6; u.len = 2; break;
    case 19: div3(); break;
    // 6 S(M)
    case 20: mul_m(Src::J); break;
    case 21: u.src = Src::A; u.c = 3; u.len = 1; break;
    case 22: u.sub = true; u.c = 3; u.len = 1; break;
    case 23: mul_m(Src::Acc); break;
    case 24: u.src = Src::V; u.c = 6; u.len = 2; break;
    case 25: u.src = Src::A; u.sub = true; u.c = 3; u.len = 1; break;
    case 26: u.c = 2; u.len = 1; break;
    case 27: mul_m(Src::Acc); break;
    default: div3(); break;
  }
  return u;
}

}  // namespace

void RowReach::step(const Inputs& in) {
  // Idle without a start every register holds (an abort only keeps it idle):
  // skip the datapath, which nothing reads then, through the clocks of motion.
  if (q_.st == St::Idle && !in.start) return;
  const State& q = q_;
  State d = q;

  const Uop u = uop(q.pc);
  const i128 sum = wrapw(u.sub ? q.acc - q.mcd : q.acc + q.mcd);
  i128 bus = 0;
  switch (u.src) {
    case Src::A: bus = q.a; break;
    case Src::J: bus = q.j; break;
    case Src::V: bus = q.v; break;
    case Src::Acc: bus = q.acc; break;
  }
  const uint32_t mid = uint32_t((uint64_t(q.lo) + q.hi) >> 1);
  uint32_t m_val = 0;
  switch (q.msel) {
    case MSel::Nm1: m_val = q.nm1; break;
    case MSel::K: m_val = q.k; break;
    case MSel::Mid: m_val = mid; break;
    case MSel::Hi: m_val = q.hi; break;
  }
  const unsigned t3 = (unsigned(q.r3) << 1) | unsigned((q.mcd >> (kW - 2)) & 1);
  const bool cls0 = q.v < 0;
  const bool v_in_range = fits(q.acc, VelW + 1);
  const bool a_in_range = fits(q.acc, AccW);
  const bool rem_nz = (q.acc & ((i128(1) << (kDivSh + 1)) - 1)) != 0 || q.r3 != 0;
  const int64_t quo = sx_reach(q.mlr);
  const int64_t cand_up = sx_reach(uint64_t(quo) + (rem_nz ? 1 : 0));
  const bool a_neg = q.a < 0;

  switch (q.st) {
    case St::Idle:
      if (in.start) {
        d.st = in.clocks == 0 ? St::Done : St::Dec;
        d.ph = Ph::Start;
        d.nm1 = in.clocks - 1;
        d.one = in.clocks == 1;
        d.j = in.jerk;
        d.a = in.acc0;
        d.v = in.vel0;
        d.fwd = 0;
        d.rev = 0;
      }
      break;

    case St::Ld:
      d.st = St::Run;
      d.cnt = u.len;
      if (u.clr) d.acc = 0;
      if (u.kind != Kind::DivK) d.mcd = bus;
      if (u.kind == Kind::Div3) {
        d.mlr = neg_w(q.acc) ? kMlrMask : 0;  // floor(-1 / 3) = -1 rem 2
        d.r3 = neg_w(q.acc) ? 2 : 0;
      } else if (u.usem) {
        d.mlr = m_val;
      } else {
        d.mlr = u.c;
      }
      break;

    case St::Run:
      d.cnt = uint8_t((q.cnt - 1) & 63);
      switch (u.kind) {
        case Kind::Mul:
          if (q.mlr & 1) d.acc = sum;
          d.mcd = wrapw(q.mcd << 1);
          d.mlr = q.mlr >> 1;
          break;
        case Kind::DivK: {
          const bool take = neg_w(sum) == a_neg;
          if (take) d.acc = sum;
          d.mcd = q.mcd >> 1;
          d.mlr = ((q.mlr << 1) | (take ? 1 : 0)) & kMlrMask;
          break;
        }
        case Kind::Div3:
          d.mcd = wrapw(q.mcd << 1);
          d.mlr = ((q.mlr << 1) | (t3 >= 3 ? 1 : 0)) & kMlrMask;
          d.r3 = uint8_t(t3 >= 3 ? t3 - 3 : t3);
          break;
      }
      if (q.cnt == 0) {
        d.st = u.last ? St::Dec : St::Ld;
        d.pc = uint8_t((q.pc + 1) & 31);
      }
      break;

    case St::Dec: {
      bool search = false, srch_init2 = false, go_sat = false;
      d.st = St::Ld;
      auto go = [&](uint8_t pc, MSel m, Ph ph) {
        d.pc = pc;
        d.msel = m;
        d.ph = ph;
      };
      switch (q.ph) {
        case Ph::Start:
          if (q.one) {
            d.k = q.nm1;
            d.kc = true;
            go(kPcV, MSel::K, Ph::Vk);
          } else {
            go(kPcA, MSel::Nm1, Ph::A);
          }
          break;
        case Ph::A:
          if (!a_in_range) {
            go_sat = true;
          } else if (neg_w(q.acc) != a_neg) {
            d.kc = false;
            d.pc = kPcK;
            d.ph = Ph::K;
          } else {
            d.k = q.nm1;
            d.kc = true;
            go(kPcV, MSel::K, Ph::Vk);
          }
          break;
        case Ph::K:
          d.k = uint32_t(q.mlr);
          go(kPcV, MSel::K, Ph::Vk);
          break;
        case Ph::Vk:
        case Ph::Vn:
          if (!v_in_range) {
            go_sat = true;
          } else if (q.ph == Ph::Vk && !q.kc) {
            d.clsk = neg_w(q.acc);
            go(kPcV, MSel::Nm1, Ph::Vn);
          } else {
            if (q.ph == Ph::Vk) d.clsk = neg_w(q.acc);
            d.clsn = neg_w(q.acc);
            go(kPcSn, MSel::Nm1, Ph::Sn);
          }
          break;
        case Ph::Srch:
          if (neg_w(q.acc) == q.ref) d.lo = mid;
          else                       d.hi = mid;
          d.st = St::Dec;
          d.ph = Ph::Step;
          break;
        case Ph::Step:
          if (mid == q.lo) go(kPcS, MSel::Hi, Ph::St);
          else             go(kPcV, MSel::Mid, Ph::Srch);
          break;
        case Ph::Sn:
        case Ph::St:
          if (cand_up > q.fwd) d.fwd = cand_up;
          if (quo < q.rev) d.rev = quo;
          if (q.ph == Ph::Sn && q.clsk != cls0) {
            d.lo = 0;
            d.hi = q.k;
            d.ref = cls0;
            d.srch2 = false;
            search = true;
          } else if (!(q.ph == Ph::St && q.srch2) && q.clsn != q.clsk) {
            srch_init2 = true;
          } else {
            d.st = St::Done;
          }
          break;
      }
      if (srch_init2) {
        d.lo = q.k;
        d.hi = q.nm1;
        d.ref = q.clsk;
        d.srch2 = true;
        search = true;
      }
      if (search) {
        d.st = St::Dec;
        d.ph = Ph::Step;
      }
      if (go_sat) {
        d.fwd = kReachMax;
        d.rev = kReachMin;
        d.st = St::Done;
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
