// No-slip mirror ghosts in flows whose velocity varies along the wall
// (boundaries/NoSlipContinuity.hpp): the continuity equation takes each no-slip ghost with its
// free-slip velocity. Quick: a coarse lid-driven cavity and a closed box spun up.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "Cavity.hpp"
#include "Results.hpp"

namespace sph::verification {
namespace {

// 25 x 25 to t = 5 L/U. Measured (this test): volume 3.1e-4, 17 wall reflections; before the
// correction the run stopped at t = 3.5 s (density band; volume 14 %, 2,352 reflections).
TEST(NoSlipWalls, CoarseLidDrivenCavityKeepsItsVolume) {
  Results r;
  const CavityRun c = runCavity(cavity(25, 5.0), 5.0);
  std::printf("cavity 25 x 25 to t = 5: volume %.3e, reflections %ld, u(0.5, 0.5) %.4f\n",
              c.volumeVariation, c.reflections, velocityAt(c.last, 0.5, 0.5, 0, 0.04));
  ASSERT_TRUE(c.stable) << c.failure;
  EXPECT_TRUE(r.check("lid-driven cavity, 25 x 25, t <= 5 L/U: max volume variation",
                      c.volumeVariation, "<=", 1e-3, "measured 3.1e-4, x 3"));
}

// Water spun up as a rigid rotation (5 rad/s, the stretching pressure, p0 = 20 kPa so that nothing
// is in tension) in a closed 0.4 m box of no-slip faces, no gravity, 20 x 20, the named model's
// terms, to 3 s (2.4 turns): the walls turn the rotation into a vortex that the box's corners
// slow. Measured (this test): volume 8.1e-4, no reflection; before the correction 1.45e-2 and 214.
TEST(NoSlipWalls, SpunUpBoxKeepsItsVolume) {
  Results r;
  const std::string text =
      "name = \"spin\"\ndimension = 2\n[domain]\nlower = [0.0, 0.0]\nupper = [0.4, 0.4]\n"
      "x_lower = \"no_slip\"\nx_upper = \"no_slip\"\ny_lower = \"no_slip\"\ny_upper = "
      "\"no_slip\"\n[[phase]]\nname = \"water\"\nrho0 = 1000.0\nc0 = 20.0\nmu = 1e-3\n"
      "p0 = 20000.0\n[[fluid]]\nlower = [0.0, 0.0]\nupper = [0.4, 0.4]\n"
      "velocity_gradient = [[0.0, 5.0], [-5.0, 0.0]]\ninitial_pressure = \"stretching\"\n"
      "[physics]\nartificial_viscosity = 1.0\nmorris_viscosity = true\nvariable_h = true\n"
      "density_diffusion = 0.1\ndensity_diffusion_form = \"fourtakas\"\n[numerics]\n"
      "kernel = \"wendland_c2\"\ndx = 0.02\nh_over_dx = 2.0\nend_time = 3.0\n";
  const CavityRun c = runCavity(text, 3.0);
  std::printf("spun-up box 20 x 20 to t = 3 s: volume %.3e, reflections %ld\n", c.volumeVariation,
              c.reflections);
  ASSERT_TRUE(c.stable) << c.failure;
  EXPECT_TRUE(r.check("spun-up box, 20 x 20, t <= 3 s: max volume variation", c.volumeVariation,
                      "<=", 2.5e-3, "measured 8.1e-4, x 3"));
  EXPECT_TRUE(r.check("spun-up box: wall reflections", c.reflections, "<=", 0,
                      "no particle reaches a wall (0 measured)"));
}

}  // namespace
}  // namespace sph::verification
