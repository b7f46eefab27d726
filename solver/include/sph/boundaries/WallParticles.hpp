#pragma once
// Walls of fixed particles whose state follows the fluid (Adami, Hu & Adams 2012; FixedWalls.hpp
// holds the equations): layers outside the box's wall faces, the surface layers of solid boxes
// inside the domain (obstacles), or any layout the caller gives (the packing tanks' sloping
// walls). The box's periodic faces keep their images (buildInteractionSet); wall faces of the
// box that are not made of particles keep their mirror ghosts.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "sph/FixedWalls.hpp"
#include "sph/boundaries/Boundary.hpp"

namespace sph {

// A solid box inside the domain; `exposed[a][side]`: whether that face meets fluid (a face on
// the domain's own face does not, and is no way out for a particle inside).
template <int D>
struct SolidBox {
  Vec<D> lower, upper;
  std::array<std::array<bool, 2>, D> exposed{};
};

// The wall particles' lattice and rules, appended to x, rule and volume.
template <int D>
struct WallLattice {
  std::vector<Vec<D>> x;
  std::vector<WallVelocityRule<D>> rule;
  std::vector<double> volume;
};
// `layers` layers of particles outside each wall face of `bounds`, on the lattice of spacing
// (extent / round(extent / dx)) per axis, that is the fluid lattice's where the box is a whole
// number of dx, centred (k + 1/2) spacings beyond the face; the corners between two wall faces
// filled, and the layers continued `layers` spacings past a periodic face (the images of the
// walls beyond it). Velocity rule: no slip if any face the particle lies beyond is no slip
// (reversing every component about that face's velocity), else free slip (reversing the normal
// components of the faces it lies beyond).
template <int D>
void layBoxWalls(const Boundaries<D>& bounds, double dx, int layers, WallLattice<D>& out);
// The particles of `box` within `layers` spacings of its faces (its inside needs none: no fluid
// reaches it), rule by `wall` (free or no slip) over the faces each lies within reach of; with
// `mirroredWalls` (the box's wall faces keep mirror ghosts) continued `layers` spacings beyond
// each such face it lies on, and imaged across periodic faces within `layers` dx of them.
template <int D>
void layObstacle(const SolidBox<D>& box, FaceKind wall, const Boundaries<D>& bounds,
                 bool mirroredWalls, double dx, int layers, WallLattice<D>& out);

template <int D>
class WallParticles final : public Boundary<D> {
 public:
  // `halo`: the faces buildInteractionSet images (periodic) or mirrors (walls not made of
  // particles; `ghost` their pressure rule); `walls`: the particles; `solids`: the boxes
  // they fill, for the checks; `name` the model's, `terms` what it adds to the run file's terms.
  WallParticles(const Boundaries<D>& halo, const GhostPressure<D>& ghost,
                std::shared_ptr<const FixedWalls<D>> walls, std::vector<SolidBox<D>> solids,
                std::string name, std::vector<std::string> terms);
  std::string_view name() const override { return name_; }
  void listTerms(std::vector<std::string>& terms) const override {
    terms.insert(terms.end(), terms_.begin(), terms_.end());
  }
  void build(const SetFluid<D>& fluid, const std::vector<Phase>& phases, double reach,
             HaloMembers members, InteractionSet<D>& set) const override;
  double fixedReach() const override { return walls_->reach(); }
  bool hasInnerSolids() const override { return !solids_.empty(); }
  void putBack(Particles<D>& state, double tolerated, long& count, double& deepest) const override;
  SolidCrossing firstInside(const Particles<D>& state) const override;

  const FixedWalls<D>& walls() const { return *walls_; }

 private:
  // The depth of r inside solid s (0 outside) and the exposed face nearest to it.
  double depthIn(const SolidBox<D>& s, const Vec<D>& r, int& axis, int& side) const;

  Boundaries<D> halo_;
  GhostPressure<D> ghost_;
  std::shared_ptr<const FixedWalls<D>> walls_;
  std::vector<SolidBox<D>> solids_;
  std::string name_;
  std::vector<std::string> terms_;
};

}  // namespace sph
