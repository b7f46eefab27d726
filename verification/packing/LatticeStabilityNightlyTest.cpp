// Colagrossi et al. (2012), section 2.1.1, Table 1: stability of the Cartesian, triangular and
// hexagonal tessellations for h/dx = 0.8 .. 3.2, undamped packing dynamics, perturbation dx/100,
// with the paper's Wendland kernel and with the quadratic kernel of Lobovsky & Kren (eq. 5).
// Criterion and set-up: LatticeStability.hpp.
#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include "LatticeStability.hpp"
#include "Results.hpp"

namespace sph::packing {
namespace {

const double kHOverDx[5] = {0.8, 1.4, 2.0, 2.6, 3.2};

// Table 1 of the paper (Wendland kernel): 'S' Liapunov stable, 'U' unstable, for h/dx above.
const char* paperRow(LatticeKind k) {
  switch (k) {
    case LatticeKind::cartesian:
      return "USSUU";
    case LatticeKind::triangular:
      return "SUSSU";
    case LatticeKind::hexagonal:
      return "UUUUU";
  }
  // No default: -Wswitch names an enumerator missing above, and any other value is a bug
  // (an error here), never the last case.
  throw std::logic_error("paperRow(LatticeKind): unknown value " +
                         std::to_string(static_cast<int>(k)));
}

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

void row(LatticeKind kind, KernelKind kernel) {
  verification::Results r;
  const bool wendland = kernel == KernelKind::wendland_c2;
  std::string ours, linear, volume, bounded;
  for (int c = 0; c < 5; ++c) {
    const double hdx = kHOverDx[c];
    const CellOutcome o = lattice(kind, kernel, hdx);
    ours += o.unstable() ? 'U' : 'S';
    const std::string tag =
        std::string(name(kernel)) + ", " + std::string(name(kind)) + ", h/dx = " + fmt(hdx);
    std::printf(
        "%s: N = %zu, CFL = %.3g, %d iterations, G = %.4g, max|d|/dx = %.3g, "
        "lambda_min/lambda_max = %.3g, sigma t = %.3g, energy drift %.3g, min distance %.3g\n",
        tag.c_str(), o.particles, o.cfl, o.iterations, o.growth, o.maxDisplacement,
        o.linear.lambdaMin / o.linear.lambdaMax, o.eFolds, o.energyDrift, o.minDistance);
    // Linear theory and simulation must agree where theory is decisive: no negative eigenvalue
    // (beyond round-off of the dense eigensolver, 1e-10 of lambda_max) means G <= 1 up to
    // nonlinearity; sigma t >= 10 means the unstable mode grew by e^10 ~ 2e4 from its share of
    // the dx/100 noise (~dx/100/sqrt(N) of the rms), past G = 3. Between the two: recorded only.
    const bool linearStable = o.linear.lambdaMin >= -1e-10 * o.linear.lambdaMax;
    linear += linearStable ? 'S' : 'U';
    if (linearStable)
      EXPECT_TRUE(r.check("G, " + tag + " (Hessian: stable)", o.growth, "<", kGrowthUnstable,
                          "linear theory: normal modes from rest never exceed their start"));
    else if (o.eFolds >= 10.0)
      EXPECT_TRUE(r.check("G, " + tag + " (Hessian: sigma t = " + fmt(o.eFolds) + ")", o.growth,
                          ">=", kGrowthUnstable, "linear theory: growth exp(sigma t)"));
    else
      r.check(
          "G, " + tag + " (Hessian: weakly unstable, sigma t = " + fmt(o.eFolds) + "; recorded)",
          o.growth, ">=", kGrowthUnstable, "linear theory; too slow to decide in the run");
    // zeta = 0 conserves E (Appendix B); the leapfrog keeps it to O((omega dt)^2) without drift.
    // At omega_max dt = 0.5 the measured max|E - E0| / max T is at most 0.05 over the Wendland
    // table; threshold 0.1, the bound PackingDynamicsTest uses at CFL = 1 on the tank. Asserted
    // for the Wendland kernel and for any cell that keeps its lattice. The quadratic kernel's slope
    // at r = 0 is -3/4 N/h^3, not zero (eq. 5), so its transverse stiffness (1/r) dW/dr grows like
    // 1/r for close pairs (Wendland's stays finite): rearranging quadratic cells bring pairs to
    // 0.3-0.5 dx (min distance recorded), where the modes are several times faster than the
    // lattice's omega_max that set dt. Measured 0.21 and 0.52 at h/dx = 0.8 (triangular,
    // hexagonal); those cells are recorded only.
    const std::string drift = "max|E - E0| / max T, " + tag;
    if (wendland || !o.unstable())
      EXPECT_TRUE(r.check(drift, o.energyDrift, "<=", 0.1,
                          "Appendix B; leapfrog O(dt^2) energy error, measured, see test"));
    else
      r.check(drift + " (quadratic kernel rearranging, min distance " + fmt(o.minDistance) +
                  " dx; recorded against max T itself)",
              o.energyDrift, "<=", 1.0, "Appendix B; quadratic kernel: dW/dr(0) != 0, see test");
    // A second reading of the same outcome: a stable lattice keeps every particle within 10x the
    // noise (0.1 dx; measured at most 0.025 dx), an unstable one moves some particle further
    // (measured at least 0.165 dx). Asserted, so that G and the displacement classify alike.
    const std::string moved = "max_t max_i |x_i - x_i^lattice| / dx, " + tag;
    if (o.unstable())
      EXPECT_TRUE(r.check(moved + " (G: unstable)", o.maxDisplacement, ">=", 0.1,
                          "criterion of LatticeStability.hpp; 10x the dx/100 noise"));
    else
      EXPECT_TRUE(r.check(moved + " (G: stable)", o.maxDisplacement, "<", 0.1,
                          "criterion of LatticeStability.hpp; 10x the dx/100 noise"));
    // The paper's set-up, a bounded block with the lattice fixed around it, against the paper's
    // Table 1 (Wendland only: the paper's kernel). Periodic and bounded differ in one cell,
    // Cartesian at h/dx = 1.4: the periodic lattice is unstable only to waves longer than 5.3 dx,
    // with the weakest growth of the table (lambda_min/lambda_max = -1.5e-4), which the fixed
    // surroundings of a 20 dx block do not let grow (G = 1); the paper reports S, as the block.
    if (wendland) {
      const CellOutcome b =
          lattice(kind, kernel, hdx, kPaperSpan, Spacing::nearestNeighbour, Domain::bounded);
      bounded += b.unstable() ? 'U' : 'S';
      std::printf("  bounded: N = %zu, G = %.4g, max|d|/dx = %.3g\n", b.particles, b.growth,
                  b.maxDisplacement);
      const bool paperUnstable = paperRow(kind)[c] == 'U';
      EXPECT_TRUE(
          r.check("G, bounded block (the paper's set-up), " + tag +
                      ", against Colagrossi et al. 2012 Table 1: " + (paperUnstable ? "U" : "S"),
                  b.growth, paperUnstable ? ">=" : "<", kGrowthUnstable,
                  "Colagrossi et al. 2012 Table 1; criterion G >= 3 unstable "
                  "(LatticeStability.hpp)"));
    }
    // The other reading of dx (V0 = dx^2 for every lattice): linear theory only, printed.
    const CellOutcome v = lattice(kind, kernel, hdx, 0.0, Spacing::volume);
    volume += v.linear.lambdaMin >= -1e-10 * v.linear.lambdaMax ? 'S' : 'U';
  }
  std::printf("%s, %s (h/dx = 0.8 1.4 2.0 2.6 3.2): ours %s, Hessian %s, Hessian with V0 = dx^2 %s",
              std::string(name(kernel)).c_str(), std::string(name(kind)).c_str(), ours.c_str(),
              linear.c_str(), volume.c_str());
  if (wendland) std::printf(", bounded block %s, paper %s", bounded.c_str(), paperRow(kind));
  std::printf("\n");
}

TEST(LatticeStabilityNightly, WendlandCartesian) {
  row(LatticeKind::cartesian, KernelKind::wendland_c2);
}
TEST(LatticeStabilityNightly, WendlandTriangular) {
  row(LatticeKind::triangular, KernelKind::wendland_c2);
}
TEST(LatticeStabilityNightly, WendlandHexagonal) {
  row(LatticeKind::hexagonal, KernelKind::wendland_c2);
}
TEST(LatticeStabilityNightly, QuadraticCartesian) {
  row(LatticeKind::cartesian, KernelKind::quadratic);
}
TEST(LatticeStabilityNightly, QuadraticTriangular) {
  row(LatticeKind::triangular, KernelKind::quadratic);
}
TEST(LatticeStabilityNightly, QuadraticHexagonal) {
  row(LatticeKind::hexagonal, KernelKind::quadratic);
}

}  // namespace
}  // namespace sph::packing
