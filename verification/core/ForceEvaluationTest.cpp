// Issue 2, part 3: the whole force evaluation (ForceEvaluation.cpp: cell list, cell-sorted
// copies, compile-time term menu) against an O(N^2) loop written here from the equations of
// DESIGN.md section 1 (Lobovsky & Kren 2008):
//   eq. (11) d rho_i/dt = sum_j m_j v_ij . grad_i W_ij
//   eq. (12) dv_i/dt   = -sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2 + Pi_ij) grad_i W_ij
//                        + sum_j m_j (mu_i + mu_j)/(rho_i rho_j) (r_ij . grad_i W_ij)/(r_ij^2 +
//                        eta^2) v_ij
//   eq. (8)  p = p0 + K ((rho/rho0)^7 - 1), K = rho0 c0^2 / 7, per phase
//   eq. (10) Pi_ij = beta/2 (h_i + h_j)^2/(rho_i + rho_j) (v_ij . r_ij/(r_ij^2 + eta^2))^2 if v_ij
//   . r_ij < 0 eq. (13) dh_i/dt = h_i/D sum_j m_j/rho_j v_ij . grad_i W_ij
// with eta^2 = 0.01 h_ij^2 and W_ij = W(|r_ij|, h_ij); and the density diffusion of Molteni &
// Colagrossi (2009, eq. 9-10), d rho_i/dt += delta h_ij c0 sum_j psi_ij . grad_i W_ij m_j/rho_j,
// psi_ij = 2 (rho_j - rho_i) r_ji / (r_ij^2 + eta^2), and Fourtakas et al.'s (2019) form with
// rho_j - rho_i less the hydrostatic difference -rho0^2 g . r_ij / (K S), S = sum_k x_j^k
// x_i^(gamma-1-k), x = rho/rho0 (terms/DensityDiffusionFourtakas.hpp; S here by powers, there by
// Horner); Antuono et al.'s (2010) form with 2 (rho_j - rho_i) r_ji / |r_ij|^2 less
// (G_i + G_j), G the renormalised density gradient L_i sum_j (rho_j - rho_i) grad_i W_ij V_j,
// L_i = [sum_j r_ji (x) grad_i W_ij V_j]^-1 (the plain sum where L_i^-1 is near singular), a halo
// entry's its source's (terms/DensityDiffusionAntuono.hpp). And particle shifting's pair sums
// (terms/ConcentrationGradient.hpp, Lind et al. 2012):
//   grad C_i = sum_j V_j (1 + 0.2 (W_ij / W(dx, h_ij))^4) grad_i W_ij,  g_i = sum_j V_j grad_i
//   W_ij, div r_i = -sum_j V_j r_ij . grad_i W_ij,  V_j = m_j / rho_j.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "Results.hpp"
#include "sph/EquationOfState.hpp"
#include "sph/ForceEvaluation.hpp"
#include "sph/terms/ArtificialViscosity.hpp"
#include "sph/terms/ContinuityEquation.hpp"
#include "sph/terms/DensityDiffusionFourtakas.hpp"
#include "sph/terms/MorrisViscosity.hpp"
#include "sph/terms/PressureGradient.hpp"
#include "sph/terms/RenormalisedDensityGradient.hpp"
#include "sph/terms/TermSet.hpp"

