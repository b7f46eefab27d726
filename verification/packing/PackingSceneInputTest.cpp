// A packing scene is read by the run scenes' reader (solver/src/SceneReader.hpp): a misspelt key
// is named as unknown, malformed TOML gets its line:column, h_over_dx has the run scenes' bounds,
// a dx too small for the lattice is refused before the lattice is built, the phase's name is a
// plain name, and a key both kinds of scene hold is refused in the same words in both.
// stop_kinetic_energy is T / (N beta) in both (solver/SCENES.md).
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sph/Scene.hpp"
#include "sph/packing/PackingScene.hpp"

namespace sph::packing {
namespace {

const std::string packingBase = R"(name = "square"
[geometry]
start = [0.0, 0.0]
surface = 0.5
[[geometry.path]]
to = [1.0, 0.0]
[[geometry.path]]
to = [1.0, 1.0]
[[geometry.path]]
to = [0.0, 1.0]
[[geometry.path]]
to = [0.0, 0.0]
[fluid]
c0 = 20.0
[packing]
dx = 0.1
)";

const std::string runBase = R"(name = "square"
dimension = 2
[domain]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
[[phase]]
name = "water"
rho0 = 1000.0
c0 = 20.0
[[fluid]]
lower = [0.0, 0.0]
upper = [0.5, 0.5]
initial = "packed"
[numerics]
dx = 0.05
end_time = 0.1
)";

