// The density diffusion of Molteni & Colagrossi (2009)
// (terms/DensityDiffusionMolteniColagrossi.hpp) as a term of the pair loop, on properties of the
// operator itself. The comparison with the O(N^2) reference loop for every term combination is in
// ForceEvaluationTest.cpp.
// * Its pair sum 2 sum_j (rho_i - rho_j) F_ij V_j is Brookshaw's (1985) Laplacian of the density,
//   so d rho_i/dt = delta h c0 lap(rho), which damps a density wave of wavenumber k at the rate
//   delta h c0 k^2.
// * Antisymmetric in i and j with volume weights: sum_i V_i d rho_i/dt = 0 where no pair crosses
//   into the halo, to round-off.
// * A uniform density gives exactly zero.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "Results.hpp"
#include "sph/EquationOfState.hpp"
#include "sph/ForceEvaluation.hpp"

namespace {

constexpr double rho0 = 1000.0, c0 = 20.0, delta = 0.1;
const sph::terms::TermParameters parameters{.diffusionDelta = delta, .soundSpeed = c0};
const sph::TermSwitches diffusionOnly{.densityDiffusion = sph::DensityDiffusion::molteniColagrossi};

// A square lattice of n x n particles of spacing dx at rest (no halo), h = 1.33 dx, with
// density rho(x, y).
template <class Rho>
sph::InteractionSet<2> lattice(int n, Rho rho) {
  const double dx = 1.0 / n;
  sph::InteractionSet<2> s;
  for (int iy = 0; iy < n; ++iy)
    for (int ix = 0; ix < n; ++ix) {
      const sph::Vec<2> x((ix + 0.5) * dx, (iy + 0.5) * dx);
      const double r = rho(x);
      s.x.push_back(x), s.v.push_back(sph::Vec<2>::Zero()), s.rho.push_back(r);
      s.p.push_back(0.0), s.m.push_back(rho0 * dx * dx), s.h.push_back(1.33 * dx);
      s.mu.push_back(0.0), s.source.push_back(static_cast<int>(s.source.size()));
    }
  s.nFluid = s.size();
  return s;
}

TEST(DensityDiffusion, UniformDensityGivesZero) {
  const auto s = lattice(30, [](const sph::Vec<2>&) { return rho0; });
  sph::ForceEvaluation<2> forces(sph::KernelKind::quadratic, diffusionOnly, parameters);
  sph::Derivatives<2> out;
  forces(s, out);
  for (std::size_t i = 0; i < s.nFluid; ++i) EXPECT_EQ(out.drhodt[i], 0.0) << i;
}

TEST(DensityDiffusion, ConservesVolumeWeightedDensity) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto s = lattice(30, [&](const sph::Vec<2>&) { return rho0 * (1.0 + 0.01 * u(rng)); });
  sph::ForceEvaluation<2> forces(sph::KernelKind::quadratic, diffusionOnly, parameters);
  sph::Derivatives<2> out;
  forces(s, out);
  double sum = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < s.nFluid; ++i) {
    const double v = s.m[i] / s.rho[i] * out.drhodt[i];
    sum += v, scale += std::abs(v);
  }
  // Round-off of n terms each a sum of ~20 pair shares: n u sum|x| (Higham 2002, eq. 4.4), with
  // n = 900 particles: about 1e-13 of the scale; 1e-12 leaves a factor 10.
  sph::verification::Results results;
  EXPECT_TRUE(results.check("|sum_i V_i d rho_i/dt| / sum_i |V_i d rho_i/dt|",
                            std::abs(sum) / scale, "<=", 1e-12,
                            "antisymmetry of the pair shares; round-off bound"));
}

// rho = rho0 (1 + eps sin(k x)), k = 2 pi: away from the block's edges (3 h and more),
// d rho/dt = -delta h c0 k^2 (rho - rho0). The lattice sum of the quadratic kernel's second
// moment is not quite its integral at h/dx = 1.33, so the rate keeps a fixed misfit as the
// lattice is refined at that h/dx, plus a part of order (k h)^2 of the other sign: measured
// 0.20, 0.40, 0.49, 0.51 % of the amplitude at n = 40, 80, 160, 320. The bound, 2 %, is four
// times the limit; a wrong factor 2, sign or missing V_j is 50 % or more.
TEST(DensityDiffusion, DampsADensityWaveAtTheLaplaciansRate) {
  sph::verification::Results results;
  for (int n : {40, 80}) {
    const double k = 2.0 * std::numbers::pi, eps = 1e-3;
    const auto s =
        lattice(n, [&](const sph::Vec<2>& x) { return rho0 * (1.0 + eps * std::sin(k * x[0])); });
    sph::ForceEvaluation<2> forces(sph::KernelKind::quadratic, diffusionOnly, parameters);
    sph::Derivatives<2> out;
    forces(s, out);
    double worst = 0.0, amplitude = 0.0;
    for (std::size_t i = 0; i < s.nFluid; ++i) {
      const double margin = 3.0 * s.h[i];
      const auto& x = s.x[i];
      if (x[0] < margin || x[0] > 1 - margin || x[1] < margin || x[1] > 1 - margin) continue;
      const double expected = -delta * s.h[i] * c0 * k * k * (s.rho[i] - rho0);
      amplitude = std::max(amplitude, std::abs(expected));
      worst = std::max(worst, std::abs(out.drhodt[i] - expected));
      EXPECT_LE(out.drhodt[i] * (s.rho[i] - rho0), 0.0) << "not damping at particle " << i;
    }
    EXPECT_TRUE(results.check(
        "n = " + std::to_string(n) + ": max |d rho/dt - delta h c0 lap rho| / amplitude",
        worst / amplitude, "<=", 0.02,
        "Brookshaw (1985) Laplacian on a square lattice: 4x the measured lattice misfit"));
  }
}

}  // namespace