namespace {

using sph::KernelKind;

constexpr KernelKind kinds[] = {KernelKind::quadratic, KernelKind::cubic_spline,
                                KernelKind::wendland_c2};

const sph::Phase phases[2] = {{"water", 1000.0, 20.0, 8.9e-4, 0.0, 7.0},
                              {"heavy", 1500.0, 30.0, 5e-2, 100.0, 7.0}};

// n particles (300 unless given) in a unit-ish box with random velocity, density (+-3 %),
// h (+-20 %) and phase.
// The last 50 entries play the halo: they are neighbours but receive no rates; each of the first
// 40 of them stands for one of the first 40 fluid particles (its source), the last 10 for none
// (wall particles, source -1).
template <int D>
sph::InteractionSet<D> randomSet(unsigned seed, int n = 300) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double dx = std::pow(1.0 / n, 1.0 / D);  // mean spacing in a unit box
  sph::InteractionSet<D> s;
  for (int i = 0; i < n; ++i) {
    sph::Vec<D> x, v;
    for (int a = 0; a < D; ++a) x[a] = u(rng), v[a] = 2.0 * u(rng) - 1.0;
    const sph::Phase& ph = phases[i % 2];
    const double rho = ph.rho0 * (0.97 + 0.06 * u(rng));
    s.x.push_back(x), s.v.push_back(v), s.rho.push_back(rho);
    s.p.push_back(sph::TaitEquationOfState::pressure(rho, ph));
    s.m.push_back(rho * std::pow(dx, D) * (0.9 + 0.2 * u(rng)));
    s.h.push_back(1.33 * dx * (0.8 + 0.4 * u(rng)));
    s.mu.push_back(ph.mu), s.rho0.push_back(ph.rho0);
    s.source.push_back(i < n - 50 ? i : i < n - 10 ? i - (n - 50) : -1);
  }
  s.nFluid = n - 50;
  return s;
}

template <int D>
struct Reference {
  sph::Derivatives<D> rates;
  // Per particle, the sum of the magnitudes of the pair contributions: the scale of the
  // round-off of a sum (Higham, Accuracy and Stability, eq. 4.4: |error| <= (n-1) u sum|x_k|).
  std::vector<double> scaleV, scaleRho, scaleH;
  // Particle shifting's sums (grad C, g, div r: 2 D + 1 a particle) and their scales.
  std::vector<double> sums, scaleSums;
};

// The terms' parameters of every comparison: beta of the scenes; delta of Molteni & Colagrossi's
// paper with the c0 of the heavier phase; for Fourtakas et al.'s form the lighter phase's EOS and
// a g with a part along every axis (each of r_ij's components enters).
// Shifting's W(dx) at randomSet's mean spacing dx of n particles.
template <int D>
sph::terms::TermParameters parametersFor(int n = 300) {
  return {.beta = 1.0,
          .diffusionDelta = 0.1,
          .soundSpeed = 30.0,
          .rho0 = phases[0].rho0,
          .bulkModulus = phases[0].bulkModulus(),
          .gammaInteger = 7,
          .g = {0.7, -9.81, 0.4},
          .spacing = std::pow(1.0 / n, 1.0 / D)};
}
// Every subset of the three optional terms times each density diffusion form (none, Molteni &
// Colagrossi, Fourtakas et al., Fourtakas et al. within each phase,
// Antuono et al.), then all three with
// shifting's pair sums and each form: the menu of terms/Menu.hpp.
constexpr int menuSize = 45;
sph::TermSwitches switchesOf(int combo) {
  if (combo >= 40) return {true, true, true, static_cast<sph::DensityDiffusion>(combo - 40), true};
  return {(combo & 1) != 0, (combo & 2) != 0, (combo & 4) != 0,
          static_cast<sph::DensityDiffusion>(combo / 8)};
}
std::string describe(sph::TermSwitches t) {
  return " artificial=" + std::to_string(t.artificialViscosity) +
         " morris=" + std::to_string(t.morrisViscosity) +
         " variable_h=" + std::to_string(t.variableH) +
         " diffusion=" + std::to_string(static_cast<unsigned>(t.densityDiffusion)) +
         " shifting_sums=" + std::to_string(t.concentrationGradient);
}

// Fourtakas et al.'s hydrostatic density difference rho_ji^H of the pair, by powers, for a phase
// of rest density rho0 and bulk modulus K.
template <int D>
double hydrostaticDifference(const sph::InteractionSet<D>& s, std::size_t i, std::size_t j,
                             const sph::terms::TermParameters& par, double rho0, double K) {
  const double xi = s.rho[i] / rho0, xj = s.rho[j] / rho0;
  double S = 0.0;
  for (int k = 0; k < par.gammaInteger; ++k)
    S += std::pow(xj, k) * std::pow(xi, par.gammaInteger - 1 - k);
  double gr = 0.0;
  for (int a = 0; a < D; ++a) gr += par.g[a] * (s.x[i][a] - s.x[j][a]);
  return -rho0 * rho0 * gr / (K * S);
}

