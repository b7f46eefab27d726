#pragma once
// The pressure part of the momentum equation, Lobovsky & Kren eq. (12):
//   dv_i/dt = -sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2 + Pi_ij) grad_i W_ij + ...,
// or, with physics.continuity_form = "colagrossi_landrini", the form of Colagrossi & Landrini
// (2003, J. Comput. Phys. 191, 448-475) that goes with their continuity equation:
//   dv_i/dt = -(1/rho_i) sum_j (p_i + p_j) V_j grad_i W_ij + ...,
// whose bracket is (p_i + p_j) / (rho_i rho_j).
// Each form conserves energy with its own continuity equation (ContinuityEquation.hpp): the work
// of the pair's pressure force is the pair's change of internal energy, sum_i m_i p_i / rho_i^2
// d rho_i/dt. Eq. (12) with the continuity by volume does not; across a density jump the
// mismatch is of the order of the jump, and a tank of two layers at rest (1000 over 1500 kg/m^3)
// moves at 0.15-0.21 sqrt(g H) with that mix, against 2.5e-4 with either pair (LayeredTank and
// ContinuityForm tests).
// p from the Tait equation of state, eq. (8) (EquationOfState.hpp; computed once per particle,
// not per pair). This term puts the pressures into the bracket; artificial viscosity adds Pi_ij
// to it, and the pair force Q = bracket F r_ij - ... is formed once (TermSet.hpp).
#include "sph/terms/PairValues.hpp"

namespace sph::terms {

class PressureGradient {
 public:
  static constexpr std::string_view name = "pressure_gradient";
  static constexpr Reads reads{.density = true, .densityInverse = true, .pressure = true};
  static constexpr Writes writes{.bracket = true};
  // p_i/rho_i^2 + p_j/rho_j^2 1, and the pair force it starts: G = bracket F 1, Q = G r_ij 2;
  // each side m Q and its add, 2 x 2 (2-D); by volume 3 more.
  static constexpr Flops flops{4, 4};
  explicit PressureGradient(const TermParameters& t) : byVolume_(t.pressureGradientByVolume) {}
  template <class S, class V>
  void pair(const PairValues<S, V>& p, PairSums<V>& s) const {
    if (byVolume_)  // (p_i / rho_i) / rho_j + (p_j / rho_j) / rho_i
      s.bracket += (p.i.pOverRho2 * p.i.rho) * p.j.rhoInv + p.i.rhoInv * (p.j.pOverRho2 * p.j.rho);
    else
      s.bracket += p.i.pOverRho2 + p.j.pOverRho2;
  }

 private:
  bool byVolume_;
};

}  // namespace sph::terms
