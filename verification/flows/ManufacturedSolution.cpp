// Issue 3: the method of manufactured solutions for the whole discretisation (Manufactured.hpp).
//  * In time: fixed particles and resolution, dt refined alone over a short time against a run
//    with dt/64 of the finest. The predictor-corrector (Heun) and position Verlet are second order.
//  * In space, dt refined with h. At fixed h/dx: O(h^2) smoothing error until the discretisation
//    floor of the kernel sums, set by h/dx alone (Quinlan et al. 2006). With h/dx growing as dx
//    shrinks, h ~ dx^(1/2) (neighbours ~ N^(1/2), Zhu et al. 2015, as Negi & Ramachandran 2022
//    discuss), the floor falls with h/dx and the O(h^2) error shows: second order in h.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "FlowCases.hpp"
#include "Manufactured.hpp"
#include "Results.hpp"

namespace sph::verification {
namespace {

using M = Manufactured<2>;

// Runs to `t` with steps of exactly t / steps; returns the final particles.
Particles<2> runWithSteps(int n, const std::string& kernel, double hOverDx, double t, int steps,
                          const std::string& integrator = "predictor_corrector") {
  Simulation<2> sim = M::simulation(n, kernel, hOverDx, integrator);
  const double dt = t / steps;
  for (int s = 0; s < steps; ++s) {
    auto f = M::step(sim, dt);
    EXPECT_FALSE(f) << f->message;
  }
  return sim.particles();
}

double difference(const Particles<2>& a, const Particles<2>& b) {
  double e = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    Vec<2> dr = a.r[i] - b.r[i];
    for (int k = 0; k < 2; ++k) dr[k] -= std::round(dr[k]);  // periodic wrap
    e = std::max({e, (a.v[i] - b.v[i]).norm() / M::U,
                  std::abs(a.rho[i] - b.rho[i]) / (M::rho0 * M::eps), dr.norm() / (M::U * 0.1)});
  }
  return e;
}

// The observed order in time of `integrator` (its run file word): dt = T/8 ... T/64 against T/512.
double temporalOrder(Results& r, const std::string& integrator) {
  const double T = 0.1;  // 40 % of a CFL-limited run's first ~5 steps at n = 16
  const int n = 16;
  const Particles<2> ref = runWithSteps(n, "quadratic", 1.33, T, 512, integrator);
  std::vector<double> dts, errs;
  for (int steps : {8, 16, 32, 64}) {
    dts.push_back(T / steps);
    errs.push_back(difference(runWithSteps(n, "quadratic", 1.33, T, steps, integrator), ref));
    std::printf("%s: dt %.4e err %.4e\n", integrator.c_str(), dts.back(), errs.back());
  }
  return r.convergence("MMS temporal error (max of v, rho, r), n = 16, " + integrator, "dt", dts,
                       errs, 2.0, integrator + " is second order");
}

// Second order within 0.1 (MOOSE MMS practice, STYLE.md section 3); `name` follows the check's
// words, `why` says where the second order comes from.
void expectSecondOrderInTime(const std::string& integrator, const std::string& name,
                             const std::string& why) {
  Results r;
  const double order = temporalOrder(r, integrator);
  const std::string what = "MMS observed order in time" + (name.empty() ? "" : ", " + name);
  EXPECT_TRUE(r.check(what, order, ">=", 1.9, "theory 2 (" + why + "), minus 0.1"));
  EXPECT_TRUE(r.check(what + " (upper)", order, "<=", 2.1, "theory 2, plus 0.1"));
}

TEST(ManufacturedSolution, PredictorCorrectorIsSecondOrderInTime) {
  expectSecondOrderInTime("predictor_corrector", "", "Heun");
}

// Issue 31: the same for position Verlet (integrators/PositionVerlet.hpp), whose positions,
// velocities, density and h are each a midpoint or trapezoidal rule: second order.
TEST(ManufacturedSolution, PositionVerletIsSecondOrderInTime) {
  expectSecondOrderInTime("position_verlet", "position Verlet", "midpoint rules");
}

// Issue 31: the same for velocity Verlet (integrators/VelocityVerlet.hpp), whose new state's rates
// are its prediction's, O(dt^2) off: second order still.
TEST(ManufacturedSolution, VelocityVerletIsSecondOrderInTime) {
  expectSecondOrderInTime("velocity_verlet", "velocity Verlet",
                          "trapezoidal rules, rates O(dt^2) off");
}

// The largest errors over a run to T = 1/4 (a quarter period) at n^D particles, steps of a fixed
// dt below the acoustic (0.2 h / c0) and viscous (0.1 h^2 / nu) limits.
struct SpatialRun {
  double h, density = 0, velocity = 0;
};
template <int D>
SpatialRun spatialRun(int n, const std::string& kernel, double hOverDx,
                      const std::string& physics = "") {
  using MD = Manufactured<D>;
  const double T = 0.25, h = hOverDx / n;
  Simulation<D> sim = MD::simulation(n, kernel, hOverDx, "predictor_corrector", physics);
  const int steps =
      static_cast<int>(std::ceil(T / std::min(0.2 * h / MD::c0, 0.1 * h * h / MD::nu)));
  SpatialRun run{h};
  for (int s = 0; s < steps; ++s) {
    if (auto f = MD::step(sim, T / steps)) {
      ADD_FAILURE() << f->message;
      break;
    }
    const auto e = MD::error(sim.particles(), sim.time());
    run.density = std::max(run.density, e.density),
    run.velocity = std::max(run.velocity, e.velocity);
  }
  std::printf("%d-D %s n %d h/dx %.3f: rho %.4e v %.4e (%d steps)\n", D, kernel.c_str(), n, hOverDx,
              run.density, run.velocity, steps);
  return run;
}

// The observed orders (density, velocity) against `x` (dx or h) of the runs at n in `ns`, h/dx =
// hOverDx0 (n / ns[0])^growth, into `r` as `what`.
template <int D = 2>
std::pair<double, double> spatialOrders(Results& r, const std::string& kernel, double hOverDx0,
                                        double growth, const std::vector<int>& ns,
                                        const std::string& what, const std::string& xLabel,
                                        const std::string& physics = "") {
  std::vector<double> x, eRho, eV;
  for (int n : ns) {
    const SpatialRun run =
        spatialRun<D>(n, kernel, hOverDx0 * std::pow(double(n) / ns.front(), growth), physics);
    x.push_back(xLabel == "h" ? run.h : 1.0 / n), eRho.push_back(run.density),
        eV.push_back(run.velocity);
  }
  const std::string source = "theory 2: O(h^2) smoothing error (Quinlan et al. 2006)";
  return {r.convergence("MMS density error / (rho0 eps), " + what, xLabel, x, eRho, 2.0, source),
          r.convergence("MMS velocity error / U, " + what, xLabel, x, eV, 2.0, source)};
}

// The checks of the orders (density, velocity) of `o`: "MMS <field> observed order<what>" at or
// above their bars, for the reasons given.
void expectOrders(Results& r, const std::string& what, const std::pair<double, double>& o,
                  double rhoBar, const std::string& rhoWhy, double vBar, const std::string& vWhy) {
  EXPECT_TRUE(r.check("MMS velocity observed order" + what, o.second, ">=", vBar, vWhy));
  EXPECT_TRUE(r.check("MMS density observed order" + what, o.first, ">=", rhoBar, rhoWhy));
}

// At fixed h/dx. Measured (largest errors over the run):
//  * the paper's quadratic kernel at its h/dx = 1.33, n = 16, 32, 64: velocity 0.105, 0.020, 0.0074
//    (order 1.91), density 0.64, 0.17, 0.076 (1.54); at n = 128 the velocity error rises again to
//    0.0127 (density 0.11): the floor;
//  * the named model's Wendland C2 at its h/dx = 2, n = 16 ... 128: velocity 0.167 to 0.0043
//    (order 1.77), density 1.02 to 0.020 (1.89); its floor lies lower.
TEST(ManufacturedSolution, SpatialErrorAtFixedHOverDx) {
  Results r;
  expectOrders(
      r, ", n = 16..64, quadratic h/dx 1.33",
      spatialOrders(r, "quadratic", 1.33, 0.0, {16, 32, 64}, "quadratic h/dx = 1.33", "dx"), 1.4,
      "theory 2 before the floor; measured 1.54", 1.8, "theory 2 before the floor; measured 1.91");
  expectOrders(
      r, ", n = 16..128, Wendland C2 h/dx 2",
      spatialOrders(r, "wendland_c2", 2.0, 0.0, {16, 32, 64, 128}, "Wendland C2 h/dx = 2", "dx"),
      1.8, "theory 2 before the floor; measured 1.89", 1.7,
      "theory 2 before the floor; measured 1.77");
}

// Issue 31's bar: second order (1.9 or better) in h with h/dx growing, n = 16 ... 128, for the
// named model's kernel (Wendland C2, h/dx 1.4 to 3.96: the scene's limit is 4). Measured:
// velocity 2.04, density 2.20. The paper's quadratic kernel (h/dx 1.33 to 3.76): 1.89 and 1.92; on
// to n = 256 (h/dx 5.3, past the scene's limit, set by hand) 1.93 and 2.06, so its bar is its
// measurement.
TEST(ManufacturedSolution, SecondOrderInHWithHOverDxGrowing) {
  Results r;
  expectOrders(r, " in h, Wendland C2, h/dx growing",
               spatialOrders(r, "wendland_c2", 1.4, 0.5, {16, 32, 64, 128},
                             "Wendland C2, h ~ dx^(1/2)", "h"),
               1.9, "theory 2, minus 0.1 (issue 31)", 1.9, "theory 2, minus 0.1 (issue 31)");
  expectOrders(
      r, " in h, quadratic, h/dx growing",
      spatialOrders(r, "quadratic", 1.33, 0.5, {16, 32, 64, 128}, "quadratic, h ~ dx^(1/2)", "h"),
      1.8, "theory 2; measured 1.92 (2.06 on to n = 256)", 1.8,
      "theory 2; measured 1.89 (1.93 on to n = 256)");
}

// The named model's terms beside those (validation/scenes/*_named.toml: artificial viscosity
// beta 1 of eq. 10, variable h, Fourtakas et al.'s density diffusion delta 0.1), Wendland C2.
// Measured: at h/dx 2, n 16-128, density 2.08, velocity 1.94; with h/dx growing (1.4 to 3.96), in
// h, 2.36 and 2.30. The diffusion (delta h c0 lap rho, first order in h) and the artificial
// viscosity (a viscosity of order beta h c0 where the flow converges) do not show their O(h) over
// this range: at n = 128 the diffusion is some 0.2 % of d rho/dt here, and the velocity error falls
// with it.
TEST(ManufacturedSolution, NamedModelTerms) {
  Results r;
  const std::string named =
      "artificial_viscosity = 1.0\nvariable_h = true\ndensity_diffusion = 0.1\n"
      "density_diffusion_form = \"fourtakas\"\n";
  expectOrders(r, ", n = 16..128, named model h/dx 2",
               spatialOrders(r, "wendland_c2", 2.0, 0.0, {16, 32, 64, 128}, "named model, h/dx = 2",
                             "dx", named),
               1.8, "theory 2 before the floor; measured 2.08", 1.8,
               "theory 2 before the floor; measured 1.94");
  expectOrders(r, " in h, named model, h/dx growing",
               spatialOrders(r, "wendland_c2", 1.4, 0.5, {16, 32, 64, 128},
                             "named model, h ~ dx^(1/2)", "h", named),
               1.9, "theory 2, minus 0.1 (issue 31)", 1.9, "theory 2, minus 0.1 (issue 31)");
}

// The same in 3-D (the periodic unit cube) for the named model's kernel at its h/dx 2, n = 16, 24,
// 32 (32,768 particles; the 2-D study's finer n would take minutes). Measured: velocity 0.284,
// 0.135, 0.077 (order 1.87), density 1.92, 0.86, 0.48 (1.99); larger than in 2-D at equal n, as
// div v = 3 a k C is.
TEST(ManufacturedSolution, SpatialErrorIn3D) {
  Results r;
  expectOrders(
      r, ", 3-D, n = 16..32, Wendland C2 h/dx 2",
      spatialOrders<3>(r, "wendland_c2", 2.0, 0.0, {16, 24, 32}, "3-D, Wendland C2 h/dx = 2", "dx"),
      1.8, "theory 2 before the floor; measured 1.99", 1.7,
      "theory 2 before the floor; measured 1.87");
}

}  // namespace
}  // namespace sph::verification
