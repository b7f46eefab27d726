// The scene readers pinned to a golden text (golden/scene_reader.txt): every value read from
// every scene the project ships or tests with (validation/, verification/core/scenes/,
// fuzz/regressions/), printed %.17g so that a changed bit shows, and the exact refusal of a set
// of bad inputs for both kinds of scene (run and packing). A change of the reader that should
// not change what it reads must leave the text byte for byte; one that fixes a defect rewrites
// it on purpose: SPH_WRITE_GOLDEN=1 writes the text and fails the test, so a rewrite is never
// green by itself and the diff is reviewed in the commit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sph/Scene.hpp"
#include "sph/packing/PackingScene.hpp"

namespace {

namespace fs = std::filesystem;
using sph::packing::PackingScene;

const std::string source = SPH_SOURCE_DIR;
const std::string goldenPath = source + "/verification/core/golden/scene_reader.txt";

std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

std::string nums(const std::vector<double>& v) {
  std::string out = "[";
  for (std::size_t k = 0; k < v.size(); ++k) out += (k ? ", " : "") + num(v[k]);
  return out + "]";
}

class Summary {
 public:
  template <class T>
  void put(const std::string& key, const T& value) {
    out_ << "  " << key << " = " << value << "\n";
  }
  void put(const std::string& key, double v) { out_ << "  " << key << " = " << num(v) << "\n"; }
  void put(const std::string& key, const std::vector<double>& v) {
    out_ << "  " << key << " = " << nums(v) << "\n";
  }
  void put(const std::string& key, bool v) {
    out_ << "  " << key << " = " << (v ? "true" : "false") << "\n";
  }
  void put(const std::string& key, int v) { out_ << "  " << key << " = " << v << "\n"; }
  std::string str() const { return out_.str(); }