// The base with `from` replaced by `to`.
std::string with(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

std::string packingError(const std::string& text) {
  try {
    parsePackingScene(text, "packing.toml");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "accepted";
}

std::string runError(const std::string& text) {
  try {
    parseScene(text, "run.toml");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "accepted";
}

// What follows "key '<key>': " in a message: the same words whichever scene holds the key.
std::string problem(const std::string& message, const std::string& key) {
  const std::string head = "key '" + key + "': ";
  const std::size_t at = message.find(head);
  return at == std::string::npos ? "no key '" + key + "' in: " + message
                                 : message.substr(at + head.size());
}

TEST(PackingSceneInput, MisspeltKeyIsUnknownNotTheKeyMissing) {
  // Was "key 'packing.dx': missing value": the misspelt key itself is named now.
  EXPECT_EQ(packingError(with(packingBase, "dx = 0.1", "dxx = 0.1")),
            "packing.toml:16:1: key 'packing.dxx': unknown key");
  EXPECT_EQ(packingError(with(packingBase, "c0 = 20.0", "c00 = 20.0")),
            "packing.toml:14:1: key 'fluid.c00': unknown key");
  EXPECT_EQ(packingError(with(packingBase, "dx = 0.1", "dx = 0.1\nstop_kinetic_enrgy = 1e-6")),
            "packing.toml:17:1: key 'packing.stop_kinetic_enrgy': unknown key (did you mean "
            "'packing.stop_kinetic_energy'?)");
  EXPECT_EQ(packingError(packingBase + "[outptu]\n"),
            "packing.toml:17:2: key 'outptu': unknown key (did you mean 'output'?)");
}

TEST(PackingSceneInput, MalformedTomlNamesLineAndColumn) {
  const std::string m = packingError(with(packingBase, "c0 = 20.0", "c0 = "));
  EXPECT_EQ(m.rfind("packing.toml:14:6: malformed TOML: ", 0), 0u) << m;
}

TEST(PackingSceneInput, HOverDxHasTheRunScenesBounds) {
  for (const char* v : {"0.5", "5.0"}) {
    const std::string p =
        packingError(with(packingBase, "dx = 0.1", "dx = 0.1\nh_over_dx = " + std::string(v)));
    const std::string r =
        runError(with(runBase, "dx = 0.05", "dx = 0.05\nh_over_dx = " + std::string(v)));
    EXPECT_EQ(problem(p, "packing.h_over_dx").rfind("must lie in [1, 4], got ", 0), 0u) << p;
    EXPECT_EQ(problem(p, "packing.h_over_dx"), problem(r, "numerics.h_over_dx"));
  }
  // The bounds themselves are allowed (Table 1's h/dx 2.0 and 3.2 lie inside).
  EXPECT_EQ(packingError(with(packingBase, "dx = 0.1", "dx = 0.1\nh_over_dx = 1.0")), "accepted");
}

TEST(PackingSceneInput, TinyDxRefusedBeforeTheLatticeIsBuilt) {
  // 1e-9 in a 1 m box: 1e18 lattice nodes, which latticeInside walked for ever.
  const auto start = std::chrono::steady_clock::now();
  const std::string m = packingError(with(packingBase, "dx = 0.1", "dx = 1e-9"));
  EXPECT_NE(m.find("packing.toml:16:6: key 'packing.dx': the container's bounding box holds "),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("more than the solver can index"), std::string::npos) << m;
  // A lattice origin far away would overflow the lattice's int indices the same way.
  const std::string far =
      packingError(with(packingBase, "dx = 0.1", "dx = 0.1\nlattice_origin = [1e12, 0.0]"));
  EXPECT_NE(far.find("key 'packing.dx': "), std::string::npos) << far;
  // Refused from the numbers alone: well under a second (the walk took hours).
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  // dx = 1e-3 (1e6 nodes, 1.5e5 below the surface) is a packing scene like any other.
  EXPECT_EQ(packingError(with(packingBase, "dx = 0.1", "dx = 1e-3")), "accepted");
}

TEST(PackingSceneInput, PhaseNameIsAPlainName) {
  const std::string m =
      packingError(with(packingBase, "c0 = 20.0", "c0 = 20.0\nname = \"wa/ter\""));
  EXPECT_NE(m.find("key 'fluid.name': 'wa/ter' is not a valid name"), std::string::npos) << m;
  EXPECT_EQ(
      problem(m, "fluid.name"),
      problem(runError(with(runBase, "name = \"water\"", "name = \"wa/ter\"")), "phase[0].name"));
}

// The keys both kinds of scene hold: the same check, the same words.
TEST(PackingSceneInput, SharedKeysAreRefusedInTheSameWords) {
  struct Case {
    std::string packingKey, runKey, packingEdit, runEdit;
  };
  const std::string pk = "dx = 0.1", rn = "dx = 0.05", fl = "c0 = 20.0";
  const std::string runPacking = "initial = \"packed\"\n";
  const std::vector<Case> cases = {
      {"packing.kernel", "numerics.kernel", "kernel = \"gauss\"", "kernel = \"gauss\""},
      {"packing.alpha", "fluid[0].packing.alpha", "alpha = -1e-3", "alpha = -1e-3"},
      {"packing.max_iterations", "fluid[0].packing.max_iterations", "max_iterations = 1.5",
       "max_iterations = 1.5"},
      {"packing.max_iterations", "fluid[0].packing.max_iterations", "max_iterations = -1",
       "max_iterations = -1"},
      {"packing.stop_kinetic_energy", "fluid[0].packing.stop_kinetic_energy",
       "stop_kinetic_energy = 0.0", "stop_kinetic_energy = 0.0"},
      {"packing.dx", "numerics.dx", "dx = -0.1", "dx = -0.1"},
      {"fluid.rho0", "phase[0].rho0", "rho0 = -1.0", "rho0 = -1.0"},
      {"fluid.gamma", "phase[0].gamma", "gamma = 0.0", "gamma = 0.0"},
      {"fluid.p0", "phase[0].p0", "p0 = \"a\"", "p0 = \"a\""},
  };
  for (const Case& c : cases) {
    const bool fluidKey = c.packingKey.rfind("fluid.", 0) == 0;
    const bool controls = c.runKey.rfind("fluid[0].packing.", 0) == 0;
    std::string p, r;
    if (c.packingKey == "packing.dx") {
      p = with(packingBase, pk, c.packingEdit), r = with(runBase, rn, c.runEdit);
    } else if (fluidKey) {
      p = with(packingBase, fl, fl + "\n" + c.packingEdit);
      // The run base gives rho0 already: that line is replaced, any other key added.
      const std::string line = c.runEdit.substr(0, c.runEdit.find(" = "));
      r = line == "rho0" ? with(runBase, "rho0 = 1000.0", c.runEdit)
                         : with(runBase, "c0 = 20.0", "c0 = 20.0\n" + c.runEdit);
    } else if (controls) {
      p = with(packingBase, pk, pk + "\n" + c.packingEdit);
      r = with(runBase, runPacking, runPacking + "[fluid.packing]\n" + c.runEdit + "\n");
    } else {
      p = with(packingBase, pk, pk + "\n" + c.packingEdit);
      r = with(runBase, rn, rn + "\n" + c.runEdit);
    }
    const std::string pm = packingError(p), rm = runError(r);
    EXPECT_EQ(problem(pm, c.packingKey), problem(rm, c.runKey)) << pm << "\n" << rm;
    EXPECT_EQ(pm.rfind("packing.toml:", 0), 0u) << pm;
  }
  // A missing c0, the one phase key without a default in either kind.
  EXPECT_EQ(problem(packingError(with(packingBase, "c0 = 20.0\n", "")), "fluid.c0"),
            problem(runError(with(runBase, "c0 = 20.0\n", "")), "phase[0].c0"));
}

// The packing stops at the first iteration whose T / (N beta) falls below stop_kinetic_energy,
// as the packed start of a run scene does (InitialParticles.cpp), not on the sum T / beta.
TEST(PackingSceneInput, StopKineticEnergyIsPerParticle) {
  PackingScene s =
      readPackingScene(std::string(SPH_SOURCE_DIR) + "/validation/packing/trapezoidal_tank.toml");
  s.dx = 0.08, s.parameters.alpha = 5e-3;  // H/dx 12.5, the paper's fastest damping: quick
  s.parameters.stopKineticEnergy = 1e-6;
  const PackingSetup setup = setUp(s);
  ParticlePacking packing(setup.fluid, setup.solid.position, setup.V0, s.dx, s.parameters);
  std::vector<PackingRecord> history;
  const bool stopped = packing.run([&](const PackingRecord& r) { history.push_back(r); });
  ASSERT_TRUE(stopped);
  ASSERT_GE(history.size(), 3u);
  const PackingRecord& last = history.back();
  EXPECT_LT(last.kineticMean, 1e-6);
  for (std::size_t k = 1; k + 1 < history.size(); ++k) EXPECT_GE(history[k].kineticMean, 1e-6) << k;
  // The sum is N times the mean: still above the threshold where the mean stops (measured: 1,654
  // iterations, N = 150, T / beta = 1.5e-4 there).
  EXPECT_GE(last.kinetic, 1e-6);
  EXPECT_NEAR(last.kinetic / last.kineticMean, static_cast<double>(setup.fluid.size()),
              1e-9 * setup.fluid.size());
}

// solver/SCENES.md documents every key of a packing scene in one example: it must be one.
TEST(PackingSceneInput, ScenesMdExampleIsAPackingScene) {
  std::ifstream in(std::string(SPH_SOURCE_DIR) + "/solver/SCENES.md");
  std::stringstream b;
  b << in.rdbuf();
  const std::string doc = b.str();
  const std::size_t section = doc.find("**Packing scenes (`sph pack`).**");
  ASSERT_NE(section, std::string::npos);
  const std::size_t from = doc.find("```toml\n", section) + 8, to = doc.find("```", from);
  ASSERT_LT(from, to);
  const PackingScene s = parsePackingScene(doc.substr(from, to - from), "SCENES.md");
  EXPECT_EQ(s.name, "quarter_bowl");
  EXPECT_EQ(s.container.size(), 5u);
  EXPECT_TRUE(s.container[2].arc);
  // pressure = rho0 c0^2 / 2, its default, written out: beta = c0^2.
  EXPECT_NEAR(s.parameters.beta, 31.3 * 31.3, 1e-9);
}

}  // namespace
}  // namespace sph::packing
