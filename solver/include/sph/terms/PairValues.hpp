#pragma once
// What a pair term reads and writes. A term is a small type (one header here) with
//   name     the run file's word for it ("" for a term the simulation names itself),
//   reads    which fields of the two particles (Side) it needs, and which of the pair's shared
//            values beyond r_ij, v_ij and the kernel (the pair loop lays out and loads those
//            alone: a field no term of a set reads is 0 there),
//   writes   which of the pair's sums it adds to,
//   flops    its operations a pair, counted from its source (perf: the per-term cost table),
//   pair(p, s)    its share of one pair: p the pair's values, s the sums it adds to (a term
//                 that needs the kernel or the dimension: pair<Kernel, D>(p, s)),
//   sums<D>  where it has sums of its own (PairSums::ownI): how many a particle,
// and optionally finish(f, x) for the per-particle step after all pairs, and a constructor
// from TermParameters where it has parameters. The pair values are written over two value
// types: S for particle i's fields and V for j's and the pair's, so that the same function
// serves one pair (S = V = double) or several at once (V a vector of pairs).
//
// Every term of this solver is symmetric in the sense of Newton's third law: what the pair
// adds to j follows from what it adds to i with i and j exchanged, so each pair is visited once
// and both shares come from the same pair values.
#include <string_view>

namespace sph::terms {

// One particle of the pair.
template <class T>
struct Side {
  T m;           // mass
  T rho;         // density
  T rhoInv;      // 1 / rho
  T pOverRho2;   // p / rho^2 (Tait, eq. 8)
  T mu;          // dynamic viscosity
  T rho0;        // the rest density of its phase (eq. 8), where a term reads it
  T gradRho[3];  // its renormalised density gradient (zero beyond D), where a term reads it
};

// A particle's side from its state: the factors computed once per particle and evaluation.
inline Side<double> sideOf(double m, double rho, double p, double mu, double rho0) {
  const double rhoInv = 1.0 / rho;
  return {m, rho, rhoInv, p * rhoInv * rhoInv, mu, rho0, {}};
}

// The pair (i, j), r_ij = x_i - x_j, v_ij = v_i - v_j, within the kernel's support.
template <class S, class V>
struct PairValues {
  Side<S> i;
  Side<V> j;
  V rx, ry, rz;  // r_ij (zero beyond D)
  V vx, vy, vz;  // v_ij
  V r2;          // |r_ij|^2
  V r;           // |r_ij|
  V hInv;        // 1 / h_ij
  V vr;          // v_ij . r_ij
  V hSum;        // h_i + h_j = 2 h_ij
  V hSum2;       // (h_i + h_j)^2
  V F;           // grad_i W_ij = F r_ij: F = (1/r) dW/dr at h_ij (Kernels.hpp)
  V rEta2Inv;    // 1 / (r_ij^2 + eta^2), where a term reads it (Reads::etaInverse)
  V rhoSumInv;   // 1 / (rho_i + rho_j), where a term reads it (Reads::rhoSumInverse)
};

// The anti-crossing term of the viscosities (DESIGN.md 1): eta^2 = 0.01 h_ij^2, as a fraction
// of (h_i + h_j)^2 = 4 h_ij^2. (The paper prints eta = 0.01 H^2.)
inline constexpr double etaSquaredOfHSum2 = 0.0025;

// The most sums of its own a term may have (Writes): the renormalised density gradient's
// D (D + 1) / 2 + D in 3-D.
inline constexpr int maxOwnSums = 9;

// What one pair adds, before the driver sums it: to i's and to j's d rho/dt, to the sums of
// eq. (13) (h/D times the sum is dh/dt), and eq. (12)'s pair force per unit of the two masses,
// Q = bracket F r_ij - viscous v_ij: dv_i/dt gets -m_j Q and dv_j/dt gets +m_i Q. Each starts at
// -0, so that the first term's share is its value exactly (-0 + x = x for every x).
template <class V>
struct PairSums {
  V rhoI = -V{}, rhoJ = -V{};  // d rho/dt
  V hI = -V{}, hJ = -V{};      // the sums of eq. (13)
  V bracket = -V{};            // (p_i/rho_i^2 + p_j/rho_j^2 + Pi_ij) of eq. (12)
  V viscous = -V{};            // the factor of v_ij (Morris et al. 1997, eq. 9)
  // A term's sums of its own beside the rates (its sums<D> of them; one such term a set), which
  // it sets: i's and j's shares.
  V ownI[maxOwnSums], ownJ[maxOwnSums];
};

struct Reads {
  // the particles' fields (Side) beyond their positions, velocities and h
  bool mass = false, density = false, densityInverse = false, pressure = false, viscosity = false,
       restDensity = false;
  // the renormalised density gradient of each particle (terms/RenormalisedDensityGradient.hpp),
  // which the force evaluation computes in a pass of its own before the rates
  bool densityGradient = false;
  // the pair's shared values beyond r_ij, v_ij and the kernel
  bool etaInverse = false, rhoSumInverse = false;
};
struct Writes {
  bool density = false, smoothingLength = false, bracket = false, viscous = false;
};

// Operations a pair (add, sub, mul, compare-select, div, sqrt one each): `shared` once for the
// pair, `sided` once for each of its two particles.
struct Flops {
  int shared = 0, sided = 0;
};

// The scene's values of the terms' parameters.
struct TermParameters {
  double beta = 0.0;                      // artificial viscosity, eq. (10)
  bool continuityByVolume = false;        // terms/ContinuityEquation.hpp
  bool pressureGradientByVolume = false;  // terms/PressureGradient.hpp
  double diffusionDelta = 0.0;            // density diffusion's delta (Molteni & Colagrossi 2009)
  double soundSpeed = 0.0;                // c0 [m/s], of density diffusion
  // The hydrostatic density difference of Fourtakas et al.'s (2019) density diffusion: the
  // phase's Tait EOS (eq. 8: rho0, K = rho0 c0^2 / gamma, gamma an integer) and the uniform body
  // acceleration g (zero beyond D).
  double rho0 = 1000.0, bulkModulus = 1.0;
  int gammaInteger = 7;
  double g[3] = {0.0, 0.0, 0.0};
  double spacing = 0.0;  // the initial particle spacing dx [m], of particle shifting's W(dx)
};

// A fluid particle's rates once all its pairs are summed, for the terms' finish steps: hSum is
// eq. (13)'s sum, dhdt starts at zero, dvdt holds the pairs' part.
template <class Vec>
struct ParticleRates {
  double drhodt, hSum, dhdt;
  Vec dvdt;
};
// What a finish step may read of its particle and of the evaluation.
template <class Vec>
struct ParticleState {
  double h;
  Vec g;  // the uniform body acceleration
};

}  // namespace sph::terms
