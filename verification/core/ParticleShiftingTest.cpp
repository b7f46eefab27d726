// Particle shifting (ParticleShifting.hpp) on the operator itself, on lattices built here:
// * a uniform lattice is a fixed point: grad C vanishes inside it (the pairs at +-r cancel), so
//   no interior particle moves, and none is taken for a surface particle;
// * at a free surface only the part of dr along the surface is kept (dr . n = 0), while the raw
//   dr there points out of the fluid;
// * a perturbed periodic lattice relaxes toward the uniform one under repeated shifts;
// * in a run the shift is added to the positions at the end of the step and nothing else changes;
// * the pair loop's sums (terms/ConcentrationGradient.hpp: grad C, g, div r, each pair once) and
//   the marks and shifts made from them match this class's own scalar gather (each pair from both
//   sides, its own cell list), for every kernel and dimension, with neighbour lists built and kept.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "Results.hpp"
#include "sph/EquationOfState.hpp"
#include "sph/ForceEvaluation.hpp"
#include "sph/InteractionSet.hpp"
#include "sph/ParticleShifting.hpp"
#include "sph/Scene.hpp"
#include "sph/Simulation.hpp"

namespace {

using sph::Vec;
constexpr double rho0 = 1000.0, hOverDx = 1.33;

// n x m particles of spacing dx = 1/32 (positions exact in binary) from the origin, moving at
// speed 1 along x (so that D = A h |u| dt is not zero), h = 1.33 dx; no halo.
sph::InteractionSet<2> block(int n, int m, double jitter = 0.0, unsigned seed = 1) {
  const double dx = 1.0 / 32;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  sph::InteractionSet<2> s;
  for (int iy = 0; iy < m; ++iy)
    for (int ix = 0; ix < n; ++ix) {
      const Vec<2> x((ix + 0.5) * dx + jitter * dx * u(rng),
                     (iy + 0.5) * dx + jitter * dx * u(rng));
      s.x.push_back(x), s.v.push_back(Vec<2>(1.0, 0.0)), s.rho.push_back(rho0);
      s.p.push_back(0.0), s.m.push_back(rho0 * dx * dx), s.h.push_back(hOverDx * dx);
      s.mu.push_back(0.0), s.source.push_back(static_cast<int>(s.source.size()));
    }
  s.nFluid = s.size();
  return s;
}

sph::ShiftingParameters lind(bool freeSurface = true) {
  return {.form = sph::ShiftingForm::lind, .coefficient = 2.0, .freeSurface = freeSurface};
}

// Inside the block: more than the support (2 h = 2.66 dx) from every edge.
bool interior(const Vec<2>& x, int n, int m) {
  const double dx = 1.0 / 32, margin = 3.0 * dx;
  return x[0] > margin && x[0] < n * dx - margin && x[1] > margin && x[1] < m * dx - margin;
}

TEST(ParticleShifting, UniformLatticeInteriorIsNotShifted) {
  sph::verification::Results results;
  const int n = 24;
  const auto s = block(n, n);
  const double dx = 1.0 / 32, dt = 1e-3;
  for (auto kernel : {sph::KernelKind::quadratic, sph::KernelKind::wendland_c2}) {
    sph::ParticleShifting<2> shifting(kernel, lind(), dx);
    sph::LineVector<Vec<2>> dr;
    shifting(s, dt, dr);
    double worst = 0.0, divMin = 1e300;
    int inside = 0, flagged = 0;
    for (std::size_t i = 0; i < s.nFluid; ++i) {
      if (!interior(s.x[i], n, n)) continue;
      ++inside;
      worst = std::max(worst, shifting.gradC()[i].norm() * s.h[i]);
      divMin = std::min(divMin, shifting.divR()[i]);
      flagged += shifting.surface()[i] + shifting.nearSurface()[i];
      EXPECT_LE(dr[i].norm(), 1e-12 * dx) << i;
    }
    const std::string k(sph::name(kernel));
    std::printf("%s: max h|grad C| %.3e, min div r %.4f inside\n", k.c_str(), worst, divMin);
    ASSERT_GT(inside, 200);
    // Each grad C is some 20-50 terms of size up to ~1/h that cancel in pairs: rounding leaves a
    // few 1e-16 / h; 1e-12 / h is far below the 1e-2 / h of a lattice perturbed by 1 % of dx.
    EXPECT_TRUE(results.check("max h |grad C| inside a uniform lattice, " + k, worst, "<=", 1e-12,
                              "pairs at +-r cancel; rounding of ~50 terms"));
    // div r inside: the kernel's lattice sum of r^2 F, near D = 2 (measured 2.026 quadratic,
    // 1.959 Wendland C2 at h/dx 1.33); far above the 1.5 of the surface.
    EXPECT_TRUE(results.check("min div r inside a uniform lattice, " + k, divMin, ">", 1.8,
                              "D = 2 less the lattice sum's misfit (a few per cent)"));
    EXPECT_EQ(flagged, 0) << k;
  }
}

TEST(ParticleShifting, SurfaceKeepsOnlyTheTangentialShift) {
  sph::verification::Results results;
  const int n = 24, m = 12;
  const auto s = block(n, m, 0.05, 3);  // 5 % of dx disorder
  const double dx = 1.0 / 32, dt = 1e-3;
  sph::ParticleShifting<2> treated(sph::KernelKind::quadratic, lind(true), dx);
  sph::ParticleShifting<2> raw(sph::KernelKind::quadratic, lind(false), dx);
  sph::LineVector<Vec<2>> drTreated, drRaw;
  treated(s, dt, drTreated);
  raw(s, dt, drRaw);
  double normalPart = 0.0, outward = 1e300, tangential = 0.0, scale = 0.0;
  int top = 0, near = 0;
  for (std::size_t i = 0; i < s.nFluid; ++i) {
    if (!treated.nearSurface()[i]) continue;
    ++near;
    const Vec<2> nrm = -treated.normalSum()[i].normalized();
    scale = std::max(scale, drRaw[i].norm());
    normalPart = std::max(normalPart, std::abs(drTreated[i].dot(nrm)));
    tangential = std::max(tangential, drTreated[i].norm());
    // The top row, away from the side edges: the raw shift points up, out of the fluid.
    if (s.x[i][1] > (m - 1) * dx && s.x[i][0] > 3 * dx && s.x[i][0] < (n - 3) * dx) {
      ++top;
      EXPECT_TRUE(treated.surface()[i]) << i;
      outward = std::min(outward, drRaw[i][1]);
    }
  }
  std::printf("near the surface: max |dr.n| %.3e, max |dr| %.3e of the raw max\n",
              normalPart / scale, tangential / scale);
  ASSERT_GT(top, 10);
  ASSERT_GT(near, 3 * top);  // the surface row and those within its support
  EXPECT_GT(outward, 0.0);   // every top particle would be pushed out
  EXPECT_TRUE(results.check("max |dr . n| / max |dr_raw| near the surface", normalPart / scale,
                            "<=", 1e-12, "the normal part is removed; rounding"));
  // What is left moves the particles along the surface: not nothing (the disorder has a
  // tangential gradient); measured 0.058 of the raw shift's largest, the bound a third of it.
  EXPECT_TRUE(results.check("max |dr| near the surface / max |dr_raw|", tangential / scale, ">",
                            0.02, "a tangential shift remains (measured 0.058)"));
}

// A periodic box of 32 x 32 particles, each displaced by up to 20 % of dx, shifted 100 times
// with D = A h |u| dt at |u| dt = 0.1 dx, A = 2: the rms of h |grad C| falls from 0.165 to
// 0.0049 (measured: 0.030 of its start); the bound, 0.1, is three times that, and a shift of the
// wrong sign or none leaves the ratio at 1 or above.
TEST(ParticleShifting, PerturbedLatticeRelaxesTowardUniform) {
  sph::verification::Results results;
  const int n = 32;
  const double dx = 1.0 / n, L = 1.0;
  sph::Particles<2> p;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int iy = 0; iy < n; ++iy)
    for (int ix = 0; ix < n; ++ix) {
      p.r.push_back(Vec<2>((ix + 0.5 + 0.2 * u(rng)) * dx, (iy + 0.5 + 0.2 * u(rng)) * dx));
      p.v.push_back(Vec<2>(1.0, 0.0)), p.rho.push_back(rho0), p.m.push_back(rho0 * dx * dx);
      p.h.push_back(hOverDx * dx), p.p.push_back(0.0), p.phase.push_back(0);
    }
  sph::Boundaries<2> bounds;
  bounds.upper = Vec<2>(L, L);
  for (auto& f : bounds.face) f = {sph::FaceKind::periodic, sph::FaceKind::periodic};
  const std::vector<sph::Phase> phases{{.name = "water", .rho0 = rho0, .c0 = 10.0}};
  sph::ParticleShifting<2> shifting(sph::KernelKind::quadratic, lind(), dx);
  sph::InteractionSet<2> set;
  sph::LineVector<Vec<2>> dr;
  auto disorder = [&] {
    sph::buildInteractionSet(p, phases, bounds, 2.0 * hOverDx * dx, Vec<2>(Vec<2>::Zero()), set);
    shifting(set, 0.1 * dx, dr);  // |u| dt = 0.1 dx
    double sum = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) sum += (shifting.gradC()[i] * p.h[i]).squaredNorm();
    return std::sqrt(sum / p.size());
  };
  const double before = disorder();
  int surface = 0;
  for (std::size_t i = 0; i < p.size(); ++i) surface += shifting.nearSurface()[i];
  EXPECT_EQ(surface, 0);  // periodic: no free surface
  double after = before;
  for (int k = 0; k < 100; ++k) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.r[i] += dr[i];
      for (int a = 0; a < 2; ++a) p.r[i][a] -= L * std::floor(p.r[i][a] / L);
    }
    after = disorder();
  }
  std::printf("rms h|grad C|: %.4e -> %.4e after 100 shifts\n", before, after);
  EXPECT_TRUE(results.check("rms h |grad C|, perturbed periodic lattice, after / before 100 shifts",
                            after / before, "<", 0.1, "measured 0.030"));
}

