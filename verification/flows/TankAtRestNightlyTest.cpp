// Issue 31 (nightly): the tank at rest of TankAtRest.hpp to t sqrt(g/H) = 100 with the named
// model (the paper's terms with Fourtakas et al.'s density diffusion, delta 0.1), one ctest entry
// a case. The bottom pressures quoted below were read against rho0 g H; against the column's
// weight (TankAtRest.hpp, from 2026-12-07) each reads 0.4-0.5 % less: verification/README.md has
// both. The named model's kernel, Wendland C2 at h/dx 2, must meet issue 31's bars (measured
// with validation/stability/tank_at_rest_study.py: max|u| 3.8e-3, 4.0e-3, 2.8e-3, 5.2e-3, 5.2e-3
// sqrt(gH) and bottom pressure 0.73, 0.73, 0.60, 0.60, 0.64 % at H/dx 20 1:1, 20 4:1, 40 1:1,
// 40 4:1, 80 1:1; the last two took 284 and 553 s of one core). The paper's quadratic kernel and
// the cubic spline (h/dx 1.33) do not everywhere:
//   H/dx 20, 1:1: quadratic max|u| 2.1e-3 sqrt(gH), bottom 1.6 %; cubic 6.0e-3, 0.67 %
//   H/dx 20, 4:1: quadratic 1.8e-2, 1.5 %;                       cubic 1.9e-2, 0.59 %
//   H/dx 40, 1:1: quadratic 2.5e-3, 1.6 %;                       cubic 5.5e-3, 0.65 %
//   H/dx 40, 4:1: quadratic 8.4e-3, 1.7 %;                       cubic 6.7e-3, 0.59 %
// (4:1 at H/dx 40 not run here for them)
// so where they fail a bar their cases keep regression bounds of 2.5 times the measured values.
// In 3-D (a tank 1 x 1 x 1 H) the named model misses the speed bar at H/dx 20: max|u| 0.0157
// sqrt(gH), bottom pressure 0.71 % (1,133 s of one core, 2026-12-06); it starts to move at
// t sqrt(g/H) = 49 (verification/README.md), so that case keeps a regression bound on the speed.
// That is the cubic lattice giving way under pressure (sph/LatticeUnderPressure.hpp): started
// packed instead (initial = "packed", noise 0.1 dx; SCENES.md) the same tank meets both bars,
// max|u| 6.8e-3 sqrt(gH) and bottom 0.71 % (1,321 s of one core, 2026-12-07). Packed starts of
// the paper's kernels at 4:1, H/dx 20 (the lattice gives way there): quadratic 2.5e-3 sqrt(gH)
// and 2.2 %, cubic spline 1.2e-2 and 0.87 % (lattice starts: 1.8e-2 and 1.5 %, 1.9e-2 and 0.59 %),
// kept under regression bounds where they miss a bar.
// Not here: 4:1 at H/dx 80 (8 times the 4:1 tank at H/dx 40: about 40 min of one core).
// With Antuono et al.'s diffusion in place of Fourtakas et al.'s (the study's `antuono`), the 4:1
// tank at H/dx 40: max|u| 2.3e-3 sqrt(gH), bottom 0.82 % (543 s of one core, loaded machine).
#include <gtest/gtest.h>

#include <cstdio>
#include <ostream>
#include <string>

#include "Results.hpp"
#include "TankAtRest.hpp"