 private:
  std::ostringstream out_;
};

void phase(Summary& s, const std::string& p, const sph::Phase& ph) {
  s.put(p + ".name", ph.name), s.put(p + ".rho0", ph.rho0), s.put(p + ".c0", ph.c0);
  s.put(p + ".mu", ph.mu), s.put(p + ".p0", ph.p0), s.put(p + ".gamma", ph.gamma);
}

std::string describe(const sph::Scene& c) {
  Summary s;
  s.put("kind", std::string("run"));
  s.put("name", c.name), s.put("file", c.file),
      s.put("text_bytes", static_cast<int>(c.text.size()));
  s.put("dimension", c.dimension), s.put("lower", c.lower), s.put("upper", c.upper);
  const char* axis[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      const std::string f = std::string("face.") + axis[a] + (side ? "_upper" : "_lower");
      s.put(f, std::string(sph::name(c.faces[a][side])));
      s.put(f + ".wall_velocity", c.wallVelocity[a][side]);
    }
  s.put("hydrostatic_ghosts", c.hydrostaticGhosts);
  s.put("leaving", std::string(c.leaving == sph::Scene::Leaving::removed ? "remove" : "fail"));
  s.put("wall_model", std::string(sph::name(c.wallModel))), s.put("wall_layers", c.wallLayers);
  s.put("wall_tensile", c.tensileWalls);
  for (std::size_t k = 0; k < c.obstacles.size(); ++k) {
    const std::string p = "obstacle[" + std::to_string(k) + "]";
    s.put(p + ".lower", c.obstacles[k].lower), s.put(p + ".upper", c.obstacles[k].upper);
    s.put(p + ".wall", std::string(sph::name(c.obstacles[k].wall)));
  }
  for (std::size_t k = 0; k < c.phases.size(); ++k)
    phase(s, "phase[" + std::to_string(k) + "]", c.phases[k]);
  for (std::size_t k = 0; k < c.fluids.size(); ++k) {
    const sph::FluidBlock& b = c.fluids[k];
    const std::string p = "fluid[" + std::to_string(k) + "]";
    s.put(p + ".shape",
          std::string(b.shape == sph::FluidBlock::Shape::circle ? "circle" : "rectangle"));
    s.put(p + ".lower", b.lower), s.put(p + ".upper", b.upper), s.put(p + ".center", b.center);
    s.put(p + ".radius", b.radius), s.put(p + ".phase", b.phase),
        s.put(p + ".velocity", b.velocity);
    s.put(p + ".velocity_gradient", b.velocityGradient);
    s.put(p + ".gradient_center", b.gradientCenter);
    s.put(p + ".hydrostatic", b.hydrostatic), s.put(p + ".stretching", b.stretching);
    s.put(p + ".surface", b.surface), s.put(p + ".packed", b.packed);
    s.put(p + ".packing.alpha", b.packingAlpha);
    s.put(p + ".packing.max_iterations", b.packingMaxIterations);
    s.put(p + ".packing.stop_kinetic_energy", b.packingStop);
    s.put(p + ".packing.noise", b.packingNoise);
  }
  s.put("body_acceleration", c.bodyAcceleration);
  s.put("terms.artificial_viscosity", c.terms.artificialViscosity);
  s.put("terms.morris_viscosity", c.terms.morrisViscosity);
  s.put("terms.variable_h", c.terms.variableH);
  s.put("terms.density_diffusion", static_cast<int>(c.terms.densityDiffusion));
  s.put("beta", c.beta), s.put("diffusion_delta", c.diffusionDelta);
  s.put("continuity_by_volume", c.continuityByVolume);
  s.put("kernel", std::string(sph::name(c.kernel))), s.put("dx", c.dx);
  s.put("h_over_dx", c.hOverDx), s.put("cfl_acoustic", c.cflAcoustic);
  s.put("cfl_viscous", c.cflViscous), s.put("cfl_force", c.cflForce);
  s.put("integrator", std::string(sph::name(c.integrator))), s.put("end_time", c.endTime);
  s.put("density_band", std::vector<double>{c.densityBand[0], c.densityBand[1]});
  s.put("neighbour_skin", c.neighbourSkin), s.put("dt_floor", c.dtFloor);
  s.put("snapshot_interval", c.snapshotInterval), s.put("series_every", c.seriesEvery);
  s.put("checkpoint_interval", c.checkpointInterval);
  for (std::size_t k = 0; k < c.probes.size(); ++k) {
    const sph::Probe& q = c.probes[k];
    const std::string p = "probe[" + std::to_string(k) + "]";
    s.put(p + ".name", q.name), s.put(p + ".type", q.type), s.put(p + ".position", q.position);
    s.put(p + ".x", q.x), s.put(p + ".reference", q.reference);
    s.put(p + ".scale_length", q.scaleLength), s.put(p + ".scale_height", q.scaleHeight);
  }
  for (const std::string& w : c.warnings) s.put("warning", w);
  return s.str();
}

std::string describe(const PackingScene& c) {
  Summary s;
  s.put("kind", std::string("packing"));
  s.put("name", c.name), s.put("file", c.file),
      s.put("text_bytes", static_cast<int>(c.text.size()));
  s.put("description", c.description);
  for (std::size_t k = 0; k < c.container.size(); ++k) {
    const sph::packing::Piece& q = c.container[k];
    const std::string p = "container[" + std::to_string(k) + "]";
    s.put(p + ".kind", std::string(q.kind == sph::packing::Piece::Kind::wall ? "wall" : "surface"));
    s.put(p + ".a", std::vector<double>{q.a.x(), q.a.y()});
    s.put(p + ".b", std::vector<double>{q.b.x(), q.b.y()});
    s.put(p + ".arc", q.arc);
    s.put(p + ".center", std::vector<double>{q.center.x(), q.center.y()});
    s.put(p + ".radius", q.radius), s.put(p + ".theta0", q.theta0), s.put(p + ".sweep", q.sweep);
  }
  s.put("has_surface", c.hasSurface), s.put("surface", c.surface);
  s.put("length_scale", c.lengthScale), s.put("dx", c.dx);
  s.put("lattice_origin", std::vector<double>{c.latticeOrigin.x(), c.latticeOrigin.y()});
  phase(s, "phase", c.phase);
  s.put("gravity", c.gravity);
  const sph::packing::PackingParameters& q = c.parameters;
  s.put("kernel", std::string(sph::name(q.kernel))), s.put("h_over_dx", q.hOverDx);
  s.put("beta", q.beta), s.put("alpha", q.alpha), s.put("cfl", q.cfl);
  s.put("max_iterations", q.maxIterations), s.put("stop_kinetic_energy", q.stopKineticEnergy);
  s.put("history_every", c.historyEvery);
  const sph::packing::PackingSetup setup = sph::packing::setUp(c);
  s.put("setup.fluid_nodes", static_cast<int>(setup.fluid.size()));
  s.put("setup.solid_particles", static_cast<int>(setup.solid.position.size()));
  s.put("setup.V0", setup.V0);
  return s.str();
}

// A packing scene is the one with a [geometry] table (validation/packing/README.md).
bool isPackingScene(const std::string& text) {
  return text.rfind("[geometry]", 0) == 0 || text.find("\n[geometry]") != std::string::npos;
}

std::string read(const std::string& text, const std::string& file, bool packing) {
  try {
    return packing ? describe(sph::packing::parsePackingScene(text, file))
                   : describe(sph::parseScene(text, file));
  } catch (const sph::SceneError& e) {
    return std::string("  error: ") + e.what() + "\n";
  }
}

std::string fileText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream b;
  b << in.rdbuf();
  return b.str();
}

