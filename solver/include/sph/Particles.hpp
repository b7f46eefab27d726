#pragma once
// The fluid particles: one array per field, indexed by particle.
#include <cstddef>
#include <vector>

#include "sph/CacheLines.hpp"
#include "sph/Vector.hpp"

namespace sph {

template <int D>
struct Particles {
  LineVector<Vec<D>> r;    // position [m]
  LineVector<Vec<D>> v;    // velocity [m/s]
  LineVector<double> rho;  // density [kg/m^3]
  LineVector<double> m;    // mass [kg]
  LineVector<double> h;    // smoothing length [m]
  LineVector<double> p;    // pressure [Pa], from the equation of state
  LineVector<int> phase;   // index into Scene::phases

  std::size_t size() const { return r.size(); }
  void resize(std::size_t n) {
    r.resize(n), v.resize(n), rho.resize(n), m.resize(n), h.resize(n), p.resize(n), phase.resize(n);
  }
};

}  // namespace sph
