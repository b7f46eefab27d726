// Issue 31 (nightly): wall penetration with the paper's mirror ghosts against wall particles
// (Adami et al. 2012), on the paper's dam break (validation/scenes/dam_break.toml) and on a tank
// at rest (WallCases.hpp), each run with both models in turn. Prints, per run: wall reflections,
// the deepest reflected crossing / dx, the max volume variation, the floor probe's pressure
// against rho0 g H (tank), the largest speed over the second half / sqrt(g H) (tank), the wall
// time and its ratio to the mirror-ghost run (alternated runs, one after the other).
#include <gtest/gtest.h>

#include <cstdio>

#include "Results.hpp"
#include "WallCases.hpp"

namespace sph::verification {
namespace {

constexpr double kG = 9.81;

void print(const char* what, const char* model, const WallRun& w, double dx, double pScale,
           double speedScale, double mirrorSeconds) {
  std::printf(
      "%-22s %-15s %-8s refl %5ld deepest/dx %.3f vol %.3e p/rhogH-1 %+.3e "
      "max|u|/sqrt(gH) %.3e %7.1f s x%.2f\n",
      what, model, w.stable ? "stable" : "FAILED", w.reflections, w.deepest / dx, w.volumeVariation,
      pScale > 0 ? w.bottomPressure / pScale - 1 : 0.0,
      speedScale > 0 ? w.maxSpeed / speedScale : 0.0, w.seconds,
      mirrorSeconds > 0 ? w.seconds / mirrorSeconds : 1.0);
  if (!w.stable) std::printf("  %s\n", w.failure.c_str());
}

TEST(WallPenetrationStudy, DamBreak) {
  Results r;
  for (double dx : {0.02, 0.01}) {
    const WallRun ghosts =
        runWalls<2>(parseScene(damBreakScene("mirror_ghosts", dx, 1.3), "dam_break"), 13);
    const WallRun particles =
        runWalls<2>(parseScene(damBreakScene("wall_particles", dx, 1.3), "dam_break"), 13);
    char what[64];
    std::snprintf(what, sizeof what, "dam break dx %.3f", dx);
    print(what, "mirror_ghosts", ghosts, dx, 0, 0, 0);
    print(what, "wall_particles", particles, dx, 0, 0, ghosts.seconds);
    const std::string at = " (dx " + std::to_string(dx) + ")";
    r.figure("mirror ghosts: wall reflections" + at, ghosts.reflections, "measured");
    r.figure("mirror ghosts: volume variation" + at, ghosts.volumeVariation, "measured");
    r.figure("wall particles: volume variation" + at, particles.volumeVariation, "measured");
    EXPECT_TRUE(particles.stable) << particles.failure;
    r.figure("wall particles: wall reflections" + at, particles.reflections, "measured");
    EXPECT_TRUE(r.check("wall particles: deepest crossing / dx" + at, particles.deepest / dx,
                        "<=", 0.02, "the quick test's bound (WallParticlesTest.cpp)"));
  }
}

TEST(WallPenetrationStudy, RestingTank) {
  Results r;
  const double T = 10 * std::sqrt(1.0 / kG), pScale = 1000.0 * kG * 1.0, speed = std::sqrt(kG);
  for (int cells : {20, 40}) {
    const WallRun ghosts =
        runWalls<2>(parseScene(restingTankScene("mirror_ghosts", cells, T), "tank"));
    const WallRun particles =
        runWalls<2>(parseScene(restingTankScene("wall_particles", cells, T), "tank"));
    char what[64];
    std::snprintf(what, sizeof what, "tank H/dx %d", cells);
    print(what, "mirror_ghosts", ghosts, 1.0 / cells, pScale, speed, 0);
    print(what, "wall_particles", particles, 1.0 / cells, pScale, speed, ghosts.seconds);
    const std::string at = " (H/dx " + std::to_string(cells) + ")";
    r.figure("mirror ghosts: |p_floor / rho0 g H - 1|" + at,
             std::abs(ghosts.bottomPressure / pScale - 1), "measured");
    EXPECT_TRUE(particles.stable) << particles.failure;
    EXPECT_TRUE(r.check("wall particles: |p_floor / rho0 g H - 1|" + at,
                        std::abs(particles.bottomPressure / pScale - 1), "<=", 0.04,
                        "the quick test's bound (WallParticlesTest.cpp)"));
  }
}

}  // namespace
}  // namespace sph::verification
