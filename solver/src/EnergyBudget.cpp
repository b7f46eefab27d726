#include "sph/EnergyBudget.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sph {

double internalEnergy(double rho, const Phase& ph) {
  // e = int_rho0^rho p/s^2 ds with p = p0 + K (x^gamma - 1), x = rho/rho0, d = x - 1:
  // e rho0 = (p0 - K) d/x + K (x^(gamma-1) - 1)/(gamma - 1). For gamma = 7 the two O(d) parts
  // cancel; written as p0 d/x + K d^2 (6 + 5x + 4x^2 + 3x^3 + 2x^4 + x^5)/(6x) they do not.
  const double d = (rho - ph.rho0) / ph.rho0, x = 1.0 + d, K = ph.bulkModulus();
  if (ph.gamma == 7.0) {
    const double poly = 6 + x * (5 + x * (4 + x * (3 + x * (2 + x))));
    return (ph.p0 * d + K * d * d * poly / 6.0) / (x * ph.rho0);
  }
  // x^(gamma-1) - 1 without the subtraction's loss of digits near x = 1.
  const double rise = std::expm1((ph.gamma - 1) * std::log1p(d));
  return ((ph.p0 - K) * d / x + K * rise / (ph.gamma - 1)) / ph.rho0;
}

namespace {
// e at its minimum, where p = 0 (de/drho = p/rho^2): rho/rho0 = (1 - p0/K)^(1/gamma). Measured from
// there the internal energy is never negative, which the factor of 2 in check() needs; with a
// background pressure p0 != 0 e(rho0) = 0 is not the minimum. None where p0 >= K (p > 0 at every
// density, e unbounded below).
std::optional<double> lowestInternalEnergy(const Phase& ph) {
  const double base = 1.0 - ph.p0 / ph.bulkModulus();
  if (base <= 0.0) return std::nullopt;
  return internalEnergy(ph.rho0 * std::pow(base, 1.0 / ph.gamma), ph);
}
}  // namespace

template <int D>
void EnergyBudget<D>::setDefined(const Scene& scene) {
  for (int a = 0; a < D; ++a) {
    const bool periodic = scene.faces[a][0] == FaceKind::periodic;
    if (periodic && scene.bodyAcceleration[a] != 0.0) defined_ = false;
    for (int side = 0; side < 2; ++side)
      for (double w : scene.wallVelocity[a][side])
        if (w != 0.0) defined_ = false;
  }
  for (const Phase& ph : scene.phases) {
    const auto lowest = lowestInternalEnergy(ph);
    if (!lowest) defined_ = false;
    lowest_.push_back(lowest.value_or(0.0));
  }
}

template <int D>
EnergyBudget<D>::EnergyBudget(const Scene& scene, const Parts& start, double roundOff)
    : scene_(&scene), start_(start), roundOff_(roundOff) {
  setDefined(scene);
}

template <int D>
EnergyBudget<D>::EnergyBudget(const Scene& scene, const Particles<D>& start) : scene_(&scene) {
  setDefined(scene);
  start_ = parts(start);
  double scale = 0;
  for (std::size_t i = 0; i < start.size(); ++i) {
    double gr = 0;
    for (int a = 0; a < D; ++a) gr += std::abs(scene.bodyAcceleration[a] * start.r[i][a]);
    scale += start.m[i] * gr;
  }
  roundOff_ = 1e-9 * scale;
}

template <int D>
typename EnergyBudget<D>::Parts EnergyBudget<D>::parts(const Particles<D>& s) const {
  Parts e;
  for (std::size_t i = 0; i < s.size(); ++i) {
    double gr = 0;
    for (int a = 0; a < D; ++a) gr += scene_->bodyAcceleration[a] * s.r[i][a];
    e.kinetic += 0.5 * s.m[i] * s.v[i].squaredNorm();
    e.internal +=
        s.m[i] * (internalEnergy(s.rho[i], scene_->phases[s.phase[i]]) - lowest_[s.phase[i]]);
    e.potential -= s.m[i] * gr;
  }
  return e;
}

template <int D>
std::optional<Failure> EnergyBudget<D>::check(const Particles<D>& s, const std::vector<int>& ids,
                                              double t, long step) const {
  if (!defined_) return std::nullopt;
  const Parts now = parts(s);
  const double work = start_.potential - now.potential;  // the body force's, since the start
  // A density diffusion term changes densities with no force's work, so E is not bounded by its
  // start: the term lifts a fluid at rest (a tank at rest, H/dx 20, Fourtakas delta 0.1: 0.28 J/m
  // a second, in proportion to delta, the same at half the time step or without artificial
  // viscosity, 3.7 times less at H/dx 40; verification/README.md). There the potential energy it
  // adds is not charged to the motion, which would otherwise have to give it back: at rest, the
  // start's internal energy is the whole budget and the lift uses it up (H/dx 20: by t sqrt(g/H) =
  // 45) while the fluid still rests. An oscillation the step amplifies grows K + U all the same.
  const bool diffusion = scene_->terms.densityDiffusion != DensityDiffusion::none;
  const double charged = diffusion ? std::max(work, 0.0) : work;
  const double available = start_.kinetic + start_.internal + charged;
  const double held = now.kinetic + now.internal;
  if (held <= 2 * available + roundOff_) return std::nullopt;
  std::size_t fastest = 0;
  for (std::size_t i = 1; i < s.size(); ++i)
    if (s.v[i].squaredNorm() > s.v[fastest].squaredNorm()) fastest = i;
  const char* unit = D == 3 ? "J" : D == 2 ? "J/m" : "J/m^2";  // per unit length or area below 3-D
  const double started = start_.kinetic + start_.internal;
  std::ostringstream m;
  m << "step " << step << ", t = " << t << " s: the fluid's kinetic plus internal energy, " << held
    << " " << unit << " (kinetic " << now.kinetic << "), is more than twice the " << available
    << " " << unit << " that its start (" << started << ") and the body force's work since ("
    << charged << ") gave it";
  m << " (energy growth: the time step amplifies undamped oscillations; more artificial "
    << "viscosity or a smaller cfl_acoustic damps them)";
  m << "; the fastest particle, " << ids[fastest] << ", moves at " << s.v[fastest].norm() << " m/s";
  return Failure{FailureCause::energy_growth, step, t, ids[fastest], m.str()};
}

template class EnergyBudget<1>;
template class EnergyBudget<2>;
template class EnergyBudget<3>;

}  // namespace sph
