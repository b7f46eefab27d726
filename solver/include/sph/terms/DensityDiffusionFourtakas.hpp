#pragma once
// Density diffusion of Fourtakas, Dominguez, Vacondio & Rogers (2019, Comput. Fluids 190,
// 346-361, section 2: the delta-SPH term of their continuity equation), Molteni & Colagrossi's
// (2009) term with the hydrostatic part of the density difference taken out:
//   d rho_i/dt += delta h c0 sum_j psi_ij . grad_i W_ij V_j,
//   psi_ij = 2 (rho_ji^T - rho_ji^H) r_ji / (|r_ij|^2 + eta^2),  rho_ji^T = rho_j - rho_i,
// where rho_ji^H is the density difference that a fluid at rest under the body acceleration g has
// between j and i. Molteni & Colagrossi's term is a Laplacian of the density and the density of
// a fluid at rest is not harmonic near a free surface or a wall (the kernel is cut there), so it
// drives a flux that a tank at rest answers with spurious flow; this one vanishes at rest.
//
// The hydrostatic pressure difference is p_j - p_i = -rho0 g . r_ij (r_ij = x_i - x_j: j deeper
// gives p_j > p_i). Through the Tait equation of state (Lobovsky & Kren eq. 8, with K = rho0
// c0^2 / gamma), q = (p - p0) / K + 1 = (rho/rho0)^gamma, so q_j - q_i = -rho0 g . r_ij / K.
// Fourtakas et al. turn this into a density by the inverse EOS about rho0,
//   rho_ji^H = rho0 ((1 - rho0 g . r_ij / K)^(1/gamma) - 1),
// which is exact when rho_i = rho0 only (at the bottom of a tank with c0 = 10 sqrt(gH) it is some
// 6 % off the hydrostatic density difference). Here the same relation is taken along the secant
// of the EOS between the pair's own densities: with x = rho/rho0 and integer gamma,
//   x_j^gamma - x_i^gamma = (x_j - x_i) S,  S = sum_{k=0}^{gamma-1} x_j^k x_i^(gamma-1-k),
// so the hydrostatic difference is exactly
//   rho_ji^H = -rho0^2 (g . r_ij) / (K S),
// which is Fourtakas et al.'s to first order in rho0 g . r_ij / K (at x_i = x_j = 1, S = gamma and
// rho_ji^H = -rho0 g . r_ij / c0^2), symmetric in i and j through S (so psi_ji = -psi_ij and the
// term conserves sum_i V_i rho_i as Molteni & Colagrossi's does), and vanishes to round-off on
// the hydrostatic field p = p0 + rho0 |g| (H - y) that the scenes start from. S needs no power
// and no division by x_j - x_i: gamma - 1 multiply-adds (Horner in x_j). delta and c0 as in
// Molteni & Colagrossi's term (delta ~ 0.1); eta^2 = 0.01 h_ij^2 (DESIGN.md 1), h = h_ij. One
// phase only: the density jump at a phase interface is no hydrostatic difference (with several
// phases, DensityDiffusionFourtakasPhases.hpp diffuses within each). A wall's
// ghosts must carry the hydrostatic density too, or the term drains the fluid beside the wall
// (Fourtakas et al. build their boundary stencil for that): with ghost_pressure = "hydrostatic"
// the simulation gives each ghost the density of its pressure (Simulation.cpp).
#include "sph/terms/PairValues.hpp"

namespace sph::terms {

// -(rho_ji^T - rho_ji^H) = rho_i - rho_j + rho_ji^H of the header, rho_ji^H = -gr / S, for the
// pair's densities, 1/rho0 of their phase and gr = rho0^2 g . r_ij / K.
template <class S, class V, class R>
V fourtakasDifference(S rhoI, V rhoJ, R rho0Inverse, V gr, int gamma) {
  const S xi = rhoI * rho0Inverse;
  const V xj = rhoJ * rho0Inverse;
  V secant = V{} + 1.0;  // S of the header, by Horner in x_j: coefficient x_i^k of x_j^(gamma-1-k)
  S xiPower = 1.0;
  for (int k = 1; k < gamma; ++k) {
    xiPower *= xi;
    secant = secant * xj + xiPower;
  }
  return (rhoI - rhoJ) - gr / secant;
}

class DensityDiffusionFourtakas {
 public:
  static constexpr std::string_view name = "density_diffusion_fourtakas";
  static constexpr Reads reads{
      .mass = true, .density = true, .densityInverse = true, .etaInverse = true};
  static constexpr Writes writes{.density = true};
  // x_j 1, S 2 (gamma - 1) = 12 at gamma 7 (x_i's powers counted there too), rho0^2 g . r / K 3
  // (2-D), its division by S 1, the density difference 2, then Molteni & Colagrossi's 5; each
  // side m / rho, times psi, add 3.
  static constexpr Flops flops{24, 3};
  explicit DensityDiffusionFourtakas(const TermParameters& t)
      : deltaC0_(t.diffusionDelta * t.soundSpeed),
        rho0Inverse_(1.0 / t.rho0),
        gamma_(t.gammaInteger),
        hydrostatic_{t.rho0 * t.rho0 / t.bulkModulus * t.g[0],
                     t.rho0 * t.rho0 / t.bulkModulus * t.g[1],
                     t.rho0 * t.rho0 / t.bulkModulus * t.g[2]} {}
  template <class S, class V>
  void pair(const PairValues<S, V>& p, PairSums<V>& s) const {
    const V gr = hydrostatic_[0] * p.rx + hydrostatic_[1] * p.ry + hydrostatic_[2] * p.rz;
    const V difference = fourtakasDifference(p.i.rho, p.j.rho, rho0Inverse_, gr, gamma_);
    const V psi = (deltaC0_ * p.hSum) * difference * (p.F * p.r2) * p.rEta2Inv;
    s.rhoI += p.j.m * p.j.rhoInv * psi;
    s.rhoJ -= p.i.m * p.i.rhoInv * psi;
  }

 private:
  double deltaC0_, rho0Inverse_;
  int gamma_;
  double hydrostatic_[3];  // rho0^2 g / K
};

}  // namespace sph::terms
