// Issue 32: scene input that passed `sph check` and failed late, wrote outside --out, or ran with a
// value the user did not mean. Each case edits scenes/small_tank.toml and asserts that `sph check`
// (or `sph run`) refuses it with exit 2 and a message naming the file, the key and the problem.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "ProgramHelpers.hpp"

namespace {

using namespace sph::core_tests;
namespace fs = std::filesystem;

// Part 1. A name becomes a file name (the scene's) or an HDF5 name (a phase's, a probe's): a '/'
// in one passed the check, then the run failed with exit 4 on an HDF5 attribute after writing a
// partial run file.
TEST(SceneNames, SlashInPhaseName) {
  expectRejected("name = \"water\"", "name = \"wa/ter\"", "phase[0].name", "not a valid name");
}

TEST(SceneNames, SlashInProbeName) {
  expectRejected("name = \"front\"", "name = \"fr/ont\"", "probe[0].name", "not a valid name");
}

TEST(SceneNames, SpaceInProbeName) {
  expectRejected("name = \"front\"", "name = \"fr ont\"", "probe[0].name", "not a valid name");
}

TEST(SceneNames, SceneNameLeavingTheOutputDirectory) {
  expectRejected("name = \"small_tank\"", "name = \"../x\"", "name", "must not start with '.'");
}

TEST(SceneNames, AbsoluteSceneName) {
  expectRejected("name = \"small_tank\"", "name = \"/tmp/x\"", "name", "not a valid name");
}

TEST(SceneNames, EmptySceneName) {
  // "" wrote the hidden file <out>/.h5.
  expectRejected("name = \"small_tank\"", "name = \"\"", "name", "must not be empty");
}

// `sph run` with such a name writes nothing, neither in --out nor next to it.
TEST(SceneNames, RunWithABadNameWritesNothing) {
  const std::string path = editedScene("name = \"small_tank\"", "name = \"../escaped\"");
  const fs::path dir = fs::path(path).parent_path();
  const ProgramResult r =
      runSph("run '" + path + "' --out '" + (dir / "out").string() + "' --threads 1 --quiet");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_FALSE(fs::exists(dir / "escaped.h5"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// Part 2. A pressure probe outside the domain has no particle near it and recorded 0 Pa.
TEST(SceneProbes, PressureProbeOutsideTheDomain) {
  const std::string out = expectRejected("position = [0.05, 0.005]", "position = [0.05, 0.5]",
                                         "probe[1].position", "lies outside the domain");
  EXPECT_NE(out.find("probe 'p_bottom' at (0.05, 0.5)"), std::string::npos) << out;
  EXPECT_NE(out.find("[0, 0.2] x [0, 0.2]"), std::string::npos) << out;
}

TEST(SceneProbes, GaugeOutsideTheDomain) {
  expectRejected("type = \"surge_front\"", "type = \"water_level\"\nx = -0.1", "probe[0].x",
                 "probe 'front' at x = -0.1 lies outside the domain");
}

TEST(SceneProbes, ProbeOnTheWallIsAccepted) {
  const std::string path = editedScene("position = [0.05, 0.005]", "position = [0.0, 0.0]");
  const ProgramResult r = runSph("check '" + path + "'");
  EXPECT_EQ(r.exitCode, 0) << r.output;
}

// Issue 36: a wall_pressure probe reads the fluid at a solid face, so it must sit on one; a
// water_height line gives its D - 1 horizontal coordinates.
TEST(SceneProbes, WallPressureOnTheFloorIsAccepted) {
  const std::string path = editedScene("type = \"pressure\"\nposition = [0.05, 0.005]",
                                       "type = \"wall_pressure\"\nposition = [0.05, 0.0]");
  const ProgramResult r = runSph("check '" + path + "'");
  EXPECT_EQ(r.exitCode, 0) << r.output;
}

TEST(SceneProbes, WallPressureOffEveryFace) {
  expectRejected("type = \"pressure\"\nposition = [0.05, 0.005]",
                 "type = \"wall_pressure\"\nposition = [0.05, 0.005]", "probe[1].position",
                 "must lie on a wall face of the domain");
}

TEST(SceneProbes, WallPressureOnTheOpenTop) {
  expectRejected("type = \"pressure\"\nposition = [0.05, 0.005]",
                 "type = \"wall_pressure\"\nposition = [0.05, 0.2]", "probe[1].position",
                 "must lie on a wall face of the domain");
}

TEST(SceneProbes, WaterHeightTakesTheHorizontalCoordinates) {
  expectRejected("type = \"pressure\"\nposition = [0.05, 0.005]",
                 "type = \"water_height\"\nposition = [0.05, 0.005]", "probe[1].position",
                 "expected 1 numbers");
  expectRejected("type = \"pressure\"\nposition = [0.05, 0.005]",
                 "type = \"water_height\"\nposition = [0.3]", "probe[1].position",
                 "lies outside the domain");
}

// Part 5. A block thinner than dx/2 holds no particle (InitialParticlesTest.cpp: and none outside
// it): it is refused rather than left out of the run unsaid.
TEST(SceneBlocks, BlockThinnerThanHalfDx) {
  expectRejected("upper = [0.1, 0.1]", "upper = [0.1, 0.004]", "fluid[0].upper",
                 "0.004 m across along y, less than dx/2 = 0.005 m (numerics.dx): it would hold no "
                 "particle");
}

TEST(SceneBlocks, CircleWithoutANode) {
  expectRejected("shape = \"rectangle\"\nlower = [0.0, 0.0]\nupper = [0.1, 0.1]",
                 "shape = \"circle\"\ncenter = [0.1, 0.1]\nradius = 0.002", "fluid[0].radius",
                 "holds no lattice node");
}

// Part 3. SCENES.md says true or false; toml++ would read an integer 1 as true.
TEST(SceneTypes, IntegerForABoolean) {
  expectRejected("morris_viscosity = true", "morris_viscosity = 1", "physics.morris_viscosity",
                 "must be true or false, got an integer");
}

TEST(SceneTypes, StringForABoolean) {
  expectRejected("variable_h = true", "variable_h = \"yes\"", "physics.variable_h",
                 "must be true or false, got a string");
}

// Part 4. A misspelt required key is named itself, where it is (line:column), with the key it was
// probably meant to be, never only as the right key missing.
TEST(SceneKeys, MisspeltRequiredKey) {
  const std::string path = editedScene("end_time = 0.02", "end_tme = 0.02");
  const std::string text = readText(path);
  const auto line = 1 + std::count(text.begin(), text.begin() + text.find("end_tme"), '\n');
  const ProgramResult r = runSph("check '" + path + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find(path + ":" + std::to_string(line) + ":1: key 'numerics.end_tme': " +
                          "unknown key (did you mean 'numerics.end_time'?)"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("missing"), std::string::npos) << r.output;
}

TEST(SceneKeys, MisspeltTable) {
  const std::string out = expectRejected("[numerics]", "[numerix]", "numerix",
                                         "unknown key (did you mean 'numerics'?)");
  EXPECT_EQ(out.find("missing"), std::string::npos) << out;
}

TEST(SceneKeys, MisspeltOptionalKey) {
  expectRejected("h_over_dx = 1.33", "h_ovr_dx = 1.33", "numerics.h_ovr_dx",
                 "unknown key (did you mean 'numerics.h_over_dx'?)");
}

// A key far from every known one gets no guess.
TEST(SceneKeys, UnknownKeyWithoutAGuess) {
  const std::string out =
      expectRejected("[physics]\n", "[physics]\nzzz = 1.0\n", "physics.zzz", "unknown key");
  EXPECT_EQ(out.find("did you mean"), std::string::npos) << out;
}

// An axis the scene does not have is no key of its domain.
TEST(SceneKeys, FaceOfAMissingAxis) {
  expectRejected("y_upper = \"open\"", "y_upper = \"open\"\nz_upper = \"open\"", "domain.z_upper",
                 "unknown key");
}

}  // namespace
