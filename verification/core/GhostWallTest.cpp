// Issue 2, part 5: ghost-particle walls (buildInteractionSet; Libersky et al. 1993, Colagrossi &
// Landrini 2003; DESIGN.md section 1, "Walls").
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "Results.hpp"
#include "sph/EquationOfState.hpp"
#include "sph/InteractionSet.hpp"
#include "sph/Kernels.hpp"

namespace {

using sph::FaceKind;

template <int D>
sph::Boundaries<D> box(FaceKind kind) {
  sph::Boundaries<D> b;
  for (int a = 0; a < D; ++a) {
    b.lower[a] = -0.5 + 0.25 * a;
    b.upper[a] = 1.0 + 0.5 * a;
    b.face[a] = {kind, kind};
  }
  return b;
}

const std::vector<sph::Phase> water{{"water", 1000.0, 20.0, 1e-3, 0.0, 7.0}};

template <int D>
sph::Particles<D> single(const sph::Vec<D>& x, const sph::Vec<D>& v, double rho) {
  sph::Particles<D> p;
  p.r = {x}, p.v = {v}, p.rho = {rho}, p.m = {0.01}, p.h = {0.05}, p.phase = {0};
  p.p = {sph::TaitEquationOfState::pressure(rho, water[0])};
  return p;
}

// The entries other than the fluid particle itself.
template <int D>
std::vector<std::size_t> ghosts(const sph::InteractionSet<D>& s) {
  std::vector<std::size_t> g;
  for (std::size_t k = s.nFluid; k < s.size(); ++k) g.push_back(k);
  return g;
}

TEST(GhostWalls, MirrorAtEachWallFreeSlip) {
  const auto b = box<2>(FaceKind::free_slip);
  const double reach = 0.1;
  for (int a = 0; a < 2; ++a)
    for (int side = 0; side < 2; ++side) {
      sph::Vec<2> x(0.3, 0.6);
      const double wall = side == 0 ? b.lower[a] : b.upper[a];
      x[a] = wall + (side == 0 ? 0.037 : -0.037);
      const sph::Vec<2> v(0.7, -1.3);
      sph::InteractionSet<2> s;
      sph::buildInteractionSet<2>(single<2>(x, v, 1010.0), water, b, reach, sph::Vec<2>::Zero(), s);
      const auto g = ghosts(s);
      ASSERT_EQ(g.size(), 1u) << "axis " << a << " side " << side;
      const std::size_t k = g[0];
      // Mirror position: x_g = 2 x_wall - x along the normal, unchanged along the wall. Exact
      // in floating point up to the one rounding of 2 x_wall - x.
      EXPECT_DOUBLE_EQ(s.x[k][a], 2.0 * wall - x[a]);
      EXPECT_EQ(s.x[k][1 - a], x[1 - a]);
      // Free slip: the normal velocity reverses, the tangential one is kept.
      EXPECT_EQ(s.v[k][a], -v[a]);
      EXPECT_EQ(s.v[k][1 - a], v[1 - a]);
      // The ghost keeps the density, pressure, mass and h of its source (mirror mode).
      EXPECT_EQ(s.rho[k], s.rho[0]);
      EXPECT_EQ(s.p[k], s.p[0]);
      EXPECT_EQ(s.m[k], s.m[0]);
      EXPECT_EQ(s.h[k], s.h[0]);
      EXPECT_EQ(s.source[k], 0);
    }
}

TEST(GhostWalls, NoGhostBeyondReach) {
  const auto b = box<2>(FaceKind::free_slip);
  sph::InteractionSet<2> s;
  // Exactly the reach (0.125, representable, so the distance is exact) from the lower x wall:
  // the ghost would sit 2 x 0.125 away, outside the reach of any pair.
  const sph::Vec<2> x(b.lower[0] + 0.125, 0.5);
  sph::buildInteractionSet<2>(single<2>(x, sph::Vec<2>::Zero(), 1000.0), water, b, 0.125,
                              sph::Vec<2>::Zero(), s);
  EXPECT_EQ(s.size(), 1u);
}

TEST(GhostWalls, NoSlipRelativeToWallVelocity) {
  auto b = box<2>(FaceKind::no_slip);
  b.wallVelocity[1][1] = sph::Vec<2>(2.5e-5, 0.0);  // Couette's moving top plate
  const sph::Vec<2> x(0.3, b.upper[1] - 0.02), v(1.0e-5, 3.0e-6);
  sph::InteractionSet<2> s;
  sph::buildInteractionSet<2>(single<2>(x, v, 1000.0), water, b, 0.1, sph::Vec<2>::Zero(), s);
  ASSERT_EQ(s.size(), 2u);
  // v_g = 2 v_wall - v: the mean of source and ghost is the wall's velocity on both axes.
  EXPECT_DOUBLE_EQ(s.v[1][0], 2.0 * 2.5e-5 - 1.0e-5);
  EXPECT_DOUBLE_EQ(s.v[1][1], -3.0e-6);
}

TEST(GhostWalls, CornerDoubleMirror2D) {
  const auto b = box<2>(FaceKind::free_slip);
  const sph::Vec<2> x(b.lower[0] + 0.02, b.upper[1] - 0.03), v(0.4, 0.9);
  sph::InteractionSet<2> s;
  sph::buildInteractionSet<2>(single<2>(x, v, 1000.0), water, b, 0.1, sph::Vec<2>::Zero(), s);
  const auto g = ghosts(s);
  ASSERT_EQ(g.size(), 3u);  // one across each wall and one across the corner
  const double mx = 2.0 * b.lower[0] - x[0], my = 2.0 * b.upper[1] - x[1];
  int edgeX = 0, edgeY = 0, corner = 0;
  for (std::size_t k : g) {
    const bool fx = s.x[k][0] == mx, fy = s.x[k][1] == my;
    if (fx && fy) {
      ++corner;
      EXPECT_EQ(s.v[k], sph::Vec<2>(-v[0], -v[1]));  // both normals reversed
    } else if (fx) {
      ++edgeX;
      EXPECT_EQ(s.x[k][1], x[1]);
      EXPECT_EQ(s.v[k], sph::Vec<2>(-v[0], v[1]));
    } else if (fy) {
      ++edgeY;
      EXPECT_EQ(s.x[k][0], x[0]);
      EXPECT_EQ(s.v[k], sph::Vec<2>(v[0], -v[1]));
    }
  }
  EXPECT_EQ(edgeX, 1);
  EXPECT_EQ(edgeY, 1);
  EXPECT_EQ(corner, 1);
}

// In 3-D a particle near a corner has 7 images: 3 faces, 3 edges, 1 corner (2^3 - 1).
TEST(GhostWalls, CornerTripleMirror3D) {
  const auto b = box<3>(FaceKind::free_slip);
  const sph::Vec<3> x(b.lower[0] + 0.02, b.lower[1] + 0.03, b.upper[2] - 0.04);
  sph::InteractionSet<3> s;
  sph::buildInteractionSet<3>(single<3>(x, sph::Vec<3>(1, 2, 3), 1000.0), water, b, 0.1,
                              sph::Vec<3>::Zero(), s);
  ASSERT_EQ(s.size(), 8u);
  const sph::Vec<3> m(2.0 * b.lower[0] - x[0], 2.0 * b.lower[1] - x[1], 2.0 * b.upper[2] - x[2]);
  for (int mask = 1; mask < 8; ++mask) {
    sph::Vec<3> expected = x, vExpected(1, 2, 3);
    for (int a = 0; a < 3; ++a)
      if (mask >> a & 1) expected[a] = m[a], vExpected[a] = -vExpected[a];
    int hits = 0;
    for (std::size_t k = 1; k < s.size(); ++k)
      if (s.x[k] == expected) {
        ++hits;
        EXPECT_EQ(s.v[k], vExpected) << "mask " << mask;
      }
    EXPECT_EQ(hits, 1) << "mask " << mask;
  }
}

// Hydrostatic ghost pressure: p_g = p + rho g . (x_g - x) (InteractionSet.hpp), also for the
// corner ghost, whose x_g - x has two components.
TEST(GhostWalls, HydrostaticGhostPressure) {
  const auto b = box<2>(FaceKind::free_slip);
  const sph::Vec<2> g(1.5, -9.81);  // a tilted body force exercises both axes
  const sph::Vec<2> x(b.upper[0] - 0.01, b.lower[1] + 0.04);
  const auto fluid = single<2>(x, sph::Vec<2>::Zero(), 1003.0);
  sph::InteractionSet<2> s;
  sph::buildInteractionSet<2>(fluid, water, b, 0.1, g, s);
  ASSERT_EQ(s.size(), 4u);
  for (std::size_t k = 1; k < s.size(); ++k) {
    const double expected = s.p[0] + s.rho[0] * g.dot(s.x[k] - x);
    EXPECT_NEAR(s.p[k], expected, 1e-12 * std::abs(expected)) << k;
    EXPECT_EQ(s.rho[k], s.rho[0]);
  }
  // Mirror mode: every ghost carries the source's pressure.
  sph::buildInteractionSet<2>(fluid, water, b, 0.1, sph::Vec<2>::Zero(), s);
  for (std::size_t k = 1; k < s.size(); ++k) EXPECT_EQ(s.p[k], s.p[0]);
}

// [walls] tensile = false (GhostPressure's floor): a wall ghost of a particle in tension carries
// p0, one under compression its own pressure, the hydrostatic correction applied first; a periodic
// image keeps its source's pressure whatever the floor (it is fluid, not wall).
TEST(GhostWalls, FloorHoldsWallGhostsAtP0) {
  auto b = box<2>(FaceKind::free_slip);
  b.face[0] = {FaceKind::periodic, FaceKind::periodic};
  const sph::Vec<2> g(0.0, -9.81);
  const sph::Vec<2> x(b.upper[0] - 0.01, b.lower[1] + 0.04);  // near a periodic face and the floor
  const double p0 = water[0].p0;
  for (const double rho : {990.0, 1003.0}) {  // tension, compression
    const auto fluid = single<2>(x, sph::Vec<2>::Zero(), rho);
    sph::InteractionSet<2> s;
    sph::buildInteractionSet<2>(fluid, water, b, 0.1, sph::GhostPressure<2>(g, p0), s);
    ASSERT_EQ(s.size(), 4u);
    int walls = 0;
    for (std::size_t k = 1; k < s.size(); ++k) {
      const bool image = s.x[k][1] == x[1];  // shifted along x only: the periodic image
      const double mirrored = s.p[0] + s.rho[0] * g.dot(s.x[k] - x);
      if (image) {
        EXPECT_EQ(s.p[k], s.p[0]) << rho;
      } else {
        ++walls;
        if (mirrored < p0)
          EXPECT_EQ(s.p[k], p0) << rho << " " << k;
        else  // the corner ghost's correction is summed over two mirrors: round-off
          EXPECT_NEAR(s.p[k], mirrored, 1e-12 * std::abs(mirrored)) << rho << " " << k;
      }
    }
    EXPECT_EQ(walls, 2);                      // the floor's ghost and the ghost of the image
    if (rho < 1000.0) EXPECT_LT(s.p[0], p0);  // the case is one of tension
  }
}

// Kernel sum Gamma_i = sum_j m_j/rho_j W_ij (fluid and ghosts) on a cell-centred lattice filling a
// walled box. Mirroring a cell-centred lattice across a wall that lies on a cell face continues
// the lattice exactly, so a particle next to a wall or in a corner sees the same neighbourhood
// as one in the interior: Gamma must be the interior value up to summation round-off.
template <int D>
double kernelSumDeviation(sph::KernelKind kind) {
  const double dx = 0.1, h = 1.33 * dx;
  const int n = D == 2 ? 12 : 8;
  sph::Boundaries<D> b;
  for (int a = 0; a < D; ++a) {
    b.lower[a] = 0.0, b.upper[a] = n * dx;
    b.face[a] = {FaceKind::free_slip, FaceKind::no_slip};
  }
  sph::Particles<D> fluid;
  for (int k = 0; k < static_cast<int>(std::pow(n, D)); ++k) {
    sph::Vec<D> x;
    int rest = k;
    for (int a = 0; a < D; ++a) x[a] = (rest % n + 0.5) * dx, rest /= n;
    fluid.r.push_back(x), fluid.v.push_back(sph::Vec<D>::Zero());
    fluid.rho.push_back(1000.0), fluid.m.push_back(1000.0 * std::pow(dx, D));
    fluid.h.push_back(h), fluid.p.push_back(0.0), fluid.phase.push_back(0);
  }
  sph::InteractionSet<D> s;
  sph::buildInteractionSet<D>(fluid, water, b, 2.0 * h, sph::Vec<D>::Zero(), s);
  std::vector<double> gamma(fluid.size(), 0.0);
  for (std::size_t i = 0; i < fluid.size(); ++i)
    for (std::size_t j = 0; j < s.size(); ++j)
      gamma[i] += s.m[j] / s.rho[j] * sph::kernelValue<D>(kind, (s.x[i] - s.x[j]).norm(), h);
  // The interior reference: a particle at least 2h from every wall (n dx > 2 * 2h + dx).
  sph::Vec<D> centre = sph::Vec<D>::Constant((n / 2 + 0.5) * dx);
  std::size_t interior = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i)
    if ((fluid.r[i] - centre).norm() < 1e-9) interior = i;
  double worst = 0.0;
  for (double gi : gamma) worst = std::max(worst, std::abs(gi / gamma[interior] - 1.0));
  return worst;
}

