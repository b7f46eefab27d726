#pragma once
// The continuity equation, Lobovsky & Kren eq. (11):
//   d rho_i/dt = sum_j m_j v_ij . grad_i W_ij,
// or, with physics.continuity_form = "colagrossi_landrini", the form of Colagrossi & Landrini
// (2003, J. Comput. Phys. 191, 448-475):
//   d rho_i/dt = rho_i sum_j V_j v_ij . grad_i W_ij,  V_j = m_j / rho_j,
// -rho_i times the SPH divergence of v. Within one phase the two differ by rho_j / rho_i - 1, of
// the order of the compression (1 %). Across an interface eq. (11) weighs the other phase's
// velocities by its mass, rho0_j / rho0_i times its volume (1.5 from light to heavy in the
// 1000/1500 lock exchange): a divergence off by that ratio where the layers shear, which moves
// volume from one phase to the other (validation/README.md).
// v_ij . grad_i W_ij = v_ji . grad_j W_ji, so j's share is the same with m_i (rho_j V_i).
// The form is a branch on the scene's choice, the same for every pair (always predicted): as one
// expression for both, m_j (a + b rho_i / rho_j), the paper's scenes took 1.9 % longer.
#include "sph/terms/PairValues.hpp"

namespace sph::terms {

class ContinuityEquation {
 public:
  static constexpr std::string_view name = "continuity";
  static constexpr Reads reads{.mass = true, .density = true, .densityInverse = true};
  static constexpr Writes writes{.density = true};
  // v.gradW 1; each side m v.gradW and its add (by volume: rho_i V_j, 2 more)
  static constexpr Flops flops{1, 2};
  explicit ContinuityEquation(const TermParameters& t) : byVolume_(t.continuityByVolume) {}
  template <class S, class V>
  void pair(const PairValues<S, V>& p, PairSums<V>& s) const {
    const V vGradW = p.vr * p.F;
    if (byVolume_) {
      s.rhoI += (p.i.rho * (p.j.m * p.j.rhoInv)) * vGradW;
      s.rhoJ += (p.j.rho * (p.i.m * p.i.rhoInv)) * vGradW;
    } else {
      s.rhoI += p.j.m * vGradW;
      s.rhoJ += p.i.m * vGradW;
    }
  }

 private:
  bool byVolume_;
};

}  // namespace sph::terms
