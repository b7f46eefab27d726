// Issue 3: the solver's own continuity (eq. 11, difference form) and pressure gradient (eq. 12,
// symmetric form) through Simulation::rates on a periodic lattice, against the exact
// -rho div v and -grad p / rho of manufactured fields, and against the brute-force operators of
// SphOperators.hpp (which they must equal up to round-off on the perfect lattice).
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "Results.hpp"
#include "SphOperators.hpp"
#include "sph/EquationOfState.hpp"
#include "sph/InitialParticles.hpp"
#include "sph/Simulation.hpp"

namespace sph::verification {
namespace {

constexpr double kRho0 = 1000.0, kC0 = 10.0, kEps = 1e-3;

Scene periodicScene(int n, double hOverDx) {
  std::ostringstream s;
  s.precision(17);
  s << "name = \"forms\"\ndimension = 2\n[domain]\nlower = [0.0, 0.0]\nupper = [1.0, 1.0]\n"
    << "x_lower = \"periodic\"\nx_upper = \"periodic\"\ny_lower = \"periodic\"\ny_upper = "
       "\"periodic\"\n"
    << "[[phase]]\nname = \"w\"\nrho0 = " << kRho0 << "\nc0 = " << kC0
    << "\n[[fluid]]\nlower = [0.0, 0.0]\nupper = [1.0, 1.0]\n[numerics]\ndx = " << 1.0 / n
    << "\nh_over_dx = " << hOverDx << "\nend_time = 1.0\n";
  return parseScene(s.str(), "forms");
}

struct FormErrors {
  double continuity, momentum, continuityVsBruteForce;
};

// v = (f, f) with f the manufactured field: continuity gives -rho0 div v.
// rho = rho0 (1 + eps f): the pressure gradient gives -p'(rho) grad rho / rho.
FormErrors formErrors(int n, double hOverDx) {
  const Scene sc = periodicScene(n, hOverDx);
  Particles<2> p = latticeParticles<2>(sc);
  const std::size_t N = p.size();
  for (std::size_t i = 0; i < N; ++i) p.v[i] = V2(field(p.r[i]), field(p.r[i]));
  Simulation<2> sim(sc, p);
  Derivatives<2> d;
  sim.rates(sim.particles(), 0.0, d);
  std::vector<double> got(N), exact(N);
  for (std::size_t i = 0; i < N; ++i) {
    got[i] = d.drhodt[i];
    const V2 g = fieldGradient(p.r[i]);
    exact[i] = -kRho0 * (g[0] + g[1]);
  }
  FormErrors e;
  e.continuity = relativeMaxError(got, exact);
  // The brute-force difference form gives the same sum: drho/dt = -rho0 sum V_j (v_j - v_i).gradW
  PeriodicLattice L(n);
  const auto o = applyOperators(L, sc.kernel, sc.h0(), field);
  std::vector<double> brute(N);
  for (std::size_t i = 0; i < N; ++i) brute[i] = -kRho0 * (o.difference[i][0] + o.difference[i][1]);
  e.continuityVsBruteForce = relativeMaxError(got, brute);

  const Phase& ph = sc.phases[0];
  for (std::size_t i = 0; i < N; ++i) {
    p.v[i] = V2::Zero();
    p.rho[i] = kRho0 * (1 + kEps * field(p.r[i]));
    p.m[i] = p.rho[i] * sc.dx * sc.dx;
  }
  Simulation<2> sim2(sc, p);
  sim2.rates(sim2.particles(), 0.0, d);
  std::vector<V2> gotV(N), exactV(N);
  for (std::size_t i = 0; i < N; ++i) {
    const double rho = p.rho[i];
    const double dpdrho = ph.c0 * ph.c0 * std::pow(rho / ph.rho0, ph.gamma - 1);
    gotV[i] = d.dvdt[i];
    exactV[i] = -dpdrho * kRho0 * kEps * fieldGradient(p.r[i]) / rho;
  }
  e.momentum = relativeMaxError(gotV, exactV);
  return e;
}

TEST(SolverForms, ContinuityAndPressureGradientConverge) {
  Results r;
  std::vector<double> dx, ec, em;
  for (int n : {8, 16, 32, 64}) {
    const FormErrors e = formErrors(n, 1.33);
    dx.push_back(1.0 / n), ec.push_back(e.continuity), em.push_back(e.momentum);
    std::printf("n %d cont %.4e mom %.4e vsBrute %.2e\n", n, e.continuity, e.momentum,
                e.continuityVsBruteForce);
    // The pair loop sums the same terms as the brute-force difference form: round-off only.
    EXPECT_TRUE(
        r.check("solver continuity vs brute-force difference form, n = " + std::to_string(n),
                e.continuityVsBruteForce, "<=", 1e-12, "same sum, different order: round-off"));
  }
  const double oc = r.convergence("solver continuity (eq. 11) -rho div v, quadratic h/dx = 1.33",
                                  "dx", dx, ec, 2.0, "Quinlan et al. 2006: O(h^2) until the floor");
  const double om = r.convergence("solver pressure gradient (eq. 12), quadratic h/dx = 1.33", "dx",
                                  dx, em, 2.0, "Quinlan et al. 2006: O(h^2) until the floor");
  std::printf("orders %.3f %.3f\n", oc, om);
}

}  // namespace
}  // namespace sph::verification
