#pragma once
// Variable smoothing length, Lobovsky & Kren eq. (13):
//   dh_i/dt = h_i / D sum_j m_j / rho_j v_ij . grad_i W_ij.
// The pairs add to the sum; finish multiplies by h_i / D.
#include "sph/terms/PairValues.hpp"

namespace sph::terms {

struct VariableSmoothingLength {
  static constexpr std::string_view name = "variable_h";
  static constexpr Reads reads{.mass = true, .densityInverse = true};
  static constexpr Writes writes{.smoothingLength = true};
  static constexpr Flops flops{0, 2};  // each side m v.gradW / rho, add (v.gradW: continuity's)
  template <class S, class V>
  static void pair(const PairValues<S, V>& p, PairSums<V>& s) {
    const V vGradW = p.vr * p.F;
    s.hI += p.j.m * vGradW * p.j.rhoInv;
    s.hJ += p.i.m * p.i.rhoInv * vGradW;
  }
  template <int D, class Vec>
  static void finish(ParticleRates<Vec>& r, const ParticleState<Vec>& x) {
    r.dhdt = x.h / D * r.hSum;
  }
};

}  // namespace sph::terms
