#include <limits>
#include <memory>

#include "sph/Scene.hpp"
#include "sph/boundaries/Boundary.hpp"
#include "sph/boundaries/MirrorGhosts.hpp"
#include "sph/boundaries/WallParticles.hpp"

namespace sph {

template <int D>
std::unique_ptr<Boundary<D>> makeBoundary(const Scene& s, const Boundaries<D>& bounds) {
  Vec<D> g;
  for (int a = 0; a < D; ++a) g[a] = s.bodyAcceleration[a];
  // [walls] tensile = false: the ghosts' pressure not below p0, which the reader keeps one for
  // every phase.
  const GhostPressure<D> ghost(
      s.hydrostaticGhosts ? g : Vec<D>::Zero(),
      s.tensileWalls ? -std::numeric_limits<double>::infinity() : s.phases[0].p0);
  const bool particles = s.wallModel == WallModel::wall_particles;
  if (!particles && s.obstacles.empty()) return std::make_unique<MirrorGhosts<D>>(bounds, ghost);
  WallLattice<D> lattice;
  std::vector<std::string> terms;
  Boundaries<D> halo = bounds;  // the faces still imaged or mirrored
  if (particles) {
    layBoxWalls(bounds, s.dx, s.wallLayers, lattice);
    for (auto& axis : halo.face)
      for (FaceKind& k : axis)
        if (Boundaries<D>::isWall(k)) k = FaceKind::open;
    if (bounds.anyWall()) terms.push_back("wall_particles_adami2012");
  } else if (bounds.anyWall()) {
    terms.push_back("ghost_walls");
    if (!s.tensileWalls) terms.push_back("ghost_walls_not_tensile");
  }
  std::vector<SolidBox<D>> solids;
  for (const Obstacle& o : s.obstacles) {
    SolidBox<D> box;
    for (int a = 0; a < D; ++a) {
      box.lower[a] = o.lower[a], box.upper[a] = o.upper[a];
      // A face on the domain's own wall face meets no fluid (the scene's reader keeps obstacles
      // inside the domain; 1e-12 as it does); on a periodic face it meets the fluid beyond it.
      const bool periodic = bounds.face[a][0] == FaceKind::periodic;
      box.exposed[a] = {periodic || o.lower[a] > bounds.lower[a] + 1e-12,
                        periodic || o.upper[a] < bounds.upper[a] - 1e-12};
    }
    layObstacle(box, o.wall, bounds, !particles, s.dx, s.wallLayers, lattice);
    solids.push_back(box);
  }
  if (!solids.empty()) terms.push_back("obstacles_adami2012");
  // A wall particle takes the EOS (eq. 28) and viscosity of the phase beside it: FixedWalls.hpp.
  auto walls = std::make_shared<const FixedWalls<D>>(std::move(lattice.x), std::move(lattice.rule),
                                                     std::move(lattice.volume), s.h0(), s.kernel,
                                                     s.phases, g);
  return std::make_unique<WallParticles<D>>(
      halo, particles ? GhostPressure<D>(Vec<D>::Zero()) : ghost, std::move(walls),
      std::move(solids), std::string(name(s.wallModel)), std::move(terms));
}

template std::unique_ptr<Boundary<1>> makeBoundary<1>(const Scene&, const Boundaries<1>&);
template std::unique_ptr<Boundary<2>> makeBoundary<2>(const Scene&, const Boundaries<2>&);
template std::unique_ptr<Boundary<3>> makeBoundary<3>(const Scene&, const Boundaries<3>&);

}  // namespace sph
