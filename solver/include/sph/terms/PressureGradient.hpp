#pragma once
// The pressure part of the momentum equation, Lobovsky & Kren eq. (12):
//   dv_i/dt = -sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2 + Pi_ij) grad_i W_ij + ...,
// with p from the Tait equation of state, eq. (8) (EquationOfState.hpp; computed once per
// particle, not per pair). This term puts the pressures into the bracket; artificial viscosity
// adds Pi_ij to it, and the pair force Q = bracket F r_ij - ... is formed once (TermSet.hpp).
#include "sph/terms/PairValues.hpp"

namespace sph::terms {

struct PressureGradient {
  static constexpr std::string_view name = "pressure_gradient";
  static constexpr Reads reads{.pressure = true};
  static constexpr Writes writes{.bracket = true};
  // p_i/rho_i^2 + p_j/rho_j^2 1, and the pair force it starts: G = bracket F 1, Q = G r_ij 2;
  // each side m Q and its add, 2 x 2 (2-D).
  static constexpr Flops flops{4, 4};
  template <class S, class V>
  static void pair(const PairValues<S, V>& p, PairSums<V>& s) {
    s.bracket += p.i.pOverRho2 + p.j.pOverRho2;
  }
};

}  // namespace sph::terms
