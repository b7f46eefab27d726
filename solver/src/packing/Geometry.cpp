#include "sph/packing/Geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sph::packing {

namespace {

constexpr double twoPi = 2.0 * std::numbers::pi;

double cross(const Vec2& u, const Vec2& v) {
  return u.x() * v.y() - u.y() * v.x();
}

// The angle from theta0 to theta, measured in the turning sense `sign` (+1 ccw, -1 cw), in [0, 2
// pi).
double angleFrom(double theta0, double theta, double sign) {
  double d = std::fmod(sign * (theta - theta0), twoPi);
  return d < 0.0 ? d + twoPi : d;
}

double sgn(double v) {
  return v < 0.0 ? -1.0 : 1.0;
}

// An arc cut at the angles theta = pi/2 + k pi, where dy/dtheta changes sign, so that every
// piece is monotone in y (the crossing-number test and the surface cut then meet each piece at
// most once).
void appendMonotone(const Piece& p, std::vector<Piece>& out) {
  if (!p.arc) {
    out.push_back(p);
    return;
  }
  const double sign = sgn(p.sweep), total = std::abs(p.sweep);
  std::vector<double> cuts;  // angle offsets from theta0 in the turning sense
  for (int k = -4; k <= 4; ++k) {
    const double d = angleFrom(p.theta0, 0.5 * std::numbers::pi + k * std::numbers::pi, sign);
    if (d > 1e-12 && d < total - 1e-12) cuts.push_back(d);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end(),
                         [](double x, double y) { return std::abs(x - y) < 1e-12; }),
             cuts.end());
  cuts.push_back(total);
  double from = 0.0;
  Vec2 start = p.a;
  for (double to : cuts) {
    Piece q = p;
    q.theta0 = p.theta0 + sign * from;
    q.sweep = sign * (to - from);
    q.a = start;
    q.b = to == total ? p.b
                      : Vec2(p.center + p.radius * Vec2(std::cos(q.theta0 + q.sweep),
                                                        std::sin(q.theta0 + q.sweep)));
    out.push_back(q);
    start = q.b, from = to;
  }
}

// x where a piece monotone in y crosses the horizontal line y.
double crossingX(const Piece& p, double y) {
  if (!p.arc) return p.a.x() + (y - p.a.y()) * (p.b.x() - p.a.x()) / (p.b.y() - p.a.y());
  const double dy = y - p.center.y();
  const double side = sgn(p.point(0.5 * p.length()).x() - p.center.x());
  return p.center.x() + side * std::sqrt(std::max(0.0, p.radius * p.radius - dy * dy));
}

// The piece p cut at the point X on it: [a, X] or [X, b].
Piece headUntil(const Piece& p, const Vec2& X) {
  Piece q = p;
  q.b = X;
  if (p.arc) {
    const double theta = std::atan2(X.y() - p.center.y(), X.x() - p.center.x());
    q.sweep = sgn(p.sweep) * angleFrom(p.theta0, theta, sgn(p.sweep));
  }
  return q;
}
Piece tailFrom(const Piece& p, const Vec2& X) {
  Piece q = p;
  q.a = X;
  if (p.arc) {
    const double theta = std::atan2(X.y() - p.center.y(), X.x() - p.center.x());
    const double done = angleFrom(p.theta0, theta, sgn(p.sweep));
    q.theta0 = theta;
    q.sweep = p.sweep - sgn(p.sweep) * done;
  }
  return q;
}

double signedArea(const std::vector<Piece>& pieces) {
  double A = 0.0;
  for (const Piece& p : pieces) {
    if (!p.arc) {
      A += 0.5 * cross(p.a, p.b);
    } else {
      // (1/2) closed integral of x dy - y dx along c + R (cos t, sin t).
      const double R = p.radius, t0 = p.theta0, t1 = p.theta0 + p.sweep;
      A += 0.5 * (R * R * p.sweep + p.center.x() * R * (std::sin(t1) - std::sin(t0)) -
                  p.center.y() * R * (std::cos(t1) - std::cos(t0)));
    }
  }
  return A;
}

}  // namespace

double Piece::length() const {
  return arc ? std::abs(sweep) * radius : (b - a).norm();
}

Vec2 Piece::point(double s) const {
  if (!arc) return a + s * tangent(0.0);
  const double t = theta0 + sgn(sweep) * s / radius;
  return center + radius * Vec2(std::cos(t), std::sin(t));
}

Vec2 Piece::tangent(double s) const {
  if (!arc) return (b - a).normalized();
  const double t = theta0 + sgn(sweep) * s / radius;
  return sgn(sweep) * Vec2(-std::sin(t), std::cos(t));
}

double Piece::distance(const Vec2& p) const {
  if (!arc) {
    const Vec2 ab = b - a;
    const double u = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (a + u * ab - p).norm();
  }
  const Vec2 r = p - center;
  const double theta = std::atan2(r.y(), r.x());
  if (angleFrom(theta0, theta, sgn(sweep)) <= std::abs(sweep)) return std::abs(r.norm() - radius);
  return std::min((p - a).norm(), (p - b).norm());
}

