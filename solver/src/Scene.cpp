#include "sph/Scene.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "SceneReader.hpp"
#include "SceneWalls.hpp"

namespace sph {

std::string_view name(KernelKind k) {
  switch (k) {
    case KernelKind::quadratic:
      return "quadratic";
    case KernelKind::cubic_spline:
      return "cubic_spline";
    case KernelKind::wendland_c2:
      return "wendland_c2";
  }
  // No default: -Wswitch names an enumerator missing above; any other value is a bug.
  throw std::logic_error("name: KernelKind " + std::to_string(static_cast<int>(k)) +
                         " is not a kernel this build knows");
}

std::string_view name(TimeIntegrator i) {
  switch (i) {
    case TimeIntegrator::predictor_corrector:
      return "predictor_corrector";
    case TimeIntegrator::position_verlet:
      return "position_verlet";
    case TimeIntegrator::velocity_verlet:
      return "velocity_verlet";
  }
  throw std::logic_error("name: TimeIntegrator " + std::to_string(static_cast<int>(i)) +
                         " is not an integrator this build knows");
}

std::string_view name(FaceKind k) {
  switch (k) {
    case FaceKind::open:
      return "open";
    case FaceKind::free_slip:
      return "free_slip";
    case FaceKind::no_slip:
      return "no_slip";
    case FaceKind::periodic:
      return "periodic";
  }
  throw std::logic_error("name: FaceKind " + std::to_string(static_cast<int>(k)) +
                         " is not a face this build knows");
}

namespace {

const char* axisName[3] = {"x", "y", "z"};

FaceKind faceKind(SceneTable& t, const std::string& key, const std::string& value) {
  if (value == "open") return FaceKind::open;
  if (value == "free_slip") return FaceKind::free_slip;
  if (value == "no_slip") return FaceKind::no_slip;
  if (value == "periodic") return FaceKind::periodic;
  t.fail(key, "unknown boundary '" + value + "' (expected open, free_slip, no_slip or periodic)");
}

void readDomain(SceneTable domain, Scene& s) {
  const int D = s.dimension;
  std::vector<std::string> keys{"lower", "upper", "ghost_pressure", "wall_velocity", "leaving"},
      faces;
  for (int a = 0; a < D; ++a)
    for (const char* side : {"_lower", "_upper"}) faces.push_back(axisName[a] + std::string(side));
  keys.insert(keys.end(), faces.begin(), faces.end());
  domain.allow(keys);
  s.lower = domain.vector("lower", D);
  s.upper = domain.vector("upper", D);
  for (int a = 0; a < D; ++a)
    if (!(s.upper[a] > s.lower[a]))
      domain.fail("upper", std::string("must exceed 'lower' along ") + axisName[a]);
  SceneTable velocity = domain.sub("wall_velocity");
  velocity.allow(faces);
  for (int a = 0; a < D; ++a) {
    const std::string axis = axisName[a];
    std::vector<std::string> kinds(2);
    kinds[0] = domain.string(axis + "_lower", "open");
    kinds[1] = domain.string(axis + "_upper", "open");
    for (int side = 0; side < 2; ++side) {
      const std::string key = axis + (side == 0 ? "_lower" : "_upper");
      s.faces[a][side] = faceKind(domain, key, kinds[side]);
      s.wallVelocity[a][side] = velocity.vector(key, D, std::vector<double>(D, 0.0));
      if (s.faces[a][side] != FaceKind::no_slip && velocity.has(key))
        velocity.fail(key, "a wall velocity needs a no_slip face");
    }
    if ((s.faces[a][0] == FaceKind::periodic) != (s.faces[a][1] == FaceKind::periodic))
      domain.fail(axis + "_lower", "periodic must be set on both faces of an axis");
  }
  const std::string ghost = domain.string("ghost_pressure", "mirror");
  if (ghost != "mirror" && ghost != "hydrostatic")
    domain.fail("ghost_pressure", "expected \"mirror\" or \"hydrostatic\", got '" + ghost + "'");
  s.hydrostaticGhosts = ghost == "hydrostatic";
  const std::string leaving = domain.string("leaving", "fail");
  if (leaving != "fail" && leaving != "remove")
    domain.fail("leaving", "expected \"fail\" or \"remove\", got '" + leaving + "'");
  s.leaving = leaving == "remove" ? Scene::Leaving::removed : Scene::Leaving::fails;
  bool anyOpen = false;
  for (int a = 0; a < D; ++a)
    anyOpen |= s.faces[a][0] == FaceKind::open || s.faces[a][1] == FaceKind::open;
  if (s.leaving == Scene::Leaving::removed && !anyOpen)
    domain.fail("leaving",
                "\"remove\" needs an open face to leave through; every face is a wall or periodic");
  velocity.rejectUnknown();
  domain.rejectUnknown();
}

void readPhases(std::vector<SceneTable> phases, Scene& s, SceneTable& top) {
  if (phases.empty()) top.fail("phase", "missing: at least one [[phase]] table");
  std::set<std::string> names;
  const PhaseKeys keys;  // viscous, no default name or rho0
  for (auto& t : phases) {
    t.allow(keys.keys());
    const Phase p = readPhase(t, keys);
    if (!names.insert(p.name).second) t.fail("name", "phase '" + p.name + "' defined twice");
    t.rejectUnknown();
    s.phases.push_back(p);
  }
}

int phaseIndex(SceneTable& t, const Scene& s) {
  const std::string name =
      t.string("phase", s.phases.size() == 1 ? s.phases[0].name : std::string());
  for (std::size_t i = 0; i < s.phases.size(); ++i)
    if (s.phases[i].name == name) return static_cast<int>(i);
  t.fail("phase", "no [[phase]] named '" + name + "'");
}

std::string fmtRange(double lo, double hi) {
  std::ostringstream m;
  m << "[" << lo << ", " << hi << "]";
  return m.str();
}

// Bounding box of a block, for the inside-the-walls and overlap checks.
void bounds(const FluidBlock& b, int D, std::vector<double>& lo, std::vector<double>& hi) {
  lo.resize(D), hi.resize(D);
  for (int a = 0; a < D; ++a) {
    lo[a] = b.shape == FluidBlock::Shape::rectangle ? b.lower[a] : b.center[a] - b.radius;
    hi[a] = b.shape == FluidBlock::Shape::rectangle ? b.upper[a] : b.center[a] + b.radius;
  }
}

bool overlap(const FluidBlock& a, const FluidBlock& b, int D) {
  using S = FluidBlock::Shape;
  if (a.shape == S::circle && b.shape == S::circle) {
    double d2 = 0;
    for (int k = 0; k < D; ++k) d2 += std::pow(a.center[k] - b.center[k], 2);
    return std::sqrt(d2) < a.radius + b.radius;
  }
  if (a.shape == S::circle || b.shape == S::circle) {
    const FluidBlock& c = a.shape == S::circle ? a : b;
    const FluidBlock& r = a.shape == S::circle ? b : a;
    double d2 = 0;  // distance from the centre to the rectangle
    for (int k = 0; k < D; ++k) {
      const double q = std::clamp(c.center[k], r.lower[k], r.upper[k]);
      d2 += std::pow(c.center[k] - q, 2);
    }
    return std::sqrt(d2) < c.radius;
  }
  for (int k = 0; k < D; ++k)  // touching faces are allowed (two fluids side by side)
    if (a.upper[k] <= b.lower[k] || b.upper[k] <= a.lower[k]) return false;
  return true;
}

// initial_pressure = "stretching" solves -grad p / rho0 = G G (x - c): a pressure exists only
// when G G is symmetric (curl-free right-hand side). Round-off allowance: 1e-12 of |G|^2.
void checkStretchingPressure(SceneTable& t, const std::vector<double>& G, int D) {
  double scale = 0.0, asym = 0.0;
  for (double g : G) scale += g * g;
  auto GG = [&](int r, int c) {
    double v = 0.0;
    for (int k = 0; k < D; ++k) v += G[r * D + k] * G[k * D + c];
    return v;
  };
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) asym = std::max(asym, std::abs(GG(r, c) - GG(c, r)));
  if (asym > 1e-12 * scale)
    t.fail("velocity_gradient",
           "G G is not symmetric, so no pressure gives -grad p / rho0 = G G (x - c), as "
           "initial_pressure = \"stretching\" needs (asymmetry " +
               std::to_string(asym) + ")");
}

void readFluids(std::vector<SceneTable> fluids, Scene& s, SceneTable& top) {
  const int D = s.dimension;
  if (fluids.empty()) top.fail("fluid", "missing: at least one [[fluid]] block");
  for (auto& t : fluids) {
    FluidBlock b;
    t.allow({"shape", "lower", "upper", "center", "radius", "phase", "velocity",
             "velocity_gradient", "initial_pressure", "surface", "initial", "packing"});
    const std::string shape = t.string("shape", "rectangle");
    if (shape == "rectangle") {
      b.lower = t.vector("lower", D);
      b.upper = t.vector("upper", D);
      for (int a = 0; a < D; ++a)
        if (!(b.upper[a] > b.lower[a])) t.fail("upper", "must exceed 'lower' in every axis");
    } else if (shape == "circle") {
      b.shape = FluidBlock::Shape::circle;
      b.center = t.vector("center", D);
      b.radius = t.positive("radius");
    } else {
      t.fail("shape", "unknown shape '" + shape + "' (expected rectangle or circle)");
    }
    b.phase = phaseIndex(t, s);
    b.velocity = t.vector("velocity", D, std::vector<double>(D, 0.0));
    std::vector<double> lo, hi;
    bounds(b, D, lo, hi);
    if (t.has("velocity_gradient")) {
      b.velocityGradient = t.matrix("velocity_gradient", D);
      b.gradientCenter.resize(D);
      for (int a = 0; a < D; ++a) b.gradientCenter[a] = 0.5 * (lo[a] + hi[a]);
    }
    const std::string pressure = t.string("initial_pressure", "zero");
    if (pressure == "hydrostatic") {
      b.hydrostatic = true;
    } else if (pressure == "stretching") {
      b.stretching = true;
      if (b.velocityGradient.empty())
        t.fail("initial_pressure",
               "\"stretching\" is the pressure of a linear velocity field: "
               "it needs 'velocity_gradient'");
      checkStretchingPressure(t, b.velocityGradient, D);
    } else if (pressure != "zero") {
      t.fail("initial_pressure",
             "expected \"zero\", \"hydrostatic\" or \"stretching\", got '" + pressure + "'");
    }
    const std::string start = t.string("initial", "lattice");
    if (start == "packed") {
      b.packed = true;
      if (D == 1) t.fail("initial", "\"packed\" (Colagrossi et al. 2012 packing) needs 2-D or 3-D");
    } else if (start != "lattice") {
      t.fail("initial", "expected \"lattice\" or \"packed\", got '" + start + "'");
    }
    if (t.has("packing")) {
      SceneTable pk = t.sub("packing");
      std::vector<std::string> keys = packingControlKeys;
      keys.push_back("noise");
      pk.allow(keys);
      if (!b.packed) t.fail("packing", "packing parameters need initial = \"packed\"");
      readPackingControls(pk, b.packingAlpha, b.packingMaxIterations, b.packingStop);
      b.packingNoise = pk.nonNegative("noise", 0.0);
      // Below dx/2 every start stays inside its lattice cell, so inside the block.
      if (b.packingNoise >= 0.5) pk.fail("noise", "must be below 0.5 (a fraction of dx)");
      pk.rejectUnknown();
    }
    // (the default, the block's highest point, waits for the gravity: readScene below)
    b.surface = t.number("surface", std::numeric_limits<double>::quiet_NaN());
    for (int a = 0; a < D; ++a) {
      const bool below = lo[a] < s.lower[a] - 1e-12;
      const bool above = hi[a] > s.upper[a] + 1e-12;
      if (!below && !above) continue;
      // Name the key that puts the block out: its centre, or the corner on the offending side.
      const char* key = shape == "circle" ? "center" : below ? "lower" : "upper";
      t.fail(key, std::string("the fluid block lies outside the domain along ") + axisName[a] +
                      " (block " + fmtRange(lo[a], hi[a]) + ", domain " +
                      fmtRange(s.lower[a], s.upper[a]) + ")");
    }
    t.rejectUnknown();
    for (std::size_t k = 0; k < s.fluids.size(); ++k)
      if (overlap(b, s.fluids[k], D))
        t.fail(b.shape == FluidBlock::Shape::circle ? "center" : "lower",
               "this block overlaps fluid block " + std::to_string(k) + " (fluid[" +
                   std::to_string(k) + "])");
    s.fluids.push_back(b);
  }
}

TimeIntegrator integratorKind(SceneTable& t, const std::string& v) {
  for (TimeIntegrator i : {TimeIntegrator::predictor_corrector, TimeIntegrator::position_verlet,
                           TimeIntegrator::velocity_verlet})
    if (v == name(i)) return i;
  t.fail("integrator", "unknown integrator '" + v +
                           "' (expected predictor_corrector, position_verlet or velocity_verlet)");
}

// physics.density_diffusion (delta) and its form. Both forms diffuse density differences, and
// across a phase interface the density jumps by the phases' rho0: with several phases Fourtakas
// et al.'s form diffuses within each phase (terms/DensityDiffusionFourtakasPhases.hpp), which
// takes each phase's K from its rho0 and the phases' one c0 and gamma; Molteni & Colagrossi's
// takes one phase. Fourtakas et al.'s hydrostatic difference takes the secant of x^gamma, a sum
// of gamma powers, so gamma must be a whole number.
void readDensityDiffusion(SceneTable& physics, Scene& s) {
  s.diffusionDelta = physics.nonNegative("density_diffusion", 0.0);
  const std::string form = physics.string("density_diffusion_form", "molteni_colagrossi");
  DensityDiffusion chosen = DensityDiffusion::molteniColagrossi;
  if (form == "molteni_colagrossi")
    chosen = DensityDiffusion::molteniColagrossi;
  else if (form == "fourtakas")
    chosen = DensityDiffusion::fourtakas;
  else if (form == "antuono")
    chosen = DensityDiffusion::antuono;
  else
    physics.fail("density_diffusion_form", "unknown form '" + form +
                                               "' (expected molteni_colagrossi, fourtakas or "
                                               "antuono)");
  s.terms.densityDiffusion = s.diffusionDelta > 0.0 ? chosen : DensityDiffusion::none;
  if (s.terms.densityDiffusion == DensityDiffusion::none) return;
  const Phase& first = s.phases[0];
  if (s.phases.size() > 1) {
    if (chosen != DensityDiffusion::fourtakas)
      physics.fail("density_diffusion",
                   "\"" + form +
                       "\" diffuses the density jump at a phase interface; the scene has " +
                       std::to_string(s.phases.size()) +
                       " phases: density_diffusion_form = \"fourtakas\" diffuses within each");
    for (const Phase& p : s.phases)
      if (p.c0 != first.c0 || p.gamma != first.gamma)
        physics.fail(
            "density_diffusion",
            "with several phases the density diffusion takes one c0 and gamma, and phase '" +
                p.name + "' has c0 " + SceneTable::fmt(p.c0) + ", gamma " +
                SceneTable::fmt(p.gamma) + " against '" + first.name + "''s " +
                SceneTable::fmt(first.c0) + ", " + SceneTable::fmt(first.gamma));
    s.terms.densityDiffusion = DensityDiffusion::fourtakasPhases;
  }
  const double gamma = first.gamma;
  if (chosen == DensityDiffusion::fourtakas &&
      (gamma != std::floor(gamma) || gamma < 1.0 || gamma > 15.0))
    physics.fail("density_diffusion_form",
                 "\"fourtakas\" needs the phase's gamma a whole number from 1 to 15 (its "
                 "hydrostatic density difference sums gamma powers), got " +
                     SceneTable::fmt(gamma));
}

// physics.shifting (ParticleShifting.hpp): the form, its coefficient A, the surface threshold and
// the steps from one shift to the next.
void readShifting(SceneTable& physics, Scene& s) {
  const std::string form = physics.string("shifting", "none");
  ShiftingParameters& p = s.shifting;
  p.form = ShiftingForm::none;
  for (ShiftingForm f : {ShiftingForm::none, ShiftingForm::lind, ShiftingForm::delta_plus})
    if (form == name(f)) p.form = f;
  if (form != name(p.form))
    physics.fail("shifting", "unknown shifting '" + form + "' (expected none, lind or delta_plus)");
  if (p.form == ShiftingForm::none) {
    for (const char* key : {"shifting_coefficient", "shifting_surface_threshold", "shifting_every"})
      if (physics.has(key)) physics.fail(key, "is set, but shifting is \"none\"");
    return;
  }
  p.coefficient = physics.positive("shifting_coefficient", defaultShiftingCoefficient(p.form));
  p.surfaceThreshold =
      physics.positive("shifting_surface_threshold", defaultSurfaceThreshold(s.dimension));
  if (p.surfaceThreshold >= s.dimension)
    physics.fail("shifting_surface_threshold",
                 "must lie below the interior's div r = " + std::to_string(s.dimension) + ", got " +
                     SceneTable::fmt(p.surfaceThreshold));
  const long every = physics.integer("shifting_every", 1);
  if (every < 1) physics.fail("shifting_every", "must be a positive whole number of steps");
  p.every = static_cast<int>(every);
}

// The domain as "[l0, u0] x [l1, u1]".
std::string fmtBox(const Scene& s) {
  std::string out;
  for (int a = 0; a < s.dimension; ++a) out += (a ? " x " : "") + fmtRange(s.lower[a], s.upper[a]);
  return out;
}

// A probe must look inside the domain: a pressure probe outside has no particle near it and
// records 0 Pa for the whole run, a gauge beyond the walls an empty column. A point probe gives
// D coordinates, a water_height line the D - 1 horizontal ones, a gauge its x.
void checkProbeInside(SceneTable& t, const Probe& p, const Scene& s) {
  const bool point = !p.position.empty();
  bool inside = true;
  std::ostringstream at;
  if (point) {
    at << "(";
    for (std::size_t a = 0; a < p.position.size(); ++a) {
      inside = inside && p.position[a] >= s.lower[a] && p.position[a] <= s.upper[a];
      at << (a ? ", " : "") << p.position[a];
    }
    at << ")";
  } else {
    inside = p.x >= s.lower[0] && p.x <= s.upper[0];
    at << "x = " << p.x;
  }
  if (!inside)
    t.fail(point ? "position" : "x",
           "probe '" + p.name + "' at " + at.str() + " lies outside the domain " + fmtBox(s));
}

// A wall_pressure probe reads the fluid at a solid face (Diagnostics.hpp): the point must lie on
// a wall face of the domain (free or no slip) or on a face of an obstacle, to 1e-9 of dx. With a
// periodic face its sum would miss the images across it: refused.
void checkOnSolidFace(SceneTable& t, const Probe& p, const Scene& s) {
  const int D = s.dimension;
  const double tol = 1e-9 * s.dx;
  for (int a = 0; a < D; ++a)
    if (s.faces[a][0] == FaceKind::periodic)
      t.fail("type",
             "a wall_pressure probe sums the fluid only, not its periodic images: the "
             "scene's " +
                 std::string(axisName[a]) + " faces are periodic");
  const auto& x = p.position;
  bool on = false;
  for (int a = 0; a < D && !on; ++a)
    for (int side = 0; side < 2 && !on; ++side)
      on = Boundaries<3>::isWall(s.faces[a][side]) &&
           std::abs(x[a] - (side ? s.upper[a] : s.lower[a])) <= tol;
  for (const Obstacle& o : s.obstacles) {
    bool within = true;  // inside the box or on its surface
    for (int a = 0; a < D; ++a)
      within = within && x[a] >= o.lower[a] - tol && x[a] <= o.upper[a] + tol;
    for (int a = 0; a < D && within && !on; ++a)
      on = std::abs(x[a] - o.lower[a]) <= tol || std::abs(x[a] - o.upper[a]) <= tol;
  }
  if (!on)
    t.fail("position", "wall_pressure probe '" + p.name +
                           "' must lie on a wall face of the domain (free_slip or no_slip) or on "
                           "a face of an [[obstacle]]");
}

void readProbes(std::vector<SceneTable> probes, Scene& s) {
  std::set<std::string> names;
  for (auto& t : probes) {
    Probe p;
    t.allow({"name", "type", "position", "x", "reference", "scale_length", "scale_height"});
    p.name = t.name("name");
    if (!names.insert(p.name).second) t.fail("name", "probe '" + p.name + "' defined twice");
    p.type = t.string("type");
    if (p.type == "pressure" || p.type == "wall_pressure") {
      p.position = t.vector("position", s.dimension);
      checkProbeInside(t, p, s);
      if (p.type == "wall_pressure") checkOnSolidFace(t, p, s);
    } else if (p.type == "water_height") {
      if (s.dimension < 2) t.fail("type", "a water_height probe needs dimension 2 or 3");
      p.position = t.vector("position", s.dimension - 1);
      checkProbeInside(t, p, s);
    } else if (p.type == "water_level" || p.type == "column_height") {
      p.x = t.number("x");
      checkProbeInside(t, p, s);
    } else if (p.type != "surge_front") {
      t.fail("type", "unknown probe type '" + p.type +
                         "' (expected surge_front, column_height, pressure, water_level, "
                         "wall_pressure or water_height)");
    }
    p.reference = t.string("reference", "");
    p.scaleLength = t.nonNegative("scale_length", 0.0);
    p.scaleHeight = t.nonNegative("scale_height", 0.0);
    t.rejectUnknown();
    s.probes.push_back(p);
  }
}

// Mach number check (Lobovsky & Kren, below eq. 8): c0 >= 10 max|v| keeps density variations
// near 1 %. The expected speed is the larger of the initial speeds and the free-fall speed
// sqrt(2 g H) over the fluid's height.
void warnOnLowSoundSpeed(Scene& s) {
  const int D = s.dimension;
  double g = 0;
  for (double c : s.bodyAcceleration) g += c * c;
  g = std::sqrt(g);
  double top = -1e300, bottom = 1e300, vmax = 0;
  for (const auto& b : s.fluids) {
    std::vector<double> lo, hi;
    bounds(b, D, lo, hi);
    top = std::max(top, hi[D - 1]);
    bottom = std::min(bottom, s.lower[D - 1]);
    double v2 = 0;
    for (double c : b.velocity) v2 += c * c;
    // A linear field adds at most |G|_2 times the largest distance from its centre.
    double spread = 0.0;
    if (!b.velocityGradient.empty()) {
      const Eigen::Map<const Eigen::MatrixXd> G(b.velocityGradient.data(), D, D);
      double reach2 = 0.0;
      for (int a = 0; a < D; ++a) reach2 += 0.25 * (hi[a] - lo[a]) * (hi[a] - lo[a]);
      if (b.shape == FluidBlock::Shape::circle) reach2 = b.radius * b.radius;
      spread = Eigen::JacobiSVD<Eigen::MatrixXd>(G).singularValues()(0) * std::sqrt(reach2);
    }
    vmax = std::max(vmax, std::sqrt(v2) + spread);
  }
  const double expected = std::max(vmax, std::sqrt(2 * g * (top - bottom)));
  for (const auto& p : s.phases)
    if (p.c0 < 10 * expected) {
      std::ostringstream m;
      m << s.file << ": warning: phase '" << p.name << "' has c0 = " << p.c0
        << " m/s, below 10x the expected max speed " << expected << " m/s (Mach > 0.1)";
      s.warnings.push_back(m.str());
    }
}

// A block that holds no lattice node at dx (InitialParticles.hpp) is no fluid: a rectangle
// thinner than dx/2 along an axis (round(width/dx) = 0), or a circle of fewer than one node across
// (round(2r/dx) = 0), or of two whose nodes at dx/2 from the centre along every axis lie outside
// it (r <= sqrt(D) dx/2; an odd count has the centre's node, four and more the ones at
// sqrt(D) dx/2).
void checkBlocksHoldParticles(const Scene& s) {
  const int D = s.dimension;
  for (std::size_t k = 0; k < s.fluids.size(); ++k) {
    const FluidBlock& b = s.fluids[k];
    const std::string block = "fluid[" + std::to_string(k) + "]";
    std::ostringstream m;
    m << s.file << ": key '" << block;
    if (b.shape == FluidBlock::Shape::rectangle) {
      for (int a = 0; a < D; ++a)
        if ((b.upper[a] - b.lower[a]) / s.dx < 0.5) {
          m << ".upper': the block is " << b.upper[a] - b.lower[a] << " m across along "
            << axisName[a] << ", less than dx/2 = " << 0.5 * s.dx
            << " m (numerics.dx): it would hold no particle";
          throw SceneError(m.str());
        }
      continue;
    }
    const double across = 2.0 * b.radius / s.dx;
    if (across < 0.5 || (across < 2.5 && across >= 1.5 && b.radius <= 0.5 * std::sqrt(D) * s.dx)) {
      m << ".radius': a circle of radius " << b.radius
        << " m holds no lattice node at dx = " << s.dx << " m (numerics.dx)";
      throw SceneError(m.str());
    }
  }
}

}  // namespace

