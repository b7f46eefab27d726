#include "sph/Diagnostics.hpp"

#include <algorithm>
#include <cmath>

#include "sph/EquationOfState.hpp"
#include "sph/Kernels.hpp"

namespace sph {

namespace {

double largestH(const LineVector<double>& h) {
  double most = 0;
  for (double v : h) most = std::max(most, v);
  return most;
}

// Diagnostics.hpp, wall_pressure.
template <int D>
double wallPressure(const Scene& scene, const Vec<D>& x, const Particles<D>& s) {
  const double reach = 2.0 * largestH(s.h);  // lambda h, lambda = 2 for every kernel
  Vec<D> g;
  for (int a = 0; a < D; ++a) g[a] = scene.bodyAcceleration[a];
  double sumVW = 0, sumVPW = 0, sumMRgW = 0;
  for (std::size_t f = 0; f < s.size(); ++f) {
    const Vec<D> r_xf = x - s.r[f];
    const double r2 = r_xf.squaredNorm();
    if (r2 >= reach * reach) continue;
    const double W = kernelValue<D>(scene.kernel, std::sqrt(r2), s.h[f]);
    if (W == 0.0) continue;
    const double V = s.m[f] / s.rho[f];
    const double p = TaitEquationOfState::pressure(s.rho[f], scene.phases[s.phase[f]]);
    sumVW += V * W, sumVPW += V * p * W, sumMRgW += s.m[f] * g.dot(r_xf) * W;
  }
  return sumVW >= 0.1 ? (sumVPW + sumMRgW) / sumVW : 0.0;
}

// Diagnostics.hpp, water_height.
template <int D>
double waterHeight(const Scene& scene, const std::vector<double>& at, const Particles<D>& s) {
  const int up = D - 1;
  const double reach = 2.0 * largestH(s.h);
  std::vector<std::size_t> near;  // the particles within reach of the vertical line
  double top = scene.lower[up];
  for (std::size_t f = 0; f < s.size(); ++f) {
    double d2 = 0;
    for (int a = 0; a < up; ++a) d2 += (s.r[f][a] - at[a]) * (s.r[f][a] - at[a]);
    if (d2 < reach * reach) near.push_back(f), top = std::max(top, s.r[f][up]);
  }
  if (near.empty()) return 0.0;
  // A floor that is a wall cuts the support of the points near it; each particle's mirror image
  // beneath the floor fills the cut (as mirror ghosts do), so that phi is 1 down to the floor in
  // a wet column and a film thinner than the support still counts.
  const double floor = scene.lower[up], dz = scene.dx / 8.0;
  const bool mirrored = Boundaries<D>::isWall(scene.faces[up][0]);
  const auto phi = [&](double z) {
    Vec<D> x;
    for (int a = 0; a < up; ++a) x[a] = at[a];
    x[up] = z;
    double sum = 0;
    for (std::size_t f : near) {
      Vec<D> r = x - s.r[f];
      double w = kernelValue<D>(scene.kernel, r.norm(), s.h[f]);
      if (mirrored) {
        r[up] = z + s.r[f][up] - 2 * floor;
        w += kernelValue<D>(scene.kernel, r.norm(), s.h[f]);
      }
      sum += s.m[f] / s.rho[f] * w;
    }
    return sum;
  };
  // Downward from above the highest particle near the line to the floor: the first sample
  // with phi >= 1/2 and the one above it bracket the crossing.
  double zAbove = top + reach, phiAbove = phi(zAbove);
  for (double z = zAbove - dz; z >= floor - 1e-12 * dz; z -= dz) {
    const double here = phi(z);
    if (here >= 0.5) {
      const double frac = phiAbove < here ? (here - 0.5) / (here - phiAbove) : 0.0;
      return z + frac * (zAbove - z) - floor;
    }
    zAbove = z, phiAbove = here;
  }
  return 0.0;
}

}  // namespace

template <int D>
double probe(const Scene& scene, const Probe& p, const Particles<D>& s,
             const InteractionSet<D>& set) {
  const int up = D - 1;
  const double floor = scene.lower[up];
  if (p.type == "wall_pressure") {
    Vec<D> x;
    for (int a = 0; a < D; ++a) x[a] = p.position[a];
    return wallPressure<D>(scene, x, s);
  }
  if (p.type == "water_height") {
    if constexpr (D > 1) return waterHeight<D>(scene, p.position, s);
    return 0.0;  // refused by the scene reader
  }
  if (p.type == "surge_front") {
    double front = scene.lower[0];
    for (const auto& r : s.r) front = std::max(front, r[0]);
    return front;
  }
  if (p.type == "column_height" || p.type == "water_level") {
    const bool gauge = p.type == "water_level";
    double top = floor;
    bool any = false;
    for (const auto& r : s.r) {
      const bool in = gauge ? std::abs(r[0] - p.x) <= scene.dx : r[0] <= p.x;
      if (in) top = std::max(top, r[up]), any = true;
    }
    if (!any) return 0.0;
    return top - floor + (gauge ? 0.5 * scene.dx : 0.0);
  }
  // pressure: sum_j V_j p_j W_j / sum_j V_j W_j over fluid and halo.
  Vec<D> x;
  for (int a = 0; a < D; ++a) x[a] = p.position[a];
  double num = 0, den = 0;
  for (std::size_t j = 0; j < set.size(); ++j) {
    const double w = kernelValue<D>(scene.kernel, (x - set.x[j]).norm(), set.h[j]);
    if (w == 0.0) continue;
    const double vol = set.m[j] / set.rho[j];
    num += vol * set.p[j] * w, den += vol * w;
  }
  return den > 0 ? num / den : 0.0;
}

template <int D>
Diagnostics diagnose(const Scene& scene, const Particles<D>& s, const InteractionSet<D>& set) {
  Diagnostics d;
  d.phaseVolume.assign(scene.phases.size(), 0.0);
  d.rhoMin = s.size() ? s.rho[0] : 0, d.rhoMax = d.rhoMin;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double v2 = s.v[i].squaredNorm();
    d.kineticEnergy += 0.5 * s.m[i] * v2;
    d.maxSpeed = std::max(d.maxSpeed, std::sqrt(v2));
    d.rhoMin = std::min(d.rhoMin, s.rho[i]), d.rhoMax = std::max(d.rhoMax, s.rho[i]);
    d.phaseVolume[s.phase[i]] += s.m[i] / s.rho[i];
  }
  for (double v : d.phaseVolume) d.volume += v;
  for (const auto& p : scene.probes) d.probes.push_back(probe<D>(scene, p, s, set));
  return d;
}

#define SPH_INSTANTIATE(D)                                                                       \
  template Diagnostics diagnose<D>(const Scene&, const Particles<D>&, const InteractionSet<D>&); \
  template double probe<D>(const Scene&, const Probe&, const Particles<D>&,                      \
                           const InteractionSet<D>&);
SPH_INSTANTIATE(1)
SPH_INSTANTIATE(2)
SPH_INSTANTIATE(3)

}  // namespace sph