Vec2 Piece::nearest(const Vec2& p) const {
  if (!arc) {
    const Vec2 ab = b - a;
    return a + std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) * ab;
  }
  const Vec2 r = p - center;
  const double theta = std::atan2(r.y(), r.x());
  if (angleFrom(theta0, theta, sgn(sweep)) <= std::abs(sweep))
    return center + radius * Vec2(std::cos(theta), std::sin(theta));
  return (p - a).squaredNorm() <= (p - b).squaredNorm() ? a : b;
}

Piece Piece::reversed() const {
  Piece q = *this;
  std::swap(q.a, q.b);
  if (arc) q.theta0 = theta0 + sweep, q.sweep = -sweep;
  return q;
}

Piece segment(const Vec2& a, const Vec2& b, Piece::Kind kind) {
  Piece p;
  p.kind = kind, p.a = a, p.b = b;
  return p;
}

Piece arc(const Vec2& a, const Vec2& b, const Vec2& c, bool ccw) {
  Piece p;
  p.a = a, p.b = b, p.arc = true, p.center = c;
  p.radius = (a - c).norm();
  p.theta0 = std::atan2(a.y() - c.y(), a.x() - c.x());
  const double theta1 = std::atan2(b.y() - c.y(), b.x() - c.x());
  double d = angleFrom(p.theta0, theta1, ccw ? 1.0 : -1.0);
  if (d < 1e-12) d = twoPi;  // a == b: the full circle
  p.sweep = ccw ? d : -d;
  return p;
}

Region::Region(std::vector<Piece> pieces) {
  for (const Piece& p : pieces) appendMonotone(p, pieces_);
  if (signedArea(pieces_) < 0.0) {
    std::reverse(pieces_.begin(), pieces_.end());
    for (Piece& p : pieces_) p = p.reversed();
  }
}

double Region::area() const {
  return signedArea(pieces_);
}

bool Region::contains(const Vec2& p) const {
  // Crossing number of the ray from p towards +x; half-open in y so a vertex counts once.
  bool inside = false;
  for (const Piece& q : pieces_)
    if ((q.a.y() > p.y()) != (q.b.y() > p.y()) && crossingX(q, p.y()) > p.x()) inside = !inside;
  return inside;
}

double Region::distance(const Vec2& p) const {
  double d = INFINITY;
  for (const Piece& q : pieces_) d = std::min(d, q.distance(p));
  return d;
}

Vec2 Region::nearest(const Vec2& p) const {
  double d = INFINITY;
  Vec2 best = p;
  for (const Piece& q : pieces_)
    if (const double e = q.distance(p); e < d) d = e, best = q.nearest(p);
  return best;
}

void Region::bounds(Vec2& lo, Vec2& hi) const {
  lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
  for (const Piece& q : pieces_)
    for (int k = 0; k <= 16; ++k) {
      const Vec2 x = q.point(q.length() * k / 16.0);
      lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    }
}

Region belowSurface(const std::vector<Piece>& container, double surface) {
  const Region closed(container);  // counter-clockwise, monotone pieces
  const std::vector<Piece>& in = closed.pieces();
  Vec2 lo, hi;
  closed.bounds(lo, hi);
  const double tol = 1e-10 * std::max(1.0, (hi - lo).norm());
  auto below = [&](const Vec2& x) { return x.y() <= surface + tol; };
  const std::size_t n = in.size();
  std::size_t first = n;
  for (std::size_t i = 0; i < n; ++i)
    if (below(in[i].a)) {
      first = i;
      break;
    }
  if (first == n) throw std::invalid_argument("the free surface lies below the whole container");
  std::vector<Piece> out;
  Vec2 exit = Vec2::Zero();
  int crossings = 0;
  auto keep = [&](Piece p) {
    // A horizontal wall lying on the surface line is the free surface (a tank drawn to its
    // water line).
    if (!p.arc && std::abs(p.a.y() - surface) <= tol && std::abs(p.b.y() - surface) <= tol)
      p.kind = Piece::Kind::surface;
    out.push_back(p);
  };
  for (std::size_t k = 0; k < n; ++k) {
    const Piece& p = in[(first + k) % n];
    const bool ba = below(p.a), bb = below(p.b);
    if (ba && bb) {
      keep(p);
    } else if (ba) {
      const Vec2 X(crossingX(p, surface), surface);
      if ((X - p.a).norm() > tol) keep(headUntil(p, X));
      exit = X, ++crossings;
    } else if (bb) {
      const Vec2 X(crossingX(p, surface), surface);
      out.push_back(segment(exit, X, Piece::Kind::surface));
      if ((p.b - X).norm() > tol) keep(tailFrom(p, X));
      ++crossings;
    }
  }
  if (crossings != 0 && crossings != 2)
    throw std::invalid_argument("the free surface cuts the container " + std::to_string(crossings) +
                                " times; only one connected fluid region (2 cuts) is supported");
  return Region(out);
}