// Antuono et al.'s renormalised density gradient of every entry of the set: the fluid's from
// all its neighbours, a halo entry's its source's, a wall particle's rho g / c^2 (dp/drho of the
// parameters' Tait EOS, eq. 8), nil at rho0 (ForceEvaluation::densityGradients).
template <int D>
std::vector<sph::Vec<D>> densityGradients(const sph::InteractionSet<D>& s, KernelKind kind,
                                          const sph::terms::TermParameters& par) {
  std::vector<sph::Vec<D>> G(s.size());
  for (std::size_t i = 0; i < s.nFluid; ++i) {
    Eigen::Matrix<double, D, D> M = Eigen::Matrix<double, D, D>::Zero();
    sph::Vec<D> g = sph::Vec<D>::Zero();
    for (std::size_t j = 0; j < s.size(); ++j) {
      const sph::Vec<D> rij = s.x[i] - s.x[j];
      const double r = rij.norm(), hij = 0.5 * (s.h[i] + s.h[j]);
      if (j == i || r >= 2.0 * hij) continue;
      const sph::Vec<D> gradW = sph::kernelSlope<D>(kind, r, hij) / r * rij;
      const double V = s.m[j] / s.rho[j];
      M += V * (-rij) * gradW.transpose();
      g += (s.rho[j] - s.rho[i]) * V * gradW;
    }
    const double mean = M.trace() / D;
    const bool renormalised =
        mean > 0.0 && M.determinant() > sph::terms::RenormalisedDensityGradient::leastIsotropy *
                                            std::pow(mean, D);
    G[i] = renormalised ? sph::Vec<D>(M.inverse() * g) : g;
  }
  for (std::size_t k = s.nFluid; k < s.size(); ++k) {
    if (s.source[k] >= 0) {
      G[k] = G[s.source[k]];
      continue;
    }
    const double c2 = par.bulkModulus * par.gammaInteger / par.rho0 *
                      std::pow(s.rho[k] / par.rho0, par.gammaInteger - 1);
    for (int a = 0; a < D; ++a) G[k][a] = s.rho[k] == s.rho0[k] ? 0.0 : s.rho[k] / c2 * par.g[a];
  }
  return G;
}

