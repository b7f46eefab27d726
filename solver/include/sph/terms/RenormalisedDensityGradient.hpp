#pragma once
// The renormalised density gradient of Antuono, Colagrossi, Marrone & Molteni's (2010) density
// diffusion (terms/DensityDiffusionAntuono.hpp), after Randles & Libersky's (1996) correction:
//   <grad rho>_i = L_i sum_j (rho_j - rho_i) grad_i W_ij V_j,
//   L_i = [sum_j r_ji (x) grad_i W_ij V_j]^-1,  V_j = m_j / rho_j,  r_ji = x_j - x_i.
// On any arrangement of particles, with the kernel's support cut or not, it is exact for a
// linear field rho = a + b . x: the sum is then sum_j (r_ji . b) grad_i W_ij V_j = L_i^-1 b.
// With grad_i W_ij = F r_ij both sums are symmetric pair sums: the matrix
//   M_i = -sum_j V_j F r_ij (x) r_ij  (symmetric; the identity inside a uniform lattice)
// and the vector g_i = sum_j (rho_j - rho_i) V_j F r_ij; j's shares are i's with V_i in place of
// V_j (r_ji (x) r_ji = r_ij (x) r_ij, and (rho_i - rho_j) F r_ji = (rho_j - rho_i) F r_ij).
//
// The term writes sums of its own and no rate: sums<D> doubles a particle, M's upper triangle by
// rows then g. The force evaluation evaluates it in a pass before the rates (it needs every
// particle's sums before any pair of the diffusion) and forms <grad rho>_i = M_i^-1 g_i there.
// Where M_i is near singular (a particle whose neighbours span too few directions, off a splash:
// leastIsotropy), L_i is the identity: the plain SPH gradient (the fallback of the renormalised
// schemes, e.g. Marrone et al. 2011, Comput. Methods Appl. Mech. Engrg. 200, 1526).
#include <Eigen/Dense>

#include "sph/terms/PairValues.hpp"

namespace sph::terms {

class RenormalisedDensityGradient {
 public:
  static constexpr std::string_view name = "";
  static constexpr Reads reads{.mass = true, .density = true, .densityInverse = true};
  static constexpr Writes writes{};
  template <int D>
  static constexpr int sums = D*(D + 1) / 2 + D;
  // The isotropy of M, det M / (tr M / D)^D (the product of its eigenvalues over the D-th power
  // of their mean): 1 where M is a multiple of the identity, inside the fluid and in a corner of
  // it (a 3-D corner of a jittered block has det M down to 0.006, Wendland C2 at h/dx 2, and its
  // renormalised gradient is as exact as the interior's); 0 where M is singular, for a row of
  // particles alone or a pair, whose support spans too few directions. At or below this
  // isotropy L is the identity: 1/20 is a ratio of M's eigenvalues of about 1/80 (2-D) or 1/70
  // (3-D), which bounds L's gain along one direction against the others.
  static constexpr double leastIsotropy = 0.05;
  // rho_j - rho_i 1, r_a r_b 3 and (rho_j - rho_i) r_a 2 (2-D); each side V F 2, times those 5,
  // the sums' adds 5.
  static constexpr Flops flops{6, 12};

  template <class Kernel, int D, class S, class V>
  void pair(const PairValues<S, V>& p, PairSums<V>& s) const {
    const V Fi = p.j.m * p.j.rhoInv * p.F, Fj = p.i.m * p.i.rhoInv * p.F;  // V_j F, V_i F
    const V difference = p.j.rho - p.i.rho;
    const V r[3] = {p.rx, p.ry, p.rz};
    int k = 0;
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b, ++k) {
        const V rr = r[a] * r[b];
        s.ownI[k] = -(Fi * rr), s.ownJ[k] = -(Fj * rr);
      }
    for (int a = 0; a < D; ++a, ++k) {
      const V dr = difference * r[a];
      s.ownI[k] = Fi * dr, s.ownJ[k] = Fj * dr;
    }
  }

  // <grad rho>_i from the particle's sums<D> (above).
  template <int D>
  static Eigen::Matrix<double, D, 1> gradient(const double* sums) {
    Eigen::Matrix<double, D, D> M;
    int k = 0;
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b, ++k) M(a, b) = M(b, a) = sums[k];
    const Eigen::Matrix<double, D, 1> g = Eigen::Map<const Eigen::Matrix<double, D, 1>>(sums + k);
    const double mean = M.trace() / D;
    double meanToD = mean;
    for (int a = 1; a < D; ++a) meanToD *= mean;
    const bool renormalised = mean > 0.0 && M.determinant() > leastIsotropy * meanToD;
    // The identity blended in for a singular M, not a branch around the inverse: with
    // -fno-trapping-math the compiler may compute both sides of a branch (it inverts several
    // particles' M at once, singular ones too), and 1 / 0 would raise where exceptions trap.
    const double s = renormalised ? 1.0 : 0.0;
    const Eigen::Matrix<double, D, D> L =
        (s * M + (1.0 - s) * Eigen::Matrix<double, D, D>::Identity()).inverse();
    return L * g;
  }
};

}  // namespace sph::terms
