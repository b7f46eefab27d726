// The packing geometry (sph/packing/Geometry.hpp) and scene file: exact areas, the free-surface
// cut, the solid layers (outside the fluid, within the kernel support, about dx apart), and
// errors that name the file and the key.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "Results.hpp"
#include "sph/packing/Geometry.hpp"
#include "sph/packing/PackingScene.hpp"

namespace sph::packing {
namespace {

const std::vector<Piece> trapezoid = {
    segment({0.0, 1.2}, {0.0, 0.0}), segment({0.0, 0.0}, {0.5, 0.0}),
    segment({0.5, 0.0}, {1.7, 1.2}), segment({1.7, 1.2}, {0.0, 1.2})};

TEST(PackingGeometry, AreasAreExact) {
  // Trapezoid below H = 1: (0.5 + 1.5) / 2 = 1. A half disc of radius 1 filled to its centre
  // line: pi/2. Green's theorem is exact for both, so only round-off remains.
  EXPECT_NEAR(belowSurface(trapezoid, 1.0).area(), 1.0, 1e-13);
  const std::vector<Piece> circle = {arc({1.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}, true)};
  EXPECT_NEAR(Region(circle).area(), std::numbers::pi, 1e-13);
  EXPECT_NEAR(belowSurface(circle, 0.0).area(), 0.5 * std::numbers::pi, 1e-13);
  // A clockwise path is reversed to counter-clockwise.
  std::vector<Piece> reversed;
  for (auto it = trapezoid.rbegin(); it != trapezoid.rend(); ++it)
    reversed.push_back(it->reversed());
  EXPECT_NEAR(belowSurface(reversed, 1.0).area(), 1.0, 1e-13);
}

TEST(PackingGeometry, LatticeFillsTheRegion) {
  // Node counts of a Cartesian lattice differ from area / dx^2 by the nodes cut along the
  // boundary, at most perimeter / dx (one node per dx of boundary).
  const Region r = belowSurface(trapezoid, 1.0);
  const double dx = 0.04;
  const auto nodes = latticeInside(r, dx, Vec2::Zero());
  const double perimeter = 1.0 + 0.5 + std::sqrt(2.0) + 1.5;
  EXPECT_LE(std::abs(static_cast<double>(nodes.size()) - 1.0 / (dx * dx)), perimeter / dx);
  for (const Vec2& x : nodes)
    EXPECT_TRUE(x.y() < 1.0 && x.y() > 0.0 && x.x() > 0.0 && x.y() > x.x() - 0.5);
}

void checkLayers(verification::Results& r, const Region& region, double dx, int layers,
                 const std::string& what) {
  const SolidLayers s = solidLayers(region, dx, layers);
  double minOwn = INFINITY, maxDepth = 0.0, minGap = INFINITY;
  for (std::size_t i = 0; i < s.position.size(); ++i) {
    EXPECT_FALSE(region.contains(s.position[i])) << what << ": solid particle inside the fluid";
    const double d = region.distance(s.position[i]);
    minOwn = std::min(minOwn, d), maxDepth = std::max(maxDepth, d);
    for (std::size_t j = 0; j < i; ++j)
      minGap = std::min(minGap, (s.position[i] - s.position[j]).norm());
  }
  // Layer k sits at (k + 1/2) dx: the first at dx/2 from the fluid, the last at (layers - 1/2) dx.
  EXPECT_TRUE(r.check(what + ": min distance solid-fluid boundary / dx", minOwn / dx,
                      ">=", 0.5 - 1e-9, "layer 0 at dx/2 (construction)"));
  EXPECT_TRUE(r.check(what + ": max distance / dx", maxDepth / dx, "<=", layers - 0.5 + 1e-9,
                      "last layer at (layers - 1/2) dx (construction)"));
  // Two solid particles closer than half a spacing would be a spike in Gamma; the layers are dx
  // apart and cut on the bisector at concave corners, where neighbours stay >= dx cos(turn/2).
  EXPECT_TRUE(r.check(what + ": min solid-solid spacing / dx", minGap / dx, ">=", 0.4,
                      "dx spacing within a layer; cut layers meet on the corner bisector"));
}

TEST(PackingGeometry, SolidLayersLineWallsAndSurface) {
  verification::Results r;
  checkLayers(r, belowSurface(trapezoid, 1.0), 0.04, 4, "trapezoidal tank");
  // A round-bottomed tank (arc tangent to the left wall), a step where the arc meets the flat
  // bottom (a concave corner, 270 degrees inside), a bump into the fluid (a clockwise arc with
  // two 90-degree feet), an obtuse corner and an acute one where the slope meets the surface.
  const std::vector<Piece> bumpy = {
      segment({-1.0, 1.5}, {-1.0, 0.0}), arc({-1.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}, true),
      segment({1.0, 0.0}, {1.2, 0.0}),   arc({1.2, 0.0}, {1.6, 0.0}, {1.4, 0.0}, false),
      segment({1.6, 0.0}, {1.8, 0.0}),   segment({1.8, 0.0}, {3.0, 1.5}),
      segment({3.0, 1.5}, {-1.0, 1.5})};
  EXPECT_NEAR(belowSurface(bumpy, 1.0).area(),
              0.5 * std::numbers::pi + 2.8 + 0.5 * 1.0 * 0.8 - 0.5 * std::numbers::pi * 0.04,
              1e-12);
  checkLayers(r, belowSurface(bumpy, 1.0), 0.05, 4, "tank with arcs");
}

// Region::nearest: the boundary point the distance is measured to, on a segment, an arc and a
// vertex (used to reflect particles back across curved walls, TankRun).
TEST(PackingGeometry, NearestBoundaryPoint) {
  const Region trap(trapezoid);
  // Beyond the 45-degree wall x - y = 0.5 by 0.01 along its outward normal (1, -1)/sqrt(2).
  const Vec2 onSlope(1.2, 0.7), out = onSlope + 0.01 * Vec2(1.0, -1.0).normalized();
  EXPECT_NEAR((trap.nearest(out) - onSlope).norm(), 0.0, 1e-14);
  EXPECT_NEAR((trap.nearest(out) - out).norm(), trap.distance(out), 1e-14);
  // Below the bottom's left end: the vertex (0, 0).
  EXPECT_NEAR((trap.nearest(Vec2(-0.01, -0.02)) - Vec2(0.0, 0.0)).norm(), 0.0, 1e-14);
  // Outside a half disc's arc: on the radius through the point.
  const Region bowl(std::vector<Piece>{arc({-1.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}, true),
                                       segment({1.0, 0.0}, {-1.0, 0.0})});
  const Vec2 p = 1.03 * Vec2(std::cos(-1.0), std::sin(-1.0));
  EXPECT_NEAR((bowl.nearest(p) - p / 1.03).norm(), 0.0, 1e-14);
  EXPECT_NEAR((bowl.nearest(p) - p).norm(), bowl.distance(p), 1e-14);
}

TEST(PackingGeometry, SceneErrorsNameFileAndKey) {
  const std::string head = "name = \"t\"\n[fluid]\nc0 = 10.0\n[packing]\ndx = 0.1\n";
  auto message = [&](const std::string& geometry) {
    try {
      parsePackingScene(head + geometry, "scene.toml");
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string open =
      "[geometry]\nstart = [0.0, 0.0]\n[[geometry.path]]\nto = [1.0, 0.0]\n[[geometry.path]]\nto = "
      "[1.0, 1.0]\n";
  // 8:1, the line and column of the first [[geometry.path]], where the TOML puts the array.
  EXPECT_EQ(message(open),
            "scene.toml:8:1: key 'geometry.path': does not close: the last 'to' must equal "
            "'start'");
  const std::string badArc =
      "[geometry]\nstart = [1.0, 0.0]\n[[geometry.path]]\nto = [-1.0, 0.0]\ncenter = [0.5, 0.0]\n"
      "[[geometry.path]]\nto = [1.0, 0.0]\n";
  EXPECT_NE(message(badArc).find("key 'geometry.path[0].center'"), std::string::npos)
      << message(badArc);
  const std::string typo = open + "[[geometry.path]]\nto = [0.0, 0.0]\nsurfce = 1.0\n";
  EXPECT_NE(message(typo).find("key 'geometry.path[2].surfce': unknown key"), std::string::npos)
      << message(typo);
  const std::string square =
      "[geometry]\nstart = [0.0, 0.0]\nsurface = 0.5\n[[geometry.path]]\nto = [1.0, 0.0]\n"
      "[[geometry.path]]\nto = [1.0, 1.0]\n[[geometry.path]]\nto = [0.0, "
      "1.0]\n[[geometry.path]]\nto = [0.0, 0.0]\n";
  EXPECT_EQ(message(square), "no error");
  EXPECT_NE(message(square + "[packing.extra]\n").find("scene.toml"), std::string::npos);
}

}  // namespace
}  // namespace sph::packing