template <int D>
Reference<D> reference(const sph::InteractionSet<D>& s, KernelKind kind, sph::TermSwitches t,
                       const sph::terms::TermParameters& par) {
  const double beta = par.beta;
  const std::size_t nf = s.nFluid;
  const bool antuono = t.densityDiffusion == sph::DensityDiffusion::antuono;
  const std::vector<sph::Vec<D>> G =
      antuono ? densityGradients<D>(s, kind, par) : std::vector<sph::Vec<D>>();
  Reference<D> ref;
  ref.rates.resize(nf);
  ref.scaleV.assign(nf, 0.0), ref.scaleRho.assign(nf, 0.0), ref.scaleH.assign(nf, 0.0);
  ref.sums.assign((2 * D + 1) * nf, 0.0), ref.scaleSums.assign((2 * D + 1) * nf, 0.0);
  for (std::size_t i = 0; i < nf; ++i) {
    sph::Vec<D> dv = sph::Vec<D>::Zero();
    double drho = 0.0, dh = 0.0;
    double* sums = ref.sums.data() + (2 * D + 1) * i;
    double* scales = ref.scaleSums.data() + (2 * D + 1) * i;
    for (std::size_t j = 0; j < s.size(); ++j) {
      if (j == i) continue;
      const sph::Vec<D> rij = s.x[i] - s.x[j], vij = s.v[i] - s.v[j];
      const double r = rij.norm();
      const double hij = 0.5 * (s.h[i] + s.h[j]);
      if (r >= 2.0 * hij) continue;
      const sph::Vec<D> gradW = sph::kernelSlope<D>(kind, r, hij) / r * rij;
      const double eta2 = 0.01 * hij * hij;
      const double continuity = s.m[j] * vij.dot(gradW);
      drho += continuity;
      if (t.concentrationGradient) {
        const double V = s.m[j] / s.rho[j];
        const double w =
            sph::kernelValue<D>(kind, r, hij) / sph::kernelValue<D>(kind, par.spacing, hij);
        const sph::Vec<D> gradC = V * (1.0 + 0.2 * std::pow(w, 4)) * gradW, normal = V * gradW;
        for (int a = 0; a < D; ++a) {
          sums[a] += gradC[a], scales[a] += std::abs(gradC[a]);
          sums[D + a] += normal[a], scales[D + a] += std::abs(normal[a]);
        }
        sums[2 * D] -= V * rij.dot(gradW), scales[2 * D] += std::abs(V * rij.dot(gradW));
      }
      ref.scaleRho[i] += std::abs(continuity);
      // Within each phase only (terms/DensityDiffusionFourtakasPhases.hpp), with that phase's
      // K = rho0 c0^2 / gamma at the terms' c0.
      const bool byPhase = t.densityDiffusion == sph::DensityDiffusion::fourtakasPhases;
      if (t.densityDiffusion != sph::DensityDiffusion::none &&
          (!byPhase || s.rho0[i] == s.rho0[j])) {
        const double Ki = s.rho0[i] * par.soundSpeed * par.soundSpeed / par.gammaInteger;
        const double hydrostatic =
            t.densityDiffusion == sph::DensityDiffusion::fourtakas
                ? hydrostaticDifference<D>(s, i, j, par, par.rho0, par.bulkModulus)
            : byPhase ? hydrostaticDifference<D>(s, i, j, par, s.rho0[i], Ki)
                      : 0.0;
        sph::Vec<D> psi = 2.0 * (s.rho[j] - s.rho[i] - hydrostatic) * (-rij) / (r * r + eta2);
        // (-(G_i + G_j) . grad W with the same r^2 / (r^2 + eta^2) as the first part)
        if (antuono) psi -= r * r / (r * r + eta2) * (G[i] + G[j]);
        const double c =
            par.diffusionDelta * hij * par.soundSpeed * psi.dot(gradW) * s.m[j] / s.rho[j];
        drho += c;
        ref.scaleRho[i] += std::abs(c);
      }
      if (t.variableH) {
        const double c = s.m[j] / s.rho[j] * vij.dot(gradW);
        dh += c;
        ref.scaleH[i] += std::abs(c);
      }
      double Pi = 0.0;
      if (t.artificialViscosity && vij.dot(rij) < 0.0) {
        const double mu = vij.dot(rij) / (r * r + eta2);
        Pi = 0.5 * beta * std::pow(s.h[i] + s.h[j], 2) / (s.rho[i] + s.rho[j]) * mu * mu;
      }
      const sph::Vec<D> pressure =
          -s.m[j] * (s.p[i] / (s.rho[i] * s.rho[i]) + s.p[j] / (s.rho[j] * s.rho[j]) + Pi) * gradW;
      dv += pressure;
      ref.scaleV[i] += pressure.norm();
      if (t.morrisViscosity) {
        const sph::Vec<D> viscous = s.m[j] * (s.mu[i] + s.mu[j]) / (s.rho[i] * s.rho[j]) *
                                    rij.dot(gradW) / (r * r + eta2) * vij;
        dv += viscous;
        ref.scaleV[i] += viscous.norm();
      }
    }
    ref.rates.dvdt[i] = dv;
    ref.rates.drhodt[i] = drho;
    ref.rates.dhdt[i] = t.variableH ? s.h[i] / D * dh : 0.0;
    ref.scaleH[i] *= s.h[i] / D;
  }
  return ref;
}

