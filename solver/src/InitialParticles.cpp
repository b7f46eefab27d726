#include "sph/InitialParticles.hpp"

#include <cmath>

#include "sph/EquationOfState.hpp"

namespace sph {

template <int D>
Particles<D> latticeParticles(const Scene& scene) {
  Particles<D> out;
  const double dx = scene.dx;
  double g = 0;
  for (double c : scene.bodyAcceleration) g += c * c;
  g = std::sqrt(g);
  for (const FluidBlock& b : scene.fluids) {
    const bool circle = b.shape == FluidBlock::Shape::circle;
    Vec<D> lo, hi;
    std::array<long, D> count;
    for (int a = 0; a < D; ++a) {
      lo[a] = circle ? b.center[a] - b.radius : b.lower[a];
      hi[a] = circle ? b.center[a] + b.radius : b.upper[a];
      count[a] = std::lround((hi[a] - lo[a]) / dx);
      if (circle) lo[a] = b.center[a] - 0.5 * dx * count[a];  // lattice symmetric about the centre
    }
    std::array<long, D> idx{};
    const Phase& ph = scene.phases[b.phase];
    for (;;) {
      Vec<D> x;
      for (int a = 0; a < D; ++a) x[a] = lo[a] + (idx[a] + 0.5) * dx;
      bool inside = true;
      if (circle) {
        double d2 = 0;
        for (int a = 0; a < D; ++a) d2 += (x[a] - b.center[a]) * (x[a] - b.center[a]);
        inside = d2 < b.radius * b.radius;
      }
      if (inside) {
        double rho = ph.rho0;
        if (b.hydrostatic)
          rho = TaitEquationOfState::density(ph.p0 + ph.rho0 * g * (b.surface - x[D - 1]), ph);
        out.r.push_back(x);
        Vec<D> v;
        for (int a = 0; a < D; ++a) v[a] = b.velocity[a];
        out.v.push_back(v);
        out.rho.push_back(rho);
        out.m.push_back(rho * std::pow(dx, D));
        out.h.push_back(scene.h0());
        out.p.push_back(TaitEquationOfState::pressure(rho, ph));
        out.phase.push_back(b.phase);
      }
      int a = 0;
      while (a < D && ++idx[a] >= count[a]) idx[a++] = 0;
      if (a == D) break;
    }
  }
  return out;
}

template Particles<1> latticeParticles<1>(const Scene&);
template Particles<2> latticeParticles<2>(const Scene&);
template Particles<3> latticeParticles<3>(const Scene&);

}  // namespace sph
