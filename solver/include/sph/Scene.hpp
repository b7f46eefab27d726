#pragma once
// A checked scene: everything a run needs, read from a TOML scene file. Dimension-free (vectors
// hold `dimension` entries); Simulation<D> builds the particles from it.
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "sph/Boundaries.hpp"
#include "sph/EquationOfState.hpp"
#include "sph/ForceEvaluation.hpp"
#include "sph/Kernels.hpp"
#include "sph/ParticleShifting.hpp"

namespace sph {

// Bad input: the message names the file, the key and what is wrong.
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct FluidBlock {
  enum class Shape { rectangle, circle } shape = Shape::rectangle;
  std::vector<double> lower, upper;  // rectangle
  std::vector<double> center;        // circle (a disc in 2-D, a ball in 3-D)
  double radius = 0.0;
  int phase = 0;
  std::vector<double> velocity;
  // Linear velocity field about the block's centre c (circle: its centre; rectangle: the
  // midpoint): v = velocity + G (x - c), G row-major D x D; empty: none. Monaghan's (1994)
  // elliptical drop is G = [[A0, 0], [0, -A0]].
  std::vector<double> velocityGradient;
  std::vector<double> gradientCenter;  // c
  // Start at p = p0 + rho0 |g| (surface - z), z = -g.x/|g| the height against the body
  // acceleration (y for gravity along -y), density from the inverse EOS.
  bool hydrostatic = false;
  // Start at the pressure that keeps v = G (x - c) linear at t = 0 (dG/dt = 0 there):
  // -grad p / rho0 = G G (x - c), so p = p0 + rho0/2 (Q_max - Q(x)), Q = (x - c)^T G G (x - c),
  // which needs G G symmetric; Q_max is Q's largest value over the block (circle:
  // R^2 max(0, lambda_max(G G)); rectangle: over its corners and centre), so p = p0 there.
  bool stretching = false;
  // The free surface's height z for the hydrostatic start (default: the block's highest point).
  double surface = 0.0;
  // Where the particles start: on the Cartesian lattice, or packed (Colagrossi et al. 2012,
  // eq. 2.16, 2-D and 3-D) inside the block closed by fixed solid layers or the walls' mirror
  // images, with the scene's kernel and h/dx; then m = rho V0, V0 = block volume / N.
  bool packed = false;
  double packingAlpha = 2e-3;  // eq. (2.15)
  int packingMaxIterations = 10000;
  double packingStop = 1e-8;  // stop when T / (N beta) falls below (per particle)
  // Each coordinate of the packing's start moved by uniform noise in [-noise dx, noise dx] (fixed
  // seed): a lattice that is an equilibrium of eq. (2.16) but an unstable one (the cubic lattice
  // under Wendland C2 at h/dx 2, LatticeUnderPressure.hpp) leaves it only so.
  double packingNoise = 0.0;
};

struct Probe {
  // surge_front, column_height, pressure, water_level, wall_pressure, water_height
  std::string name, type;
  // pressure, wall_pressure: the point (D numbers); water_height: the vertical line's
  // horizontal coordinates (D - 1 numbers)
  std::vector<double> position;
  double x = 0.0;  // water_level: gauge position; column_height: band 0..x from the lower wall
  // For the report (reports/README.md): reference data keys and the scales of their nondimensional
  // form, written as attributes of /series/probe_<name>. Zero or empty: not given.
  std::string reference;
  double scaleLength = 0.0, scaleHeight = 0.0;
};

// What the box's wall faces are made of (solver/SCENES.md, [walls]): the paper's mirror ghosts
// (boundaries/MirrorGhosts.hpp) or layers of fixed wall particles with Adami et al.'s (2012)
// pressure extrapolation (boundaries/WallParticles.hpp).
enum class WallModel { mirror_ghosts, wall_particles };
std::string_view name(WallModel);

// The time integrator ([numerics] integrator, solver/SCENES.md): the paper's predictor-corrector
// (integrators/PredictorCorrector.hpp), position Verlet (integrators/PositionVerlet.hpp) or
// velocity Verlet with one force evaluation a step (integrators/VelocityVerlet.hpp).
enum class TimeIntegrator { predictor_corrector, position_verlet, velocity_verlet };
std::string_view name(TimeIntegrator);

// A solid box inside the domain made of fixed wall particles ([[obstacle]]).
struct Obstacle {
  std::vector<double> lower, upper;
  FaceKind wall = FaceKind::free_slip;  // free_slip or no_slip
};

struct Scene {
  std::string name, file, text;
  int dimension = 2;
  std::vector<double> lower, upper;
  std::array<std::array<FaceKind, 2>, 3> faces{};
  std::array<std::array<std::vector<double>, 2>, 3> wallVelocity{};
  bool hydrostaticGhosts =
      false;  // ghost pressure: the source's (paper) or hydrostatically corrected
  // A particle that crosses an open face ([domain] leaving): a failure (escaped_domain) or taken
  // out of the run and kept in its record of departures (Simulation::departures).
  enum class Leaving { fails, removed } leaving = Leaving::fails;
  WallModel wallModel = WallModel::mirror_ghosts;
  int wallLayers =
      0;  // layers of wall particles (set by the reader: [walls] layers or its default)
  // [walls] tensile: mirror ghosts carry pressure below p0 (the paper: the wall pulls fluid in
  // tension toward it), or not (a wall pushes and never pulls, as wall particles always do).
  bool tensileWalls = true;
  std::vector<Obstacle> obstacles;
  std::vector<Phase> phases;
  std::vector<FluidBlock> fluids;
  std::vector<double> bodyAcceleration;  // gravity plus any driving force, F/rho [m/s^2]
  TermSwitches terms;
  double beta = 0.0;  // artificial viscosity, eq. (10)
  // physics.continuity_form: d rho_i/dt from the neighbours' masses (eq. 11) or from their
  // volumes (Colagrossi & Landrini 2003; terms/ContinuityEquation.hpp), and with it the pressure
  // gradient of the same pair (terms/PressureGradient.hpp).
  bool continuityByVolume = false;
  double diffusionDelta = 0.0;  // density diffusion delta (terms.densityDiffusion: its form)
  ShiftingParameters shifting;  // particle shifting, once a step (ParticleShifting.hpp)
  KernelKind kernel = KernelKind::quadratic;
  double dx = 0.0, hOverDx = 1.33;
  double cflAcoustic = 0.25, cflViscous = 0.125, cflForce = 0.25;  // Morris et al. 1997
  TimeIntegrator integrator = TimeIntegrator::predictor_corrector;
  double endTime = 0.0;
  std::array<double, 2> densityBand{0.8, 1.2};  // a run fails when rho/rho0 leaves this band
  double neighbourSkin = 0.1;     // neighbour lists' skin, a fraction of the support (Simulation)
  double dtFloor = 0.0;           // a run fails when dt falls below (0: 1e-4 of the first dt)
  double snapshotInterval = 0.0;  // 0: first and last only
  int seriesEvery = 1;            // record the time series every n steps
  // A checkpoint (Checkpoint.hpp) after the first step at or past every multiple of this
  // simulated time [s]; 0: only where the run stops early (failure, signal, --stop-at).
  double checkpointInterval = 0.0;
  std::vector<Probe> probes;
  std::vector<std::string> warnings;

  double h0() const { return hOverDx * dx; }
};

// The unit vector against the scene's body acceleration g, -g / |g|, or the last axis where g = 0.
// Along an axis it is exactly 1 there and 0 elsewhere, so that a height is that coordinate to the
// bit.
std::vector<double> upward(const Scene& s);
// The height of x along `up`: up . x.
double height(const std::vector<double>& up, const double* x);
// The lowest and highest such height over a fluid block.
void heightRange(const Scene& s, const FluidBlock& b, double& lowest, double& highest);

// Reads and checks a scene file. Throws SceneError naming the file, the key and the problem.
Scene readScene(const std::string& path);
// The same, from text (tests); `file` names it in messages.
Scene parseScene(const std::string& text, const std::string& file);

}  // namespace sph
