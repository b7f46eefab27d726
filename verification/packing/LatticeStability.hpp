#pragma once
// Table 1 of Colagrossi, Bouscasse, Antuono & Marrone (2012): are the Cartesian, triangular and
// hexagonal tessellations stable under the undamped packing dynamics (eq. 2.16, zeta = 0)?
//
// Set-up (section 2.1.1): the lattice perturbed by noise of order dx/100, zeta = 0, and the
// evolution followed to t (beta/V0)^(1/2) = 6200 (the time of the paper's Fig. 3 snapshots).
// Two domains: (1a) a periodic box of about 20 dx (periodicity removes the boundary's influence
// instead of keeping it far away, and leaves only the rigid translations neutral, which a start
// from rest does not excite; the Hessian below applies to it exactly), and (1b) the paper's
// set-up, a block of about 20 x 20 dx whose surroundings, the same lattice to a depth of
// 2h + dx, are fixed solid particles (which also removes the neutral directions). Further:
// (2) dx is the nearest-neighbour distance of each lattice, as the unit spacing of the paper's
// Fig. 3 suggests (the paper does not define it; the alternative, V0 = dx^2 for all three, is
// computed too); (3) the time step resolves the fastest mode: eq. (2.17) with CFL = 1 gives
// omega_max dt = 2.6 for the Cartesian lattice at h/dx = 0.8, beyond the stability limit 2 of the
// leapfrog, so a blow-up there would be the integrator's, not the lattice's. We take
// CFL = min(1, 0.5 / (omega_max sqrt(V0/beta))), omega_max^2 the largest eigenvalue of the Hessian
// below, and run 6200 / CFL iterations.
//
// Criterion: the growth G = max_t rms|x_i(t) - x_i^lattice| / rms|x_i(0) - x_i^lattice|. For a
// stable lattice the motion is a sum of normal modes started from rest, each of amplitude at most
// its initial one, so G <= 1 up to O(perturbation) nonlinearity; an unstable mode grows like
// exp(sigma t) until the particles rearrange (or settle in a nearby configuration). The lattice is
// called unstable when G >= 3. Measured over both tables (LatticeStabilityNightlyTest.cpp): G of
// the stable cells 1.000 (to 4 digits), of the unstable ones at least 12.6 (quadratic kernel,
// triangular, h/dx = 3.2, which settles at max displacement 0.17 dx); 3 lies between with a factor
// 3-4 margin either way.
//
// Alongside, linear theory: the smallest eigenvalue of the Hessian of V (eq. B.34) on the same
// periodic lattice (solver/include/sph/packing/LatticeStability.hpp) gives the growth rate sigma.
#include <algorithm>
#include <cmath>
#include <random>

#include "sph/packing/LatticeStability.hpp"
#include "sph/packing/Lattices.hpp"
#include "sph/packing/ParticlePacking.hpp"

