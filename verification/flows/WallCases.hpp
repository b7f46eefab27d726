#pragma once
// The scenes of the wall-model comparison (issue 31): the paper's dam break and a tank at rest,
// each with the paper's mirror ghosts or with wall particles (Adami et al. 2012), and what a run
// of one measures at its walls.
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "FlowCases.hpp"
#include "sph/Diagnostics.hpp"

namespace sph::verification {

// validation/scenes/dam_break.toml at spacing dx to `endTime`, its walls of `model`
// ("mirror_ghosts": the scene as it is; "wall_particles": without its ghost_pressure key).
inline std::string damBreakScene(const std::string& model, double dx, double endTime) {
  std::ifstream in(std::string(SPH_SOURCE_DIR) + "/validation/scenes/dam_break.toml");
  std::stringstream b;
  b << in.rdbuf();
  std::string s = b.str();
  auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = s.find(from);
    if (at == std::string::npos) throw std::logic_error("dam_break.toml lacks '" + from + "'");
    s.replace(at, from.size(), to);
  };
  std::ostringstream n;
  n.precision(17);
  n << "dx = " << dx << "\n";
  replace("dx = 0.01\n", n.str());
  n.str("");
  n << "end_time = " << endTime << "\n";
  replace("end_time = 1.3\n", n.str());
  if (model == "wall_particles") {
    replace("ghost_pressure = \"hydrostatic\"\n", "");
    s += "\n[walls]\nmodel = \"wall_particles\"\n";
  }
  return s;
}

// Water of depth H = 1 m at rest in a 1 m wide tank (the nightly Hydrostatic test's, H/dx =
// `cells`): free-slip sides and floor, open top, c0 = 10 sqrt(2 g H), beta = 1, water viscosity,
// hydrostatic start, to `endTime`. Mirror ghosts carry the hydrostatic correction.
inline std::string restingTankScene(const std::string& model, int cells, double endTime,
                                    const std::string& kernel = "quadratic",
                                    double hOverDx = 1.33) {
  const double H = 1.0, g = 9.81, c0 = 10 * std::sqrt(2 * g * H);
  std::ostringstream s;
  s.precision(17);
  s << "name = \"resting_tank\"\ndimension = 2\n[domain]\nlower = [0.0, 0.0]\nupper = [1.0, 1.5]\n"
    << "x_lower = \"free_slip\"\nx_upper = \"free_slip\"\ny_lower = \"free_slip\"\n"
    << "y_upper = \"open\"\n"
    << (model == "mirror_ghosts" ? "ghost_pressure = \"hydrostatic\"\n" : "")
    << "[walls]\nmodel = \"" << model << "\"\n"
    << "[[phase]]\nname = \"water\"\nrho0 = 1000.0\nc0 = " << c0 << "\nmu = 8.9e-4\n"
    << "[[fluid]]\nlower = [0.0, 0.0]\nupper = [1.0, " << H << "]\n"
    << "initial_pressure = \"hydrostatic\"\n[physics]\ngravity = [0.0, " << -g
    << "]\nartificial_viscosity = 1.0\nmorris_viscosity = true\n[numerics]\nkernel = \"" << kernel
    << "\"\nh_over_dx = " << hOverDx << "\ndx = " << H / cells << "\nend_time = " << endTime
    << "\n";
  return s.str();
}

