#pragma once
// The elliptical-drop comparison shared by the quick and nightly tests: a Cartesian and a packed
// start (validation/packing/elliptical_drop{,_packed}.toml) at one R/dx, semi-axis errors against
// the ODE at Monaghan's (1994) times, written to the results file.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "EllipticalDrop.hpp"
#include "Results.hpp"

namespace sph::verification {

// Monaghan (1994): A0 = 100 1/s, R = 1 m, c0 = 1400 m/s, to t = 0.0076 s (t A0 = 0.76).
inline const std::vector<double> kDropTimes = {0.0, 0.0025, 0.005, 0.0076};

// The asserted figures at one R/dx. Measured (max over t = 0 .. 0.0076 s of the larger relative
// semi-axis error, second moments; Wendland C2, h/dx = 2, no viscosity, Monaghan's A0, R, c0):
//   R/dx      Cartesian   packed    packed / Cartesian
//   20        1.28e-2     2.92e-3   0.23
//   40        1.17e-2     4.07e-3   0.35
//   80        1.25e-2     2.30e-3   0.18
// The error does not fall with dx at fixed h/dx: it is the minor axis that lags (b too large;
// a b grows to 1.012 R^2 from the Cartesian start, 1.004 R^2 from the packed one), the rows of a
// Cartesian start resisting compression across them (Colagrossi et al. 2012, Fig. 16: particles
// "clump along straight lines"). Tolerances: 1.5 times the largest measured error of each start
// over the resolutions, and the paper's claim that the packed start is closer, as packed error
// below half the Cartesian one (measured 0.18-0.35).
constexpr double kDropToleranceCartesian = 0.02;  // 1.5 x 1.28e-2
constexpr double kDropTolerancePacked = 0.006;    // 1.5 x 4.07e-3
constexpr double kDropPackedOverCartesian = 0.5;  // measured 0.18-0.35

struct DropRun {
  std::vector<DropSample> samples;
  double maxError = 0.0;  // max over the times of DropSample::errorMoment
};

inline DropRun dropRun(const std::string& start, double ROverDx, Results& r) {
  const std::string scene = std::string(SPH_SOURCE_DIR) + "/validation/packing/elliptical_drop" +
                            (start == "packed" ? "_packed" : "") + ".toml";
  long steps = 0;
  DropRun run;
  run.samples = runDrop(scene, ROverDx, kDropTimes, &steps);
  const std::string tag = start + " start, R/dx = " + std::to_string(static_cast<int>(ROverDx));
  for (const DropSample& s : run.samples) {
    std::printf(
        "%s, t = %.4f: a %.5f (ODE %.5f), b %.5f (ODE %.5f), err %.2e; extent a %.4f "
        "b %.4f; raggedness %.4f\n",
        tag.c_str(), s.t, s.aMoment, s.ode.a, s.bMoment, s.ode.b, s.errorMoment(), s.aExtent,
        s.bExtent, s.raggedness);
    char t[32];
    std::snprintf(t, sizeof t, "%.4g", s.t);
    r.check("elliptical drop, " + tag + ", t = " + t +
                " s: max(|a/a_ode - 1|, |b/b_ode - 1|), second moments",
            s.errorMoment(),
            "<=", start == "packed" ? kDropTolerancePacked : kDropToleranceCartesian,
            "Monaghan 1994 ODE (GSL rk8pd); tolerance of EllipticalDropCommon.hpp");
    run.maxError = std::max(run.maxError, s.errorMoment());
  }
  std::printf("%s: %ld steps\n", tag.c_str(), steps);
  return run;
}

inline void checkDropErrors(Results& r, double ROverDx, double cartesian, double packed) {
  const std::string at = "R/dx = " + std::to_string(static_cast<int>(ROverDx)) +
                         ": max semi-axis error to t = 0.0076 s";
  EXPECT_TRUE(r.check("elliptical drop, Cartesian start, " + at, cartesian,
                      "<=", kDropToleranceCartesian,
                      "Monaghan 1994 ODE; measured, EllipticalDropCommon.hpp"));
  EXPECT_TRUE(r.check("elliptical drop, packed start, " + at, packed, "<=", kDropTolerancePacked,
                      "Monaghan 1994 ODE; measured, EllipticalDropCommon.hpp"));
  EXPECT_TRUE(r.check("elliptical drop, packed / Cartesian error, " + at, packed / cartesian,
                      "<=", kDropPackedOverCartesian,
                      "Colagrossi et al. 2012 section 3.4: the packed start is closer to the "
                      "analytical boundary; measured ratio, EllipticalDropCommon.hpp"));
}

}  // namespace sph::verification