// A dam-break column (dx 0.02, after the paper's scene) run 20 steps, then one step with and
// without shifting from the same state: the step's velocities, densities and h are the same bits,
// and each position differs by exactly the shift the step reports (computed from the trial state,
// added after the corrector: no force, no other field). With the paper's terms the sums come from
// the pair loop (terms/Menu.hpp); without Morris viscosity, from the shifting pass's own gather.
std::string column(const std::string& shifting, bool morris) {
  return "name = \"column\"\ndimension = 2\n[domain]\nlower = [0.0, 0.0]\nupper = [0.6, 0.4]\n"
         "x_lower = \"free_slip\"\nx_upper = \"free_slip\"\ny_lower = \"free_slip\"\n"
         "y_upper = \"open\"\nghost_pressure = \"hydrostatic\"\n"
         "[[phase]]\nname = \"water\"\nrho0 = 1000.0\nc0 = 24.4\nmu = 8.9e-4\n"
         "[[fluid]]\nlower = [0.0, 0.0]\nupper = [0.2, 0.1]\ninitial_pressure = \"hydrostatic\"\n"
         "[physics]\ngravity = [0.0, -9.81]\nartificial_viscosity = 1.0\nmorris_viscosity = " +
         std::string(morris ? "true" : "false") + "\nvariable_h = true\n" + shifting +
         "[numerics]\ndx = 0.02\nend_time = 1.0\n";
}

