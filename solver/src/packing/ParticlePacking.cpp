#include "sph/packing/ParticlePacking.hpp"

#include <cmath>
#include <stdexcept>

#include "sph/CellList.hpp"

namespace sph::packing {

ParticlePacking::ParticlePacking(std::vector<Vec2> fluid, std::vector<Vec2> solid, double V0,
                                 double dx, const PackingParameters& parameters)
    : parameters_(parameters),
      x_(std::move(fluid)),
      u_(x_.size(), Vec2::Zero()),
      solid_(std::move(solid)),
      V0_(V0),
      h_(parameters.hOverDx * dx) {
  // eqs. (2.15) and (2.17) with D = 2: the length scale is V0^(1/2).
  const double l0 = std::sqrt(V0_), c = std::sqrt(parameters_.beta);
  dt_ = parameters_.cfl * l0 / c;
  zeta_ = parameters_.alpha * c / l0;
  evaluate();
}

ParticlePacking::ParticlePacking(std::vector<Vec2> fluid, std::vector<Vec2> solid, double V0,
                                 double dx, const PackingParameters& parameters,
                                 const PeriodicBox& box)
    : ParticlePacking(std::vector<Vec2>{}, std::move(solid), V0, dx, parameters) {
  // Delegated with no fluid so that the first evaluation below already sees the images.
  const double support = 2.0 * h_;  // lambda h, lambda = 2 for every kernel here
  for (int a = 0; a < 2; ++a)
    if (!(box.hi[a] - box.lo[a] > 2.0 * support))
      throw std::invalid_argument("periodic box narrower than twice the kernel support");
  periodic_ = true;
  box_ = box;
  x_ = std::move(fluid);
  u_.assign(x_.size(), Vec2::Zero());
  wrap();
  evaluate();
}

void ParticlePacking::setMirrorWalls(std::vector<MirrorWall> walls) {
  mirrors_ = std::move(walls);
  evaluate();
}

void ParticlePacking::wrap() {
  for (Vec2& x : x_)
    for (int a = 0; a < 2; ++a) {
      const double L = box_.hi[a] - box_.lo[a];
      x[a] -= L * std::floor((x[a] - box_.lo[a]) / L);
    }
}

void ParticlePacking::evaluate() {
  const std::size_t nf = x_.size();
  all_.assign(x_.begin(), x_.end());
  if (periodic_) {
    // Images of the fluid particles within the kernel support of the box, shifted by the sides:
    // they act as fluid particles (the same Gamma, and the fluid half of eq. B.34).
    const double support = 2.0 * h_;
    const Vec2 L = box_.hi - box_.lo;
    for (std::size_t i = 0; i < nf; ++i)
      for (int sx = -1; sx <= 1; ++sx)
        for (int sy = -1; sy <= 1; ++sy) {
          if (sx == 0 && sy == 0) continue;
          const Vec2 y = x_[i] + Vec2(sx * L.x(), sy * L.y());
          if (y.x() > box_.lo.x() - support && y.x() < box_.hi.x() + support &&
              y.y() > box_.lo.y() - support && y.y() < box_.hi.y() + support)
            all_.push_back(y);
        }
  }
  if (!mirrors_.empty()) {
    // Images across each wall within the kernel support, and across pairs of walls (corners).
    const double support = 2.0 * h_;
    auto reflect = [](Vec2 y, const MirrorWall& w) {
      y[w.axis] = 2.0 * w.at - y[w.axis];
      return y;
    };
    auto near = [&](const Vec2& y, const MirrorWall& w) {
      return std::abs(y[w.axis] - w.at) < support;
    };
    for (std::size_t i = 0; i < nf; ++i)
      for (std::size_t a = 0; a < mirrors_.size(); ++a) {
        if (!near(x_[i], mirrors_[a])) continue;
        all_.push_back(reflect(x_[i], mirrors_[a]));
        for (std::size_t b = a + 1; b < mirrors_.size(); ++b)
          if (mirrors_[b].axis != mirrors_[a].axis && near(x_[i], mirrors_[b]))
            all_.push_back(reflect(reflect(x_[i], mirrors_[a]), mirrors_[b]));
      }
  }
  const std::size_t nFluidLike = all_.size();
  all_.insert(all_.end(), solid_.begin(), solid_.end());
  gradGamma_.assign(nf, Vec2::Zero());
  gamma_.assign(nf, 0.0);
  potentialTerm_.assign(nf, 0.0);
  withKernel(parameters_.kernel, [&](auto kernel) {
    using K = decltype(kernel);
    const double radius = K::support * h_, radius2 = radius * radius, h = h_;
    CellList<2> cells;
    cells.build(all_, radius);
    const auto& order = cells.order();
    const std::int64_t ncells = cells.cells();
#pragma omp parallel for schedule(dynamic, 64) if (nf > 4096)
    for (std::int64_t c = 0; c < ncells; ++c) {
      for (int k = cells.cellBegin(c); k < cells.cellEnd(c); ++k) {
        const int i = order[k];
        if (static_cast<std::size_t>(i) >= nf) continue;  // solid particles do not move
        const Vec2 xi = all_[i];
        double sumFluid = 0.0, sumSolid = 0.0;
        Vec2 grad = Vec2::Zero();
        cells.forEachAdjacentRange(c, [&](int begin, int end) {
          for (int kk = begin; kk < end; ++kk) {
            const int j = order[kk];
            const Vec2 r_ij = xi - all_[j];
            const double r2 = r_ij.squaredNorm();
            if (r2 >= radius2) continue;
            const double r = std::sqrt(r2);
            const double W_ij = K::template W<2>(r, h);
            (static_cast<std::size_t>(j) < nFluidLike ? sumFluid : sumSolid) += W_ij;
            // grad_i W_ij = dW/dr r_ij / r; the self term (r = 0) has no direction.
            if (r > 0.0) grad += (K::template dWdr<2>(r, h) / r) * r_ij;
          }
        });
        gamma_[i] = V0_ * (sumFluid + sumSolid);
        gradGamma_[i] = V0_ * grad;
        // Particle i's share of eq. (B.34): the fluid-fluid double sum counts each pair twice.
        potentialTerm_[i] = V0_ * (0.5 * sumFluid + sumSolid);
      }
    }
  });
  double V = 0.0;
  for (double v : potentialTerm_) V += v;
  potential_ = parameters_.beta * V;
}

void ParticlePacking::step() {
  // Strang splitting of eq. (2.16): the damping half steps are exact (u *= exp(-zeta dt/2)), the
  // conservative part in between is velocity Verlet (kick, drift, kick). With zeta = 0 it is
  // velocity Verlet itself: symplectic, so E = T + V oscillates by O(dt^2) without drift.
  const double damp = std::exp(-0.5 * zeta_ * dt_), half = 0.5 * dt_, beta = parameters_.beta;
  const std::size_t n = x_.size();
  for (std::size_t i = 0; i < n; ++i) {
    u_[i] = damp * u_[i] - half * beta * gradGamma_[i];
    x_[i] += dt_ * u_[i];
  }
  if (periodic_) wrap();
  // A particle that drifted across a mirror wall is reflected back, its normal velocity reversed
  // (as the run does, Simulation: wall reflections).
  for (const MirrorWall& w : mirrors_)
    for (std::size_t i = 0; i < n; ++i)
      if (w.fluidSide * (x_[i][w.axis] - w.at) < 0.0) {
        x_[i][w.axis] = 2.0 * w.at - x_[i][w.axis];
        u_[i][w.axis] = -u_[i][w.axis];
      }
  evaluate();
  for (std::size_t i = 0; i < n; ++i) u_[i] = damp * (u_[i] - half * beta * gradGamma_[i]);
  ++iteration_;
}

PackingRecord ParticlePacking::record() const {
  PackingRecord r;
  r.iteration = iteration_;
  double T = 0.0, g = 0.0;
  for (const Vec2& u : u_) T += 0.5 * u.squaredNorm();
  for (const Vec2& gg : gradGamma_) g = std::max(g, gg.norm());
  r.kinetic = T / parameters_.beta;
  r.kineticMean = x_.empty() ? 0.0 : r.kinetic / static_cast<double>(x_.size());
  r.potential = potential_ / parameters_.beta;
  r.maxGradGamma = g;
  return r;
}

bool ParticlePacking::run(const std::function<void(const PackingRecord&)>& observe) {
  if (observe) observe(record());
  while (iteration_ < parameters_.maxIterations) {
    step();
    const PackingRecord r = record();
    if (observe) observe(r);
    if (r.kineticMean < parameters_.stopKineticEnergy) return true;
  }
  return false;
}

HydrostaticFields hydrostatic(const std::vector<Vec2>& x, double V0, const Phase& phase,
                              double gravity, double surface) {
  HydrostaticFields f;
  for (const Vec2& p : x) {
    const double pressure = phase.p0 + phase.rho0 * gravity * (surface - p.y());
    const double rho = TaitEquationOfState::density(pressure, phase);
    f.pressure.push_back(pressure);
    f.density.push_back(rho);
    f.mass.push_back(rho * V0);
  }
  return f;
}

}  // namespace sph::packing
