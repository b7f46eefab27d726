#include <hdf5.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "sph/Run.hpp"
#include "sph/RunFile.hpp"
#include "sph/packing/PackingScene.hpp"

// `sph pack`: packs a packing scene (PackingScene.hpp) and writes its pack file.
namespace sph::packing {

namespace {

void writeExtra(const std::string& path, const std::string& dataset, const std::vector<double>& v,
                std::size_t columns) {
  hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file < 0) throw std::runtime_error(path + ": cannot reopen the pack file");
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  hsize_t dims[2] = {v.size() / columns, columns};
  hid_t space = H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr);
  hid_t d =
      H5Dcreate2(file, dataset.c_str(), H5T_NATIVE_DOUBLE, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  herr_t st = d < 0 ? -1 : H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  if (d >= 0) H5Dclose(d);
  H5Sclose(space), H5Pclose(lcpl), H5Fclose(file);
  if (st < 0) throw std::runtime_error(path + ": cannot write " + dataset);
}

SnapshotFields fields(const std::vector<Vec2>& x, const PackingScene& s,
                      const PackingSetup& setup) {
  const double surface = s.hasSurface ? s.surface : -INFINITY;
  const HydrostaticFields hs = hydrostatic(x, setup.V0, s.phase, s.hasSurface ? s.gravity : 0.0,
                                           s.hasSurface ? surface : 0.0);
  SnapshotFields f;
  for (const Vec2& p : x) f.position.insert(f.position.end(), {p.x(), p.y(), 0.0});
  f.velocity.assign(3 * x.size(), 0.0);
  f.density = hs.density, f.pressure = hs.pressure, f.mass = hs.mass;
  f.h.assign(x.size(), s.parameters.hOverDx * s.dx);
  f.phase.assign(x.size(), 0);
  return f;
}

}  // namespace