void runAddsTheShift(bool morris);
TEST(ParticleShifting, RunAddsTheShiftToThePositionsOnly) {
  for (bool morris : {true, false}) {
    SCOPED_TRACE(morris ? "sums in the pair loop" : "sums gathered by the shifting pass");
    runAddsTheShift(morris);
  }
}

void runAddsTheShift(bool morris) {
  sph::Simulation<2> plain(sph::parseScene(column("", morris), "column"));
  for (int k = 0; k < 20; ++k) ASSERT_FALSE(plain.advance());
  sph::Simulation<2> shifted(
      sph::parseScene(column("shifting = \"lind\"\n", morris), "column_lind"), plain.particles());
  EXPECT_EQ(shifted.termNames().back(), "shifting_lind");
  sph::Simulation<2> same(sph::parseScene(column("", morris), "column"), plain.particles());
  ASSERT_FALSE(same.advance());
  ASSERT_FALSE(shifted.advance());
  const auto &a = same.particles(), &b = shifted.particles();
  const auto& dr = shifted.lastShift();
  ASSERT_EQ(dr.size(), a.size());
  EXPECT_EQ(shifted.wallReflections(), 0);
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(b.r[i], a.r[i] + dr[i]) << i;
    EXPECT_EQ(b.v[i], a.v[i]) << i;
    EXPECT_EQ(b.rho[i], a.rho[i]) << i;
    EXPECT_EQ(b.h[i], a.h[i]) << i;
    largest = std::max(largest, dr[i].norm());
  }
  EXPECT_GT(largest, 0.0);  // the column has started to move: |u| > 0, and its edges have grad C
  EXPECT_TRUE(same.lastShift().empty());
}

