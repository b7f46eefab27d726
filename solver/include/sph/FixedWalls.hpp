#pragma once
// Fixed wall particles for walls of any shape (box faces, obstacles, sloping or curved walls), in
// 1, 2 or 3 dimensions: the wall model of Adami, Hu & Adams (2012), J. Comput. Phys. 231,
// 7057-7075, eqs. (22)-(23) and (27)-(28), for walls at rest (a_w = 0). Each wall particle w sits
// still outside the fluid and, before every force evaluation, takes its state from the entries f
// (fluid and its periodic images) within the kernel support:
//   p_w = ( sum_f p_f W_wf + g . sum_f rho_f (r_w - r_f) W_wf ) / sum_f W_wf      (eq. 27, a_w = 0)
//   rho_w = rho0 ((p_w - p0) / K + 1)^(1/gamma)              (the inverse Tait EOS, eq. 28)
//   v~_w = sum_f v_f W_wf / sum_f W_wf                                              (eq. 22)
//   v_w = 0 (at rest), or v_w = 2 v_wall - v~_w (no slip, eq. 23) component by component along
//   the axes a particle's rule reverses (below),  m_w = rho_w V0,  h_w = h.
// Several phases: a wall particle is of the phase whose fluid weighs most in its sum (the W_wf
// of eq. 27 by phase, the first phase on a tie), and takes that phase's rho0, K, p0 and
// viscosity. Adami et al. write eq. (28) for one fluid; with the first phase's EOS at every wall,
// a wall particle beside a phase of another rest density would have a density, and so a mass
// m_w and a pair force, of the wrong fluid (the pressure term of fluid i against w scales with
// m_w / rho_i^2 = V0 rho_w / rho_i^2: 1.5 times too strong for a phase of 1000 against walls of
// 1500 kg/m^3). Of its own phase, m_w / rho_w = V0 and rho_w ~ rho_i, as in one fluid.
// The g term extends the fluid's hydrostatic pressure into the wall, so a fluid at rest feels the
// wall push back with rho g (a mirrored, even pressure would lack it). A wall particle with no
// fluid in reach has p0, rho0 and v~ = 0, and p_w is not let below p0: near the free surface a
// wall particle above its fluid neighbours gets p_w < p0 from the g term (the hydrostatic
// pressure extrapolated above the surface), which would hold surface particles to the wall by
// tension.
// Velocity: one v per entry serves both the continuity equation and the viscous terms. Adami uses
// v_w of eq. (23) in the viscous term only and the wall's own velocity in the continuity
// equation; a second velocity would need a per-pair test in the loop. A wall particle's rule
// reverses, about the wall's velocity, the components its mirror ghost would (InteractionSet.hpp):
// every component for no slip (eq. 23: the shear stress of a no-slip wall), the normal ones only
// for free slip (Adami's free slip omits the viscous wall term; keeping v~'s tangential part
// gives the viscous terms no tangential velocity difference across the wall, to the accuracy of
// the extrapolation). The reversed normal component keeps the kinematic condition of the
// continuity equation: a particle moving into the wall compresses and is pushed back, twice as
// strongly as against v_w = 0, as against a mirror ghost. The volume m_w / rho_w is the fluid's
// particle volume V0, so the balance sum_j grad W_ij V0 = 0 holds against these walls too.
// Chosen over the fixed ghosts of Marrone et al. (2011) because eq. (27) needs no mirror point
// and no interpolation inside the fluid, which on acute corners and arcs are ambiguous.
#include <array>
#include <vector>

#include "sph/CellList.hpp"
#include "sph/EquationOfState.hpp"
#include "sph/InteractionSet.hpp"
#include "sph/Kernels.hpp"
#include "sph/Particles.hpp"

namespace sph {

// How a wall particle's velocity follows the fluid (see the header).
template <int D>
struct WallVelocityRule {
  bool atRest = true;                    // v_w = 0 (the packing tanks' walls)
  Vec<D> reversed = Vec<D>::Zero();      // 1 where v_w = 2 v_wall - v~, else 0 (v_w = v~)
  Vec<D> wallVelocity = Vec<D>::Zero();  // v_wall
};

template <int D>
class FixedWalls {
 public:
  // `position`: the wall particles; V0: the particle volume; h: the smoothing length; `phases`:
  // the scene's, in the order of the set's phase indices (at least one); g: the body
  // acceleration the fluid feels [m/s^2]. Every wall particle at rest.
  FixedWalls(std::vector<Vec<D>> position, double V0, double h, KernelKind kernel,
             std::vector<Phase> phases, const Vec<D>& g);
  // The same with a velocity rule and a volume per particle (as many as positions).
  FixedWalls(std::vector<Vec<D>> position, std::vector<WallVelocityRule<D>> velocity,
             std::vector<double> volume, double h, KernelKind kernel, std::vector<Phase> phases,
             const Vec<D>& g);

  // Writes the wall particles after the fluid and its halo of `set` (set.haloEnd()), their state
  // from eqs. (22)-(28) over those entries (whose pressure `set` already holds). Only those
  // within `reach` (a pair's support plus the skin) of a fluid entry are written (set.walls), the
  // others counted in set.leftOut: chosen anew with HaloMembers::rescan, kept with ::same (the
  // same entries in the same places, for neighbour lists that are reused). With them, each one's
  // fluid within its support plus half the skin (reach - 2 h_max of the fluid) is listed
  // (set.wallNeighbours) and the lists kept: the fluid moves less than half the skin while the
  // pair loop keeps its lists. A kept list sums its fluid in the order of the build, a new one
  // in the order of the cells now.
  void append(InteractionSet<D>& set, double reach, HaloMembers members) const;

  const std::vector<Vec<D>>& positions() const { return x_; }
  std::size_t size() const { return x_.size(); }
  // How far from a wall particle the fluid lies that it takes its state from (the support).
  double reach() const { return 2.0 * h_; }
  double volume(std::size_t w) const { return volume_.empty() ? V0_ : volume_[w]; }

 private:
  std::vector<Vec<D>> x_;
  std::vector<WallVelocityRule<D>> velocity_;  // empty: all at rest
  std::vector<double> volume_;                 // empty: all V0
  double V0_ = 0.0, h_;
  KernelKind kernel_;
  std::vector<Phase> phases_;
  Vec<D> g_;
  // Scratch between calls: the fluid entries in cells of the kernel support, on a grid fixed by
  // the wall particles alone (their box grown by the support), so that a wall particle sums its
  // fluid in the same order whatever part of the fluid a process holds (DomainDecomposition.hpp).
  mutable CellList<D> cells_;
  typename CellList<D>::Frame frame_;
  mutable std::array<std::vector<double>, D> sorted_;  // the entries' coordinates in cell order
  mutable CellList<D> fluidCells_;  // the fluid in cells, for choosing the wall particles in a set
  mutable std::vector<Vec<D>> cellLo_, cellHi_;  // each cell's box of its fluid, at its first place
  Vec<D> lo_, hi_;                               // the wall particles' box
  void choose(InteractionSet<D>& set, double reach) const;
  // The chosen wall particles' lists from the fluid in cells, then their state.
  void sumAndList(InteractionSet<D>& set, std::size_t base, double reach) const;
  // Their state, eqs. (22)-(28), from the fluid of their lists, into set entries base + q.
  void sumListed(InteractionSet<D>& set, std::size_t base) const;
  void frameTheWalls();
};

}  // namespace sph