// Largest |out - reference| / (sum of |pair contributions|) over particles and fields.
template <int D>
double error(const sph::InteractionSet<D>& s, KernelKind kind, sph::TermSwitches t,
             const sph::Derivatives<D>& out) {
  const Reference<D> ref = reference<D>(s, kind, t, parametersFor<D>());
  EXPECT_EQ(out.dvdt.size(), s.nFluid);
  double worst = 0.0;
  auto relative = [](double diff, double scale) { return scale > 0 ? diff / scale : diff; };
  for (std::size_t i = 0; i < s.nFluid; ++i) {
    worst = std::max(worst, relative((out.dvdt[i] - ref.rates.dvdt[i]).norm(), ref.scaleV[i]));
    worst =
        std::max(worst, relative(std::abs(out.drhodt[i] - ref.rates.drhodt[i]), ref.scaleRho[i]));
    if (t.variableH)
      worst = std::max(worst, relative(std::abs(out.dhdt[i] - ref.rates.dhdt[i]), ref.scaleH[i]));
    else
      EXPECT_EQ(out.dhdt[i], 0.0);
  }
  if (t.concentrationGradient) {
    EXPECT_EQ(out.sumsWidth, 2 * D + 1);
    EXPECT_EQ(out.sums.size(), ref.sums.size());
    for (std::size_t k = 0; k < ref.sums.size() && k < out.sums.size(); ++k)
      worst = std::max(worst, relative(std::abs(out.sums[k] - ref.sums[k]), ref.scaleSums[k]));
  } else {
    EXPECT_EQ(out.sumsWidth, 0);
    EXPECT_TRUE(out.sums.empty());
  }
  return worst;
}

template <int D>
double compare(const sph::InteractionSet<D>& s, KernelKind kind, sph::TermSwitches t) {
  sph::ForceEvaluation<D> forces(kind, t, parametersFor<D>());
  sph::Derivatives<D> out;
  forces(s, out);
  return error<D>(s, kind, t, out);
}

// Tolerance: the two loops add the same pair terms in a different order (cell order against
// index order) and group a few products differently, so they differ by a few ulp per term:
// (n_neighbours + a few) * 1.1e-16 * sum|terms| ~ 1e-14 sum|terms| for ~40 neighbours. 1e-12 of
// the sum of the magnitudes leaves a factor 100 over that, and is 1e10 times smaller than any
// missing factor, sign or term.
constexpr double tolerance = 1e-12;

template <int D>
void allCombinations(unsigned seed) {
  const auto set = randomSet<D>(seed);
  sph::verification::Results results;
  for (KernelKind kind : kinds) {
    double worst = 0.0;
    for (int combo = 0; combo < menuSize; ++combo) {
      const sph::TermSwitches t = switchesOf(combo);
      const double e = compare<D>(set, kind, t);
      EXPECT_LE(e, tolerance) << sph::name(kind) << describe(t);
      worst = std::max(worst, e);
    }
    results.check("max |code - O(N^2) reference| / sum|pair terms|, " +
                      std::string(sph::name(kind)) + ", D=" + std::to_string(D) +
                      ", all 45 term combinations",
                  worst, "<=", tolerance, "summation round-off bound (n u sum|x_k|, Higham 2002)");
  }
}

TEST(ForceEvaluation, MatchesReferenceLoop1D) {
  allCombinations<1>(10);
}
TEST(ForceEvaluation, MatchesReferenceLoop2D) {
  allCombinations<2>(11);
}
TEST(ForceEvaluation, MatchesReferenceLoop3D) {
  allCombinations<3>(12);
}

// The set with every entry moved by `d` in a random direction and its h changed by up to +-dh.
template <int D>
sph::InteractionSet<D> moved(sph::InteractionSet<D> s, double d, double dh, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t k = 0; k < s.size(); ++k) {
    sph::Vec<D> dir;
    for (int a = 0; a < D; ++a) dir[a] = n(rng);
    s.x[k] += d / dir.norm() * dir;
    s.h[k] += dh * u(rng);
  }
  return s;
}