namespace sph::packing {

constexpr double kGrowthUnstable = 3.0;  // G >= 3: unstable (criterion above)
constexpr double kPaperSpan = 6200.0;    // t (beta/V0)^(1/2) of Fig. 3

struct CellOutcome {
  double growth = 0.0;           // G of the criterion
  double maxDisplacement = 0.0;  // max_t max_i |x_i - x_i^lattice| / dx
  double energyDrift = 0.0;      // max_t |E - E0| / max_t T (zeta = 0: E conserved, App. B)
  double minDistance = 0.0;      // min_t min_(i != j) |x_i - x_j| / dx (minimum image)
  LinearStability linear;        // Hessian of V on the unperturbed lattice
  double eFolds = 0.0;           // sigma t_end: linear growth exponent over the run
  double cfl = 1.0;              // of eq. (2.17), see above
  int iterations = 0;
  std::size_t particles = 0;
  bool unstable() const { return growth >= kGrowthUnstable; }
};

enum class Spacing { nearestNeighbour, volume };  // dx: the lattice's spacing, or V0 = dx^2
// periodic: our set-up; bounded: the paper's, a block of about 20 x 20 dx of the lattice whose
// surroundings, the same lattice to a depth of 2h + dx, are fixed solid particles.
enum class Domain { periodic, bounded };

// One cell of the table: lattice `kind`, kernel, h/dx, run to t (beta/V0)^(1/2) = `span`.
// dx = 1, beta = 1. With span = 0 only the linear theory (always on the periodic lattice) is
// computed.
inline CellOutcome lattice(LatticeKind kind, KernelKind kernel, double hOverDx,
                           double span = kPaperSpan, Spacing spacing = Spacing::nearestNeighbour,
                           Domain domain = Domain::periodic) {
  const double dx = 1.0;
  const double a = spacing == Spacing::volume ? nearestNeighbour(kind, dx) : dx;
  // Side: 20 dx as the paper's Fig. 3 (-10 .. 10 dx), and wider than twice the support 2 h.
  const PeriodicLattice base =
      periodicLattice(kind, a, std::max(20.0 * dx, 4.0 * hOverDx * dx + dx));
  const Vec2 L = base.box.hi - base.box.lo;
  const double V0 = L.x() * L.y() / static_cast<double>(base.position.size());
  PackingParameters p;
  p.kernel = kernel, p.hOverDx = hOverDx, p.beta = 1.0, p.alpha = 0.0;
  CellOutcome out;
  out.particles = base.position.size();
  out.linear = linearStability(base, kernel, hOverDx * dx, V0, p.beta);
  const double dt1 = std::sqrt(V0 / p.beta);  // eq. (2.17) at CFL = 1
  p.cfl = std::min(1.0, 0.5 / (std::sqrt(out.linear.lambdaMax) * dt1));
  out.cfl = p.cfl;
  out.eFolds = out.linear.sigma * span * dt1;
  if (span <= 0.0) return out;
  const int iterations = static_cast<int>(std::ceil(span / p.cfl));
  // Noise of order dx/100: each coordinate uniform in [-dx/100, dx/100], fixed seed.
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> noise(-0.01 * dx, 0.01 * dx);
  std::vector<Vec2> reference = base.position, solid;  // the moving particles' lattice sites
  PeriodicBox<2> box = base.box;
  if (domain == Domain::bounded) {
    const double margin = 2.0 * hOverDx * dx + dx;
    const PeriodicLattice big = periodicLattice(kind, a, 20.0 * dx + 2.0 * margin);
    box = big.box;
    reference.clear();
    for (const Vec2& x : big.position) {
      const bool inside = x.x() > margin && x.x() < big.box.hi.x() - margin && x.y() > margin &&
                          x.y() < big.box.hi.y() - margin;
      (inside ? reference : solid).push_back(x);
    }
    out.particles = reference.size();
  }
  const Vec2 Lm = box.hi - box.lo;  // for the minimum image (periodic) or harmless (bounded)
  std::vector<Vec2> start = reference;
  for (Vec2& x : start) x += Vec2(noise(rng), noise(rng));
  // ParticlePacking's h = hOverDx times its dx argument.
  ParticlePacking packing = domain == Domain::bounded ? ParticlePacking(start, solid, V0, dx, p)
                                                      : ParticlePacking(start, {}, V0, dx, p, box);

  auto displacement = [&](std::size_t i) {  // minimum image of x_i - x_i^lattice
    Vec2 d = packing.positions()[i] - reference[i];
    for (int a = 0; a < 2; ++a) d[a] -= Lm[a] * std::round(d[a] / Lm[a]);
    return d;
  };
  auto rms = [&] {
    double s = 0.0;
    for (std::size_t i = 0; i < reference.size(); ++i) s += displacement(i).squaredNorm();
    return std::sqrt(s / static_cast<double>(reference.size()));
  };
  const double rms0 = rms();
  const PackingRecord r0 = packing.record();
  const double E0 = r0.kinetic + r0.potential;
  double maxRms = rms0, maxT = 0.0, maxDrift = 0.0, minDistance = INFINITY;
  for (int n = 1; n <= iterations; ++n) {
    packing.step();
    const PackingRecord r = packing.record();
    maxT = std::max(maxT, r.kinetic);
    maxDrift = std::max(maxDrift, std::abs(r.kinetic + r.potential - E0));
    if (n % 20 == 0 || n == iterations) {
      maxRms = std::max(maxRms, rms());
      for (std::size_t i = 0; i < reference.size(); ++i) {
        out.maxDisplacement = std::max(out.maxDisplacement, displacement(i).norm() / dx);
        for (std::size_t j = 0; j < i; ++j) {
          Vec2 d = packing.positions()[i] - packing.positions()[j];
          for (int a = 0; a < 2; ++a) d[a] -= Lm[a] * std::round(d[a] / Lm[a]);
          minDistance = std::min(minDistance, d.norm() / dx);
        }
      }
    }
  }
  out.growth = maxRms / rms0;
  out.energyDrift = maxDrift / maxT;
  out.iterations = iterations;
  out.minDistance = minDistance;
  return out;
}

}  // namespace sph::packing
