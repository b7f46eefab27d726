// Issue 31 (nightly): the paper's dam break (validation/scenes/dam_break.toml, dx 0.01, to 1.3 s)
// with each form of particle shifting (ParticleShifting.hpp) beside the paper's model, once a step
// and once in 5 steps (shifting_every). Measured here (2026-12-05; volume over every 10th step):
// volume variation 0.166 % (paper), 0.238 % (Lind), 0.182 % (Lind every 5), 0.215 % (delta-plus),
// 0.190 % (delta-plus every 5); the largest x of the fluid at t sqrt(g/H) = 2 4.620 H (paper),
// 4.638 H and 4.638 H (Lind), 4.632 H and 4.622 H (delta-plus): 0.39 % ahead at most, and the
// shift every 5 steps within 0.22 % of the shift every step. Bars: the paper's 0.3 % (Lobovsky &
// Kren, section 3) for the volume; the front within 2 % of the paper model's, five times the
// measured 0.4 %, as shifting moves particles by a fraction of their displacement and should not
// change the flow's front; and within 1 % of the shift every step's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "FlowCases.hpp"
#include "Results.hpp"

namespace sph::verification {
namespace {

struct DamBreak {
  double volume = 0.0;  // max |V / V0 - 1| over every 10th step
  double front = 0.0;   // the largest x of the fluid at t sqrt(g/H) = 2, over H
};

DamBreak run(ShiftingForm form, int every = 1) {
  Scene scene = readScene(DAM_BREAK_SCENE);
  scene.shifting = {.form = form,
                    .coefficient = defaultShiftingCoefficient(form),
                    .surfaceThreshold = defaultSurfaceThreshold(2),
                    .every = every};
  Simulation<2> sim(scene);
  const double H = 0.25, g = 9.81, tFront = 2.0 * std::sqrt(H / g);
  auto volume = [&] {
    double V = 0.0;
    for (std::size_t i = 0; i < sim.particles().size(); ++i)
      V += sim.particles().m[i] / sim.particles().rho[i];
    return V;
  };
  const double V0 = volume();
  DamBreak out;
  bool fronted = false;
  while (sim.time() < scene.endTime * (1 - 1e-12)) {
    const double next = fronted ? scene.endTime : tFront;
    for (int k = 0; k < 10 && sim.time() < next * (1 - 1e-12); ++k) {
      const auto f = sim.advance(next - sim.time());
      if (f) ADD_FAILURE() << f->message;
      if (f) return out;
    }
    out.volume = std::max(out.volume, std::abs(volume() / V0 - 1.0));
    if (!fronted && sim.time() >= tFront * (1 - 1e-12)) {
      for (const auto& r : sim.particles().r) out.front = std::max(out.front, r[0] / H);
      fronted = true;
    }
  }
  return out;
}

TEST(ShiftingDamBreakNightly, KeepsVolumeAndFront) {
  Results r;
  const DamBreak paper = run(ShiftingForm::none);
  std::printf("paper: volume %.4f %%, front %.4f H\n", 100 * paper.volume, paper.front);
  for (ShiftingForm form : {ShiftingForm::lind, ShiftingForm::delta_plus}) {
    DamBreak each;
    for (int every : {1, 5}) {
      const DamBreak s = run(form, every);
      const std::string what = "dam break dx 0.01, shifting " + std::string(name(form)) +
                               (every > 1 ? " every " + std::to_string(every) + " steps" : "");
      std::printf("%s: volume %.4f %%, front %.4f H\n", what.c_str(), 100 * s.volume, s.front);
      EXPECT_TRUE(r.check(what + ": max volume variation", s.volume, "<", 0.003,
                          "Lobovsky & Kren, section 3: volume variations less than 0.3 %"));
      EXPECT_TRUE(r.check(what + ": |front - paper model's| / paper model's at t* = 2",
                          std::abs(s.front - paper.front) / paper.front, "<", 0.02,
                          "five times the measured 0.4 %"));
      if (every == 1)
        each = s;
      else
        EXPECT_TRUE(r.check(what + ": |front - a shift every step's| / that at t* = 2",
                            std::abs(s.front - each.front) / each.front, "<", 0.01,
                            "about five times the measured 0.22 % (delta-plus)"));
    }
  }
}

}  // namespace
}  // namespace sph::verification
