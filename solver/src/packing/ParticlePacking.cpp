#include "sph/packing/ParticlePacking.hpp"

#include <cmath>
#include <stdexcept>

#include "sph/CellList.hpp"

namespace sph::packing {

namespace {

template <int D>
void appendImages(const Vec<D>& x, const Vec<D>& y, const std::vector<MirrorWall>& walls,
                  double reach, std::size_t first, unsigned axes, std::vector<Vec<D>>& out) {
  for (std::size_t k = first; k < walls.size(); ++k) {
    const MirrorWall& w = walls[k];
    if ((axes >> w.axis) & 1u || !(std::abs(x[w.axis] - w.at) < reach)) continue;
    Vec<D> z = y;
    z[w.axis] = 2.0 * w.at - z[w.axis];
    out.push_back(z);
    appendImages<D>(x, z, walls, reach, k + 1, axes | (1u << w.axis), out);
  }
}

}  // namespace

template <int D>
void appendMirrorImages(const Vec<D>& x, const std::vector<MirrorWall>& walls, double reach,
                        std::vector<Vec<D>>& out) {
  appendImages<D>(x, x, walls, reach, 0, 0u, out);
}

template <int D>
ParticlePacking<D>::ParticlePacking(std::vector<Vec<D>> fluid, std::vector<Vec<D>> solid, double V0,
                                    double dx, const PackingParameters& parameters)
    : parameters_(parameters),
      x_(std::move(fluid)),
      u_(x_.size(), Vec<D>::Zero()),
      solid_(std::move(solid)),
      V0_(V0),
      h_(parameters.hOverDx * dx) {
  // eqs. (2.15) and (2.17): the length scale is V0^(1/D).
  const double l0 = std::pow(V0_, 1.0 / D), c = std::sqrt(parameters_.beta);
  dt_ = parameters_.cfl * l0 / c;
  zeta_ = parameters_.alpha * c / l0;
  evaluate();
}

template <int D>
ParticlePacking<D>::ParticlePacking(std::vector<Vec<D>> fluid, std::vector<Vec<D>> solid, double V0,
                                    double dx, const PackingParameters& parameters,
                                    const PeriodicBox<D>& box)
    : ParticlePacking(std::vector<Vec<D>>{}, std::move(solid), V0, dx, parameters) {
  // Delegated with no fluid so that the first evaluation below already sees the images.
  const double support = 2.0 * h_;  // lambda h, lambda = 2 for every kernel here
  for (int a = 0; a < D; ++a)
    if (!(box.hi[a] - box.lo[a] > 2.0 * support))
      throw std::invalid_argument("periodic box narrower than twice the kernel support");
  periodic_ = true;
  box_ = box;
  x_ = std::move(fluid);
  u_.assign(x_.size(), Vec<D>::Zero());
  wrap();
  evaluate();
}

template <int D>
void ParticlePacking<D>::setMirrorWalls(std::vector<MirrorWall> walls) {
  mirrors_ = std::move(walls);
  evaluate();
}

template <int D>
void ParticlePacking<D>::wrap() {
  for (Vec<D>& x : x_)
    for (int a = 0; a < D; ++a) {
      const double L = box_.hi[a] - box_.lo[a];
      x[a] -= L * std::floor((x[a] - box_.lo[a]) / L);
    }
}

template <int D>
void ParticlePacking<D>::evaluate() {
  const std::size_t nf = x_.size();
  const double support = 2.0 * h_;
  all_.assign(x_.begin(), x_.end());
  if (periodic_) {
    // Images of the fluid particles within the kernel support of the box, shifted by the sides:
    // they act as fluid particles (the same Gamma, and the fluid half of eq. B.34).
    const Vec<D> L = box_.hi - box_.lo;
    int shifts = 1;
    for (int a = 0; a < D; ++a) shifts *= 3;
    for (std::size_t i = 0; i < nf; ++i)
      for (int code = 0; code < shifts; ++code) {
        Vec<D> y = x_[i];
        bool moved = false, near = true;
        for (int a = D - 1, rest = code; a >= 0; --a, rest /= 3) {
          const int s = rest % 3 - 1;  // -1, 0, 1; the first axis varies slowest
          y[a] += s * L[a];
          moved |= s != 0;
          near &= y[a] > box_.lo[a] - support && y[a] < box_.hi[a] + support;
        }
        if (moved && near) all_.push_back(y);
      }
  }
  if (!mirrors_.empty()) {
    for (std::size_t i = 0; i < nf; ++i) appendMirrorImages<D>(x_[i], mirrors_, support, all_);
  }
  const std::size_t nFluidLike = all_.size();
  all_.insert(all_.end(), solid_.begin(), solid_.end());
  gradGamma_.assign(nf, Vec<D>::Zero());
  gamma_.assign(nf, 0.0);
  potentialTerm_.assign(nf, 0.0);
  withKernel(parameters_.kernel, [&](auto kernel) {
    using K = decltype(kernel);
    const double radius = K::support * h_, radius2 = radius * radius, h = h_;
    CellList<D> cells;
    cells.build(all_, radius);
    const auto& order = cells.order();
    const std::int64_t ncells = cells.cells();
#pragma omp parallel for schedule(dynamic, 64) if (nf > 4096)
    for (std::int64_t c = 0; c < ncells; ++c) {
      for (int k = cells.cellBegin(c); k < cells.cellEnd(c); ++k) {
        const int i = order[k];
        if (static_cast<std::size_t>(i) >= nf) continue;  // solid particles do not move
        const Vec<D> xi = all_[i];
        double sumFluid = 0.0, sumSolid = 0.0;
        Vec<D> grad = Vec<D>::Zero();
        cells.forEachAdjacentRange(c, [&](int begin, int end) {
          for (int kk = begin; kk < end; ++kk) {
            const int j = order[kk];
            const Vec<D> r_ij = xi - all_[j];
            const double r2 = r_ij.squaredNorm();
            if (r2 >= radius2) continue;
            const double r = std::sqrt(r2);
            const double W_ij = K::template W<D>(r, h);
            (static_cast<std::size_t>(j) < nFluidLike ? sumFluid : sumSolid) += W_ij;
            // grad_i W_ij = dW/dr r_ij / r; the self term (r = 0) has no direction.
            if (r > 0.0) grad += (K::template dWdr<D>(r, h) / r) * r_ij;
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

template <int D>
void ParticlePacking<D>::step() {
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

template <int D>
PackingRecord ParticlePacking<D>::record() const {
  PackingRecord r;
  r.iteration = iteration_;
  double T = 0.0, g = 0.0;
  for (const Vec<D>& u : u_) T += 0.5 * u.squaredNorm();
  for (const Vec<D>& gg : gradGamma_) g = std::max(g, gg.norm());
  r.kinetic = T / parameters_.beta;
  r.kineticMean = x_.empty() ? 0.0 : r.kinetic / static_cast<double>(x_.size());
  r.potential = potential_ / parameters_.beta;
  r.maxGradGamma = g;
  return r;
}

template <int D>
bool ParticlePacking<D>::run(const std::function<void(const PackingRecord&)>& observe) {
  if (observe) observe(record());
  while (iteration_ < parameters_.maxIterations) {
    step();
    const PackingRecord r = record();
    if (observe) observe(r);
    if (r.kineticMean < parameters_.stopKineticEnergy) return true;
  }
  return false;
}

template <int D>
HydrostaticFields hydrostatic(const std::vector<Vec<D>>& x, double V0, const Phase& phase,
                              double gravity, double surface) {
  HydrostaticFields f;
  for (const Vec<D>& p : x) {
    const double pressure = phase.p0 + phase.rho0 * gravity * (surface - p[D - 1]);
    const double rho = TaitEquationOfState::density(pressure, phase);
    f.pressure.push_back(pressure);
    f.density.push_back(rho);
    f.mass.push_back(rho * V0);
  }
  return f;
}

template void appendMirrorImages<2>(const Vec<2>&, const std::vector<MirrorWall>&, double,
                                    std::vector<Vec<2>>&);
template void appendMirrorImages<3>(const Vec<3>&, const std::vector<MirrorWall>&, double,
                                    std::vector<Vec<3>>&);
template class ParticlePacking<2>;
template class ParticlePacking<3>;
template HydrostaticFields hydrostatic<2>(const std::vector<Vec<2>>&, double, const Phase&, double,
                                          double);
template HydrostaticFields hydrostatic<3>(const std::vector<Vec<3>>&, double, const Phase&, double,
                                          double);

}  // namespace sph::packing