// Two layers at rest in the same tank, each H/2 deep: a light phase (1000 kg/m^3) over a heavy
// one (by default 1500, the paper's two fluids), listed in the scene with the heavy phase
// first or second (the fluid blocks in the same order either way), the named model's kernel and
// density diffusion (Wendland C2 at h/dx 2, Fourtakas et al.'s delta 0.1 within each phase), one
// c0 = 10 sqrt(2 g H) for both. The heavy layer starts at the pressure of the light one above it
// (its `surface` the height of light fluid of its weight). The floor reads g (rho_l + rho_h) H/2.
// `continuityForm`: physics.continuity_form (SCENES.md); `heavy`: the heavy phase's rho0.
inline std::string layeredTankScene(const std::string& model, int cells, double endTime,
                                    bool heavyFirst,
                                    const std::string& continuityForm = "lobovsky_kren",
                                    double heavy = 1500.0) {
  const double H = 1.0, g = 9.81, c0 = 10 * std::sqrt(2 * g * H), light = 1000.0;
  std::ostringstream s;
  s.precision(17);
  s << "name = \"layered_tank\"\ndimension = 2\n[domain]\nlower = [0.0, 0.0]\nupper = [1.0, 1.5]\n"
    << "x_lower = \"free_slip\"\nx_upper = \"free_slip\"\ny_lower = \"free_slip\"\n"
    << "y_upper = \"open\"\n"
    << (model == "mirror_ghosts" ? "ghost_pressure = \"hydrostatic\"\n" : "")
    << "[walls]\nmodel = \"" << model << "\"\n";
  auto phase = [&](const char* name, double rho0) {
    s << "[[phase]]\nname = \"" << name << "\"\nrho0 = " << rho0 << "\nc0 = " << c0
      << "\nmu = 8.9e-4\n";
  };
  if (heavyFirst) phase("heavy", heavy);
  phase("light", light);
  if (!heavyFirst) phase("heavy", heavy);
  s << "[[fluid]]\nlower = [0.0, 0.0]\nupper = [1.0, " << H / 2 << "]\nphase = \"heavy\"\n"
    << "initial_pressure = \"hydrostatic\"\nsurface = " << H / 2 * (1 + light / heavy) << "\n"
    << "[[fluid]]\nlower = [0.0, " << H / 2 << "]\nupper = [1.0, " << H << "]\nphase = \"light\"\n"
    << "initial_pressure = \"hydrostatic\"\n[physics]\ngravity = [0.0, " << -g
    << "]\nartificial_viscosity = 1.0\nmorris_viscosity = true\ndensity_diffusion = 0.1\n"
    << "density_diffusion_form = \"fourtakas\"\ncontinuity_form = \"" << continuityForm
    << "\"\n[numerics]\nkernel = \"wendland_c2\"\n"
    << "h_over_dx = 2.0\ndx = " << H / cells << "\nend_time = " << endTime << "\n";
  return s.str();
}

struct WallRun {
  bool stable = true;
  std::string failure;
  long reflections = 0;
  double deepest = 0;          // the deepest reflected crossing [m]
  double volumeVariation = 0;  // max |sum m/rho / V(0) - 1| over the samples
  double bottomPressure = 0;   // the floor probe at mid-width, mean over the second half [Pa]
  double maxSpeed = 0;         // max |v| over the second half [m/s]
  double seconds = 0;          // wall time of the run
  long steps = 0;
};

// Runs `scene` to its end time in `samples` legs, measuring at the end of each.
template <int D>
WallRun runWalls(const Scene& scene, int samples = 40) {
  Simulation<D> sim(scene);
  sim.keepCellOrder(10);  // as sph run does
  auto volume = [&] {
    double v = 0;
    for (std::size_t i = 0; i < sim.particles().size(); ++i)
      v += sim.particles().m[i] / sim.particles().rho[i];
    return v;
  };
  Probe floor;
  floor.type = "pressure";
  floor.position.assign(D, 0.0);
  for (int a = 0; a < D; ++a) floor.position[a] = 0.5 * (scene.lower[a] + scene.upper[a]);
  floor.position[D - 1] = scene.lower[D - 1];
  const double v0 = volume();
  WallRun out;
  int late = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int k = 1; k <= samples; ++k) {
    if (!runTo(sim, scene.endTime * k / samples, &out.failure)) {
      out.stable = false;
      break;
    }
    out.volumeVariation = std::max(out.volumeVariation, std::abs(volume() / v0 - 1));
    if (2 * k > samples) {
      for (const auto& v : sim.particles().v) out.maxSpeed = std::max(out.maxSpeed, v.norm());
      out.bottomPressure += probe<D>(scene, floor, sim.particles(), sim.interactionSet());
      ++late;
    }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.bottomPressure /= std::max(late, 1);
  out.reflections = sim.wallReflections(), out.deepest = sim.maxReflectionDepth();
  out.steps = sim.step();
  return out;
}

}  // namespace sph::verification
