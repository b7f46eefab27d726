// Issue 36: 3-D speed and memory on the SPHERIC test 2 dam break (validation/scenes/
// spheric_dam_break*.toml). Three figures, each a mode of its own:
//
//   sph_bench_3d --memory SCENE
//       the scene's particles (fluid, wall) and this process's peak RSS after two steps of it,
//       bytes a particle (fluid + wall; the wall particles are entries of every force evaluation)
//   sph_bench_3d --force SCENE [--threads 1,2]
//       the force evaluation alone on the scene's start, ns a fluid particle, best of 5 batches
//   sph_bench_3d --run SCENE [--threads 1,2] [--end-time T]
//       the case end to end as `sph run` does it (set-up, run, probes, output), wall time
//
// One process a scene for --memory: the peak RSS is the process's. Timings are for a quiet
// machine (perf/README.md); the memory and the counts do not depend on the load. The idle threads
// wait as `sph`'s do (WaitPolicy.hpp) unless OMP_WAIT_POLICY or GOMP_SPINCOUNT is set.
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "sph/Run.hpp"
#include "sph/Scene.hpp"
#include "sph/Simulation.hpp"
#include "sph/WaitPolicy.hpp"

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

std::vector<int> parseThreads(const std::string& s) {
  std::vector<int> v;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) v.push_back(std::stoi(item));
  return v;
}

double peakRss() {  // VmHWM of /proc/self/status [bytes]
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("VmHWM:", 0) == 0) return 1024.0 * std::stod(line.substr(6));
  return 0.0;
}

std::string withEndTime(std::string text, double endTime) {
  if (endTime <= 0) return text;
  std::ostringstream e;
  e.precision(17);
  e << "end_time = " << endTime;
  return std::regex_replace(text, std::regex(R"(\nend_time\s*=\s*[0-9.eE+-]+)"), "\n" + e.str());
}

sph::Scene sceneOf(const std::string& path, double endTime = 0) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("sph_bench_3d: cannot open the scene " + path);
  std::stringstream buf;
  buf << in.rdbuf();
  return sph::parseScene(withEndTime(buf.str(), endTime), path);
}

// Wall particles: the entries of the interaction set after the fluid and its halo, and those left
// out of it as in no pair (all of the scene's).
std::size_t wallParticles(const sph::Simulation<3>& sim) {
  const auto& set = sim.interactionSet();
  return set.size() - set.haloEnd() + set.leftOut.count;
}

int memory(const std::string& path) {
  const double before = peakRss();
  sph::Simulation<3> sim(sceneOf(path));
  for (int k = 0; k < 2; ++k)
    if (sim.advance(1.0)) throw std::runtime_error("sph_bench_3d: " + path + " failed");
  const double after = peakRss();
  const std::size_t fluid = sim.particles().size(), wall = wallParticles(sim);
  std::printf(
      "memory %s: %zu fluid + %zu wall = %zu particles, peak RSS %.1f MB (baseline %.1f MB): "
      "%.0f bytes a particle, %.0f a fluid particle\n",
      sim.scene().name.c_str(), fluid, wall, fluid + wall, after / 1e6, before / 1e6,
      after / double(fluid + wall), after / double(fluid));
  return 0;
}

int force(const std::string& path, const std::vector<int>& threads) {
  sph::Simulation<3> sim(sceneOf(path));
  if (sim.advance(1.0)) throw std::runtime_error("sph_bench_3d: " + path + " failed");
  const sph::InteractionSet<3> set = sim.interactionSet();
  sph::ForceEvaluation<3> evaluate = sim.forces();
  sph::Derivatives<3> out;
  out.resize(set.size());
  sph::Vec<3> g;
  for (int a = 0; a < 3; ++a) g[a] = sim.scene().bodyAcceleration[a];
  for (int t : threads) {
    omp_set_num_threads(t);
    evaluate(set, out, g);  // warm-up: cell list and workspace allocated
    double best = 1e300;
    for (int batch = 0; batch < 5; ++batch) {
      const int calls = 5;
      const auto t0 = Clock::now();
      for (int k = 0; k < calls; ++k) evaluate(set, out, g);
      best = std::min(best, seconds(t0, Clock::now()) / calls);
    }
    std::printf(
        "force %s, %d thread(s): %zu fluid, %zu entries: %.1f ms an evaluation, %.0f ns a "
        "fluid particle\n",
        sim.scene().name.c_str(), t, set.nFluid, set.size(), 1e3 * best,
        1e9 * best / double(set.nFluid));
  }
  return 0;
}

int run(const std::string& path, const std::vector<int>& threads, double endTime) {
  const sph::Scene scene = sceneOf(path, endTime);
  const auto scratch =
      std::filesystem::temp_directory_path() / ("sph_bench_3d_" + std::to_string(::getpid()));
  bool ok = true;
  for (int t : threads) {
    std::filesystem::create_directories(scratch);
    sph::RunOptions options;
    options.outDir = scratch.string(), options.threads = t, options.quiet = true;
    const auto t0 = Clock::now();
    const int code = sph::runScene(scene, options);
    const double wall = seconds(t0, Clock::now());
    std::filesystem::remove_all(scratch);
    ok = ok && code == sph::exitDone;
    std::printf("run %s to t = %g s, %d thread(s): %.2f s wall%s\n", scene.name.c_str(),
                scene.endTime, t, wall, code == sph::exitDone ? "" : " FAILED");
    std::fflush(stdout);
  }
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  sph::chooseWaitPolicy(argv);  // first: it may execute the program again
  std::string mode, scene;
  std::vector<int> threads{1, 2};
  double endTime = 1.0;
  for (int a = 1; a < argc; ++a) {
    const std::string k = argv[a];
    auto next = [&]() -> std::string {
      if (a + 1 >= argc) throw std::runtime_error("missing value after " + k);
      return argv[++a];
    };
    if (k == "--memory" || k == "--force" || k == "--run")
      mode = k, scene = next();
    else if (k == "--threads")
      threads = parseThreads(next());
    else if (k == "--end-time")
      endTime = std::stod(next());
    else {
      std::cerr << "sph_bench_3d: unknown option " << k << "\n";
      return 2;
    }
  }
  if (mode.empty()) {
    std::cerr << "usage: sph_bench_3d --memory SCENE | --force SCENE [--threads 1,2] | --run "
                 "SCENE [--threads 1,2] [--end-time T]\n";
    return 2;
  }
  if (mode == "--memory") return memory(scene);
  if (mode == "--force") return force(scene, threads);
  return run(scene, threads, endTime);
}
