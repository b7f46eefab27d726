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
               "[[phase]]\nname = \"oil\"\nrho0 = 900.0\nc0 = 20.0\nmu = 1.0e-3\n\n[[fluid]]\nphase = \"water\"");
  const std::string path = dir + "/two_phases.toml";
  writeText(path, text);
  const ProgramResult r = runSph("check '" + path + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("'physics.density_diffusion'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("2 phases"), std::string::npos) << r.output;
}

}  // namespace
