#include "sph/boundaries/WallParticles.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "sph/Parallel.hpp"

namespace sph {

namespace {
// Points per axis: the extent in whole spacings of about dx, at least one.
int spacings(double extent, double dx) {
  return std::max(1, static_cast<int>(std::lround(extent / dx)));
}
}  // namespace

template <int D>
void layBoxWalls(const Boundaries<D>& b, double dx, int layers, WallLattice<D>& out) {
  std::array<int, D> n{}, first{}, last{};  // lattice index range [first, last) per axis
  std::array<double, D> d{};
  double volume = 1.0;
  auto continued = [](FaceKind k) { return Boundaries<D>::isWall(k) || k == FaceKind::periodic; };
  for (int a = 0; a < D; ++a) {
    const double extent = b.upper[a] - b.lower[a];
    n[a] = spacings(extent, dx), d[a] = extent / n[a], volume *= d[a];
    first[a] = continued(b.face[a][0]) ? -layers : 0;
    last[a] = n[a] + (continued(b.face[a][1]) ? layers : 0);
  }
  std::array<int, D> i = first;
  for (;;) {
    Vec<D> x;
    WallVelocityRule<D> rule;
    rule.atRest = false;
    bool beyondWall = false, noSlip = false;
    for (int a = 0; a < D; ++a) {
      x[a] = b.lower[a] + (i[a] + 0.5) * d[a];
      const int side = i[a] < 0 ? 0 : i[a] >= n[a] ? 1 : -1;
      if (side < 0 || !Boundaries<D>::isWall(b.face[a][side])) continue;
      beyondWall = true, rule.reversed[a] = 1.0;
      if (b.face[a][side] == FaceKind::no_slip && !noSlip)
        noSlip = true, rule.wallVelocity = b.wallVelocity[a][side];
    }
    if (beyondWall) {
      if (noSlip) rule.reversed = Vec<D>::Ones();
      out.x.push_back(x), out.rule.push_back(rule), out.volume.push_back(volume);
    }
    int a = 0;
    while (a < D && ++i[a] == last[a]) i[a] = first[a], ++a;
    if (a == D) break;
  }
}

template <int D>
void layObstacle(const SolidBox<D>& box, FaceKind wall, const Boundaries<D>& bounds,
                 bool mirroredWalls, double dx, int layers, WallLattice<D>& out) {
  std::array<int, D> n{}, first{}, last{};  // lattice index range [first, last) per axis
  std::array<double, D> d{};
  double volume = 1.0;
  for (int a = 0; a < D; ++a) {
    const double extent = box.upper[a] - box.lower[a];
    n[a] = spacings(extent, dx), d[a] = extent / n[a], volume *= d[a];
    // On a mirrored wall face the box goes on beyond it, as the fluid's ghosts do: without these
    // rows the fluid at the box's foot has an empty quarter of its support beyond the face, and
    // its pressure drives it there (water at rest over a step: 0.15 sqrt(gH), 12,593 wall
    // reflections, verification/flows/ObstacleTest.cpp).
    auto continued = [&](int side) {
      return mirroredWalls && !box.exposed[a][side] && Boundaries<D>::isWall(bounds.face[a][side]);
    };
    first[a] = continued(0) ? -layers : 0;
    last[a] = n[a] + (continued(1) ? layers : 0);
  }
  const std::size_t from = out.x.size();
  std::array<int, D> i = first;
  for (;;) {
    Vec<D> x;
    WallVelocityRule<D> rule;
    rule.atRest = false;
    bool surface = false;
    for (int a = 0; a < D; ++a) {
      x[a] = box.lower[a] + (i[a] + 0.5) * d[a];
      if (std::min(i[a], n[a] - 1 - i[a]) < layers) surface = true, rule.reversed[a] = 1.0;
    }
    if (surface) {
      if (wall == FaceKind::no_slip) rule.reversed = Vec<D>::Ones();
      out.x.push_back(x), out.rule.push_back(rule), out.volume.push_back(volume);
    }
    int a = 0;
    while (a < D && ++i[a] == last[a]) i[a] = first[a], ++a;
    if (a == D) break;
  }
  // Across a periodic face the fluid's images meet the box's images: those of its particles
  // within `layers` spacings of the face, a period away (axis by axis, so corners too).
  for (int a = 0; a < D; ++a) {
    if (bounds.face[a][0] != FaceKind::periodic) continue;
    const double period = bounds.upper[a] - bounds.lower[a], reach = layers * dx;
    for (std::size_t k = from, end = out.x.size(); k < end; ++k) {
      const double shift = out.x[k][a] - bounds.lower[a] < reach   ? period
                           : bounds.upper[a] - out.x[k][a] < reach ? -period
                                                                   : 0.0;
      if (shift == 0.0) continue;
      // (copies: a push_back may move the elements it would read)
      Vec<D> image = out.x[k];
      const WallVelocityRule<D> rule = out.rule[k];
      const double volume = out.volume[k];
      image[a] += shift;
      out.x.push_back(image), out.rule.push_back(rule), out.volume.push_back(volume);
    }
  }
}

template <int D>
WallParticles<D>::WallParticles(const Boundaries<D>& halo, const GhostPressure<D>& ghost,
                                std::shared_ptr<const FixedWalls<D>> walls,
                                std::vector<SolidBox<D>> solids, std::string name,
                                std::vector<std::string> terms)
    : halo_(halo),
      ghost_(ghost),
      walls_(std::move(walls)),
      solids_(std::move(solids)),
      name_(std::move(name)),
      terms_(std::move(terms)) {}

template <int D>
void WallParticles<D>::build(const SetFluid<D>& fluid, const std::vector<Phase>& phases,
                             double reach, HaloMembers members, InteractionSet<D>& set) const {
  buildInteractionSet(fluid, phases, halo_, reach, ghost_, set, members);
  walls_->append(set, reach, members);
}

template <int D>
double WallParticles<D>::depthIn(const SolidBox<D>& s, const Vec<D>& r, int& axis,
                                 int& side) const {
  for (int a = 0; a < D; ++a)
    if (!(r[a] > s.lower[a] && r[a] < s.upper[a])) return 0.0;
  double depth = std::numeric_limits<double>::max();
  for (int a = 0; a < D; ++a)
    for (int k = 0; k < 2; ++k) {
      if (!s.exposed[a][k]) continue;
      const double to = k == 0 ? r[a] - s.lower[a] : s.upper[a] - r[a];
      if (to < depth) depth = to, axis = a, side = k;
    }
  return depth;
}

template <int D>
void WallParticles<D>::putBack(Particles<D>& state, double tolerated, long& count,
                               double& deepest) const {
  const std::int64_t n = static_cast<std::int64_t>(state.size());
  long put = 0;
  double most = deepest;
#pragma omp parallel for schedule(static) if (n >= parallelFrom()) reduction(+ : put) \
    reduction(max : most)
  for (std::int64_t i = 0; i < n; ++i)
    for (const SolidBox<D>& s : solids_) {
      int axis = 0, side = 0;
      const double depth = depthIn(s, state.r[i], axis, side);
      if (depth <= 0 || depth > tolerated) continue;  // deeper: firstInside reports it
      const double face = side == 0 ? s.lower[axis] : s.upper[axis];
      state.r[i][axis] = 2.0 * face - state.r[i][axis];
      state.v[i][axis] = -state.v[i][axis];  // the solid is at rest
      ++put, most = std::max(most, depth);
    }
  count += put, deepest = most;
}

template <int D>
SolidCrossing WallParticles<D>::firstInside(const Particles<D>& state) const {
  for (std::size_t i = 0; i < state.size(); ++i)
    for (std::size_t k = 0; k < solids_.size(); ++k) {
      int axis = 0, side = 0;
      if (const double depth = depthIn(solids_[k], state.r[i], axis, side); depth > 0)
        return {static_cast<std::int64_t>(i), depth, "obstacle " + std::to_string(k)};
    }
  return {};
}

#define SPH_WALL_PARTICLES(D)                                                                    \
  template void layBoxWalls<D>(const Boundaries<D>&, double, int, WallLattice<D>&);              \
  template void layObstacle<D>(const SolidBox<D>&, FaceKind, const Boundaries<D>&, bool, double, \
                               int, WallLattice<D>&);                                            \
  template class WallParticles<D>;
SPH_WALL_PARTICLES(1)
SPH_WALL_PARTICLES(2)
SPH_WALL_PARTICLES(3)

}  // namespace sph
