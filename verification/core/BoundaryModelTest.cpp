// Issues 30/31: the scene's wall model ([walls], [[obstacle]]; solver/SCENES.md) is read, refused
// with a message naming the key when wrong, and named in the run file (reports/SCHEMA.md).
#include <gtest/gtest.h>

#include "ProgramHelpers.hpp"

namespace sph::core_tests {
namespace {

// The small tank with wall particles: its ghost_pressure key (a mirror-ghost setting) removed.
const std::pair<std::string, std::string> noGhostPressure{"ghost_pressure = \"hydrostatic\"\n", ""};
const std::pair<std::string, std::string> wallParticles{"[[phase]]\n",
                                                        "[walls]\nmodel = \"wall_particles\"\n"
                                                        "[[phase]]\n"};

TEST(BoundaryModel, RunFileNamesTheModel) {
  const std::string out = freshOutputDirectory();
  const std::string particles = editedScene({noGhostPressure, wallParticles});
  const ProgramResult a =
      runSph("run '" + particles + "' --out '" + out + "/particles' --threads 1 --quiet");
  ASSERT_EQ(a.exitCode, 0) << a.output;
  const std::string h5 = out + "/particles/small_tank.h5";
  EXPECT_EQ(stringAttribute(h5, "/", "boundary_model"), "wall_particles");
  const auto terms = stringAttribute(h5, "/", "terms");
  ASSERT_TRUE(terms);
  EXPECT_NE(terms->find("wall_particles_adami2012"), std::string::npos) << *terms;
  EXPECT_EQ(terms->find("ghost_walls"), std::string::npos) << *terms;

  const ProgramResult b = runSph("run '" + scenePath("small_tank.toml") + "' --out '" + out +
                                 "/ghosts' --threads 1 --quiet");
  ASSERT_EQ(b.exitCode, 0) << b.output;
  EXPECT_EQ(stringAttribute(out + "/ghosts/small_tank.h5", "/", "boundary_model"), "mirror_ghosts");
  const auto ghostTerms = stringAttribute(out + "/ghosts/small_tank.h5", "/", "terms");
  ASSERT_TRUE(ghostTerms);
  EXPECT_EQ(ghostTerms->find("ghost_walls_not_tensile"), std::string::npos) << *ghostTerms;

  // [walls] tensile = false is named among the terms.
  const ProgramResult c =
      runSph("run '" + editedScene("[[phase]]\n", "[walls]\ntensile = false\n[[phase]]\n") +
             "' --out '" + out + "/held' --threads 1 --quiet");
  ASSERT_EQ(c.exitCode, 0) << c.output;
  const auto heldTerms = stringAttribute(out + "/held/small_tank.h5", "/", "terms");
  ASSERT_TRUE(heldTerms);
  EXPECT_NE(heldTerms->find("ghost_walls,ghost_walls_not_tensile"), std::string::npos)
      << *heldTerms;
}

TEST(BoundaryModel, AcceptsWallParticlesAndAnObstacle) {
  const std::string scene =
      editedScene({noGhostPressure,
                   {"[[phase]]\n",
                    "[walls]\nmodel = \"wall_particles\"\nlayers = 4\n[[obstacle]]\n"
                    "lower = [0.15, 0.0]\nupper = [0.2, 0.05]\nwall = \"no_slip\"\n[[phase]]\n"}});
  const ProgramResult r = runSph("check '" + scene + "'");
  EXPECT_EQ(r.exitCode, 0) << r.output;
}

TEST(BoundaryModel, RefusesAnUnknownModel) {
  expectRejected("[[phase]]\n", "[walls]\nmodel = \"dynamic\"\n[[phase]]\n", "walls.model",
                 "expected \"mirror_ghosts\" or \"wall_particles\"");
}

TEST(BoundaryModel, RefusesAnUnknownWallsKey) {
  expectRejected("[[phase]]\n", "[walls]\nlayer = 3\n[[phase]]\n", "walls.layer", "unknown key");
}

TEST(BoundaryModel, RefusesTooFewLayers) {
  // h/dx 1.33: a particle dx/2 from the wall reaches 2.16 dx beyond it, so 3 layers at least.
  expectRejected("[[phase]]\n", "[walls]\nmodel = \"wall_particles\"\nlayers = 2\n[[phase]]\n",
                 "walls.layers", "expected a whole number from 3");
}

TEST(BoundaryModel, RefusesGhostPressureWithWallParticles) {
  expectRejected("[[phase]]\n", "[walls]\nmodel = \"wall_particles\"\n[[phase]]\n",
                 "domain.ghost_pressure", "a mirror-ghost setting");
}

// [walls] tensile: wall particles never pull the fluid, so asking them to is refused; the
// mirror ghosts' floor is one p0, so phases of other p0 are refused with it.
TEST(BoundaryModel, RefusesTensileWallParticles) {
  expectRejected("[[phase]]\n", "[walls]\nmodel = \"wall_particles\"\ntensile = true\n[[phase]]\n",
                 "walls.tensile", "wall particles never pull the fluid");
}

TEST(BoundaryModel, RefusesATensionFreeWallUnderPhasesOfOtherP0) {
  const auto withOil = [](const std::string& p0) {
    return editedScene({{"[[phase]]\n",
                         "[walls]\ntensile = false\n[[phase]]\nname = \"oil\"\nrho0 = 900.0\n"
                         "c0 = 20.0\nmu = 1.0e-3\np0 = " +
                             p0 + "\n[[phase]]\n"},
                        {"initial_pressure = \"hydrostatic\"\n",
                         "initial_pressure = \"hydrostatic\"\nphase = \"water\"\n"}});
  };
  const ProgramResult r = runSph("check '" + withOil("100.0") + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("'walls.tensile'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("phase 'water' has p0"), std::string::npos) << r.output;
  const ProgramResult same = runSph("check '" + withOil("0.0") + "'");  // one p0: accepted
  EXPECT_EQ(same.exitCode, 0) << same.output;
}

TEST(BoundaryModel, RefusesAnObstacleOutsideTheDomain) {
  expectRejected("[[phase]]\n",
                 "[[obstacle]]\nlower = [0.15, 0.0]\nupper = [0.25, 0.05]\n[[phase]]\n",
                 "obstacle[0].upper", "outside the domain");
}

TEST(BoundaryModel, RefusesAnObstacleInTheFluid) {
  expectRejected("[[phase]]\n",
                 "[[obstacle]]\nlower = [0.05, 0.0]\nupper = [0.15, 0.05]\n[[phase]]\n",
                 "obstacle[0].lower", "overlaps fluid block 0");
}

TEST(BoundaryModel, RefusesAnUnknownObstacleWall) {
  expectRejected("[[phase]]\n",
                 "[[obstacle]]\nlower = [0.15, 0.0]\nupper = [0.2, 0.05]\nwall = \"sticky\"\n"
                 "[[phase]]\n",
                 "obstacle[0].wall", "expected \"free_slip\" or \"no_slip\"");
}

}  // namespace
}  // namespace sph::core_tests
