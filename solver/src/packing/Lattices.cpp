#include "sph/packing/Lattices.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sph::packing {

std::string_view name(LatticeKind k) {
  switch (k) {
    case LatticeKind::cartesian:
      return "Cartesian";
    case LatticeKind::triangular:
      return "triangular";
    case LatticeKind::hexagonal:
      return "hexagonal";
  }
  // No default: -Wswitch names an enumerator missing above, and any other value is a bug
  // (an error here), never the last case.
  throw std::logic_error("name(LatticeKind): unknown value " + std::to_string(static_cast<int>(k)));
}

double nearestNeighbour(LatticeKind kind, double dx) {
  const double s3 = std::sqrt(3.0);
  switch (kind) {
    case LatticeKind::cartesian:
      return dx;
    case LatticeKind::triangular:
      return dx * std::sqrt(2.0 / s3);
    case LatticeKind::hexagonal:
      return dx * std::sqrt(4.0 / (3.0 * s3));
  }
  // No default: -Wswitch names an enumerator missing above, and any other value is a bug
  // (an error here), never the last case.
  throw std::logic_error("nearestNeighbour(LatticeKind): unknown value " +
                         std::to_string(static_cast<int>(kind)));
}

PeriodicLattice periodicLattice(LatticeKind kind, double a, double minSide) {
  const double s3 = std::sqrt(3.0);
  // One rectangular period (width w, height t) and its particles.
  double w = a, t = a;
  std::vector<Vec2> basis = {Vec2(0.5 * a, 0.5 * a)};
  if (kind == LatticeKind::triangular) {
    t = s3 * a;  // two rows, the second shifted by a/2
    basis = {Vec2(0.25 * a, 0.25 * t), Vec2(0.75 * a, 0.75 * t)};
  } else if (kind == LatticeKind::hexagonal) {
    // Honeycomb of bond b = a: rows of zigzag bonds; each particle has 3 neighbours at b.
    w = s3 * a, t = 3.0 * a;
    basis = {Vec2(0.0, 0.0), Vec2(0.0, a), Vec2(0.5 * s3 * a, 1.5 * a),
             Vec2(0.5 * s3 * a, 2.5 * a)};
    for (Vec2& p : basis) p += Vec2(0.25 * w, 0.25 * a);
  }
  const int nx = static_cast<int>(std::ceil(minSide / w - 1e-9));
  const int ny = static_cast<int>(std::ceil(minSide / t - 1e-9));
  PeriodicLattice out;
  out.box.hi = Vec2(nx * w, ny * t);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      for (const Vec2& b : basis) out.position.push_back(b + Vec2(i * w, j * t));
  return out;
}

}  // namespace sph::packing