SolidLayers solidLayers(const Region& region, double dx, int layers) {
  const auto& P = region.pieces();
  const std::size_t n = P.size();
  SolidLayers out;
  auto add = [&](const Vec2& x, Piece::Kind kind) {
    // A safety net for boundaries that come back within the band (narrow features): a solid
    // particle may not sit inside the fluid or closer to it than dx/4.
    if (region.contains(x) || region.distance(x) < 0.25 * dx) return;
    out.position.push_back(x);
    out.kind.push_back(kind);
  };
  // Turning angle from piece i to piece i+1: > 0 a convex corner of the fluid (the layers turn
  // around the vertex), < 0 a concave one (the layers of the two pieces overlap and are cut).
  auto turn = [&](std::size_t i) {
    const Piece& p = P[i];
    const Piece& q = P[(i + 1) % n];
    const Vec2 t0 = p.tangent(p.length()), t1 = q.tangent(0.0);
    return std::atan2(cross(t0, t1), t0.dot(t1));
  };
  constexpr double smooth = 1e-6;  // joints turning less than this are tangent (split arcs)
  for (std::size_t i = 0; i < n; ++i) {
    const Piece& p = P[i];
    const Piece& prev = P[(i + n - 1) % n];
    const Piece& next = P[(i + 1) % n];
    const double L = p.length(), turnIn = turn((i + n - 1) % n), turnOut = turn(i);
    for (int k = 0; k < layers; ++k) {
      const double d = (k + 0.5) * dx;
      const double scale = p.arc ? (p.radius + (p.sweep > 0 ? d : -d)) / p.radius : 1.0;
      if (scale <= 0.0) continue;  // an arc bulging into the fluid, tighter than this layer
      auto offset = [&](double s) { return Vec2(p.point(s) + d * p.rightNormal(s)); };
      // At a concave corner the layer ends where it gets closer to the neighbouring piece than
      // d: the two layers then meet on the corner's bisector.
      auto cutAgainst = [&](const Piece& other, bool fromStart) {
        double in = 0.0, out = L;  // `in`: still too close to `other`
        if (fromStart) {
          if (other.distance(offset(L)) < d) return L;
        } else {
          in = L, out = 0.0;
          if (other.distance(offset(0.0)) < d) return 0.0;
        }
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (in + out);
          (other.distance(offset(mid)) < d * (1.0 - 1e-12) ? in : out) = mid;
        }
        return out;
      };
      const double s0 = turnIn < -smooth ? cutAgainst(prev, true) : 0.0;
      const double s1 = turnOut < -smooth ? cutAgainst(next, false) : L;
      if (s1 <= s0) continue;
      // Spacing at most dx (ceil): an under-dense spot in the solid draws fluid particles in
      // (w = -grad Gamma points at the lack of mass, section 2) and, once inside, on through
      // the band's outer edge, where Gamma falls to zero. Over-dense spots only repel.
      const int m = static_cast<int>(std::ceil((s1 - s0) * scale / dx - 1e-9));
      for (int j = 0; j < m; ++j) add(offset(s0 + (j + 0.5) * (s1 - s0) / m), p.kind);
      // Convex corner at the end of p: the layer turns on an arc of radius d around the vertex.
      if (turnOut > smooth) {
        const Vec2 n0 = p.rightNormal(L);
        const double phi0 = std::atan2(n0.y(), n0.x());
        const int mc = static_cast<int>(std::ceil(turnOut * d / dx - 1e-9));
        const Piece::Kind kind = p.kind == Piece::Kind::surface || next.kind == Piece::Kind::surface
                                     ? Piece::Kind::surface
                                     : Piece::Kind::wall;
        for (int j = 0; j < mc; ++j) {
          const double phi = phi0 + (j + 0.5) * turnOut / mc;
          add(Vec2(p.b + d * Vec2(std::cos(phi), std::sin(phi))), kind);
        }
      }
    }
  }
  return out;
}

std::vector<Vec2> latticeInside(const Region& region, double dx, const Vec2& origin) {
  Vec2 lo, hi;
  region.bounds(lo, hi);
  const int i0 = static_cast<int>(std::floor((lo.x() - origin.x()) / dx)) - 1;
  const int i1 = static_cast<int>(std::ceil((hi.x() - origin.x()) / dx)) + 1;
  const int j0 = static_cast<int>(std::floor((lo.y() - origin.y()) / dx)) - 1;
  const int j1 = static_cast<int>(std::ceil((hi.y() - origin.y()) / dx)) + 1;
  std::vector<Vec2> out;
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const Vec2 x = origin + dx * Vec2(i + 0.5, j + 0.5);
      if (region.contains(x)) out.push_back(x);
    }
  return out;
}

}  // namespace sph::packing
