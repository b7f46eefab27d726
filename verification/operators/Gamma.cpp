// Issue 3: Gamma_i = sum_j W_ij V_j and grad Gamma_i = sum_j grad_i W_ij V_j (Colagrossi et al.,
// particle packing, eq. 1.12): 1 and 0 in the interior of a perfect lattice up to the kernel's
// discretisation error; at a free surface the kernel is cut and Gamma falls towards 1/2; at a
// ghost wall the mirrored lattice continues the perfect one, so Gamma and grad Gamma take their
// interior values (the InteractionSet's ghosts, Libersky et al. 1993).
#include <gtest/gtest.h>

#include <cstdio>

#include "Results.hpp"
#include "SphOperators.hpp"
#include "sph/EquationOfState.hpp"
#include "sph/InteractionSet.hpp"

namespace sph::verification {
namespace {

struct GammaAt {
  double gamma, gradGammaTimesH;  // gradGamma's y component times h
};

// Fluid in 0 <= y <= 1 (20 rows of dx = 0.05), periodic in x; below it a wall of kind `lower`
// (or nothing), above it a free surface. Returns Gamma and h dGamma/dy of the rows `rows`.
std::vector<GammaAt> gammaProfile(KernelKind kind, FaceKind lower, const std::vector<int>& rows) {
  const int nx = 20, ny = 20;
  const double dx = 1.0 / nx, h = 1.33 * dx;
  Particles<2> p;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      p.r.push_back(V2((i + 0.5) * dx, (j + 0.5) * dx));
      p.v.push_back(V2::Zero());
      p.rho.push_back(1000.0), p.m.push_back(1000.0 * dx * dx), p.h.push_back(h), p.p.push_back(0);
      p.phase.push_back(0);
    }
  Boundaries<2> b;
  b.lower = V2(0, 0), b.upper = V2(1, 2);
  b.face[0] = {FaceKind::periodic, FaceKind::periodic};
  b.face[1] = {lower, FaceKind::open};
  InteractionSet<2> set;
  buildInteractionSet<2>(p, {Phase{}}, b, 2 * h, V2::Zero(), set);
  std::vector<GammaAt> out;
  for (int row : rows) {
    const int i = row * nx + nx / 2;
    double g = 0, gy = 0;
    for (std::size_t j = 0; j < set.size(); ++j) {
      const V2 rij = set.x[i] - set.x[j];
      const double r = rij.norm(), V = set.m[j] / set.rho[j];
      g += V * kernelValue<2>(kind, r, h);
      if (r > 0) gy += V * kernelSlope<2>(kind, r, h) * rij[1] / r;
    }
    out.push_back({g, gy * h});
  }
  return out;
}

TEST(Gamma, InteriorOfPerfectLattice) {
  Results r;
  for (KernelKind kind :
       {KernelKind::quadratic, KernelKind::cubic_spline, KernelKind::wendland_c2}) {
    const PeriodicLattice L(32);
    const double h = 1.33 * L.dx;
    const auto o = applyOperators(L, kind, h, [](const V2&) { return 0.0; });
    double gMax = 0, gradMax = 0;
    for (std::size_t i = 0; i < L.x.size(); ++i)
      gMax = std::max(gMax, std::abs(o.gamma[i] - 1)),
      gradMax = std::max(gradMax, o.gradGamma[i].norm() * h);
    std::printf("%s: |Gamma-1| %.4e, h|grad Gamma| %.3e\n", std::string(name(kind)).c_str(), gMax,
                gradMax);
    const std::string k = std::string(name(kind)) + ", h/dx = 1.33";
    // grad Gamma vanishes by the lattice's point symmetry: round-off only.
    EXPECT_TRUE(r.check("interior h |grad Gamma|, " + k, gradMax, "<=", 1e-12,
                        "zero by symmetry of the perfect lattice; round-off of ~50 terms of O(1)"));
    // |Gamma - 1| is the kernel's discretisation error at h/dx = 1.33 (Quinlan et al. 2006),
    // measured 4.9e-2 (quadratic), 5.1e-4 (cubic spline), 9.0e-3 (Wendland C2); 6 % bounds all.
    EXPECT_TRUE(
        r.check("interior |Gamma - 1|, " + k, gMax, "<=", 0.06,
                "discretisation floor of the lattice sum, measured per kernel (quick test)"));
  }
}

TEST(Gamma, FreeSurfaceAndGhostWall) {
  Results r;
  const std::vector<int> rows{0, 1, 2, 10};  // 10: interior (more than 2h from both ends)
  const auto open = gammaProfile(KernelKind::quadratic, FaceKind::open, rows);
  const auto wall = gammaProfile(KernelKind::quadratic, FaceKind::free_slip, rows);
  for (std::size_t k = 0; k < rows.size(); ++k)
    std::printf("row %d  surface: Gamma %.4f h dG/dy %.4f | wall: Gamma %.4f h dG/dy %.3e\n",
                rows[k], open[k].gamma, open[k].gradGammaTimesH, wall[k].gamma,
                wall[k].gradGammaTimesH);
  const double interior = open[3].gamma;
  // At a free surface the kernel is cut in half: Gamma near 1/2 on the first row (the row sits
  // dx/2 inside, so a little more) and grad Gamma of order 1/h (Colagrossi et al., section 1).
  // Relative to the interior value (which carries the lattice floor): the half-space integral 1/2
  // plus the strip of width dx/2 = 0.38 h between the row and the surface, which holds at most
  // 0.3 of the kernel's 1-D marginal (its peak is below 0.8/h for all three kernels).
  const double ratio = open[0].gamma / interior;
  EXPECT_TRUE(r.check("free surface Gamma / Gamma_interior, first row", ratio, "<=", 0.8,
                      "half-space kernel integral 1/2 plus the dx/2 strip (<= 0.3)"));
  EXPECT_TRUE(r.check("free surface Gamma / Gamma_interior, first row (lower)", ratio, ">=", 0.5,
                      "half-space kernel integral 1/2 plus the dx/2 strip (>= 0)"));
  EXPECT_TRUE(r.check("free surface h |grad Gamma|, first row", std::abs(open[0].gradGammaTimesH),
                      ">=", 0.1, "grad Gamma = O(1/h) at a cut kernel (Colagrossi et al.)"));
  // The mirrored ghosts continue the lattice: interior values to round-off.
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_TRUE(r.check("ghost wall |Gamma - Gamma_interior|, row " + std::to_string(rows[k]),
                        std::abs(wall[k].gamma - interior), "<=", 1e-12,
                        "mirror ghosts continue the perfect lattice: equal up to round-off"));
    EXPECT_TRUE(r.check("ghost wall h |grad Gamma|, row " + std::to_string(rows[k]),
                        std::abs(wall[k].gradGammaTimesH), "<=", 1e-12,
                        "mirror ghosts continue the perfect lattice: zero up to round-off"));
  }
}

}  // namespace
}  // namespace sph::verification
