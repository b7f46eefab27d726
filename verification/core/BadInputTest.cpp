// Issue 2, part 6: bad input. Each case edits one line of scenes/small_tank.toml, runs
// `sph check` on the result and asserts exit code 2 (Run.hpp: exitBadInput) and a message that
// names the file, the key and the problem (STYLE.md section 6; the LAMMPS #4364 lesson: test the
// wording too).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "ProgramHelpers.hpp"

namespace {

using namespace sph::core_tests;

TEST(BadInput, BaseSceneIsAccepted) {
  const ProgramResult r = runSph("check '" + scenePath("small_tank.toml") + "'");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
}

TEST(BadInput, MalformedToml) {
  const std::string path = editedScene("dx = 0.01", "dx = = 0.01");
  // The line of `dx` in the base scene, which the parser's message must point at.
  const std::string text = readText(path);
  const auto line = 1 + std::count(text.begin(), text.begin() + text.find("dx = ="), '\n');
  const ProgramResult r = runSph("check '" + path + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find(path + ":" + std::to_string(line) + ":"), std::string::npos)
      << "file:line not named: " << r.output;
  EXPECT_NE(r.output.find("malformed TOML"), std::string::npos) << r.output;
}

TEST(BadInput, UnknownKey) {
  expectRejected("[physics]\n", "[physics]\nviscosity = 1.0\n", "physics.viscosity", "unknown key");
}

TEST(BadInput, UnknownTopLevelKey) {
  expectRejected("dimension = 2\n", "dimension = 2\ndimensions = 2\n", "dimensions", "unknown key");
}

TEST(BadInput, WrongType) {
  expectRejected("dx = 0.01", "dx = \"0.01\"", "numerics.dx", "wrong type");
}

TEST(BadInput, WrongTypeInArray) {
  expectRejected("gravity = [0.0, -9.81]", "gravity = [0.0, \"down\"]", "physics.gravity",
                 "wrong type");
}

TEST(BadInput, MissingValue) {
  expectRejected("end_time = 0.02\n", "", "numerics.end_time", "missing value");
}

TEST(BadInput, NonPositiveDx) {
  expectRejected("dx = 0.01", "dx = 0.0", "numerics.dx", "must be positive");
}

TEST(BadInput, NonPositiveHOverDx) {
  expectRejected("h_over_dx = 1.33", "h_over_dx = -1.33", "numerics.h_over_dx", "must be positive");
}

TEST(BadInput, NonPositiveC0) {
  expectRejected("c0 = 20.0", "c0 = 0.0", "phase[0].c0", "must be positive");
}

TEST(BadInput, NonPositiveEndTime) {
  expectRejected("end_time = 0.02", "end_time = -0.02", "numerics.end_time", "must be positive");
}

TEST(BadInput, FluidBlockOutsideWalls) {
  expectRejected("upper = [0.1, 0.1]", "upper = [0.25, 0.1]", "fluid[0].upper",
                 "outside the domain along x");
}

TEST(BadInput, FluidBlockBelowFloor) {
  expectRejected("lower = [0.0, 0.0]\nupper = [0.1, 0.1]",
                 "lower = [0.0, -0.05]\nupper = [0.1, 0.1]", "fluid[0].lower",
                 "outside the domain along y");
}

TEST(BadInput, OverlappingBlocks) {
  expectRejected("[physics]\n",
                 "[[fluid]]\nlower = [0.05, 0.05]\nupper = [0.15, 0.15]\n\n[physics]\n",
                 "fluid[1].lower", "overlaps fluid block 0");
}

TEST(BadInput, UnknownKernel) {
  expectRejected("kernel = \"quadratic\"", "kernel = \"gaussian\"", "numerics.kernel",
                 "unknown kernel 'gaussian'");
}

TEST(BadInput, UnknownIntegrator) {
  expectRejected("kernel = \"quadratic\"", "kernel = \"quadratic\"\nintegrator = \"leapfrog\"",
                 "numerics.integrator", "unknown integrator 'leapfrog'");
}

TEST(BadInput, UnknownShifting) {
  expectRejected("[physics]\n", "[physics]\nshifting = \"xsph\"\n", "physics.shifting",
                 "unknown shifting 'xsph'");
}

TEST(BadInput, ShiftingCoefficientWithoutShifting) {
  expectRejected("[physics]\n", "[physics]\nshifting_coefficient = 2.0\n",
                 "physics.shifting_coefficient", "shifting is \"none\"");
}

TEST(BadInput, NonPositiveShiftingCoefficient) {
  expectRejected("[physics]\n", "[physics]\nshifting = \"lind\"\nshifting_coefficient = -1.0\n",
                 "physics.shifting_coefficient", "must be positive");
}

TEST(BadInput, ShiftingEveryWithoutShifting) {
  expectRejected("[physics]\n", "[physics]\nshifting_every = 5\n", "physics.shifting_every",
                 "shifting is \"none\"");
}

TEST(BadInput, ShiftingEveryNotAPositiveWholeNumber) {
  expectRejected("[physics]\n", "[physics]\nshifting = \"lind\"\nshifting_every = 0\n",
                 "physics.shifting_every", "must be a positive whole number of steps");
  expectRejected("[physics]\n", "[physics]\nshifting = \"lind\"\nshifting_every = 2.5\n",
                 "physics.shifting_every", "must be a whole number");
}

TEST(BadInput, NonIntegerDimension) {
  expectRejected("dimension = 2\n", "dimension = 2.5\n", "dimension", "must be 1, 2 or 3");
}

TEST(BadInput, NaNValue) {
  expectRejected("c0 = 20.0", "c0 = nan", "phase[0].c0", "finite");
}

TEST(BadInput, InfValue) {
  expectRejected("end_time = 0.02", "end_time = inf", "numerics.end_time", "finite");
}

TEST(BadInput, NaNInArray) {
  expectRejected("gravity = [0.0, -9.81]", "gravity = [0.0, nan]", "physics.gravity", "finite");
}

// Lobovsky & Kren below eq. (8): c0 >= 10 max|v|. For this column sqrt(2 g H) = 1.4 m/s, so
// c0 = 5 m/s is accepted with a warning that names the file, the phase and c0.
TEST(BadInput, LowSoundSpeedWarns) {
  const std::string path = editedScene("c0 = 20.0", "c0 = 5.0");
  const ProgramResult r = runSph("check '" + path + "'");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find(path + ": warning"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("phase 'water'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("c0 = 5"), std::string::npos) << r.output;
}

TEST(BadInput, RejectedSceneWritesNoRunFile) {
  const std::string path = editedScene("dx = 0.01", "dx = 0.0");
  const std::string out = std::filesystem::path(path).parent_path() / "out";
  const ProgramResult r = runSph("run '" + path + "' --out '" + out + "' --threads 1");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("numerics.dx"), std::string::npos) << r.output;
  int files = 0;
  if (std::filesystem::exists(out))
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(out)) ++files;
  EXPECT_EQ(files, 0) << "a rejected scene left files in " << out;
}

TEST(BadInput, MissingSceneFile) {
  const std::string path = freshOutputDirectory() + "/no_such_scene.toml";
  const ProgramResult r = runSph("check '" + path + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find(path), std::string::npos) << r.output;
}

}  // namespace
