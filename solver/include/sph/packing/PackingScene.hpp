#pragma once
// A packing scene (TOML, keys in solver/SCENES.md): a 2-D container of walls and
// arcs, a free-surface height, the fluid's equation of state and the packing parameters. `sph
// pack SCENE --out DIR` builds the lattice and the solid layers, packs, assigns the hydrostatic
// state and writes <DIR>/<name>.h5.
#include <string>
#include <vector>

#include "sph/EquationOfState.hpp"
#include "sph/Scene.hpp"  // SceneError
#include "sph/packing/Geometry.hpp"
#include "sph/packing/ParticlePacking.hpp"

namespace sph::packing {

struct PackingScene {
  std::string name, file, text, description;
  std::vector<Piece> container;  // closed path as given
  bool hasSurface = false;
  double surface = 0.0;      // free-surface height y
  double lengthScale = 0.0;  // H, for H |grad Gamma| (default: surface minus the lowest point)
  double dx = 0.0;
  Vec2 latticeOrigin = Vec2::Zero();
  Phase phase;
  double gravity = 9.81;  // acting along -y
  PackingParameters parameters;
  int historyEvery = 1;
};

PackingScene readPackingScene(const std::string& path);
PackingScene parsePackingScene(const std::string& text, const std::string& file);

// The start of a packing: the fluid region, the Cartesian lattice inside it, V0 = area / N
// (section 2) and the fixed solid layers to the depth of the kernel support.
struct PackingSetup {
  Region region;
  std::vector<Vec2> fluid;
  SolidLayers solid;
  double V0 = 0.0;
  double lengthScale = 0.0;
};
PackingSetup setUp(const PackingScene& scene);

struct PackOptions {
  std::string outDir = ".";
  int threads = 0;
  bool quiet = false;
};
// Packs the scene and writes its file; returns an ExitCode (exitDone, or exitNumericalFailure
// when the packing did not reach the kinetic energy threshold within max_iterations).
int packScene(const PackingScene& scene, const PackOptions& options);

}  // namespace sph::packing
