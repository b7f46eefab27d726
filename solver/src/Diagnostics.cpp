#include "sph/Diagnostics.hpp"

#include <algorithm>
#include <cmath>

namespace sph {

template <int D>
double probe(const Scene& scene, const Probe& p, const Particles<D>& s,
             const InteractionSet<D>& set) {
  const int up = D - 1;
  const double floor = scene.lower[up];
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

#define SPH_INSTANTIATE(D)                                                                      \
  template Diagnostics diagnose<D>(const Scene&, const Particles<D>&, const InteractionSet<D>&); \
  template double probe<D>(const Scene&, const Probe&, const Particles<D>&, const InteractionSet<D>&);
SPH_INSTANTIATE(1)
SPH_INSTANTIATE(2)
SPH_INSTANTIATE(3)

}  // namespace sph