// Neighbour lists kept between evaluations (ForceEvaluation.hpp, Verlet 1967): built with a skin
// on one set, then reused on the same entries each moved by d and grown in h by at most dh. With
// 2 d + 2 dh = 0.9 skin every pair inside the support is still listed, and the listed pairs beyond
// it must add exactly nothing: the rates of the moved set match the O(N^2) reference to the same
// 1e-12. The build itself, with its skin, is compared too. A second part moves the entries by two
// skins: the kept lists then miss pairs and the error must be large, so that the first part can
// fail (1e-3: a missed pair is a whole term of the sum, not round-off).
template <int D>
void keptLists(unsigned seed) {
  const auto set = randomSet<D>(seed);
  double hMax = 0;
  for (double h : set.h) hMax = std::max(hMax, h);
  const double skin = 0.1 * 2.0 * hMax;  // the scenes' default fraction of the support
  const auto near = moved<D>(set, 0.2 * skin, 0.25 * skin, seed + 1);  // 2 d + 2 dh = 0.9 skin
  const auto far = moved<D>(set, 2.0 * skin, 0.0, seed + 2);
  sph::verification::Results results;
  for (KernelKind kind : kinds) {
    double worst = 0.0, worstFar = 1e300;
    for (int combo = 0; combo < menuSize; ++combo) {
      const sph::TermSwitches t = switchesOf(combo);
      sph::ForceEvaluation<D> forces(kind, t, parametersFor<D>());
      sph::Derivatives<D> out;
      forces(set, out, sph::Vec<D>::Zero(), {skin, false});
      worst = std::max(worst, error<D>(set, kind, t, out));
      forces(near, out, sph::Vec<D>::Zero(), {skin, true});
      worst = std::max(worst, error<D>(near, kind, t, out));
      forces(set, out, sph::Vec<D>::Zero(), {skin, false});
      forces(far, out, sph::Vec<D>::Zero(), {skin, true});
      worstFar = std::min(worstFar, error<D>(far, kind, t, out));
    }
    const std::string what = std::string(sph::name(kind)) + ", D=" + std::to_string(D);
    EXPECT_LE(worst, tolerance) << what;
    EXPECT_GE(worstFar, 1e-3) << what;
    results.check("kept neighbour lists, moved within the skin: max error / sum|pair terms|, " +
                      what + ", all 45 term combinations",
                  worst, "<=", tolerance, "summation round-off bound, as the full build");
  }
}

// The pair loop lays out and loads the fields the set's terms read (terms::Reads): the extra
// record {mu, 1/rho} only with a term that reads either, rho in 3-D only with one that reads it.
// The reference loops above check that each term's declaration is complete: a field a term reads
// but does not declare is 0 in the loop.
TEST(ForceEvaluation, RecordHoldsTheFieldsTheTermsRead) {
  using namespace sph::terms;
  // The continuity equation reads m, rho and 1 / rho (either form: ContinuityEquation.hpp).
  using Inviscid = TermSet<ContinuityEquation, PressureGradient, ArtificialViscosity>;
  EXPECT_TRUE(Inviscid::reads.mass && Inviscid::reads.pressure && Inviscid::reads.density);
  EXPECT_TRUE(Inviscid::reads.rhoSumInverse);  // 1 / (rho_i + rho_j) of eq. (10)
  EXPECT_FALSE(Inviscid::reads.viscosity || Inviscid::reads.restDensity);  // no extra record
  using Morris = TermSet<ContinuityEquation, PressureGradient, MorrisViscosity>;
  EXPECT_TRUE(Morris::reads.viscosity && Morris::reads.densityInverse);
  EXPECT_FALSE(Morris::reads.rhoSumInverse || Morris::reads.restDensity);  // no extra record
  using Diffusive = TermSet<ContinuityEquation, PressureGradient, DensityDiffusionFourtakas>;
  EXPECT_TRUE(Diffusive::reads.density && Diffusive::reads.densityInverse);
  EXPECT_FALSE(Diffusive::reads.viscosity);
}

TEST(ForceEvaluation, KeptNeighbourListsMatchReference1D) {
  keptLists<1>(20);
}
TEST(ForceEvaluation, KeptNeighbourListsMatchReference2D) {
  keptLists<2>(21);
}
TEST(ForceEvaluation, KeptNeighbourListsMatchReference3D) {
  keptLists<3>(22);
}

