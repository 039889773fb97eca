// Independent double-precision minimum-time 7-segment (or trapezoid)
// profile: accelerate/decelerate vs -> vp -> ve with zero acceleration at
// vp and at both ends, cruise at vp. vp = min(vc, rate limit) if the distance
// allows it, else (vc >= vs, ve) the largest feasible vp, (vc < max(vs,ve))
// the smallest feasible vp >= vc.
#pragma once
#include <algorithm>
#include <cmath>

namespace rt {

struct Trans { double T = 0, D = 0; };

// Transition v0 -> v1 with jerk j_in while |a| rises, j_out while it falls.
inline Trans trans(double v0, double v1, double a, double jin, double jout, bool trap) {
  Trans r;
  const double dv = std::fabs(v1 - v0);
  const double s = v1 >= v0 ? 1 : -1;
  if (dv == 0) return r;
  if (trap) {
    r.T = dv / a;
    r.D = 0.5 * (v0 + v1) * r.T;
    return r;
  }
  const double thresh = a * a * (0.5 / jin + 0.5 / jout);
  double ap, t2;
  if (dv >= thresh) { ap = a; t2 = (dv - thresh) / a; }
  else { ap = std::sqrt(2 * dv / (1 / jin + 1 / jout)); t2 = 0; }
  const double t1 = ap / jin, t3 = ap / jout;
  double v = v0, D = 0;
  D += v * t1 + s * jin * t1 * t1 * t1 / 6; v += s * ap * t1 / 2;
  D += v * t2 + s * ap * t2 * t2 / 2;        v += s * ap * t2;
  D += v * t3 + s * (ap * t3 * t3 / 2 - jout * t3 * t3 * t3 / 6);
  r.T = t1 + t2 + t3;
  r.D = D;
  return r;
}

struct RefPlan { bool ok = false; double vp = 0, T = 0; };

inline RefPlan ref_plan(double L, double vs, double vc, double ve, double a, const double j[4], bool trap,
                        double vrate) {
  vc = std::min(vc, vrate);
  auto D = [&](double vp, double* T) {
    const bool up1 = vp >= vs, up2 = ve >= vp;
    Trans t1 = trans(vs, vp, a, up1 ? j[0] : j[2], up1 ? j[1] : j[3], trap);
    Trans t2 = trans(vp, ve, a, up2 ? j[0] : j[2], up2 ? j[1] : j[3], trap);
    if (T) *T = t1.T + t2.T + (vp > 0 ? (L - t1.D - t2.D) / vp : 0);
    return t1.D + t2.D;
  };
  RefPlan r;
  double vp;
  const double vfar = std::max(vs, ve);
  if (D(vc, nullptr) <= L) vp = vc;
  else if (vc >= vfar) {
    if (D(vfar, nullptr) > L && vfar > 0) return r;
    double lo = vfar, hi = vc;
    for (int i = 0; i < 200; ++i) { const double m = 0.5 * (lo + hi); (D(m, nullptr) <= L ? lo : hi) = m; }
    vp = lo;
  } else {
    if (D(vfar, nullptr) > L) return r;
    double lo = vc, hi = vfar;  // smallest feasible
    for (int i = 0; i < 200; ++i) { const double m = 0.5 * (lo + hi); (D(m, nullptr) <= L ? hi : lo) = m; }
    vp = hi;
  }
  if (vp <= 0) return r;
  r.ok = true;
  r.vp = vp;
  D(vp, &r.T);
  return r;
}

}  // namespace rt