std::vector<std::string> shippedScenes() {
  std::vector<std::string> out;
  for (const char* dir :
       {"validation/scenes", "validation/packing", "verification/core/scenes", "fuzz/regressions"})
    for (const auto& e : fs::directory_iterator(source + "/" + dir))
      if (e.path().extension() == ".toml") out.push_back(fs::relative(e.path(), source).string());
  std::sort(out.begin(), out.end());
  return out;
}

// The bad inputs: a valid base scene of each kind with one edit (appended tables, or a line
// replaced), named by what they break.
const std::string runBase = R"(name = "base"
dimension = 2
[domain]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
x_lower = "free_slip"
x_upper = "free_slip"
y_lower = "free_slip"
[[phase]]
name = "water"
rho0 = 1000.0
c0 = 40.0
[[fluid]]
lower = [0.0, 0.0]
upper = [0.5, 0.5]
[physics]
gravity = [0.0, -9.81]
[numerics]
dx = 0.05
end_time = 0.1
)";

const std::string packingBase = R"(name = "base"
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

struct Edit {
  std::string label, from, to;  // `from` empty: append `to`
};

std::string edited(const std::string& base, const Edit& e) {
  if (e.from.empty()) return base + e.to;
  const std::size_t at = base.find(e.from);
  if (at == std::string::npos) ADD_FAILURE() << e.label << ": '" << e.from << "' not in the base";
  std::string out = base;
  return out.replace(at, e.from.size(), e.to);
}

const std::vector<Edit> runEdits = {
    {"malformed TOML", "dimension = 2", "dimension = "},
    {"misspelt key", "end_time = 0.1", "end_tme = 0.1"},
    {"missing dx", "dx = 0.05\n", ""},
    {"dx a string", "dx = 0.05", "dx = \"0.05\""},
    {"dx zero", "dx = 0.05", "dx = 0.0"},
    {"dx tiny", "dx = 0.05", "dx = 1e-300"},
    {"h_over_dx below 1", "", "h_over_dx = 0.5\n"},
    {"h_over_dx above 4", "", "h_over_dx = 5.0\n"},
    {"unknown kernel", "", "kernel = \"gauss\"\n"},
    {"phase name with a slash", "name = \"water\"", "name = \"wa/ter\""},
    {"phase name missing", "name = \"water\"\n", ""},
    {"rho0 missing", "rho0 = 1000.0\n", ""},
    {"rho0 negative", "rho0 = 1000.0", "rho0 = -1.0"},
    {"c0 missing", "c0 = 40.0\n", ""},
    {"gamma zero", "c0 = 40.0", "c0 = 40.0\ngamma = 0.0"},
    {"p0 a string", "c0 = 40.0", "c0 = 40.0\np0 = \"a\""},
    {"phase key misspelt", "c0 = 40.0", "c0 = 40.0\nrho = 1.0"},
    {"packing without packed", "upper = [0.5, 0.5]\n",
     "upper = [0.5, 0.5]\n[fluid.packing]\nalpha = 1e-3\n"},
    {"packing alpha negative", "upper = [0.5, 0.5]\n",
     "upper = [0.5, 0.5]\ninitial = \"packed\"\n[fluid.packing]\nalpha = -1e-3\n"},
    {"packing max_iterations fractional", "upper = [0.5, 0.5]\n",
     "upper = [0.5, 0.5]\ninitial = \"packed\"\n[fluid.packing]\nmax_iterations = 1.5\n"},
    {"packing max_iterations negative", "upper = [0.5, 0.5]\n",
     "upper = [0.5, 0.5]\ninitial = \"packed\"\n[fluid.packing]\nmax_iterations = -1\n"},
    {"packing stop zero", "upper = [0.5, 0.5]\n",
     "upper = [0.5, 0.5]\ninitial = \"packed\"\n[fluid.packing]\nstop_kinetic_energy = 0.0\n"},
    {"packing key misspelt", "upper = [0.5, 0.5]\n",
     "upper = [0.5, 0.5]\ninitial = \"packed\"\n[fluid.packing]\nalpah = 1e-3\n"},
    {"packing accepted", "upper = [0.5, 0.5]\n",
     "upper = [0.5, 0.5]\ninitial = \"packed\"\n[fluid.packing]\nalpha = 1e-3\nmax_iterations = "
     "50\nstop_kinetic_energy = 1e-9\n"},
    {"integer as boolean", "gravity = [0.0, -9.81]", "gravity = [0.0, -9.81]\nvariable_h = 1"},
    {"scene name missing", "name = \"base\"\n", ""},
};

