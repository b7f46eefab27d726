#pragma once
// The elliptical-drop comparison shared by the quick and nightly tests: a Cartesian and a packed
// start (validation/packing/elliptical_drop{,_packed}.toml) at one R/dx, semi-axis errors against
// the ODE, written to the results file.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "EllipticalDrop.hpp"
#include "Results.hpp"

namespace sph::verification {

// Monaghan (1994): A0 = 100 1/s, R = 1 m, c0 = 1400 m/s, to t = 0.0076 s (t A0 = 0.76); and on
// to t A0 = 2, the time of Colagrossi et al. (2012) Fig. 16.
inline const std::vector<double> kDropTimes = {0.0, 0.0025, 0.005, 0.0076};
inline const std::vector<double> kDropTimesLong = {0.0, 0.0025, 0.005, 0.0076, 0.01, 0.015, 0.02};
constexpr double kMonaghanEnd = 0.0076;

// Measured: the larger relative semi-axis error (second moments), max over the times up to the
// end given; Wendland C2, h/dx = 2, no viscosity, Monaghan's A0, R, c0; packing alpha = 5e-3:
//   R/dx   to t = 0.0076 s: Cartesian  packed   ratio   to t = 0.02 s: Cartesian  packed  ratio
//   20                      1.28e-2    2.94e-3  0.23                   1.55e-1    1.55e-2 0.10
//   40                      1.17e-2    3.34e-3  0.29                   1.43e-1    4.06e-3 0.028
//   80                      1.25e-2    2.61e-3  0.21                   2.14e-2    4.42e-3 0.21
// (R/dx = 80 to t = 0.02 s measured once, outside the tests: about 15 min). Up to t = 0.0076 s the
// error does not fall with dx at fixed h/dx: it is the minor axis that lags (b too large; a b
// grows to 1.012 R^2 by t = 0.0076 s from the Cartesian start, 1.003 R^2 from the packed one),
// the rows of a Cartesian start resisting compression across them (Colagrossi et al. 2012,
// Fig. 16: particles "clump along straight lines"). Later the Cartesian start's minor axis stalls
// at R/dx = 20 and 40 (b 14-16 % too large at t A0 = 2) but not at R/dx = 80 (max 2.1 %, at
// t = 0.015 s). Tolerances: 1.5 times the largest measured error of each start over the
// resolutions the tests run, and the paper's claim that the packed start is closer, as the packed
// error below a fraction of the Cartesian one: half to t = 0.0076 s (measured 0.21-0.29), and to
// t A0 = 2 a fifth at the R/dx = 40 of the test (measured 0.028 at 40, 0.10 at 20; at 80 it is
// 0.21, so the bound holds for R/dx <= 40 only).
struct DropTolerance {
  double cartesian, packed, ratio;
};
constexpr DropTolerance kDropToMonaghan = {0.02, 0.005, 0.5};  // 1.5 x 1.28e-2, 1.5 x 3.34e-3
constexpr DropTolerance kDropToFig16 = {0.23, 0.023, 0.2};     // 1.5 x 1.55e-1, 1.5 x 1.55e-2

inline const DropTolerance& dropTolerance(double t) {
  return t <= kMonaghanEnd * (1 + 1e-12) ? kDropToMonaghan : kDropToFig16;
}

struct DropRun {
  std::vector<DropSample> samples;
  // max of DropSample::errorMoment over the times up to `end`
  double maxError(double end) const {
    double e = 0.0;
    for (const DropSample& s : samples)
      if (s.t <= end * (1 + 1e-9)) e = std::max(e, s.errorMoment());
    return e;
  }
};

inline DropRun dropRun(const std::string& start, double ROverDx, const std::vector<double>& times,
                       Results& r) {
  const std::string scene = std::string(SPH_SOURCE_DIR) + "/validation/packing/elliptical_drop" +
                            (start == "packed" ? "_packed" : "") + ".toml";
  long steps = 0;
  DropRun run;
  run.samples = runDrop(scene, ROverDx, times, &steps);
  const std::string tag = start + " start, R/dx = " + std::to_string(static_cast<int>(ROverDx));
  for (const DropSample& s : run.samples) {
    std::printf(
        "%s, t = %.4f: a %.5f (ODE %.5f), b %.5f (ODE %.5f), err %.2e; extent a %.4f "
        "b %.4f; raggedness %.4f\n",
        tag.c_str(), s.t, s.aMoment, s.ode.a, s.bMoment, s.ode.b, s.errorMoment(), s.aExtent,
        s.bExtent, s.raggedness);
    char t[32];
    std::snprintf(t, sizeof t, "%.4g", s.t);
    const DropTolerance& tol = dropTolerance(s.t);
    r.check("elliptical drop, " + tag + ", t = " + t +
                " s: max(|a/a_ode - 1|, |b/b_ode - 1|), second moments",
            s.errorMoment(), "<=", start == "packed" ? tol.packed : tol.cartesian,
            "Monaghan 1994 ODE (GSL rk8pd); tolerance of EllipticalDropCommon.hpp");
  }
  std::printf("%s: %ld steps\n", tag.c_str(), steps);
  return run;
}

// The asserted figures of one resolution, to t = 0.0076 s and, when the runs went on, to the end.
inline void checkDropErrors(Results& r, double ROverDx, const DropRun& cartesian,
                            const DropRun& packed) {
  std::vector<double> ends = {kMonaghanEnd};
  if (cartesian.samples.back().t > kMonaghanEnd * (1 + 1e-9))
    ends.push_back(cartesian.samples.back().t);
  for (double end : ends) {
    const DropTolerance& tol = dropTolerance(end);
    char t[32];
    std::snprintf(t, sizeof t, "%.4g", end);
    const std::string at = "R/dx = " + std::to_string(static_cast<int>(ROverDx)) +
                           ": max semi-axis error to t = " + t + " s";
    const double c = cartesian.maxError(end), p = packed.maxError(end);
    const std::string source = "Monaghan 1994 ODE; measured, EllipticalDropCommon.hpp";
    EXPECT_TRUE(r.check("elliptical drop, Cartesian start, " + at, c, "<=", tol.cartesian, source));
    EXPECT_TRUE(r.check("elliptical drop, packed start, " + at, p, "<=", tol.packed, source));
    EXPECT_TRUE(r.check("elliptical drop, packed / Cartesian error, " + at, p / c, "<=", tol.ratio,
                        "Colagrossi et al. 2012 section 3.4: the packed start is closer to the "
                        "analytical boundary; measured ratio, EllipticalDropCommon.hpp"));
  }
}

}  // namespace sph::verification
