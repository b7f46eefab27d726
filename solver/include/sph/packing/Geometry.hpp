#pragma once
// 2-D fluid regions for the particle packing algorithm (Colagrossi et al. 2012, section 2): a
// closed boundary of straight walls and circular arcs, cut by a horizontal free surface. The
// region's boundary (walls below the surface plus the surface itself) is what the fixed solid
// particles line, one layer per dx out to the kernel support.
#include <string>
#include <vector>

#include "sph/Vector.hpp"

namespace sph::packing {

using Vec2 = Vec<2>;

// One piece of a closed path: the segment a -> b, or the circular arc from a to b around
// `center` sweeping `sweep` radians (> 0 counter-clockwise, < 0 clockwise).
struct Piece {
  enum class Kind { wall, surface } kind = Kind::wall;
  Vec2 a = Vec2::Zero(), b = Vec2::Zero();
  bool arc = false;
  Vec2 center = Vec2::Zero();
  double radius = 0.0, theta0 = 0.0, sweep = 0.0;

  double length() const;
  Vec2 point(double s) const;    // at arc length s from a
  Vec2 tangent(double s) const;  // unit, in the direction of travel
  // Unit normal to the right of the direction of travel: outward for a counter-clockwise region.
  Vec2 rightNormal(double s) const {
    const Vec2 t = tangent(s);
    return Vec2(t.y(), -t.x());
  }
  double distance(const Vec2& p) const;  // Euclidean distance from p to the piece
  Vec2 nearest(const Vec2& p) const;     // the point of the piece nearest to p
  Piece reversed() const;
};

Piece segment(const Vec2& a, const Vec2& b, Piece::Kind kind = Piece::Kind::wall);
// Arc from a to b around c; `ccw` picks the turning sense; a == b gives the full circle.
Piece arc(const Vec2& a, const Vec2& b, const Vec2& c, bool ccw);

// A closed, simple path oriented counter-clockwise (the region on its left).
class Region {
 public:
  Region() = default;
  // `pieces` must join end to start and close; a clockwise path is reversed.
  explicit Region(std::vector<Piece> pieces);

  const std::vector<Piece>& pieces() const { return pieces_; }
  double area() const;                   // Green's theorem, exact for segments and arcs
  bool contains(const Vec2& p) const;    // crossing number, exact for arcs
  double distance(const Vec2& p) const;  // to the boundary
  Vec2 nearest(const Vec2& p) const;     // the boundary point nearest to p
  void bounds(Vec2& lo, Vec2& hi) const;

 private:
  std::vector<Piece> pieces_;  // arcs split into pieces monotone in y
};

// The fluid region: the inside of `container` below y = surface (pieces on the surface become
// Kind::surface). Throws std::invalid_argument when the surface does not cut the container into
// exactly one region (0 or 2 crossings).
Region belowSurface(const std::vector<Piece>& container, double surface);

// Fixed solid particles lining the region from outside: layer k at distance (k + 1/2) dx for
// k = 0 .. layers - 1, about dx apart along each layer; at a convex corner the layers turn on
// arcs around the vertex, at a concave one they are cut where they meet. `kind[i]` says whether
// solid particle i lines a wall or the free surface.
struct SolidLayers {
  std::vector<Vec2> position;
  std::vector<Piece::Kind> kind;
};
SolidLayers solidLayers(const Region& region, double dx, int layers);

// Nodes origin + (i + 1/2, j + 1/2) dx of the Cartesian lattice that lie inside the region.
std::vector<Vec2> latticeInside(const Region& region, double dx, const Vec2& origin);

}  // namespace sph::packing
