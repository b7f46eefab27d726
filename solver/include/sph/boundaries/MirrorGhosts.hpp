#pragma once
// The paper's walls: each box face that is a wall mirrors the fluid within reach of it into
// ghosts (Libersky et al. 1993; Colagrossi & Landrini 2003; Lobovsky & Kren 2008, section 2),
// and a periodic face images it; free slip reverses a ghost's normal velocity, no slip the whole
// velocity, about the wall's own (buildInteractionSet, InteractionSet.hpp, which holds the
// arithmetic and the ghost's pressure rule, GhostPressure).
#include <limits>

#include "sph/boundaries/Boundary.hpp"

namespace sph {

template <int D>
class MirrorGhosts final : public Boundary<D> {
 public:
  MirrorGhosts(const Boundaries<D>& bounds, const GhostPressure<D>& ghost)
      : bounds_(bounds), ghost_(ghost) {}
  std::string_view name() const override { return "mirror_ghosts"; }
  void listTerms(std::vector<std::string>& terms) const override {
    if (bounds_.anyWall()) terms.push_back("ghost_walls");
    if (bounds_.anyWall() && ghost_.floor > -std::numeric_limits<double>::infinity())
      terms.push_back("ghost_walls_not_tensile");
  }
  void build(const SetFluid<D>& fluid, const std::vector<Phase>& phases, double reach,
             HaloMembers members, InteractionSet<D>& set) const override {
    buildInteractionSet(fluid, phases, bounds_, reach, ghost_, set, members);
  }

 private:
  Boundaries<D> bounds_;
  GhostPressure<D> ghost_;
};

}  // namespace sph
