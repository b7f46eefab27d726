#pragma once
// Artificial viscosity, Lobovsky & Kren eq. (10) (Monaghan 1992 without the linear term):
//   Pi_ij = beta mu_ij^2 / rho_ij  for v_ij . r_ij < 0, else 0,
//   mu_ij = h_ij v_ij . r_ij / (r_ij^2 + eta^2),  rho_ij = (rho_i + rho_j) / 2,
// added to the bracket of eq. (12). With h_ij^2 = (h_i + h_j)^2 / 4 and 1/rho_ij = 2/(rho_i +
// rho_j): Pi_ij = beta/2 (h_i + h_j)^2 / (rho_i + rho_j) (v_ij . r_ij / (r_ij^2 + eta^2))^2.
// Symmetric in i and j.
#include "sph/terms/PairValues.hpp"

namespace sph::terms {

class ArtificialViscosity {
 public:
  static constexpr std::string_view name = "artificial_viscosity";
  static constexpr Reads reads{.density = true, .etaInverse = true, .rhoSumInverse = true};
  static constexpr Writes writes{.bracket = true};
  static constexpr Flops flops{11, 0};  // mu_ij 1, Pi 7, compare-select 2, add 1
  explicit ArtificialViscosity(const TermParameters& t) : halfBeta_(0.5 * t.beta) {}
  template <class S, class V>
  void pair(const PairValues<S, V>& p, PairSums<V>& s) const {
    const V mu = p.vr * p.rEta2Inv;  // mu_ij / h_ij
    const V pi = halfBeta_ * p.hSum2 * p.rhoSumInv * mu * mu;
    s.bracket += p.vr < 0.0 ? pi : V{};  // approaching pairs only: a select, not a branch
  }

 private:
  double halfBeta_;
};

}  // namespace sph::terms
