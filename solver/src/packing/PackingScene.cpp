#include "sph/packing/PackingScene.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "../SceneReader.hpp"

namespace sph::packing {

namespace {

void readGeometry(SceneTable g, PackingScene& s) {
  g.allow({"start", "path", "surface", "length_scale"});
  Vec2 at = g.point("start");
  const Vec2 start = at;
  std::vector<SceneTable> path = g.array("path");
  if (path.size() < 1) g.fail("path", "missing: at least one [[geometry.path]] piece");
  double scale = 0.0;
  for (SceneTable& piece : path) {
    piece.allow({"to", "turn", "center"});
    const Vec2 to = piece.point("to");
    const std::string turn = piece.string("turn", "ccw");
    if (piece.has("center")) {
      const Vec2 c = piece.point("center");
      const double r0 = (at - c).norm(), r1 = (to - c).norm();
      if (!(r0 > 0.0)) piece.fail("center", "coincides with the arc's start point");
      if (std::abs(r0 - r1) > 1e-9 * r0)
        piece.fail("center", "is " + SceneTable::fmt(r0) + " from the start but " +
                                 SceneTable::fmt(r1) +
                                 " from 'to': not the centre of an arc through both");
      if (turn != "ccw" && turn != "cw") piece.fail("turn", "expected \"ccw\" or \"cw\"");
      s.container.push_back(arc(at, to, c, turn == "ccw"));
    } else {
      if (piece.has("turn")) piece.fail("turn", "only an arc (with 'center') has a turning sense");
      if ((to - at).norm() == 0.0)
        piece.fail("to", "repeats the previous point (a segment of zero length)");
      s.container.push_back(segment(at, to));
    }
    scale = std::max(scale, (to - start).norm());
    at = to;
    piece.rejectUnknown();
  }
  if ((at - start).norm() > 1e-9 * scale)
    g.fail("path", "does not close: the last 'to' must equal 'start'");
  s.container.back().b = start;
  s.hasSurface = g.has("surface");
  if (s.hasSurface) s.surface = g.number("surface");
  if (g.has("length_scale")) s.lengthScale = g.positive("length_scale");
  g.rejectUnknown();
}

// The lattice that latticeInside (Geometry.hpp) walks spans the container's bounding box (an
// arc's whole circle, an upper bound) in int indices from lattice_origin: the indices must fit
// an int, and the nodes the count the run scenes allow (RunBudget.cpp: half INT_MAX, the
// solver's particle indices). A dx of 1e-9 in a 1 m tank hung in that walk.
void checkLatticeSize(SceneTable& packing, const PackingScene& s) {
  Vec2 lo = s.container.front().a, hi = lo;
  for (const Piece& p : s.container)
    for (const Vec2& x : {p.a, p.b, p.arc ? Vec2((p.center.array() - p.radius).matrix()) : p.a,
                          p.arc ? Vec2((p.center.array() + p.radius).matrix()) : p.b})
      lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const double most = 0.5 * std::numeric_limits<int>::max();
  const Vec2 from = (lo - s.latticeOrigin) / s.dx, to = (hi - s.latticeOrigin) / s.dx;
  const double nodes = (to.x() - from.x() + 3.0) * (to.y() - from.y() + 3.0);
  if (!(from.cwiseAbs().maxCoeff() < most && to.cwiseAbs().maxCoeff() < most && nodes <= most))
    packing.fail("dx", "the container's bounding box holds " + SceneTable::fmt(nodes) +
                           " lattice nodes at dx = " + SceneTable::fmt(s.dx) +
                           " from lattice_origin, more than the solver can index (" +
                           SceneTable::fmt(most) + ")");
}

}  // namespace

PackingScene parsePackingScene(const std::string& text, const std::string& file) {
  PackingScene s;
  s.file = file, s.text = text;
  const toml::table root = parseSceneToml(text, file);
  SceneTable top(root, "", s.file);
  top.allow({"name", "description", "geometry", "fluid", "packing", "output"});
  s.name = top.name("name");
  s.description = top.string("description", "");
  readGeometry(top.sub("geometry"), s);

  SceneTable fluid = top.sub("fluid");
  const PhaseKeys phase{false, "water", 1000.0};  // no viscosity in the packing
  std::vector<std::string> fluidKeys = phase.keys();
  fluidKeys.push_back("gravity");
  fluid.allow(fluidKeys);
  s.phase = readPhase(fluid, phase);
  s.gravity = fluid.number("gravity", 9.81);
  if (s.gravity < 0.0)
    fluid.fail("gravity", "is the magnitude of g (acting along -y): must not be negative");
  fluid.rejectUnknown();

  SceneTable p = top.sub("packing");
  std::vector<std::string> packingKeys{"dx",  "lattice_origin", "kernel", "h_over_dx",
                                       "cfl", "pressure"};
  packingKeys.insert(packingKeys.end(), packingControlKeys.begin(), packingControlKeys.end());
  p.allow(packingKeys);
  PackingParameters& q = s.parameters;
  s.dx = readDx(p);
  s.latticeOrigin = p.point("lattice_origin", Vec2::Zero());
  checkLatticeSize(p, s);
  q.kernel = readKernel(p, KernelKind::wendland_c2);
  q.hOverDx = readHOverDx(p, 2.0);
  readPackingControls(p, q.alpha, q.maxIterations, q.stopKineticEnergy);
  q.cfl = p.positive("cfl", 1.0);
  if (q.cfl > 2.0)
    p.fail("cfl", "above 2 leapfrog is unstable for any oscillation it resolves; the paper uses 1");
  // beta = 2 p0 / rho0 (eq. 2.14) only sets the time unit: dt ~ 1/sqrt(beta) and zeta ~ sqrt(beta)
  // (eqs. 2.15, 2.17), so the iterates are the same for any beta. Default: beta = c0^2.
  const double packingPressure =
      p.positive("pressure", 0.5 * s.phase.rho0 * s.phase.c0 * s.phase.c0);
  q.beta = 2.0 * packingPressure / s.phase.rho0;
  p.rejectUnknown();

  SceneTable output = top.sub("output");
  output.allow({"history_every"});
  const long every = output.integer("history_every", 1);
  if (every < 1) output.fail("history_every", "must be a positive whole number");
  s.historyEvery = static_cast<int>(every);
  output.rejectUnknown();
  top.rejectUnknown();

  if (s.lengthScale == 0.0) {
    Region closed(s.container);
    Vec2 lo, hi;
    closed.bounds(lo, hi);
    s.lengthScale = (s.hasSurface ? std::min(s.surface, hi.y()) : hi.y()) - lo.y();
    if (!(s.lengthScale > 0.0))
      throw SceneError(file + ": key 'geometry.surface': lies below the container");
  }
  try {
    setUp(s);  // the geometry must give a region and particles
  } catch (const std::invalid_argument& e) {
    throw SceneError(file + ": key 'geometry': " + e.what());
  }
  return s;
}

PackingScene readPackingScene(const std::string& path) {
  return parsePackingScene(sceneText(path), path);
}

PackingSetup setUp(const PackingScene& s) {
  PackingSetup setup;
  setup.region = s.hasSurface ? belowSurface(s.container, s.surface) : Region(s.container);
  setup.fluid = latticeInside(setup.region, s.dx, s.latticeOrigin);
  if (setup.fluid.size() < 4)
    throw std::invalid_argument("the fluid region holds " + std::to_string(setup.fluid.size()) +
                                " lattice nodes at this dx; it needs at least 4");
  setup.V0 = setup.region.area() / static_cast<double>(setup.fluid.size());  // section 2
  // Solid layers to the kernel support lambda h (lambda = 2 for every kernel here).
  const int layers = static_cast<int>(std::ceil(2.0 * s.parameters.hOverDx - 1e-9));
  setup.solid = solidLayers(setup.region, s.dx, layers);
  setup.lengthScale = s.lengthScale;
  return setup;
}

}  // namespace sph::packing
