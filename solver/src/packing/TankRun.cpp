#include "sph/packing/TankRun.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "sph/CellList.hpp"

namespace sph::packing {

namespace {
// The run's scene: an open box around the container and its wall layers (the walls are the
// FixedWalls particles, not box faces), the packing scene's fluid, kernel and h/dx.
Scene runScene(const PackingScene& p, const TankRunOptions& o, const Vec2& lo, const Vec2& hi) {
  Scene s;
  s.name = p.name + (o.packed ? "_packed" : "_lattice");
  s.file = p.file;
  s.dimension = 2;
  const double margin = (2.0 * p.parameters.hOverDx + 2.0) * p.dx;
  s.lower = {lo.x() - margin, lo.y() - margin};
  s.upper = {hi.x() + margin, hi.y() + margin};
  for (auto& f : s.faces) f = {FaceKind::open, FaceKind::open};
  for (auto& w : s.wallVelocity) w = {std::vector<double>(2, 0.0), std::vector<double>(2, 0.0)};
  s.phases = {p.phase};
  // nu = alpha h c0 / 8 (TankRunOptions); the walls take the same phase.
  s.phases[0].mu = o.alpha * p.parameters.hOverDx * p.dx * p.phase.c0 / 8.0 * p.phase.rho0;
  s.terms.morrisViscosity = o.alpha > 0;
  if (s.phases[0].name.empty()) s.phases[0].name = "water";
  s.bodyAcceleration = {0.0, -p.gravity};
  s.terms.artificialViscosity = o.beta > 0;
  s.beta = o.beta;
  s.kernel = p.parameters.kernel;
  s.dx = p.dx;
  s.hOverDx = p.parameters.hOverDx;
  s.endTime = 1e300;
  s.cflAcoustic = o.cflAcoustic;
  return s;
}
}  // namespace

TankRun::TankRun(const PackingScene& scene, const TankRunOptions& options)
    : scene_(scene), options_(options) {
  if (!scene.hasSurface)
    throw std::invalid_argument(scene.file +
                                ": a tank run needs a free surface (geometry.surface)");
  const PackingSetup setup = setUp(scene);
  region_ = setup.region;
  container_ = Region(scene.container);
  H_ = setup.lengthScale;
  timeScale_ = std::sqrt(H_ / scene.gravity);

  // The walls: the packing's solid layers along the walls (the packed fluid was packed against
  // exactly these), continued above the free surface by the wall layers of the container cut
  // higher, where those are not within 0.7 dx of a packing wall particle (the seam). Without the
  // continuation the free-surface particle in the 45-degree corner of the trapezoidal tank sees
  // no wall above it, is pushed up into the slope and crosses it by t sqrt(g/H) = 0.7 (measured).
  // The packing itself keeps its own closure of the surface (setUp): packing against the
  // continued walls and a thinned surface layer let a particle escape at the acute corner at
  // H/dx = 50 (measured).
  Vec2 lo, hi;
  container_.bounds(lo, hi);
  const double h = scene.parameters.hOverDx * scene.dx;
  const int layers = static_cast<int>(std::ceil(2.0 * scene.parameters.hOverDx - 1e-9));
  const double cut = scene.surface + std::min(0.75 * (hi.y() - scene.surface), 2.0 * h + scene.dx);
  const SolidLayers tall = solidLayers(belowSurface(scene.container, cut), scene.dx, layers);
  std::vector<Vec2> wall;
  for (std::size_t k = 0; k < setup.solid.position.size(); ++k)
    if (setup.solid.kind[k] == Piece::Kind::wall) wall.push_back(setup.solid.position[k]);
  const std::size_t below = wall.size();
  const double seam = 0.7 * scene.dx;
  CellList<2> packingWall;  // O(N) seam test
  packingWall.build(
      below, [&](std::size_t j, int a) { return wall[j][a]; }, seam);
  for (std::size_t k = 0; k < tall.position.size(); ++k) {
    if (tall.kind[k] != Piece::Kind::wall) continue;
    const Vec2 x = tall.position[k];
    bool clear = true;
    if (const std::int64_t c = packingWall.cellOf(x); c >= 0)
      packingWall.forEachAdjacentRange(c, [&](int begin, int end) {
        for (int j = begin; j < end; ++j)
          clear = clear && (wall[packingWall.order()[j]] - x).norm() >= seam;
      });
    if (clear) wall.push_back(x);
  }

  std::vector<Vec2> fluid = setup.fluid;
  if (options.packed) {
    ParticlePacking packing(setup.fluid, setup.solid.position, setup.V0, scene.dx,
                            scene.parameters);
    packing.run();
    packingIterations_ = packing.iteration();
    fluid = packing.positions();
    V0_ = setup.V0;  // the volume the packing gave every particle (section 2)
  } else {
    V0_ = scene.dx * scene.dx;  // a lattice cell
  }

  Scene run = runScene(scene, options, lo, hi);
  walls_ = std::make_shared<FixedWalls<2>>(std::move(wall), V0_, h, scene.parameters.kernel,
                                           run.phases, Vec2(0.0, -scene.gravity));

  const HydrostaticFields hs = hydrostatic(fluid, V0_, scene.phase, scene.gravity, scene.surface);
  Particles<2> y;
  y.resize(fluid.size());
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    y.r[i] = fluid[i], y.v[i] = Vec2::Zero();
    y.rho[i] = hs.density[i], y.m[i] = hs.mass[i], y.h[i] = h, y.p[i] = hs.pressure[i];
    y.phase[i] = 0;
    volume_ += V0_;
  }
  sim_ = std::make_unique<Simulation<2>>(run, std::move(y));

