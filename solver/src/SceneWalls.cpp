#include "SceneWalls.hpp"

#include <cmath>
#include <string>

namespace sph {

std::string_view name(WallModel m) {
  switch (m) {
    case WallModel::mirror_ghosts:
      return "mirror_ghosts";
    case WallModel::wall_particles:
      return "wall_particles";
  }
  throw std::logic_error("name: WallModel " + std::to_string(static_cast<int>(m)) +
                         " is not a wall model this build knows");
}

namespace {

const char* axisName[3] = {"x", "y", "z"};

// The least number of layers that fills the support beyond a wall: a fluid particle half a
// spacing from the face (the lattice's first row) reaches 2 h - dx/2 beyond it, and L layers
// centred at (k + 1/2) dx cover L dx.
int leastLayers(const Scene& s) {
  return static_cast<int>(std::ceil(2.0 * s.hOverDx - 0.5 - 1e-9));
}

void readObstacle(SceneTable& t, Scene& s) {
  const int D = s.dimension;
  t.allow({"lower", "upper", "wall"});
  Obstacle o;
  o.lower = t.vector("lower", D);
  o.upper = t.vector("upper", D);
  for (int a = 0; a < D; ++a) {
    if (!(o.upper[a] - o.lower[a] >= s.dx))
      t.fail("upper", std::string("the obstacle must be at least dx thick along ") + axisName[a]);
    if (o.lower[a] < s.lower[a] - 1e-12 || o.upper[a] > s.upper[a] + 1e-12)
      t.fail(o.lower[a] < s.lower[a] - 1e-12 ? "lower" : "upper",
             std::string("the obstacle lies outside the domain along ") + axisName[a]);
  }
  const std::string wall = t.string("wall", "free_slip");
  if (wall == "free_slip")
    o.wall = FaceKind::free_slip;
  else if (wall == "no_slip")
    o.wall = FaceKind::no_slip;
  else
    t.fail("wall", "expected \"free_slip\" or \"no_slip\", got '" + wall + "'");
  t.rejectUnknown();
  // A fluid block inside an obstacle would start particles in the solid (bounding boxes: a
  // circle's box is refused even where only its corner meets the obstacle).
  for (std::size_t k = 0; k < s.fluids.size(); ++k) {
    const FluidBlock& b = s.fluids[k];
    bool apart = false;
    for (int a = 0; a < D; ++a) {
      const bool rect = b.shape == FluidBlock::Shape::rectangle;
      const double lo = rect ? b.lower[a] : b.center[a] - b.radius;
      const double hi = rect ? b.upper[a] : b.center[a] + b.radius;
      apart = apart || hi <= o.lower[a] || o.upper[a] <= lo;
    }
    if (!apart)
      t.fail("lower", "the obstacle overlaps fluid block " + std::to_string(k) + " (fluid[" +
                          std::to_string(k) + "])");
  }
  s.obstacles.push_back(o);
}

}  // namespace

void readWalls(SceneTable walls, std::vector<SceneTable> obstacles, SceneTable domain, Scene& s) {
  walls.allow({"model", "layers", "tensile"});
  const std::string model = walls.string("model", "mirror_ghosts");
  if (model == "mirror_ghosts")
    s.wallModel = WallModel::mirror_ghosts;
  else if (model == "wall_particles")
    s.wallModel = WallModel::wall_particles;
  else
    walls.fail("model", "expected \"mirror_ghosts\" or \"wall_particles\", got '" + model + "'");
  const int least = leastLayers(s);
  const long layers = walls.integer("layers", least);
  if (layers < least || layers > 64)
    walls.fail("layers", "expected a whole number from " + std::to_string(least) +
                             " (the layers that fill the kernel's support 2 h beyond a wall at "
                             "h/dx " +
                             SceneTable::fmt(s.hOverDx) + ") to 64, got " + std::to_string(layers));
  s.wallLayers = static_cast<int>(layers);
  const bool particles = s.wallModel == WallModel::wall_particles;
  s.tensileWalls = walls.boolean("tensile", !particles);
  if (particles && s.tensileWalls)
    walls.fail("tensile",
               "wall particles never pull the fluid (their pressure is not below p0, "
               "Adami et al. 2012 eq. 27 as solver/SCENES.md applies it): remove it or "
               "set [walls] model = \"mirror_ghosts\"");
  for (const Phase& ph : s.phases)
    if (!s.tensileWalls && ph.p0 != s.phases[0].p0)
      walls.fail("tensile",
                 "tensile = false holds the ghosts' pressure at p0, one for every phase: "
                 "phase '" +
                     ph.name + "' has p0 " + SceneTable::fmt(ph.p0) + ", phase '" +
                     s.phases[0].name + "' " + SceneTable::fmt(s.phases[0].p0));
  walls.rejectUnknown();
  if (particles && domain.has("ghost_pressure"))
    domain.fail("ghost_pressure",
                "a mirror-ghost setting; wall particles extrapolate the fluid's pressure (Adami "
                "et al. 2012, eq. 27): remove it or set [walls] model = \"mirror_ghosts\"");
  // Wall particles stand still: a no-slip face may slide along itself (Couette), not move
  // through its normal.
  for (int a = 0; particles && a < s.dimension; ++a)
    for (int side = 0; side < 2; ++side)
      if (s.faces[a][side] == FaceKind::no_slip && s.wallVelocity[a][side][a] != 0.0)
        domain.sub("wall_velocity")
            .fail(std::string(axisName[a]) + (side == 0 ? "_lower" : "_upper"),
                  "wall particles stand still: a wall velocity along the face's normal needs "
                  "[walls] model = \"mirror_ghosts\"");
  for (auto& t : obstacles) {
    readObstacle(t, s);
  }
}

}  // namespace sph