Scene parseScene(const std::string& text, const std::string& file) {
  const toml::table root = parseSceneToml(text, file);
  Scene s;
  s.file = file;
  s.text = text;
  SceneTable top(root, "", s.file);
  top.allow({"name", "description", "dimension", "domain", "phase", "fluid", "physics", "numerics",
             "output", "probe", "walls", "obstacle"});
  s.name = top.name("name");
  top.string("description", "");
  const double dimension = top.number("dimension");  // 2.5 must not pass as 2
  if (dimension != 1 && dimension != 2 && dimension != 3)
    top.fail("dimension", "must be 1, 2 or 3, got " + std::to_string(dimension));
  s.dimension = static_cast<int>(dimension);
  const int D = s.dimension;
  readDomain(top.sub("domain"), s);
  readPhases(top.array("phase"), s, top);
  readFluids(top.array("fluid"), s, top);

  SceneTable physics = top.sub("physics");
  physics.allow({"gravity", "body_force", "artificial_viscosity", "morris_viscosity", "variable_h",
                 "density_diffusion", "density_diffusion_form", "shifting", "shifting_coefficient",
                 "shifting_surface_threshold", "shifting_every", "continuity_form"});
  s.bodyAcceleration = physics.vector("gravity", D, std::vector<double>(D, 0.0));
  const auto force = physics.vector("body_force", D, std::vector<double>(D, 0.0));
  for (int a = 0; a < D; ++a) s.bodyAcceleration[a] += force[a];
  for (FluidBlock& b : s.fluids)
    if (std::isnan(b.surface)) {
      double lowest = 0;
      heightRange(s, b, lowest, b.surface);
    }
  s.beta = physics.nonNegative("artificial_viscosity", 0.0);
  s.terms.artificialViscosity = s.beta > 0.0;
  s.terms.morrisViscosity = physics.boolean("morris_viscosity", false);
  s.terms.variableH = physics.boolean("variable_h", false);
  const std::string continuity = physics.string("continuity_form", "lobovsky_kren");
  if (continuity != "lobovsky_kren" && continuity != "colagrossi_landrini")
    physics.fail("continuity_form", "unknown form '" + continuity +
                                        "' (expected lobovsky_kren or colagrossi_landrini)");
  s.continuityByVolume = continuity == "colagrossi_landrini";
  readDensityDiffusion(physics, s);
  readShifting(physics, s);
  physics.rejectUnknown();

  SceneTable numerics = top.sub("numerics");
  numerics.allow({"kernel", "dx", "h_over_dx", "cfl_acoustic", "cfl_viscous", "cfl_force",
                  "end_time", "density_band", "dt_floor", "neighbour_skin", "integrator"});
  s.kernel = readKernel(numerics, KernelKind::quadratic);
  s.dx = readDx(numerics);
  s.hOverDx = readHOverDx(numerics, 1.33);
  s.cflAcoustic = numerics.positive("cfl_acoustic", 0.25);
  s.cflViscous = numerics.positive("cfl_viscous", 0.125);
  s.cflForce = numerics.positive("cfl_force", 0.25);
  s.integrator = integratorKind(numerics, numerics.string("integrator", "predictor_corrector"));
  s.endTime = numerics.positive("end_time");
  const auto band = numerics.vector("density_band", 2, std::vector<double>{0.8, 1.2});
  if (!(band[0] > 0 && band[0] < 1 && band[1] > 1))
    numerics.fail("density_band", "expected [low, high] with 0 < low < 1 < high (rho/rho0)");
  s.densityBand = {band[0], band[1]};
  s.dtFloor = numerics.nonNegative("dt_floor", 0.0);
  s.neighbourSkin = numerics.nonNegative("neighbour_skin", 0.1);
  if (s.neighbourSkin > 1.0)
    numerics.fail("neighbour_skin", "expected 0 <= skin <= 1 (a fraction of the kernel's support)");
  numerics.rejectUnknown();
  for (int a = 0; a < D; ++a)
    if (s.dx > 0.5 * (s.upper[a] - s.lower[a])) numerics.fail("dx", "larger than half the domain");
  checkBlocksHoldParticles(s);
  readWalls(top.sub("walls"), top.array("obstacle"), top.sub("domain"), s);

  SceneTable output = top.sub("output");
  output.allow({"snapshot_interval", "series_every", "checkpoint_interval"});
  s.snapshotInterval = output.nonNegative("snapshot_interval", 0.0);
  s.checkpointInterval = output.nonNegative("checkpoint_interval", 0.0);
  const long seriesEvery = output.integer("series_every", 1);
  if (seriesEvery < 1) output.fail("series_every", "must be a positive whole number");
  s.seriesEvery = static_cast<int>(seriesEvery);
  output.rejectUnknown();
  readProbes(top.array("probe"), s);
  top.rejectUnknown();
  warnOnLowSoundSpeed(s);
  return s;
}