// shifting_every = 3: the first step shifts for three steps (D with 3 dt: three times the
// shift of shifting_every = 1 from the same state, to round-off), and the next two move the
// particles as a run without shifting does. The sums follow a cell order that the two runs may
// not share after a step, so those positions agree to round-off only: 1e-9 dx, some 1e3 times
// below the shift the column's step makes (checked).
TEST(ParticleShifting, EveryKthStepShiftsForTheKSteps) {
  constexpr double dx = 0.02;
  sph::Simulation<2> plain(sph::parseScene(column("", true), "column"));
  for (int k = 0; k < 20; ++k) ASSERT_FALSE(plain.advance());
  const std::string lind = "shifting = \"lind\"\n";
  sph::Simulation<2> each(sph::parseScene(column(lind, true), "column_lind"), plain.particles());
  sph::Simulation<2> third(
      sph::parseScene(column(lind + "shifting_every = 3\n", true), "column_lind_3"),
      plain.particles());
  ASSERT_FALSE(each.advance());
  ASSERT_FALSE(third.advance());
  const auto &one = each.lastShift(), &three = third.lastShift();
  ASSERT_EQ(three.size(), one.size());
  double largest = 0.0;
  for (const auto& dr : one) largest = std::max(largest, dr.norm());
  ASSERT_GT(largest, 1e3 * 1e-9 * dx);  // the tolerance below is far under a step's shift
  // Round-off against the largest shift (measured up to 3.2e-14 of it): near the surface a shift
  // is what is left of one across it, and that difference carries the rounding of the whole.
  for (std::size_t i = 0; i < one.size(); ++i)
    EXPECT_LE((three[i] - 3.0 * one[i]).norm(), 1e-12 * largest) << i;

  sph::Simulation<2> unshifted(sph::parseScene(column("", true), "column"), third.particles());
  for (int k = 0; k < 2; ++k) {
    ASSERT_FALSE(third.advance());
    ASSERT_FALSE(unshifted.advance());
  }
  const auto &a = third.particles(), &b = unshifted.particles();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_LE((a.r[i] - b.r[i]).norm(), 1e-9 * dx) << i;
}