TEST(GhostWalls, KernelSumNextToWallEqualsInterior) {
  sph::verification::Results results;
  for (auto kind :
       {sph::KernelKind::quadratic, sph::KernelKind::cubic_spline, sph::KernelKind::wendland_c2}) {
    // Round-off of a sum of ~30 (2-D) or ~150 (3-D) positive terms in different orders:
    // n u ~ 2e-14 at most; 1e-12 leaves a margin, and a missing ghost changes Gamma by O(10 %).
    EXPECT_TRUE(results.check("max |Gamma_i / Gamma_interior - 1| on a walled lattice, 2-D, " +
                                  std::string(sph::name(kind)),
                              kernelSumDeviation<2>(kind), "<=", 1e-12,
                              "exact lattice mirror; summation round-off"));
    EXPECT_LE(kernelSumDeviation<3>(kind), 1e-12) << sph::name(kind);
  }
}

// HaloMembers::same (for kept neighbour lists) recomputes the last build's images from the moved
// fluid: while no particle crosses a reach line it must give the very set a rescan gives, bit for
// bit, on one thread and on two. A lattice of 120 x 80 (above parallelFrom()) fills a box periodic
// in x, walled in y (free slip below, a moving no-slip lid above); rows lie 2.5 and 3.5 dx from
// the faces, the reach is 2.66 dx, and each particle moves by at most 0.1 dx a component.
TEST(GhostWalls, SameMembersGiveTheRescannedSet) {
  const int nx = 120, ny = 80;
  const double dx = 1.0 / nx, reach = 2.66 * dx;
  sph::Boundaries<2> b;
  b.lower = {0.0, 0.0}, b.upper = {1.0, ny * dx};
  b.face[0] = {FaceKind::periodic, FaceKind::periodic};
  b.face[1] = {FaceKind::free_slip, FaceKind::no_slip};
  b.wallVelocity[1][1] = {0.3, 0.0};
  sph::Particles<2> a;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      a.r.push_back({(i + 0.5) * dx, (j + 0.5) * dx}), a.v.push_back({0.1 * i, -0.05 * j});
      a.rho.push_back(1000.0 + 0.01 * j), a.m.push_back(0.01), a.h.push_back(1.33 * dx);
      a.phase.push_back(0), a.p.push_back(0.0);
    }
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-0.1 * dx, 0.1 * dx);
  sph::Particles<2> moved = a;
  for (std::size_t k = 0; k < moved.size(); ++k) {
    moved.r[k] += sph::Vec<2>(u(rng), u(rng)), moved.v[k] *= 1.5, moved.rho[k] += 2.0;
  }
  const sph::Vec<2> g(0.0, -9.81);
  const int saved = omp_get_max_threads();
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    sph::InteractionSet<2> kept, rescanned;
    sph::buildInteractionSet<2>(a, water, b, reach, g, kept);
    sph::buildInteractionSet<2>(moved, water, b, 0.0, g, kept, sph::HaloMembers::same);
    sph::buildInteractionSet<2>(moved, water, b, reach, g, rescanned);
    ASSERT_EQ(kept.size(), rescanned.size()) << threads << " threads";
    EXPECT_GT(kept.size(), moved.size() + 2 * nx) << "images of the lowest rows and lid, at least";
    for (std::size_t k = 0; k < kept.size(); ++k) {
      ASSERT_EQ(kept.x[k], rescanned.x[k]) << threads << " threads, entry " << k;
      ASSERT_EQ(kept.v[k], rescanned.v[k]) << threads << " threads, entry " << k;
      ASSERT_EQ(kept.p[k], rescanned.p[k]) << threads << " threads, entry " << k;
      ASSERT_EQ(kept.rho[k], rescanned.rho[k]) << threads << " threads, entry " << k;
      ASSERT_EQ(kept.source[k], rescanned.source[k]) << threads << " threads, entry " << k;
    }
  }
  omp_set_num_threads(saved);
}

}  // namespace
