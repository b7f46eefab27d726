#pragma once
// The pair sums of particle shifting (ParticleShifting.hpp): the gradient of the particle
// concentration with Monaghan's (2000) anti-clumping factor, as Lind, Xu, Stansby & Rogers (2012,
// J. Comput. Phys. 231, 1499, eqs. 21-24 as PySPH's shifting module numbers them) take it,
//   grad C_i = sum_j V_j (1 + R (W_ij / W(dx))^n) grad_i W_ij,  V_j = m_j / rho_j,
// R = 0.2, n = 4, W(dx) the kernel at the initial spacing dx with h_ij; the same without the
// factor, whose direction is the free surface's normal,
//   g_i = sum_j V_j grad_i W_ij;
// and the divergence of the position, which marks the free surface,
//   div r_i = -sum_j V_j r_ij . grad_i W_ij.
// With grad_j W_ji = -grad_i W_ij = -F r_ij and r_ji = -r_ij, j's shares are i's with V_i in
// place of V_j: -V_i (...) F r_ij for the two gradients, and the same -V_i F r_ij^2 for div r.
// The kernel's normalisation cancels in W_ij / W(dx): its shape at q_ij = r / h_ij over its
// shape at dx / h_ij (Kernel::shape).
//
// The term writes sums of its own, beside the rates: sums<D> doubles a particle, in the order
// gradC (D axes), g (D axes), div r (the offsets below). It adds nothing to the rates, and the
// simulation names it with the shifting form, so its name is empty.
#include "sph/terms/PairValues.hpp"

namespace sph::terms {

class ConcentrationGradient {
 public:
  static constexpr std::string_view name = "";
  static constexpr Reads reads{.mass = true, .densityInverse = true};
  static constexpr Writes writes{};
  static constexpr double anticlumpingR = 0.2;  // Lind et al. 2012 after Monaghan 2000
  static constexpr int anticlumpingN = 4;
  // Where each sum lies in a particle's sums<D> doubles.
  template <int D>
  static constexpr int sums = 2 * D + 1;
  static constexpr int gradCAt = 0;
  template <int D>
  static constexpr int normalAt = D;
  template <int D>
  static constexpr int divRAt = 2 * D;
  // q 1, the two shapes (quadratic) 5 + 5, their quotient 1, w^4 2, (1 + R w^4) V F 3, V F r^2 1
  // (2-D); each side V m/rho 1, the two gradients' products and adds 2 x 2 x 2, div r's 2.
  static constexpr Flops flops{18, 11};
  explicit ConcentrationGradient(const TermParameters& t) : spacing_(t.spacing) {}

  template <class Kernel, int D, class S, class V>
  void pair(const PairValues<S, V>& p, PairSums<V>& s) const {
    static_assert(anticlumpingN == 4);  // w^4 below as (w^2)^2
    const V w =
        Kernel::template shape<D>(p.r * p.hInv) / Kernel::template shape<D>(spacing_ * p.hInv);
    const V w2 = w * w;
    const V Fi = p.j.m * p.j.rhoInv * p.F, Fj = p.i.m * p.i.rhoInv * p.F;  // V_j F, V_i F
    const V clump = 1.0 + anticlumpingR * (w2 * w2);
    const V r[3] = {p.rx, p.ry, p.rz};
    for (int a = 0; a < D; ++a) {
      s.ownI[gradCAt + a] = (Fi * clump) * r[a], s.ownJ[gradCAt + a] = -((Fj * clump) * r[a]);
      s.ownI[normalAt<D> + a] = Fi * r[a], s.ownJ[normalAt<D> + a] = -(Fj * r[a]);
    }
    s.ownI[divRAt<D>] = -(Fi * p.r2), s.ownJ[divRAt<D>] = -(Fj * p.r2);
  }

 private:
  double spacing_;
};

}  // namespace sph::terms
