#pragma once
// The fluid particles: one array per field, indexed by particle.
#include <cstddef>
#include <vector>

#include "sph/Vector.hpp"

namespace sph {

template <int D>
struct Particles {
  std::vector<Vec<D>> r;      // position [m]
  std::vector<Vec<D>> v;      // velocity [m/s]
  std::vector<double> rho;    // density [kg/m^3]
  std::vector<double> m;      // mass [kg]
  std::vector<double> h;      // smoothing length [m]
  std::vector<double> p;      // pressure [Pa], from the equation of state
  std::vector<int> phase;     // index into Scene::phases

  std::size_t size() const { return r.size(); }
  void resize(std::size_t n) {
    r.resize(n), v.resize(n), rho.resize(n), m.resize(n), h.resize(n), p.resize(n), phase.resize(n);
  }
};

}  // namespace sph
