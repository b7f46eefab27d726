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
// wall push back with rho g (a mirrored, even pressure would lack it). A wall particle with no
// fluid in reach has p0 and rho0, and p_w is not let below p0: near the free surface a wall
// particle above its fluid neighbours gets p_w < p0 from the g term (the hydrostatic pressure
// extrapolated above the surface), which would hold surface particles to the wall by tension.
// Velocity: v_w = 0 enters the continuity equation (the kinematic condition: a particle moving
// into the wall compresses and is pushed back) and any viscous term, where it acts as a no-slip
// wall; Adami's free slip (no viscous wall term) would need a per-pair test in the loop, and a
// tank at rest has no tangential flow for it to matter. The volume m_w / rho_w is the fluid's
// particle volume V0, the volume the packing gave every solid particle, so the packing's balance
// sum_j grad W_ij V0 = 0 (eq. 1.12) holds against these walls too (not rho0 dx^2: the packed V0
// is area / N).
// Chosen over the fixed ghosts of Marrone et al. (2011) because eq. (27) needs no mirror point
// and no interpolation inside the fluid, which on acute corners and arcs are ambiguous.
#include <vector>

#include "sph/CellList.hpp"
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
  // Scratch between calls: the fluid entries in cells of the kernel support, the walls' state.
  mutable CellList<2> cells_;
  mutable std::vector<double> p_, rho_;
};

}  // namespace sph
