#pragma once
// Fixed wall particles for walls of any shape (sloping, curved), 2-D only: the wall model of
// Adami, Hu & Adams (2012), J. Comput. Phys. 231, 7057-7075, eqs. (27)-(28), for walls at rest.
// Each wall particle w sits still outside the fluid (the solid layers of the packing, Colagrossi
// et al. 2012, section 2) and, before every force evaluation, takes its state from the fluid
// particles f within the kernel support:
//   p_w = ( sum_f p_f W_wf + g . sum_f rho_f (r_w - r_f) W_wf ) / sum_f W_wf      (eq. 27, a_w = 0)
//   rho_w = rho0 ((p_w - p0) / K + 1)^(1/gamma)              (the inverse Tait EOS, eq. 28)
//   v_w = 0,  m_w = rho_w V0,  h_w = h.
// The g term extends the fluid's hydrostatic pressure into the wall, so a fluid at rest feels the
// wall push back with exactly rho g (a mirrored, even pressure would lack it). A wall particle
// with no fluid in reach has p0 and rho0, and p_w is not let below p0: near the free surface a
// wall particle above its fluid neighbours gets p_w < p0 from the g term (the hydrostatic
// pressure extrapolated above the surface) and pulls the fluid into the wall (measured: the
// surface particle in the 45-degree corner of the trapezoidal tank crossed the wall by
// t sqrt(g/H) = 0.7 without the bound). The wall is free slip: its velocity enters only the
// continuity equation (the kinematic condition, v_w = 0) and the artificial viscosity, which the
// tank runs leave out or keep small; no viscous wall stress is imposed. The volume m_w / rho_w is
// the fluid's particle volume V0, so a packed fluid (sum_j grad W_ij V0 = 0 with these walls,
// eq. 1.12) starts with no pressure imbalance.
// Chosen over the fixed ghosts of Marrone et al. (2011) because eq. (27) needs no mirror point
// and no interpolation inside the fluid, which on acute corners and arcs are ambiguous.
#include <vector>

#include "sph/EquationOfState.hpp"
#include "sph/InteractionSet.hpp"
#include "sph/Kernels.hpp"
#include "sph/Particles.hpp"

namespace sph {

class FixedWalls {
 public:
  // `position`: the wall particles; V0: the particle volume; h: the smoothing length; g: the body
  // acceleration the fluid feels [m/s^2].
  FixedWalls(std::vector<Vec<2>> position, double V0, double h, KernelKind kernel,
             const Phase& phase, const Vec<2>& g);

  // Appends the wall particles after the fluid (and any halo) of `set`, their pressure from eq.
  // (27) over the fluid entries (the first set.nFluid, whose pressure `set` already holds).
  void append(InteractionSet<2>& set) const;

  const std::vector<Vec<2>>& positions() const { return x_; }
  std::size_t size() const { return x_.size(); }

 private:
  std::vector<Vec<2>> x_;
  double V0_, h_;
  KernelKind kernel_;
  Phase phase_;
  Vec<2> g_;
  // Scratch between calls: fluid entries sorted into square cells of the kernel support.
  mutable std::vector<int> cellStart_, cellEntries_;
  mutable std::vector<double> p_, rho_;
};

}  // namespace sph
