#pragma once
// Laminar viscosity of Morris, Fox & Zhu (1997), Lobovsky & Kren eq. (9):
//   dv_i/dt = ... + sum_j m_j (mu_i + mu_j) / (rho_i rho_j) (r_ij . grad_i W_ij) /
//             (r_ij^2 + eta^2) v_ij.
// With r_ij . grad_i W_ij = F r_ij^2 this is m_j Y v_ij, Y the factor below; j's share is
// -m_i Y v_ij (Y is symmetric, v_ji = -v_ij), so it joins eq. (12)'s pair force as
// Q = bracket F r_ij - Y v_ij (TermSet.hpp).
#include "sph/terms/PairValues.hpp"

namespace sph::terms {

struct MorrisViscosity {
  static constexpr std::string_view name = "morris_viscosity";
  static constexpr Reads reads{.densityInverse = true, .viscosity = true, .etaInverse = true};
  static constexpr Writes writes{.viscous = true};
  static constexpr Flops flops{11, 0};  // Y 7, Q -= Y v_ij 2 x 2 (2-D)
  template <class S, class V>
  static void pair(const PairValues<S, V>& p, PairSums<V>& s) {
    s.viscous += (p.i.mu + p.j.mu) * (p.F * p.r2) * p.rEta2Inv * p.j.rhoInv * p.i.rhoInv;
  }
};

}  // namespace sph::terms