// A jittered block of particles in a box with free-slip walls below and at the sides (mirror
// ghosts: a halo) and an open top (a free surface), moving at random velocities, h +-10 %.
template <int D>
sph::InteractionSet<D> walledBlock(int n, double dx, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  sph::Particles<D> p;
  std::array<int, D> k{};
  for (;;) {
    Vec<D> x, v;
    for (int a = 0; a < D; ++a) x[a] = (k[a] + 0.5 + 0.15 * u(rng)) * dx, v[a] = u(rng);
    p.r.push_back(x), p.v.push_back(v), p.rho.push_back(rho0 * (1.0 + 0.01 * u(rng)));
    p.m.push_back(rho0 * std::pow(dx, D)), p.h.push_back(hOverDx * dx * (1.0 + 0.1 * u(rng)));
    p.p.push_back(0.0), p.phase.push_back(0);
    int a = 0;
    while (a < D && ++k[a] == n) k[a++] = 0;
    if (a == D) break;
  }
  sph::Boundaries<D> bounds;
  bounds.upper = Vec<D>::Constant(2.0 * n * dx);
  for (int a = 0; a < D; ++a) bounds.face[a] = {sph::FaceKind::free_slip, sph::FaceKind::free_slip};
  bounds.face[D - 1][1] = sph::FaceKind::open;
  const std::vector<sph::Phase> phases{{.name = "water", .rho0 = rho0, .c0 = 10.0}};
  sph::InteractionSet<D> set;
  sph::buildInteractionSet(p, phases, bounds, 2.4 * hOverDx * dx, Vec<D>(Vec<D>::Zero()), set);
  return set;
}

// The set with each entry moved by d in a random direction (halo entries too: the lists are
// kept for the same entries).
template <int D>
sph::InteractionSet<D> movedBy(sph::InteractionSet<D> s, double d, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  for (auto& x : s.x) {
    Vec<D> dir;
    for (int a = 0; a < D; ++a) dir[a] = g(rng);
    x += d / dir.norm() * dir;
  }
  return s;
}

// Per fluid entry, the sums of the magnitudes of the pair terms of grad C, g and div r (O(N^2),
// |grad_i W_ij| = |dW/dr|): the scale of a sum's round-off (Higham 2002, eq. 4.4).
template <int D>
std::array<std::vector<double>, 3> magnitudes(const sph::InteractionSet<D>& s, sph::KernelKind kind,
                                              double dx) {
  std::array<std::vector<double>, 3> out;
  for (auto& v : out) v.assign(s.nFluid, 0.0);
  for (std::size_t i = 0; i < s.nFluid; ++i)
    for (std::size_t j = 0; j < s.size(); ++j) {
      const double r = (s.x[i] - s.x[j]).norm(), hij = 0.5 * (s.h[i] + s.h[j]);
      if (j == i || !(r > 0) || r >= 2.0 * hij) continue;
      const double VF = s.m[j] / s.rho[j] * std::abs(sph::kernelSlope<D>(kind, r, hij));
      const double w =
          sph::kernelValue<D>(kind, r, hij) / sph::kernelValue<D>(kind, dx, hij);  // W_ij / W(dx)
      out[0][i] += (1.0 + 0.2 * std::pow(w, 4)) * VF, out[1][i] += VF, out[2][i] += VF * r;
    }
  return out;
}

