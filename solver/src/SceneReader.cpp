#include "SceneReader.hpp"

#include <fstream>
#include <sstream>

namespace sph {

std::string sceneText(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw SceneError(path + ": cannot open the scene file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

toml::table parseSceneToml(const std::string& text, const std::string& file) {
  try {
    return toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    std::ostringstream m;
    m << file << ":" << e.source().begin.line << ":" << e.source().begin.column
      << ": malformed TOML: " << e.description();
    throw SceneError(m.str());
  }
}

std::vector<std::string> PhaseKeys::keys() const {
  std::vector<std::string> k{"name", "rho0", "c0", "p0", "gamma"};
  if (viscous) k.push_back("mu");
  return k;
}

Phase readPhase(SceneTable& t, const PhaseKeys& k) {
  Phase p;
  p.name = k.name && !t.has("name") ? *k.name : t.name("name");
  p.rho0 = t.positive("rho0", k.rho0);
  p.c0 = t.positive("c0");
  if (k.viscous) p.mu = t.nonNegative("mu", 0.0);
  p.p0 = t.number("p0", 0.0);
  p.gamma = t.positive("gamma", 7.0);
  return p;
}

KernelKind readKernel(SceneTable& t, KernelKind fallback) {
  const std::string v = t.string("kernel", std::string(name(fallback)));
  for (KernelKind k : {KernelKind::quadratic, KernelKind::cubic_spline, KernelKind::wendland_c2})
    if (v == name(k)) return k;
  t.fail("kernel", "unknown kernel '" + v + "' (expected quadratic, cubic_spline or wendland_c2)");
}

double readDx(SceneTable& t) {
  return t.positive("dx");
}

double readHOverDx(SceneTable& t, double fallback) {
  const double v = t.positive("h_over_dx", fallback);
  // Below 1 the kernel sum of a uniform lattice, sum_j dx^D W_ij, is off 1 by more than 12 %
  // (quadratic kernel, 2-D: 1.12 at h/dx 1, 1.24 at 0.75, 1.91 at 0.5, against 1.05 at 1.33):
  // the particles no longer see a continuum. Above 4 a particle lists some 240 neighbours in 2-D
  // and 2900 in 3-D (11 kB of memory a particle, RunBudget.hpp) while the sum is within 0.2 % of
  // 1 from h/dx 3 on: more only smooths the flow more (the O(h^2) error grows).
  if (v < 1.0 || v > 4.0)
    t.fail("h_over_dx", "must lie in [1, 4], got " + SceneTable::fmt(v) +
                            " (below 1 the kernel's support holds too few neighbours for "
                            "its sums to approximate integrals; above 4 it only smooths "
                            "and costs: solver/SCENES.md)");
  return v;
}

void readPackingControls(SceneTable& t, double& alpha, int& maxIterations,
                         double& stopKineticEnergy) {
  alpha = t.nonNegative("alpha", alpha);
  const long n = t.integer("max_iterations", maxIterations);  // |n| <= 1e9 (SceneTable)
  if (n < 0) t.fail("max_iterations", "must not be negative");
  maxIterations = static_cast<int>(n);
  stopKineticEnergy = t.positive("stop_kinetic_energy", stopKineticEnergy);
}

}  // namespace sph
