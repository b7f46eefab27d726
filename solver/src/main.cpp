// The `sph` program: run or check a scene file.
#include <CLI/CLI.hpp>
#include <iostream>
#include <stdexcept>

#include "sph/Run.hpp"
#include "sph/Scene.hpp"
#include "sph/packing/PackingScene.hpp"

namespace {

// Bad input (SceneError, invalid_argument: named by file and key) exits 2; anything else that stops
// a run is the output failing to be written (HDF5, the file system) and exits 4.
int reportError(const std::exception& e) {
  std::cerr << "error: " << e.what() << "\n";
  const bool badInput = dynamic_cast<const sph::SceneError*>(&e) != nullptr ||
                        dynamic_cast<const std::invalid_argument*>(&e) != nullptr;
  return badInput ? sph::exitBadInput : sph::exitOutputError;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sph: weakly compressible SPH (Lobovsky & Kren) with a V&V harness"};
  app.set_version_flag("--version",
                       std::string("sph ") + SPH_VERSION + " (" + SPH_GIT_COMMIT + ")");
  app.require_subcommand(1);
  std::string scenePath;
  sph::RunOptions options;
  options.progress = true;

  auto* run = app.add_subcommand("run", "run a scene to its end time and write <out>/<name>.h5");
  run->add_option("scene", scenePath, "scene file (TOML)")->required();
  run->add_option("--out", options.outDir, "output directory")->capture_default_str();
  run->add_option("--threads", options.threads, "OpenMP threads (default: all)")
      ->check(CLI::NonNegativeNumber);
  run->add_flag("--quiet", options.quiet, "print nothing but errors");

  auto* check = app.add_subcommand("check", "read and validate a scene file, run nothing");
  check->add_option("scene", scenePath, "scene file (TOML)")->required();

  // Colagrossi et al. (2012) particle packing: its own scene format (validation/packing/README.md).
  sph::packing::PackOptions packOptions;
  auto* pack =
      app.add_subcommand("pack", "pack the particles of a packing scene, write <out>/<name>.h5");
  pack->add_option("scene", scenePath, "packing scene file (TOML)")->required();
  pack->add_option("--out", packOptions.outDir, "output directory")->capture_default_str();
  pack->add_option("--threads", packOptions.threads, "OpenMP threads (default: all)")
      ->check(CLI::NonNegativeNumber);
  pack->add_flag("--quiet", packOptions.quiet, "print nothing but errors");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : sph::exitBadInput;
  }
  if (pack->parsed()) {
    try {
      return sph::packing::packScene(sph::packing::readPackingScene(scenePath), packOptions);
    } catch (const std::exception& e) {
      return reportError(e);
    }
  }
  sph::Scene scene;
  try {
    scene = sph::readScene(scenePath);
  } catch (const sph::SceneError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return sph::exitBadInput;
  }
  for (const auto& w : scene.warnings) std::cerr << w << "\n";
  if (check->parsed()) {
    std::cout << scenePath << ": ok (scene '" << scene.name << "', " << scene.dimension << "-D, "
              << scene.fluids.size() << " fluid blocks, " << scene.phases.size() << " phases)\n";
    return sph::exitDone;
  }
  try {
    return sph::runScene(scene, options);
  } catch (const std::exception& e) {
    return reportError(e);
  }
}
