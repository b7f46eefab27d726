#pragma once
// Density diffusion of Molteni & Colagrossi (2009, Comput. Phys. Commun. 180, 861, eq. 9-10),
// the first "delta-SPH" term: the continuity equation gains
//   d rho_i/dt += delta h c0 sum_j psi_ij . grad_i W_ij V_j,
//   psi_ij = 2 (rho_j - rho_i) r_ji / |r_ij|^2,  V_j = m_j / rho_j,
// a discrete Laplacian of the density that damps its particle-scale noise (delta ~ 0.1 in their
// paper). With grad_i W_ij = F r_ij and r_ji . r_ij = -|r_ij|^2 the pair's value is
//   psi_ij . grad_i W_ij = 2 (rho_i - rho_j) F,
// taken here with |r_ij|^2 / (|r_ij|^2 + eta^2) against a pair at r -> 0, and h = h_ij, so that
// 2 h_ij = h_i + h_j: i gains V_j psi, j loses V_i psi (psi_ji = -psi_ij). Across a phase
// interface the density jumps, and this form would diffuse the jump: a scene may use it with
// one phase only (a per-phase form is the numerics issue's).
#include "sph/terms/PairValues.hpp"

namespace sph::terms {

class DensityDiffusionMolteniColagrossi {
 public:
  static constexpr std::string_view name = "density_diffusion_molteni_colagrossi";
  static constexpr Reads reads{
      .mass = true, .density = true, .densityInverse = true, .etaInverse = true};
  static constexpr Writes writes{.density = true};
  // psi: delta c0 (h_i + h_j) 1, rho_i - rho_j 1, F r^2 1, the three products 3; each side
  // m / rho, times psi, add 3.
  static constexpr Flops flops{6, 3};
  explicit DensityDiffusionMolteniColagrossi(const TermParameters& t)
      : deltaC0_(t.diffusionDelta * t.soundSpeed) {}
  template <class S, class V>
  void pair(const PairValues<S, V>& p, PairSums<V>& s) const {
    const V psi = (deltaC0_ * p.hSum) * (p.i.rho - p.j.rho) * (p.F * p.r2) * p.rEta2Inv;
    s.rhoI += p.j.m * p.j.rhoInv * psi;
    s.rhoJ -= p.i.m * p.i.rhoInv * psi;
  }

 private:
  double deltaC0_;
};

}  // namespace sph::terms