// The pair loop's sums against the gather on `s`, after `forces` has evaluated it; returns the
// largest error of grad C, g, div r and dr over their scales, and counts differing marks.
template <int D>
double againstGather(const sph::InteractionSet<D>& s, sph::KernelKind kind, double dx,
                     sph::ForceEvaluation<D>& forces, const sph::Derivatives<D>& sums,
                     int& marksDiffer, int& surface) {
  const double dt = 1e-3;
  sph::ParticleShifting<D> loop(kind, lind(), dx), gather(kind, lind(), dx);
  sph::LineVector<Vec<D>> drLoop, drGather;
  loop(s, dt, sums, forces, drLoop);
  gather(s, dt, drGather);
  const auto scale = magnitudes<D>(s, kind, dx);
  double worst = 0.0;
  for (std::size_t i = 0; i < s.nFluid; ++i) {
    const double eC = (loop.gradC()[i] - gather.gradC()[i]).norm() / scale[0][i];
    const double eG = (loop.normalSum()[i] - gather.normalSum()[i]).norm() / scale[1][i];
    const double eR = std::abs(loop.divR()[i] - gather.divR()[i]) / scale[2][i];
    // dr = -A h |u| dt grad C, less its part along n = -g/|g| near the surface: an error e of
    // g turns n by e/|g|.
    const double D_i = 2.0 * s.h[i] * s.v[i].norm() * dt;
    const double gNorm = gather.normalSum()[i].norm();
    const double drScale =
        D_i * (scale[0][i] + (gather.nearSurface()[i] && gNorm > 0
                                  ? 2.0 * gather.gradC()[i].norm() * scale[1][i] / gNorm
                                  : 0.0));
    const double eDr = (drLoop[i] - drGather[i]).norm() / drScale;
    worst = std::max({worst, eC, eG, eR, eDr});
    marksDiffer += (loop.surface()[i] != gather.surface()[i]) +
                   (loop.nearSurface()[i] != gather.nearSurface()[i]);
    surface += gather.surface()[i];
  }
  return worst;
}

template <int D>
void pairLoopMatchesGather() {
  sph::verification::Results results;
  const int n = D == 1 ? 64 : D == 2 ? 20 : 9;
  const double dx = 1.0 / 32;
  const auto set = walledBlock<D>(n, dx, 5 + D);
  double hMax = 0.0;
  for (double h : set.h) hMax = std::max(hMax, h);
  const double skin = 0.1 * 2.0 * hMax;
  const auto near = movedBy<D>(set, 0.4 * skin, 9 + D);  // 2 d < skin: the lists are kept
  // (the menu has the sums with every optional term: terms/Menu.hpp)
  const sph::TermSwitches terms{true, true, true, sph::DensityDiffusion::none, true};
  const sph::terms::TermParameters parameters{.beta = 1.0, .spacing = dx};
  for (auto kind :
       {sph::KernelKind::quadratic, sph::KernelKind::cubic_spline, sph::KernelKind::wendland_c2}) {
    sph::ForceEvaluation<D> forces(kind, terms, parameters);
    sph::Derivatives<D> out;
    int marksDiffer = 0, surface = 0;
    forces(set, out, Vec<D>::Zero(), {0.0, false});
    double worst = againstGather<D>(set, kind, dx, forces, out, marksDiffer, surface);
    forces(set, out, Vec<D>::Zero(), {skin, false});
    worst = std::max(worst, againstGather<D>(set, kind, dx, forces, out, marksDiffer, surface));
    forces(near, out, Vec<D>::Zero(), {skin, true});
    worst = std::max(worst, againstGather<D>(near, kind, dx, forces, out, marksDiffer, surface));
    const std::string what = std::string(sph::name(kind)) + ", D=" + std::to_string(D);
    std::printf("%s: %d surface marks, largest error %.3e\n", what.c_str(), surface, worst);
    EXPECT_GT(surface, 0) << what;  // the open top has a surface, and the marks are compared
    EXPECT_EQ(marksDiffer, 0) << what;
    // The two add the same pair terms in different orders and group a few products differently:
    // a few ulp a term, ~1e-14 of the sum of the magnitudes for ~40 neighbours; as the force
    // evaluation's comparison with its O(N^2) loop (ForceEvaluationTest.cpp).
    EXPECT_TRUE(results.check("pair loop's shifting sums and shifts against the gather, " + what +
                                  ", lists none, built and kept",
                              worst, "<=", 1e-12, "summation round-off bound (Higham 2002)"));
  }
}

TEST(ParticleShifting, PairLoopSumsMatchTheGather1D) {
  pairLoopMatchesGather<1>();
}
TEST(ParticleShifting, PairLoopSumsMatchTheGather2D) {
  pairLoopMatchesGather<2>();
}
TEST(ParticleShifting, PairLoopSumsMatchTheGather3D) {
  pairLoopMatchesGather<3>();
}

}  // namespace