std::vector<double> upward(const Scene& s) {
  double g2 = 0;
  for (int a = 0; a < s.dimension; ++a) g2 += s.bodyAcceleration[a] * s.bodyAcceleration[a];
  std::vector<double> up(s.dimension, 0.0);
  if (!(g2 > 0)) {
    up[s.dimension - 1] = 1.0;
    return up;
  }
  const double g = std::sqrt(g2);
  for (int a = 0; a < s.dimension; ++a) up[a] = -s.bodyAcceleration[a] / g;
  return up;
}

double height(const std::vector<double>& up, const double* x) {
  double z = 0;
  for (std::size_t a = 0; a < up.size(); ++a) z += up[a] * x[a];
  return z;
}

void heightRange(const Scene& s, const FluidBlock& b, double& lowest, double& highest) {
  const std::vector<double> up = upward(s);
  if (b.shape == FluidBlock::Shape::circle) {
    const double z = height(up, b.center.data());
    lowest = z - b.radius, highest = z + b.radius;
    return;
  }
  // A box's extremes are corners: along each axis the side that up (or down) points to.
  lowest = highest = 0.0;
  for (int a = 0; a < s.dimension; ++a) {
    highest += up[a] * (up[a] >= 0 ? b.upper[a] : b.lower[a]);
    lowest += up[a] * (up[a] >= 0 ? b.lower[a] : b.upper[a]);
  }
}

Scene readScene(const std::string& path) {
  return parseScene(sceneText(path), path);
}

}  // namespace sph