const std::vector<Edit> packingEdits = {
    {"malformed TOML", "c0 = 20.0", "c0 = "},
    {"misspelt packing key", "dx = 0.1", "dxx = 0.1"},
    {"misspelt fluid key", "c0 = 20.0", "c00 = 20.0"},
    {"missing dx", "dx = 0.1\n", ""},
    {"dx a string", "dx = 0.1", "dx = \"0.1\""},
    {"dx zero", "dx = 0.1", "dx = 0.0"},
    {"h_over_dx below 1", "dx = 0.1", "dx = 0.1\nh_over_dx = 0.5"},
    {"h_over_dx above 4", "dx = 0.1", "dx = 0.1\nh_over_dx = 5.0"},
    {"unknown kernel", "dx = 0.1", "dx = 0.1\nkernel = \"gauss\""},
    {"phase name with a slash", "c0 = 20.0", "c0 = 20.0\nname = \"wa/ter\""},
    {"rho0 negative", "c0 = 20.0", "c0 = 20.0\nrho0 = -1.0"},
    {"rho0 a string", "c0 = 20.0", "c0 = 20.0\nrho0 = \"a\""},
    {"c0 missing", "c0 = 20.0\n", ""},
    {"gamma zero", "c0 = 20.0", "c0 = 20.0\ngamma = 0.0"},
    {"gravity negative", "c0 = 20.0", "c0 = 20.0\ngravity = -9.81"},
    {"alpha negative", "dx = 0.1", "dx = 0.1\nalpha = -1e-3"},
    {"max_iterations fractional", "dx = 0.1", "dx = 0.1\nmax_iterations = 1.5"},
    {"max_iterations zero", "dx = 0.1", "dx = 0.1\nmax_iterations = 0"},
    {"stop zero", "dx = 0.1", "dx = 0.1\nstop_kinetic_energy = 0.0"},
    {"cfl above 2", "dx = 0.1", "dx = 0.1\ncfl = 3.0"},
    {"history_every zero", "", "[output]\nhistory_every = 0\n"},
    {"path not closed", "to = [0.0, 0.0]\n", "to = [0.0, 0.5]\n"},
    {"scene name missing", "name = \"base\"\n", ""},
    {"integer as boolean in name", "name = \"base\"", "name = 1"},
    {"all keys", "dx = 0.1",
     "dx = 0.1\nh_over_dx = 1.5\nkernel = \"cubic_spline\"\nalpha = 4e-3\ncfl = 0.5\n"
     "max_iterations = 200\nstop_kinetic_energy = 1e-6\npressure = 5.0\nlattice_origin = [0.05, "
     "0.05]\n[output]\nhistory_every = 10\n"},
};

std::string goldenText() {
  std::string out;
  for (const std::string& f : shippedScenes()) {
    const std::string text = fileText(source + "/" + f);
    out += "== " + f + "\n" + read(text, f, isPackingScene(text));
  }
  out += "== run scene: base\n" + read(runBase, "run.toml", false);
  out += "== packing scene: base\n" + read(packingBase, "packing.toml", true);
  for (const Edit& e : runEdits)
    out += "== run scene: " + e.label + "\n" + read(edited(runBase, e), "run.toml", false);
  for (const Edit& e : packingEdits)
    out +=
        "== packing scene: " + e.label + "\n" + read(edited(packingBase, e), "packing.toml", true);
  return out;
}

TEST(SceneGolden, ReadersGiveTheGoldenSummaryOfEveryScene) {
  const std::string now = goldenText();
  if (std::getenv("SPH_WRITE_GOLDEN")) {
    fs::create_directories(fs::path(goldenPath).parent_path());
    std::ofstream(goldenPath) << now;
    FAIL() << "SPH_WRITE_GOLDEN: wrote " << goldenPath << "; review its diff, then run without it";
  }
  const std::string golden = fileText(goldenPath);
  ASSERT_FALSE(golden.empty()) << goldenPath << " is missing or empty";
  if (now == golden) return;
  std::istringstream a(golden), b(now);
  std::string la, lb;
  int line = 0, differing = 0;
  std::string first;
  for (bool ga = true, gb = true; ga || gb;) {
    ga = static_cast<bool>(std::getline(a, la)), gb = static_cast<bool>(std::getline(b, lb));
    if (!ga) la = "<end>";
    if (!gb) lb = "<end>";
    ++line;
    if ((ga || gb) && la != lb && differing++ == 0)
      first = "line " + std::to_string(line) + ":\n  golden: " + la + "\n  now:    " + lb;
  }
  FAIL() << differing << " lines differ from " << goldenPath << "; first at " << first;
}

}  // namespace
