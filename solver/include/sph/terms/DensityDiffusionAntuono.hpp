#pragma once
// Density diffusion of Antuono, Colagrossi, Marrone & Molteni (2010, Comput. Phys. Commun. 181,
// 532-549), the delta-SPH term with the renormalised density gradient:
//   d rho_i/dt += delta h c0 sum_j psi_ij . grad_i W_ij V_j,
//   psi_ij = 2 (rho_j - rho_i) r_ji / |r_ij|^2 - (<grad rho>_i + <grad rho>_j),
// with <grad rho> the renormalised gradient of terms/RenormalisedDensityGradient.hpp. Molteni &
// Colagrossi's term (its first part alone) is a Laplacian of the density, which is not zero on
// a fluid at rest where the kernel is cut (the free surface, a wall), and it drives a flux that
// lifts a resting column. Here the second part takes out, pair by pair, what a linear density
// field gives the first: since <grad rho> is exact for a linear field on any arrangement, with
// the support cut or not, the term vanishes to round-off on every linear field. The hydrostatic
// field is linear up to the Tait equation's curvature, d^2 rho/dz^2 = (gamma - 1) rho0 (g/c0^2)^2
// (over a depth H it leaves the line by (gamma - 1) (g H / c0^2)^2 rho0 / 2: 3 % of the density
// range at c0 = 10 sqrt(g H)), so the term nearly vanishes there, at the free surface too, without
// the hydrostatic pressure that Fourtakas et al.'s (2019) form takes out exactly. A mirror ghost or
// periodic image takes its source's gradient (the force evaluation's pass), which is a hydrostatic
// ghost's (ghost_pressure = "hydrostatic"): its density continues the fluid's field across the
// wall.
//
// With grad_i W_ij = F r_ij and r_ji . r_ij = -|r_ij|^2 the pair's value is
//   psi_ij . grad_i W_ij = [2 (rho_i - rho_j) - (<grad rho>_i + <grad rho>_j) . r_ij] F,
// taken, as Molteni & Colagrossi's, with |r_ij|^2 / (|r_ij|^2 + eta^2) against a pair at r -> 0
// (on both parts, so that they still cancel on a linear field), and h = h_ij. psi_ji = -psi_ij:
// i gains V_j psi, j loses V_i psi, and sum_i V_i rho_i is conserved. delta ~ 0.1 (Antuono et
// al.); one phase only, as Molteni & Colagrossi's.
#include "sph/terms/PairValues.hpp"

namespace sph::terms {

class DensityDiffusionAntuono {
 public:
  static constexpr std::string_view name = "density_diffusion_antuono";
  static constexpr Reads reads{.mass = true,
                               .density = true,
                               .densityInverse = true,
                               .densityGradient = true,
                               .etaInverse = true};
  static constexpr Writes writes{.density = true};
  // (<grad rho>_i + <grad rho>_j) . r_ij 4 and half of it with rho_i - rho_j 2 (2-D), then
  // Molteni & Colagrossi's 5; each side m / rho, times psi, add 3.
  static constexpr Flops flops{11, 3};
  explicit DensityDiffusionAntuono(const TermParameters& t)
      : deltaC0_(t.diffusionDelta * t.soundSpeed) {}
  template <class Kernel, int D, class S, class V>
  void pair(const PairValues<S, V>& p, PairSums<V>& s) const {
    const V r[3] = {p.rx, p.ry, p.rz};
    V linear = (p.i.gradRho[0] + p.j.gradRho[0]) * r[0];
    for (int a = 1; a < D; ++a) linear += (p.i.gradRho[a] + p.j.gradRho[a]) * r[a];
    const V difference = (p.i.rho - p.j.rho) - 0.5 * linear;
    const V psi = (deltaC0_ * p.hSum) * difference * (p.F * p.r2) * p.rEta2Inv;
    s.rhoI += p.j.m * p.j.rhoInv * psi;
    s.rhoJ -= p.i.m * p.i.rhoInv * psi;
  }

 private:
  double deltaC0_;
};

}  // namespace sph::terms
