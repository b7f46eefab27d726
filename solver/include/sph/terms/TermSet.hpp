#pragma once
// A set of pair terms composed at compile time: what the pair loop evaluates for each pair and
// each particle. The terms' shares are summed in the order of the list, then eq. (12)'s pair
// force is formed once from the bracket and the viscous factor:
//   Q = bracket F r_ij - viscous v_ij,  dv_i/dt -= m_j Q,  dv_j/dt += m_i Q.
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "sph/terms/PairValues.hpp"

namespace sph::terms {

namespace detail {
// A term's sums of its own a particle (its sums<D>), 0 for a term without.
template <int D, class T>
constexpr int ownSumsOf() {
  if constexpr (requires { T::template sums<D>; })
    return T::template sums<D>;
  else
    return 0;
}
}  // namespace detail

template <class... Ts>
class TermSet {
 public:
  explicit TermSet(const TermParameters& t) : terms_(make<Ts>(t)...) {}

  // What its terms read; the masses also for eq. (12)'s pair force below, the densities for
  // 1/(rho_i + rho_j).
  static constexpr Reads reads{
      .mass = true,
      .density = (Ts::reads.density || ...) || (Ts::reads.rhoSumInverse || ...),
      .densityInverse = (Ts::reads.densityInverse || ...),
      .pressure = (Ts::reads.pressure || ...),
      .viscosity = (Ts::reads.viscosity || ...),
      .restDensity = (Ts::reads.restDensity || ...),
      .densityGradient = (Ts::reads.densityGradient || ...),
      .etaInverse = (Ts::reads.etaInverse || ...),
      .rhoSumInverse = (Ts::reads.rhoSumInverse || ...)};
  static constexpr Writes writes{(Ts::writes.density || ...), (Ts::writes.smoothingLength || ...),
                                 (Ts::writes.bracket || ...), (Ts::writes.viscous || ...)};
  // The pair's shared values every set computes (DESIGN.md 1; quadratic kernel): h_ij 1,
  // 1/h_ij 1, the kernel's F 7, v_ij and v.r 5; and 1/(r^2 + eta^2) 4 where a term reads it.
  static constexpr Flops flops{14 + (reads.etaInverse ? 4 : 0) + (Ts::flops.shared + ... + 0),
                               (Ts::flops.sided + ... + 0)};

  // The sums of its own that the set's term with such sums has (PairSums::ownI), a particle.
  template <int D>
  static constexpr int ownSums = (detail::ownSumsOf<D, Ts>() + ... + 0);
  static_assert(((detail::ownSumsOf<1, Ts>() > 0 ? 1 : 0) + ... + 0) <= 1,
                "at most one term of a set has sums of its own");

  // i's and j's shares of one pair, in the order of D axes: {d rho/dt, eq. 13's sum, dv/dt}, and
  // the own sums.
  template <int D, class V>
  struct Shares {
    V rho, h, v[3];
    V own[ownSums<D> > 0 ? ownSums<D> : 1];
  };
  template <int D, class Kernel, class S, class V>
  void pair(const PairValues<S, V>& p, Shares<D, V>& i, Shares<D, V>& j) const {
    PairSums<V> s;
    auto one = [&]<class T>(const T& t) {
      if constexpr (requires { t.template pair<Kernel, D>(p, s); })
        t.template pair<Kernel, D>(p, s);
      else
        t.pair(p, s);
    };
    std::apply([&](const auto&... t) { (one(t), ...); }, terms_);
    i.rho = s.rhoI, j.rho = s.rhoJ, i.h = s.hI, j.h = s.hJ;
    for (int k = 0; k < ownSums<D>; ++k) i.own[k] = s.ownI[k], j.own[k] = s.ownJ[k];
    const V G = s.bracket * p.F;
    auto Q = [&](V r, V v) {
      if constexpr (writes.viscous)
        return G * r - s.viscous * v;
      else
        return G * r;
    };
    const V Qx = Q(p.rx, p.vx), Qy = D > 1 ? Q(p.ry, p.vy) : V{}, Qz = D > 2 ? Q(p.rz, p.vz) : V{};
    i.v[0] = -(p.j.m * Qx), i.v[1] = -(p.j.m * Qy), i.v[2] = -(p.j.m * Qz);
    j.v[0] = p.i.m * Qx, j.v[1] = p.i.m * Qy, j.v[2] = p.i.m * Qz;
  }

  // A fluid particle's finish steps, in the order of the list.
  template <int D, class Vec>
  void finish(ParticleRates<Vec>& r, const ParticleState<Vec>& x) const {
    auto one = [&]<class T>(const T&) {
      if constexpr (requires { T::template finish<D>(r, x); }) T::template finish<D>(r, x);
    };
    std::apply([&](const auto&... t) { (one(t), ...); }, terms_);
  }

  static std::vector<std::string> names() {
    std::vector<std::string> out;
    ((Ts::name.empty() ? void() : void(out.emplace_back(Ts::name))), ...);
    return out;
  }

 private:
  template <class T>
  static T make(const TermParameters& t) {
    if constexpr (std::is_constructible_v<T, const TermParameters&>)
      return T(t);
    else
      return T{};
  }
  std::tuple<Ts...> terms_;
};

}  // namespace sph::terms
