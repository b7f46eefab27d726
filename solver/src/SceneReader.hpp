#pragma once
// What a run scene (Scene.cpp) and a packing scene (packing/PackingScene.cpp) read alike: the
// file and its TOML, the scene's name, a fluid phase, the kernel, dx and h/dx, and the packing's
// controls. Each key is read by one function here, so that it means the same, is checked the same
// and is refused in the same words in both kinds of scene (solver/SCENES.md). Internal to the
// solver library.
#include <toml++/toml.h>

#include <optional>
#include <string>
#include <vector>

#include "SceneTable.hpp"
#include "sph/EquationOfState.hpp"
#include "sph/Kernels.hpp"

namespace sph {

// The scene file's text; SceneError "<path>: cannot open the scene file".
std::string sceneText(const std::string& path);

// The text as TOML; malformed TOML is a SceneError "<file>:<line>:<column>: malformed TOML: ...".
toml::table parseSceneToml(const std::string& text, const std::string& file);

// A fluid phase's keys: name, rho0, c0, p0, gamma and, where `viscous`, mu. A run scene's
// [[phase]] has no defaults for name and rho0; a packing scene's [fluid] has ("water", 1000).
struct PhaseKeys {
  bool viscous = true;
  std::optional<std::string> name;
  std::optional<double> rho0;
  std::vector<std::string> keys() const;
};
Phase readPhase(SceneTable& t, const PhaseKeys& k);

KernelKind readKernel(SceneTable& t, KernelKind fallback);
// dx: positive. The scene kinds check it against their extent themselves (Scene.cpp: half the
// domain; PackingScene.cpp: the lattice the container spans).
double readDx(SceneTable& t);
// h_over_dx in [1, 4] (the reason beside the check).
double readHOverDx(SceneTable& t, double fallback);

// The controls of a Colagrossi et al. (2012) packing, a run scene's [fluid.packing] and a
// packing scene's [packing]: alpha (eq. 2.15), max_iterations and stop_kinetic_energy, which is
// T / (N beta), the kinetic energy of eq. (2.18) per fluid particle in units of beta
// (ParticlePacking.hpp), in both. The values passed in are the defaults.
inline const std::vector<std::string> packingControlKeys{"alpha", "max_iterations",
                                                         "stop_kinetic_energy"};
void readPackingControls(SceneTable& t, double& alpha, int& maxIterations,
                         double& stopKineticEnergy);

}  // namespace sph
