// The scene's choice of optional terms reaches the pair loop: a term the scene switches on is
// named in the run file and changes the run; one the scene cannot use is refused with its key.
#include <gtest/gtest.h>

#include <string>

#include "ProgramHelpers.hpp"

namespace {

using namespace sph::core_tests;

// scenes/small_tank.toml with `extra` added to its [physics] table, in the test's directory.
std::string withPhysics(const std::string& extra, const std::string& dir) {
  std::string text = readText(scenePath("small_tank.toml"));
  text.replace(text.find("[physics]\n"), 10, "[physics]\n" + extra + "\n");
  const std::string path = dir + "/scene.toml";
  writeText(path, text);
  return path;
}

TEST(SceneTerms, DensityDiffusionRunsWhenTheSceneAsksForIt) {
  const std::string dir = freshOutputDirectory();
  const std::string on = withPhysics("density_diffusion = 0.1", dir);
  ASSERT_EQ(runSph("run '" + on + "' --quiet --out '" + dir + "/on'").exitCode, 0);
  ASSERT_EQ(
      runSph("run '" + scenePath("small_tank.toml") + "' --quiet --out '" + dir + "/off'").exitCode,
      0);
  const std::string a = dir + "/on/small_tank.h5", b = dir + "/off/small_tank.h5";
  const auto terms = stringAttribute(a, "/", "terms");
  ASSERT_TRUE(terms.has_value());
  EXPECT_NE(terms->find("density_diffusion_molteni_colagrossi"), std::string::npos) << *terms;
  EXPECT_EQ(stringAttribute(b, "/", "terms")->find("density_diffusion"), std::string::npos);
  EXPECT_EQ(stringAttribute(a, "/", "status"), "stable");
  EXPECT_NE(readDoubles(a, "/series/rho_max"), readDoubles(b, "/series/rho_max"))
      << "the term changed nothing";
}

TEST(SceneTerms, DensityDiffusionIsRefusedWithTwoPhases) {
  const std::string dir = freshOutputDirectory();
  std::string text = readText(withPhysics("density_diffusion = 0.1", dir));
  text.replace(text.find("[[fluid]]"), 9,
               "[[phase]]\nname = \"oil\"\nrho0 = 900.0\nc0 = 20.0\nmu = "
               "1.0e-3\n\n[[fluid]]\nphase = \"water\"");
  const std::string path = dir + "/two_phases.toml";
  writeText(path, text);
  const ProgramResult r = runSph("check '" + path + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("'physics.density_diffusion'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("2 phases"), std::string::npos) << r.output;
}

// With several phases Fourtakas et al.'s form diffuses within each
// (terms/DensityDiffusionFourtakasPhases.hpp), named so in the run file; the phases must share
// c0 and gamma, else the scene is refused naming the phase.
std::string twoPhases(const std::string& dir, double oilC0) {
  std::string text =
      readText(withPhysics("density_diffusion = 0.1\ndensity_diffusion_form = \"fourtakas\"", dir));
  text.replace(text.find("[[fluid]]"), 9,
               "[[phase]]\nname = \"oil\"\nrho0 = 900.0\nc0 = " + std::to_string(oilC0) +
                   "\nmu = 1.0e-3\n\n[[fluid]]\nphase = \"water\"");
  const std::string path = dir + "/two_phases.toml";
  writeText(path, text);
  return path;
}

TEST(SceneTerms, FourtakasFormDiffusesWithinEachOfTwoPhases) {
  const std::string dir = freshOutputDirectory();
  ASSERT_EQ(runSph("run '" + twoPhases(dir, 20.0) + "' --quiet --out '" + dir + "'").exitCode, 0);
  const auto terms = stringAttribute(dir + "/small_tank.h5", "/", "terms");
  ASSERT_TRUE(terms.has_value());
  EXPECT_NE(terms->find("density_diffusion_fourtakas_phases"), std::string::npos) << *terms;
  EXPECT_EQ(stringAttribute(dir + "/small_tank.h5", "/", "status"), "stable");
}

TEST(SceneTerms, FourtakasFormIsRefusedForPhasesOfOtherSoundSpeeds) {
  const std::string dir = freshOutputDirectory();
  const ProgramResult r = runSph("check '" + twoPhases(dir, 25.0) + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("'physics.density_diffusion'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("phase 'oil' has c0 25"), std::string::npos) << r.output;
}

// The form key picks Fourtakas et al.'s (2019) term: named in the run file, and a tank at rest
// starting hydrostatic changes (the forms differ where the kernel is cut).
TEST(SceneTerms, FourtakasFormRunsWhenTheSceneAsksForIt) {
  const std::string dir = freshOutputDirectory();
  writeText(dir + "/mc.toml", readText(withPhysics("density_diffusion = 0.1", dir)));
  const std::string fourtakas =
      withPhysics("density_diffusion = 0.1\ndensity_diffusion_form = \"fourtakas\"", dir);
  ASSERT_EQ(runSph("run '" + fourtakas + "' --quiet --out '" + dir + "/f'").exitCode, 0);
  ASSERT_EQ(runSph("run '" + dir + "/mc.toml' --quiet --out '" + dir + "/mc'").exitCode, 0);
  const std::string a = dir + "/f/small_tank.h5", b = dir + "/mc/small_tank.h5";
  const auto terms = stringAttribute(a, "/", "terms");
  ASSERT_TRUE(terms.has_value());
  EXPECT_NE(terms->find("density_diffusion_fourtakas"), std::string::npos) << *terms;
  EXPECT_EQ(terms->find("density_diffusion_molteni_colagrossi"), std::string::npos) << *terms;
  EXPECT_EQ(stringAttribute(a, "/", "status"), "stable");
  EXPECT_NE(readDoubles(a, "/series/rho_max"), readDoubles(b, "/series/rho_max"))
      << "the form changed nothing";
}

TEST(SceneTerms, UnknownDensityDiffusionFormIsRefusedWithItsKey) {
  const std::string dir = freshOutputDirectory();
  const ProgramResult r = runSph(
      "check '" +
      withPhysics("density_diffusion = 0.1\ndensity_diffusion_form = \"delta_les\"", dir) + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("'physics.density_diffusion_form'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("delta_les"), std::string::npos) << r.output;
}

// Antuono et al.'s (2010) form: named in the run file, and the tank runs stable.
TEST(SceneTerms, AntuonoFormRunsWhenTheSceneAsksForIt) {
  const std::string dir = freshOutputDirectory();
  const std::string antuono =
      withPhysics("density_diffusion = 0.1\ndensity_diffusion_form = \"antuono\"", dir);
  ASSERT_EQ(runSph("run '" + antuono + "' --quiet --out '" + dir + "/a'").exitCode, 0);
  const std::string a = dir + "/a/small_tank.h5";
  const auto terms = stringAttribute(a, "/", "terms");
  ASSERT_TRUE(terms.has_value());
  EXPECT_NE(terms->find("density_diffusion_antuono"), std::string::npos) << *terms;
  EXPECT_EQ(stringAttribute(a, "/", "status"), "stable");
}

// With two phases the form would diffuse the density jump at their interface.
TEST(SceneTerms, AntuonoFormIsRefusedWithTwoPhases) {
  const std::string dir = freshOutputDirectory();
  std::string text = readText(twoPhases(dir, 20.0));
  const std::string form = "density_diffusion_form = \"fourtakas\"";
  ASSERT_NE(text.find(form), std::string::npos);
  text.replace(text.find(form), form.size(), "density_diffusion_form = \"antuono\"");
  writeText(dir + "/antuono.toml", text);
  const ProgramResult r = runSph("check '" + dir + "/antuono.toml'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("'physics.density_diffusion'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\"antuono\" diffuses the density jump"), std::string::npos) << r.output;
}

TEST(SceneTerms, FourtakasFormNeedsAWholeGamma) {
  const std::string dir = freshOutputDirectory();
  std::string text =
      readText(withPhysics("density_diffusion = 0.1\ndensity_diffusion_form = \"fourtakas\"", dir));
  text.replace(text.find("mu = 1.0e-3"), 11, "mu = 1.0e-3\ngamma = 7.5");
  const std::string path = dir + "/gamma.toml";
  writeText(path, text);
  const ProgramResult r = runSph("check '" + path + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("'physics.density_diffusion_form'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("7.5"), std::string::npos) << r.output;
}

// continuity_form = "colagrossi_landrini" (terms/ContinuityEquation.hpp) changes a two-phase run;
// an unknown form is refused with its key.
TEST(SceneTerms, ContinuityByVolumeRunsWhenTheSceneAsksForIt) {
  const std::string dir = freshOutputDirectory();
  const std::string byMass = twoPhases(dir, 20.0);
  std::string text = readText(byMass);
  text.replace(text.find("[physics]\n"), 10,
               "[physics]\ncontinuity_form = \"colagrossi_landrini\"\n");
  writeText(dir + "/by_volume.toml", text);
  ASSERT_EQ(runSph("run '" + byMass + "' --quiet --out '" + dir + "/m'").exitCode, 0);
  ASSERT_EQ(runSph("run '" + dir + "/by_volume.toml' --quiet --out '" + dir + "/v'").exitCode, 0);
  const std::string a = dir + "/v/small_tank.h5", b = dir + "/m/small_tank.h5";
  EXPECT_EQ(stringAttribute(a, "/", "status"), "stable");
  EXPECT_NE(readDoubles(a, "/series/rho_max"), readDoubles(b, "/series/rho_max"))
      << "the form changed nothing";
  const ProgramResult r =
      runSph("check '" + withPhysics("continuity_form = \"summation\"", dir) + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("'physics.continuity_form'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("summation"), std::string::npos) << r.output;
}

}  // namespace
