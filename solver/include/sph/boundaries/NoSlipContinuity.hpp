#pragma once
// The continuity equation against no-slip mirror ghosts. A no-slip ghost carries 2 v_wall - v of
// its fluid particle in every component, which the viscous terms need (the shear across the
// wall), and the pair loop has one velocity an entry. In the continuity equation (eq. 11) the
// tangential part is wrong: along the wall the ghosts' tangential velocity then varies against the
// fluid's (d u_g / dx = -d u / dx), so the ghosts add about -2 du/dx to the density rate of the
// particles beside the wall, where the fluid has no divergence. A lid-driven cavity at Re 100 was
// stopped at t = 2.5 s by it (the fluid's volume +6.9 %, particles gathered on the wall line).
// Free slip has no such term: its ghost keeps the tangential velocity, so the ghosts' field has
// the fluid's divergence. Adami et al. (2012) give their wall particles the wall's own velocity in
// the continuity equation for the same reason. Here the continuity equation takes each no-slip
// ghost with its free-slip velocity (the normal component reversed about the wall's, across every
// wall face the ghost lies beyond); the viscous terms keep the no-slip one. The loop has added
// m_g (v_i - v_g) . grad_i W_ig; this pass adds m_g (v_g - v_g^free) . grad_i W_ig for each such
// pair (rho_i V_g in place of m_g with the continuity equation by volume), at h_ij as the loop,
// and to dh/dt (eq. 13, variable h) h_i / D V_g (v_g - v_g^free) . grad_i W_ig.
// Scenes without a no-slip mirrored face skip it (their rates are the loop's, to the bit).
#include "sph/Boundaries.hpp"
#include "sph/ForceEvaluation.hpp"
#include "sph/InteractionSet.hpp"
#include "sph/Kernels.hpp"

namespace sph {

// Adds the correction to out.drhodt for the fluid entries whose rates out holds (every fluid
// entry, or over several processes the owned ones, InteractionSet::ownedParticle).
template <int D>
void noSlipGhostContinuity(const InteractionSet<D>& set, const Boundaries<D>& bounds,
                           KernelKind kernel, bool byVolume, bool variableH, Derivatives<D>& out);

}  // namespace sph