int packScene(const PackingScene& s, const PackOptions& options) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
  const auto wallStart = std::chrono::steady_clock::now();
  const PackingSetup setup = setUp(s);
  ParticlePacking packing(setup.fluid, setup.solid.position, setup.V0, s.dx, s.parameters);
  const double H = setup.lengthScale;
  const std::vector<Vec2> start = packing.positions();
  std::vector<double> gradStart;
  for (const Vec2& g : packing.gradGamma()) gradStart.push_back(H * g.norm());

  namespace fs = std::filesystem;
  fs::create_directories(options.outDir);
  const std::string path = (fs::path(options.outDir) / (s.name + ".h5")).string();
  bool finite = true, stopped = false;
  {
    RunFile out(path);
    out.attribute("format", std::string("sph-pack-1"));
    const Provenance pv = provenance();
    out.attribute("sph_version", pv.version), out.attribute("git_commit", pv.commit);
    out.attribute("compiler", pv.compiler), out.attribute("cxx_flags", pv.flags);
    out.attribute("build_type", pv.buildType), out.attribute("machine", pv.machine);
    out.attribute("date", pv.date);
    out.attribute("threads", std::int64_t{omp_get_max_threads()});
    out.attribute("scene_name", s.name), out.attribute("scene_file", s.file);
    out.attribute("dimension", std::int64_t{2});
    out.attribute("kernel", std::string(name(s.parameters.kernel)));
    out.attribute("gravity", s.gravity), out.attribute("rho0", s.phase.rho0);
    out.text("/scene", s.text);
    const std::string P = "/packing";
    out.attribute("dx", s.dx, P), out.attribute("h", packing.h(), P),
        out.attribute("V0", setup.V0, P);
    out.attribute("h_over_dx", s.parameters.hOverDx, P),
        out.attribute("beta", s.parameters.beta, P);
    out.attribute("alpha", s.parameters.alpha, P), out.attribute("zeta", packing.zeta(), P);
    out.attribute("cfl", s.parameters.cfl, P), out.attribute("dt", packing.dt(), P);
    out.attribute("stop_kinetic_energy", s.parameters.stopKineticEnergy, P);
    out.attribute("length_scale", H, P);
    out.attribute("fluid_area", setup.region.area(), P);
    out.attribute("fluid_particles", static_cast<std::int64_t>(setup.fluid.size()), P);
    out.attribute("solid_particles", static_cast<std::int64_t>(setup.solid.position.size()), P);
    out.attribute("free_surface", s.hasSurface ? s.surface : NAN, P);

    std::vector<SeriesColumn> columns(5);
    columns[0].name = "step";
    columns[1].name = "kinetic_energy_over_beta";
    columns[1].text = {{"meaning", "T/beta, T = sum_i |u_i|^2/2 over fluid particles (eq. 2.18)"}};
    columns[2].name = "mean_kinetic_energy_over_beta";
    columns[2].text = {{"meaning", "T/(N beta)"}};
    columns[3].name = "potential_energy_over_beta";
    columns[3].text = {{"meaning", "(V - V(0))/beta, V of eq. (B.34)"}};
    columns[4].name = "max_grad_gamma_H";
    columns[4].text = {{"meaning", "H max_i |grad Gamma_i| over fluid particles"}};
    const double V0 = packing.record().potential;
    out.attribute("potential_energy_initial_over_beta", V0, P);
    stopped = packing.run([&](const PackingRecord& r) {
      if (!std::isfinite(r.kinetic)) finite = false;
      if (r.iteration % s.historyEvery != 0 && r.kineticMean >= s.parameters.stopKineticEnergy)
        return;
      columns[0].values.push_back(r.iteration);
      columns[1].values.push_back(r.kinetic);
      columns[2].values.push_back(r.kineticMean);
      columns[3].values.push_back(r.potential - V0);
      columns[4].values.push_back(H * r.maxGradGamma);
      if (!options.quiet && r.iteration % 500 == 0)
        std::cerr << "iteration " << r.iteration << ": T/(N beta) = " << r.kineticMean
                  << ", H max|grad Gamma| = " << H * r.maxGradGamma << "\n";
    });
    out.appendSeries(columns);
    double gStart = 0.0, gEnd = 0.0;
    for (double g : gradStart) gStart = std::max(gStart, g);
    for (const Vec2& g : packing.gradGamma()) gEnd = std::max(gEnd, H * g.norm());
    const PackingRecord last = packing.record();
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    const std::string M = "/metrics";
    out.attribute("iterations", static_cast<std::int64_t>(packing.iteration()), M);
    out.attribute("converged", std::int64_t{stopped && finite ? 1 : 0}, M);
    out.attribute("final_kinetic_energy_over_beta", last.kinetic, M);
    out.attribute("max_grad_gamma_H_initial", gStart, M);
    out.attribute("max_grad_gamma_H_final", gEnd, M);
    out.attribute("wall_time_s", wall, M);
    out.attribute("particles", static_cast<std::int64_t>(setup.fluid.size()), M);
    out.snapshot(0.0, 0, fields(start, s, setup));
    out.snapshot(packing.iteration() * packing.dt(), packing.iteration(),
                 fields(packing.positions(), s, setup));
    if (!options.quiet)
      std::cerr << s.name << ": " << setup.fluid.size() << " fluid, " << setup.solid.position.size()
                << " solid particles; " << packing.iteration()
                << " iterations, T/(N beta) = " << last.kineticMean << ", H max|grad Gamma| "
                << gStart << " -> " << gEnd << " (" << wall << " s)\n";
    if (!(stopped && finite))
      std::cerr << "error: the packing "
                << (finite ? "did not reach" : "produced a non-finite value before")
                << " T/(N beta) < " << s.parameters.stopKineticEnergy << " within "
                << s.parameters.maxIterations << " iterations\n";
    out.finish();
  }
  // Beside the snapshots: H |grad Gamma| per fluid particle before and after, and the solid
  // particles (kind 0 wall, 1 free surface), which the SPH start does not carry.
  std::vector<double> gradEnd, solid, kind;
  for (const Vec2& g : packing.gradGamma()) gradEnd.push_back(H * g.norm());
  for (std::size_t i = 0; i < setup.solid.position.size(); ++i) {
    const Vec2& p = setup.solid.position[i];
    solid.insert(solid.end(), {p.x(), p.y(), 0.0});
    kind.push_back(setup.solid.kind[i] == Piece::Kind::surface ? 1.0 : 0.0);
  }
  writeExtra(path, "/snapshots/00000/grad_gamma_H", gradStart, 1);
  writeExtra(path, "/snapshots/00001/grad_gamma_H", gradEnd, 1);
  writeExtra(path, "/solid/position", solid, 3);
  writeExtra(path, "/solid/kind", kind, 1);
  return finite && stopped ? exitDone : exitNumericalFailure;
}

}  // namespace sph::packing
