// Reads a 2-D scene whose fluid starts at rest with hydrostatic pressure (the dam break) and
// evaluates its rates once through the installed library: the particle count, and the mean
// vertical acceleration of the fluid over |g|, which the pressure gradient nearly cancels.
#include <cmath>
#include <cstdio>
#include <exception>

#include "sph/Scene.hpp"
#include "sph/Simulation.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SCENE.toml (a 2-D scene)\n", argv[0]);
    return 2;
  }
  try {
    const sph::Scene scene = sph::readScene(argv[1]);
    if (scene.dimension != 2) {
      std::fprintf(stderr, "%s: dimension is %d, this program reads 2-D scenes\n", argv[1],
                   scene.dimension);
      return 2;
    }
    sph::Simulation<2> simulation(scene);
    sph::Derivatives<2> rates;
    simulation.rates(simulation.particles(), 0.0, rates);
    const std::size_t n = simulation.particles().size();
    double g2 = 0.0;
    for (double a : scene.bodyAcceleration) g2 += a * a;
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) sum += rates.dvdt[i][1];
    std::printf("particles %zu\nmean vertical acceleration / g %.6f\n", n,
                sum / static_cast<double>(n) / std::sqrt(g2));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
