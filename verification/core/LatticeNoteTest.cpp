// `sph check` says whether the lattice a scene's fluid starts on holds under the pressure it starts
// at (sph/LatticeUnderPressure.hpp), and if not at what rate a still fluid leaves it: the line the
// program prints against the library's analysis of the same scene.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "ProgramHelpers.hpp"
#include "sph/LatticeUnderPressure.hpp"

namespace {

using namespace sph::core_tests;

// The rate `sph check` prints, or -1 where its lattice line gives none.
double printedRate(const std::string& output) {
  const auto at = output.find("a mode grows at ");
  double sigma = -1.0;
  if (at != std::string::npos) std::sscanf(output.c_str() + at, "a mode grows at %lf", &sigma);
  return sigma;
}

TEST(CheckLatticeNote, TheSmallTanksLatticeGivesWayWithTheQuadraticKernel) {
  // small_tank.toml: 0.1 m of water at rest on its lattice, quadratic kernel at h/dx 1.33, dx 0.01.
  const ProgramResult r = runSph("check '" + scenePath("small_tank.toml") + "'");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("lattice: the square lattice the fluid starts on gives way under "
                          "pressure with quadratic at h/dx 1.33"),
            std::string::npos)
      << r.output;
  const double S = sph::leastStiffLatticeMode<2>(sph::KernelKind::quadratic, 1.33, 32).stiffness;
  const double sigma = sph::latticeGrowthRate(S, 9.81 * 0.1, 0.01);
  EXPECT_NEAR(printedRate(r.output), sigma, 5e-3 * sigma) << r.output;  // printed to 3 digits
}

TEST(CheckLatticeNote, WendlandAtH2HoldsTheSquareLatticeAndNotTheCubicOne) {
  const ProgramResult square =
      runSph("check '" +
             editedScene({{"kernel = \"quadratic\"", "kernel = \"wendland_c2\""},
                          {"h_over_dx = 1.33", "h_over_dx = 2.0"}}) +
             "'");
  ASSERT_EQ(square.exitCode, 0) << square.output;
  EXPECT_NE(square.output.find("lattice: the square lattice the fluid starts on holds under "
                               "pressure with wendland_c2 at h/dx 2"),
            std::string::npos)
      << square.output;
  EXPECT_EQ(printedRate(square.output), -1.0) << square.output;
  // hydrostatic_box_3d.toml: 0.1 m of water in a box, dx 0.0125.
  const ProgramResult cubic =
      runSph("check '" +
             editedScene({{"kernel = \"quadratic\"", "kernel = \"wendland_c2\"\nh_over_dx = 2.0"}},
                         "hydrostatic_box_3d.toml") +
             "'");
  ASSERT_EQ(cubic.exitCode, 0) << cubic.output;
  EXPECT_NE(cubic.output.find("lattice: the cubic lattice the fluid starts on gives way"),
            std::string::npos)
      << cubic.output;
  const double S = sph::leastStiffLatticeMode<3>(sph::KernelKind::wendland_c2, 2.0, 8).stiffness;
  const double sigma = sph::latticeGrowthRate(S, 9.81 * 0.1, 0.0125);
  EXPECT_NEAR(printedRate(cubic.output), sigma, 5e-3 * sigma) << cubic.output;
}

TEST(CheckLatticeNote, APackedStartOffTheLatticeHasNoLineAndOneOnItHas) {
  // The 3-D box packed from its lattice: its lattice and layers are at rest, so the packing keeps
  // the cubic lattice and the line stays; moved off it by noise, the start is no lattice.
  const std::string wendland = "kernel = \"wendland_c2\"\nh_over_dx = 2.0";
  const std::string fluid = "initial_pressure = \"hydrostatic\"\n";
  const ProgramResult onLattice = runSph(
      "check '" +
      editedScene({{"kernel = \"quadratic\"", wendland}, {fluid, fluid + "initial = \"packed\"\n"}},
                  "hydrostatic_box_3d.toml") +
      "'");
  ASSERT_EQ(onLattice.exitCode, 0) << onLattice.output;
  EXPECT_NE(onLattice.output.find("lattice: the cubic lattice the fluid starts on gives way"),
            std::string::npos)
      << onLattice.output;
  EXPECT_NE(onLattice.output.find("a packed start moved off the lattice holds"), std::string::npos)
      << onLattice.output;
  const ProgramResult offLattice =
      runSph("check '" +
             editedScene({{"kernel = \"quadratic\"", wendland},
                          {fluid, fluid + "initial = \"packed\"\n[fluid.packing]\nnoise = 0.1\n"}},
                         "hydrostatic_box_3d.toml") +
             "'");
  ASSERT_EQ(offLattice.exitCode, 0) << offLattice.output;
  EXPECT_EQ(offLattice.output.find("lattice:"), std::string::npos) << offLattice.output;
}

TEST(CheckLatticeNote, AFluidWithoutPressureHasNoLine) {
  const ProgramResult r =
      runSph("check '" + editedScene("initial_pressure = \"hydrostatic\"\n", "") + "'");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("lattice:"), std::string::npos) << r.output;
}

}  // namespace