namespace sph::verification::tank_at_rest {
namespace {

struct NightlyCase {
  Case tank;
  double speedBound, bottomBound;  // the bars, or the regression bounds above
  const char* source;
  const Model* model = &fourtakas;
};

// The case's name for gtest (and so for ctest): its kernel, aspect and resolution, not its bytes.
void PrintTo(const NightlyCase& n, std::ostream* out) {
  *out << n.tank.kernel.name << " " << n.tank.aspect << ":1 H/dx " << n.tank.cells
       << (n.tank.dimension == 3 ? " 3-D" : "") << (n.tank.packed ? " packed" : "") << ", "
       << n.model->name;
}

const char* const bar = "issue 31's bar";
const char* const regression = "finding: regression bound, 2.5 x the measured value";

class TankAtRestNightly : public ::testing::TestWithParam<NightlyCase> {};

TEST_P(TankAtRestNightly, HoldsStill) {
  const NightlyCase& n = GetParam();
  const Model& model = *n.model;
  const Outcome o = run(n.tank, model);
  const std::string what =
      std::string(n.tank.dimension == 3 ? "3-D " : "") + (n.tank.packed ? "packed " : "") +
      "tank at rest, H/dx " + std::to_string(n.tank.cells) + ", " +
      std::to_string(int(n.tank.aspect)) + ":1, " + n.tank.kernel.name + ", " + model.name;
  std::printf("%s: ran %d to %.1f, max|u|/sqrt(gH) %.3e, bottom %.3e, %.1f s\n", what.c_str(),
              o.ran, o.stoppedAt, o.speed, o.bottom, o.seconds);
  ASSERT_TRUE(o.ran) << what << ": " << o.why;
  Results r;
  EXPECT_TRUE(r.check(what + ": max|u| / sqrt(gH), second half of t sqrt(g/H) = 100", o.speed, "<",
                      n.speedBound, n.source));
  EXPECT_TRUE(r.check(what + ": max |p_bottom / (g M / A) - 1|, second half", o.bottom, "<",
                      n.bottomBound, n.source));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, TankAtRestNightly,
    ::testing::Values(
        NightlyCase{{1.0, 20, wendland, 100.0}, speedBar, bottomPressureBar, bar},
        NightlyCase{{4.0, 20, wendland, 100.0}, speedBar, bottomPressureBar, bar},
        NightlyCase{{1.0, 40, wendland, 100.0}, speedBar, bottomPressureBar, bar},
        NightlyCase{{4.0, 40, wendland, 100.0}, speedBar, bottomPressureBar, bar},
        NightlyCase{{1.0, 80, wendland, 100.0}, speedBar, bottomPressureBar, bar},
        NightlyCase{{1.0, 20, quadratic, 100.0}, 5.3e-3, 0.041, regression},
        NightlyCase{{4.0, 20, quadratic, 100.0}, 0.046, 0.038, regression},
        NightlyCase{{1.0, 40, quadratic, 100.0}, 6.2e-3, 0.040, regression},
        NightlyCase{{1.0, 20, cubicSpline, 100.0}, speedBar, bottomPressureBar, bar},
        NightlyCase{{4.0, 20, cubicSpline, 100.0}, 0.049, bottomPressureBar, regression},
        NightlyCase{{1.0, 40, cubicSpline, 100.0}, speedBar, bottomPressureBar, bar},
        NightlyCase{{1.0, 20, wendland, 100.0, 0.25, 3}, 0.039, bottomPressureBar, regression},
        NightlyCase{{4.0, 40, wendland, 100.0}, speedBar, bottomPressureBar, bar, &antuono},
        NightlyCase{
            {1.0, 20, wendland, 100.0, 0.25, 3, true, 0.1}, speedBar, bottomPressureBar, bar},
        NightlyCase{{4.0, 20, quadratic, 100.0, 0.25, 2, true, 0.1}, speedBar, 0.054, regression},
        NightlyCase{{4.0, 20, cubicSpline, 100.0, 0.25, 2, true, 0.1},
                    0.031,
                    bottomPressureBar,
                    regression}),
    [](const ::testing::TestParamInfo<NightlyCase>& i) {
      return i.param.tank.kernel.name + "_aspect" + std::to_string(int(i.param.tank.aspect)) +
             "_cells" + std::to_string(i.param.tank.cells) +
             (i.param.tank.dimension == 3 ? "_3d" : "") +
             (i.param.model == &antuono ? "_antuono" : "") + (i.param.tank.packed ? "_packed" : "");
    });

// The named model with particle shifting (ParticleShifting.hpp, each form at its default A),
// Wendland C2, H/dx 20, 1:1, to t sqrt(g/H) = 100: measured max|u| 3.8e-3 and 3.8e-3 sqrt(gH),
// bottom pressure 0.73 % and 0.84 % (Lind, delta-plus), against 3.8e-3 and 0.73 % without.
TEST(TankAtRestShiftingNightly, NamedModelWithShiftingHoldsStill) {
  Results r;  // one for the test: each Results writes the test's one file when destroyed
  for (const Model* m : {&fourtakasLind, &fourtakasDeltaPlus}) {
    const Outcome o = run({1.0, 20, wendland, 100.0}, *m);
    const std::string what = "tank at rest, H/dx 20, 1:1, wendland_c2, " + m->name;
    std::printf("%s: ran %d to %.1f, max|u|/sqrt(gH) %.3e, bottom %.3e, %.1f s\n", what.c_str(),
                o.ran, o.stoppedAt, o.speed, o.bottom, o.seconds);
    ASSERT_TRUE(o.ran) << what << ": " << o.why;
    EXPECT_TRUE(r.check(what + ": max|u| / sqrt(gH), second half of t sqrt(g/H) = 100", o.speed,
                        "<", speedBar, bar));
    EXPECT_TRUE(r.check(what + ": max |p_bottom / (g M / A) - 1|, second half", o.bottom, "<",
                        bottomPressureBar, bar));
  }
}

}  // namespace
}  // namespace sph::verification::tank_at_rest
