// One tank at rest (TankAtRest.hpp) per call, as a CSV line, for the study over models, kernels,
// aspects and resolutions (validation/stability/tank_at_rest_study.py runs the matrix):
//   tank_at_rest_study MODEL KERNEL ASPECT CELLS [HORIZON [H_OVER_DX]]
// MODEL paper | mc | fourtakas | lind | delta_plus | fourtakas_lind | fourtakas_delta_plus (the
// last four with particle shifting), KERNEL quadratic | cubic_spline | wendland_c2, CELLS = H/dx,
// HORIZON t sqrt(g/H) (100), H_OVER_DX the kernel's h/dx (TankAtRest.hpp's for the kernel).
#include <cstdio>
#include <cstdlib>
#include <string>

#include "TankAtRest.hpp"

int main(int argc, char** argv) {
  using namespace sph::verification::tank_at_rest;
  if (argc < 5 || argc > 7) {
    std::fprintf(stderr,
                 "usage: tank_at_rest_study paper|mc|fourtakas|lind|delta_plus|fourtakas_lind|"
                 "fourtakas_delta_plus quadratic|cubic_spline|wendland_c2 "
                 "ASPECT CELLS [HORIZON [H_OVER_DX]]\n");
    return 2;
  }
  const std::string model = argv[1], kernel = argv[2];
  const Model* m = model == "paper"                  ? &paper
                   : model == "mc"                   ? &molteniColagrossi
                   : model == "fourtakas"            ? &fourtakas
                   : model == "lind"                 ? &paperLind
                   : model == "delta_plus"           ? &paperDeltaPlus
                   : model == "fourtakas_lind"       ? &fourtakasLind
                   : model == "fourtakas_delta_plus" ? &fourtakasDeltaPlus
                                                     : nullptr;
  const Kernel* k = kernel == "quadratic"      ? &quadratic
                    : kernel == "cubic_spline" ? &cubicSpline
                    : kernel == "wendland_c2"  ? &wendland
                                               : nullptr;
  if (!m || !k) {
    std::fprintf(stderr, "tank_at_rest_study: unknown model '%s' or kernel '%s'\n", argv[1],
                 argv[2]);
    return 2;
  }
  Case c{std::atof(argv[3]), std::atoi(argv[4]), *k, argc >= 6 ? std::atof(argv[5]) : 100.0};
  if (argc == 7) c.kernel.hOverDx = std::atof(argv[6]);
  if (!(c.aspect > 0) || c.cells < 2 || !(c.horizon > 0) || !(c.kernel.hOverDx > 0)) {
    std::fprintf(stderr,
                 "tank_at_rest_study: ASPECT, HORIZON and H_OVER_DX must be > 0, CELLS >= 2\n");
    return 2;
  }
  const Outcome o = run(c, *m);
  std::printf("%s,%s,%g,%d,%g,%d,%.4g,%.4e,%.4e,%.1f,%s\n", model.c_str(), kernel.c_str(), c.aspect,
              c.cells, c.horizon, o.ran ? 1 : 0, o.stoppedAt, o.speed, o.bottom, o.seconds,
              o.passes() ? "pass" : "fail");
  return 0;
}
