// One tank at rest (TankAtRest.hpp) per call, as a CSV line, for the study over models, kernels,
// aspects and resolutions (validation/stability/tank_at_rest_study.py runs the matrix):
//   tank_at_rest_study MODEL KERNEL ASPECT CELLS [HORIZON [H_OVER_DX [CFL [DIMENSION [START]]]]]
// MODEL paper | mc | fourtakas | fourtakas_fixed_h | fourtakas_02 | fourtakas_005 | fourtakas_pv |
// fourtakas_vv | antuono | lind | delta_plus | fourtakas_lind | fourtakas_delta_plus (fourtakas
// with a fixed h, with delta 0.2 and 0.05, with position and velocity Verlet; Antuono et al.'s
// form; the last four with shifting),
// KERNEL quadratic | cubic_spline | wendland_c2, CELLS = H/dx, HORIZON t sqrt(g/H) (100),
// H_OVER_DX the kernel's h/dx (- or TankAtRest.hpp's for the kernel), CFL the acoustic one (0.25),
// DIMENSION 2 or 3 (3: a tank ASPECT x 1 x 1 H), START lattice (the default), packed or
// packed:NOISE (Colagrossi et al. 2012, eq. 2.16, against the walls' mirror images and solid layers
// above, from the lattice moved by [fluid.packing] noise, a fraction of dx). With
// TANK_AT_REST_SERIES=FILE set, the 100 samples go to FILE as CSV (t sqrt(g/H), max|u|/sqrt(gH) and
// its x and height, p_b/(rho0 g H) - 1, the lowest p/(rho0 g H) and its height): where and when a
// tank starts to move.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "TankAtRest.hpp"

int main(int argc, char** argv) {
  using namespace sph::verification::tank_at_rest;
  if (argc < 5 || argc > 10) {
    std::fprintf(stderr,
                 "usage: tank_at_rest_study paper|mc|fourtakas|fourtakas_fixed_h|fourtakas_02|"
                 "fourtakas_005|fourtakas_pv|fourtakas_vv|antuono|lind|delta_plus|fourtakas_lind|"
                 "fourtakas_delta_plus quadratic|cubic_spline|wendland_c2 "
                 "ASPECT CELLS [HORIZON [H_OVER_DX [CFL [DIMENSION [lattice|packed[:NOISE]]]]]]\n");
    return 2;
  }
  const std::string model = argv[1], kernel = argv[2];
  const Model* m = model == "paper"                  ? &paper
                   : model == "mc"                   ? &molteniColagrossi
                   : model == "fourtakas"            ? &fourtakas
                   : model == "fourtakas_fixed_h"    ? &fourtakasFixedH
                   : model == "fourtakas_02"         ? &fourtakas02
                   : model == "fourtakas_005"        ? &fourtakas005
                   : model == "fourtakas_pv"         ? &fourtakasVerlet
                   : model == "fourtakas_vv"         ? &fourtakasVelocityVerlet
                   : model == "antuono"              ? &antuono
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
  if (argc >= 7 && std::string(argv[6]) != "-") c.kernel.hOverDx = std::atof(argv[6]);
  if (argc >= 8) c.cfl = std::atof(argv[7]);
  if (argc >= 9) c.dimension = std::atoi(argv[8]);
  const std::string start = argc == 10 ? argv[9] : "lattice";
  c.packed = start.rfind("packed", 0) == 0;
  if (start.rfind("packed:", 0) == 0) c.packingNoise = std::atof(start.c_str() + 7);
  if (!(c.aspect > 0) || c.cells < 2 || !(c.horizon > 0) || !(c.kernel.hOverDx > 0) ||
      !(c.cfl > 0) || (c.dimension != 2 && c.dimension != 3) || (start != "lattice" && !c.packed) ||
      !(c.packingNoise >= 0 && c.packingNoise < 0.5)) {
    std::fprintf(stderr,
                 "tank_at_rest_study: ASPECT, HORIZON, H_OVER_DX and CFL must be > 0, CELLS >= 2, "
                 "DIMENSION 2 or 3, START lattice, packed or packed:NOISE (0 <= NOISE < 0.5)\n");
    return 2;
  }
  const Outcome o = run(c, *m);
  if (!o.ran) std::fprintf(stderr, "tank_at_rest_study: stopped: %s\n", o.why.c_str());
  if (const char* path = std::getenv("TANK_AT_REST_SERIES")) {
    std::FILE* f = std::fopen(path, "w");
    if (!f) {
      std::fprintf(stderr, "tank_at_rest_study: cannot write TANK_AT_REST_SERIES '%s'\n", path);
      return 1;
    }
    std::fprintf(f, "t_sqrt_g_over_H,speed,x,z,bottom,p_min,z_p_min\n");
    for (const Sample& s : o.series)
      std::fprintf(f, "%.4g,%.4e,%.4f,%.4f,%.4e,%.4e,%.4f\n", s.t, s.speed, s.x, s.z, s.bottom,
                   s.pMin, s.zMin);
    if (std::fclose(f) != 0) {
      std::fprintf(stderr, "tank_at_rest_study: writing '%s' failed\n", path);
      return 1;
    }
  }
  std::printf("%s,%s,%g,%d,%g,%d,%.4g,%.4e,%.4e,%.1f,%s\n", model.c_str(), kernel.c_str(), c.aspect,
              c.cells, c.horizon, o.ran ? 1 : 0, o.stoppedAt, o.speed, o.bottom, o.seconds,
              o.passes() ? "pass" : "fail");
  return 0;
}
