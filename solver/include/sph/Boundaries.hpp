#pragma once
// The domain box and what each of its faces is: a ghost-particle wall (free or no slip), a
// periodic face, or open (a particle that leaves through it has left the domain).
#include <array>
#include <string_view>

#include "sph/Vector.hpp"

namespace sph {

enum class FaceKind { open, free_slip, no_slip, periodic };
std::string_view name(FaceKind);

template <int D>
struct Boundaries {
  Vec<D> lower = Vec<D>::Zero();
  Vec<D> upper = Vec<D>::Ones();
  std::array<std::array<FaceKind, 2>, D> face{};        // [axis][0 lower, 1 upper]
  std::array<std::array<Vec<D>, 2>, D> wallVelocity{};  // for no-slip walls (Couette)

  Boundaries() {
    for (auto& a : face) a = {FaceKind::open, FaceKind::open};
    for (auto& a : wallVelocity) a = {Vec<D>::Zero(), Vec<D>::Zero()};
  }
  static bool isWall(FaceKind k) { return k == FaceKind::free_slip || k == FaceKind::no_slip; }
  bool anyWall() const {
    for (const auto& a : face)
      if (isWall(a[0]) || isWall(a[1])) return true;
    return false;
  }
  bool anyPeriodic() const {
    for (const auto& a : face)
      if (a[0] == FaceKind::periodic) return true;
    return false;
  }
};

}  // namespace sph
