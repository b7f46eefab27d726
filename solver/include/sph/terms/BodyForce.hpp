#pragma once
// A uniform body acceleration g (F/rho of Lobovsky & Kren eq. 12), added to dv/dt once a
// particle's pairs are summed: no pair share. The simulation names it in the run file where
// g is not zero.
#include "sph/terms/PairValues.hpp"

namespace sph::terms {

struct BodyForce {
  static constexpr std::string_view name = "";
  static constexpr Reads reads{};
  static constexpr Writes writes{};
  static constexpr Flops flops{};
  template <class S, class V>
  static void pair(const PairValues<S, V>&, PairSums<V>&) {}
  template <int D, class Vec>
  static void finish(ParticleRates<Vec>& r, const ParticleState<Vec>& x) {
    for (int a = 0; a < D; ++a) r.dvdt[a] += x.g[a];
  }
};

}  // namespace sph::terms
