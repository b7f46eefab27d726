#pragma once
// The continuity equation, Lobovsky & Kren eq. (11):
//   d rho_i/dt = sum_j m_j v_ij . grad_i W_ij.
// v_ij . grad_i W_ij = v_ji . grad_j W_ji, so j's share is the same with m_i.
#include "sph/terms/PairValues.hpp"

namespace sph::terms {

struct ContinuityEquation {
  static constexpr std::string_view name = "continuity";
  static constexpr Reads reads{.mass = true};
  static constexpr Writes writes{.density = true};
  static constexpr Flops flops{1, 2};  // v.gradW; each side m v.gradW and its add
  template <class S, class V>
  static void pair(const PairValues<S, V>& p, PairSums<V>& s) {
    const V vGradW = p.vr * p.F;
    s.rhoI += p.j.m * vGradW;
    s.rhoJ += p.i.m * vGradW;
  }
};

}  // namespace sph::terms