// The pair loop visits each pair once, in bands of cell layers that run in a fixed order of two
// phases (ForceEvaluation.cpp), so every rate is summed in an order that the cell list alone
// fixes: the thread count must not change a single bit. 300 particles make 6 bands here, 3,000
// make 18 (so that two threads each run even bands between the ends of their shares, in the
// order 2, 1, 4, 3, ...). The threads' shares are cut by entries in a first evaluation and by the
// work counted in the last one after that, so each count evaluates twice; 5 threads leave some
// without an even band.
class ThreadCount : public ::testing::TestWithParam<int> {};
// Antuono et al.'s diffusion, with its pass for the density gradient, too.
void threadCountKeepsBits(int n, sph::DensityDiffusion form) {
  const auto set = randomSet<2>(13, n);
  const sph::TermSwitches all{true, true, true, form, true};
  const auto parameters = parametersFor<2>(n);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  sph::Derivatives<2> one;
  sph::ForceEvaluation<2>(KernelKind::quadratic, all, parameters)(set, one);
  // The loop without the sums: the same rates, bit for bit.
  sph::Derivatives<2> plain;
  sph::ForceEvaluation<2>(KernelKind::quadratic, all, parameters)(set, plain, {}, {}, false);
  EXPECT_TRUE(plain.sums.empty());
  for (std::size_t i = 0; i < one.dvdt.size(); ++i) {
    EXPECT_EQ(one.dvdt[i], plain.dvdt[i]) << "without the sums, particle " << i;
    EXPECT_EQ(one.drhodt[i], plain.drhodt[i]) << "without the sums, particle " << i;
    EXPECT_EQ(one.dhdt[i], plain.dhdt[i]) << "without the sums, particle " << i;
  }
  for (int threads : {2, 3, 5}) {
    omp_set_num_threads(threads);
    sph::ForceEvaluation<2> force(KernelKind::quadratic, all, parameters);
    for (int evaluation = 0; evaluation < 2; ++evaluation) {
      sph::Derivatives<2> many;
      force(set, many);
      ASSERT_EQ(one.dvdt.size(), many.dvdt.size());
      for (std::size_t i = 0; i < one.dvdt.size(); ++i) {
        EXPECT_EQ(one.dvdt[i], many.dvdt[i]) << threads << " threads, particle " << i;
        EXPECT_EQ(one.drhodt[i], many.drhodt[i]) << threads << " threads, particle " << i;
        EXPECT_EQ(one.dhdt[i], many.dhdt[i]) << threads << " threads, particle " << i;
      }
      ASSERT_EQ(one.sums.size(), 5 * one.dvdt.size());
      for (std::size_t k = 0; k < one.sums.size(); ++k)
        EXPECT_EQ(one.sums[k], many.sums[k]) << threads << " threads, sum " << k;
    }
  }
  omp_set_num_threads(saved);
}
TEST_P(ThreadCount, DoesNotChangeBits) {
  threadCountKeepsBits(GetParam(), sph::DensityDiffusion::fourtakas);
}
TEST_P(ThreadCount, DoesNotChangeBitsWithAntuonoDiffusion) {
  threadCountKeepsBits(GetParam(), sph::DensityDiffusion::antuono);
}
INSTANTIATE_TEST_SUITE_P(ForceEvaluation, ThreadCount, ::testing::Values(300, 3000));

// A build finds the entries' box inside the pair loop's parallel region: where no entry has a
// number along an axis, the error must leave the region as an exception naming the axis (not end
// the program), whatever the thread count, and the evaluation must work again afterwards.
TEST(ForceEvaluation, NoNumberAlongAnAxisIsAnError) {
  const int saved = omp_get_max_threads();
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    auto set = randomSet<2>(17);
    const auto good = set;
    for (auto& x : set.x) x[1] = std::numeric_limits<double>::quiet_NaN();
    sph::ForceEvaluation<2> force(KernelKind::quadratic, {true, true, true}, 1.0);
    sph::Derivatives<2> out;
    try {
      force(set, out);
      ADD_FAILURE() << threads << " threads: no error";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("empty along axis 1"), std::string::npos) << e.what();
    }
    force(good, out);
    for (const auto& a : out.dvdt) EXPECT_TRUE(a.allFinite()) << threads << " threads";
  }
  omp_set_num_threads(saved);
}

}  // namespace