  // The container's walls are its wall particles (the box's faces are all open: no halo).
  Boundaries<2> open;
  open.lower = Vec2(run.lower[0], run.lower[1]), open.upper = Vec2(run.upper[0], run.upper[1]);
  sim_->setBoundary(std::make_unique<WallParticles<2>>(
      open, GhostPressure<2>(Vec2::Zero()), walls_, std::vector<SolidBox<2>>{}, "fixed_walls",
      std::vector<std::string>{"fixed_walls_adami2012"}));
  // Section 3.1.1: dv/dt += -zeta v while t < t_damp, zeta = (zeta H / c0) c0 / H.
  if (options.dampingZeta > 0 && options.dampingTime > 0) {
    const double zeta = options.dampingZeta * scene.phase.c0 / H_;
    const double until = options.dampingTime * timeScale_;
    sim_->setSource([zeta, until](double t, const Particles<2>& s, Derivatives<2>& out) {
      if (t >= until) return;
      for (std::size_t i = 0; i < s.size(); ++i) out.dvdt[i] -= zeta * s.v[i];
    });
  }
  // A fluid particle outside the container has entered the solid: the wall failed to hold it.
  // As at the box walls (Simulation::reflectAtWalls), one that ended the step at most dx/2 beyond
  // the wall line, short of the first layer of wall particles, is put back (reflected with the
  // coefficient of restitution e of TankRunOptions about the nearest point q of the wall: r' =
  // q - e (r - q), normal velocity times -e) and counted; a deeper one is a wall_penetration
  // failure. Why the Adami walls need it (measured with the Cartesian start, without it): they
  // push through the pressure gradient alone, -(p_i/rho_i^2 + p_w/rho_w^2) m_w grad W summed,
  // which vanishes on top of a wall particle (Wendland C2 has dW/dr = 0 at r = 0) and weakens with
  // the pressure, so a particle next to the wall finds its balance of fluid push, wall push and
  // gravity anywhere between the wall line and the first layer. In the trapezoidal tank at
  // H/dx = 50 particle 2186, 4.5 dx below the surface on the 45-degree wall (where the lattice
  // puts nodes on the wall line), is 0.08 dx beyond it at t sqrt(g/H) = 14.5, 0.3 dx at 24.5,
  // and from t = 27 on sits inside the first layer (0.46-0.52 dx beyond the line, between two wall
  // particles, 0.1-0.5 dx from one), its normal accelerations balanced (fluid +19, walls -26,
  // gravity +7 m/s^2), with 26-29 wall particles within 2h and none of their p_w clipped to p0. In
  // the complex tank at H/dx = 20 particles from above the step slip round its corner into the
  // strip between the round bottom and its first layer, ride down it at 0.1-0.3 dx beyond the line
  // and cross the layer from t = 73 (one passes 2 dx at t = 87). Putting them back at the wall line
  // keeps every particle out of that strip.
  const Region container = container_;
  const double tolerated = 0.5 * scene.dx;
  if (options.reflect) {
    std::shared_ptr<Reflections> reflections = reflections_;
    const double e = options.restitution;
    sim_->setReflection([container, tolerated, e, reflections](Particles<2>& s) {
      for (std::size_t i = 0; i < s.size(); ++i) {
        if (container.contains(s.r[i])) continue;
        const Vec2 q = container.nearest(s.r[i]), out = s.r[i] - q;
        const double depth = out.norm();
        if (depth == 0.0 || depth > tolerated) continue;  // deeper: the check's failure
        // Past an acute corner of the container the mirror image can lie outside too: left to
        // the check (no tank here has such a corner below its surface).
        const Vec2 back = q - e * out;
        if (e > 0.0 && !container.contains(back)) continue;
        const Vec2 n = out / depth;
        s.r[i] = back;
        s.v[i] -= (1.0 + e) * s.v[i].dot(n) * n;
        ++reflections->count;
        reflections->deepest = std::max(reflections->deepest, depth);
      }
    });
  }
  sim_->setCheck(
      [container, tolerated](const Particles<2>& s, double t, long step) -> std::optional<Failure> {
        for (std::size_t i = 0; i < s.size(); ++i) {
          if (container.contains(s.r[i]) || container.distance(s.r[i]) <= tolerated) continue;
          std::ostringstream m;
          m << "step " << step << ", t = " << t << " s, particle " << i << ": position ("
            << s.r[i].x() << ", " << s.r[i].y() << ") m is " << container.distance(s.r[i])
            << " m beyond the tank's wall (crossed into the fixed wall particles)";
          return Failure{FailureCause::wall_penetration, step, t, static_cast<int>(i), m.str()};
        }
        return std::nullopt;
      });
}

TankSample TankRun::sample() const {
  const Particles<2>& y = sim_->particles();
  const double g = scene_.gravity, U = std::sqrt(g * H_);
  TankSample s;
  s.t = sim_->time() / timeScale_;
  double v2 = 0, ek = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    v2 = std::max(v2, y.v[i].squaredNorm());
    ek += 0.5 * y.m[i] * y.v[i].squaredNorm();
  }
  s.maxSpeed = std::sqrt(v2) / U;
  s.kinetic = ek / (scene_.phase.rho0 * g * H_ * volume_);
  return s;
}

std::optional<Failure> TankRun::runTo(double tEnd,
                                      const std::function<void(const TankSample&)>& observe) {
  if (observe && sim_->step() == 0) observe(sample());
  while (sim_->time() < tEnd * timeScale_) {
    if (auto failure = sim_->advance()) return failure;
    if (observe) observe(sample());
  }
  return std::nullopt;
}

}  // namespace sph::packing
