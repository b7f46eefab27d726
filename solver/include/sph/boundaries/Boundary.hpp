#pragma once
// A boundary model: what the fluid interacts with besides itself, built into the interaction set
// before every force evaluation, and what it adds to the checks of a new state. The pair loop
// sees only entries (InteractionSet.hpp): a boundary costs nothing per pair, and its one virtual
// call a force evaluation is nothing beside the set's build.
//   MirrorGhosts (MirrorGhosts.hpp): the paper's ghost walls, mirrored across the box's faces.
//   WallParticles (WallParticles.hpp): fixed wall particles (Adami et al. 2012) outside the box's
//   wall faces, on an obstacle's surface, or along any wall the caller lays out.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "sph/Boundaries.hpp"
#include "sph/InteractionSet.hpp"
#include "sph/Particles.hpp"

namespace sph {

struct Scene;

// A fluid particle inside a solid of the boundary, other than beyond the box's faces (which
// Simulation checks itself).
struct SolidCrossing {
  std::int64_t particle = -1;  // the first by index; -1: none
  double depth = 0.0;          // how far inside [m]
  std::string solid;           // e.g. "obstacle 0", for the failure's message
};

template <int D>
class Boundary {
 public:
  virtual ~Boundary() = default;
  // The model's name, the run file's boundary_model attribute.
  virtual std::string_view name() const = 0;
  // The names it adds to the run file's list of terms (e.g. "ghost_walls").
  virtual void listTerms(std::vector<std::string>& terms) const = 0;
  // Fills `set` from `fluid`: the fluid entries (pressure from the phase's EOS), the halo of the
  // box's faces within `reach`, then any fixed particles. HaloMembers::same as in
  // buildInteractionSet.
  virtual void build(const SetFluid<D>& fluid, const std::vector<Phase>& phases, double reach,
                     HaloMembers members, InteractionSet<D>& set) const = 0;
  // How far from a fixed particle the fluid lies that it takes its state from (0: no fixed
  // particles): a process holding part of the fluid needs that much more of the rest.
  virtual double fixedReach() const { return 0.0; }
  // Solids inside the domain (obstacles): a fluid particle in one has crossed a wall. False:
  // the two calls below are never made.
  virtual bool hasInnerSolids() const { return false; }
  // Puts back each fluid particle at most `tolerated` inside such a solid (mirrored across the
  // nearest face, its normal velocity reversed); counts them and the deepest.
  virtual void putBack(Particles<D>& /*state*/, double /*tolerated*/, long& /*count*/,
                       double& /*deepest*/) const {}
  // The first fluid particle inside such a solid.
  virtual SolidCrossing firstInside(const Particles<D>& /*state*/) const { return {}; }
};

// The scene's boundary: its [walls] model over the box `bounds`, and its obstacles.
template <int D>
std::unique_ptr<Boundary<D>> makeBoundary(const Scene& scene, const Boundaries<D>& bounds);

}  // namespace sph
