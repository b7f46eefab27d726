#include "sph/packing/PackingScene.hpp"

#include <hdf5.h>
#include <omp.h>
#include <toml++/toml.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>

#include "../SceneTable.hpp"
#include "sph/Run.hpp"
#include "sph/RunFile.hpp"

namespace sph::packing {

namespace {

void readGeometry(SceneTable g, PackingScene& s) {
  Vec2 at = g.point("start");
  const Vec2 start = at;
  std::vector<SceneTable> path = g.array("path");
  if (path.size() < 1) g.fail("path", "missing: at least one [[geometry.path]] piece");
  double scale = 0.0;
  for (SceneTable& piece : path) {
    const Vec2 to = piece.point("to");
    const std::string turn = piece.string("turn", "ccw");
    if (piece.has("center")) {
      const Vec2 c = piece.point("center");
      const double r0 = (at - c).norm(), r1 = (to - c).norm();
      if (!(r0 > 0.0)) piece.fail("center", "coincides with the arc's start point");
      if (std::abs(r0 - r1) > 1e-9 * r0)
        piece.fail("center", "is " + SceneTable::fmt(r0) + " from the start but " +
                                 SceneTable::fmt(r1) +
                                 " from 'to': not the centre of an arc through both");
      if (turn != "ccw" && turn != "cw") piece.fail("turn", "expected \"ccw\" or \"cw\"");
      s.container.push_back(arc(at, to, c, turn == "ccw"));
    } else {
      if (piece.has("turn")) piece.fail("turn", "only an arc (with 'center') has a turning sense");
      if ((to - at).norm() == 0.0)
        piece.fail("to", "repeats the previous point (a segment of zero length)");
      s.container.push_back(segment(at, to));
    }
    scale = std::max(scale, (to - start).norm());
    at = to;
    piece.rejectUnknown();
  }
  if ((at - start).norm() > 1e-9 * scale)
    g.fail("path", "does not close: the last 'to' must equal 'start'");
  s.container.back().b = start;
  s.hasSurface = g.has("surface");
  if (s.hasSurface) s.surface = g.number("surface");
  if (g.has("length_scale")) s.lengthScale = g.positive("length_scale");
  g.rejectUnknown();
}

}  // namespace

PackingScene parsePackingScene(const std::string& text, const std::string& file) {
  PackingScene s;
  s.file = file, s.text = text;
  toml::table root;
  try {
    root = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << file << ":" << e.source().begin.line << ": " << e.description();
    throw SceneError(msg.str());
  }
  SceneTable top(root, "", s.file);
  s.name = top.name("name");
  s.description = top.string("description", "");
  readGeometry(top.sub("geometry"), s);

  SceneTable fluid = top.sub("fluid");
  s.phase.name = fluid.string("name", "water");
  s.phase.rho0 = fluid.positive("rho0", 1000.0);
  s.phase.c0 = fluid.positive("c0");
  s.phase.p0 = fluid.number("p0", 0.0);
  s.phase.gamma = fluid.positive("gamma", 7.0);
  s.gravity = fluid.number("gravity", 9.81);
  if (s.gravity < 0.0)
    fluid.fail("gravity", "is the magnitude of g (acting along -y): must not be negative");
  fluid.rejectUnknown();

  SceneTable p = top.sub("packing");
  PackingParameters& q = s.parameters;
  s.dx = p.positive("dx");
  s.latticeOrigin = p.point("lattice_origin", Vec2::Zero());
  const std::string kernel = p.string("kernel", "wendland_c2");
  if (kernel == "wendland_c2")
    q.kernel = KernelKind::wendland_c2;
  else if (kernel == "cubic_spline")
    q.kernel = KernelKind::cubic_spline;
  else if (kernel == "quadratic")
    q.kernel = KernelKind::quadratic;
  else
    p.fail("kernel",
           "unknown kernel '" + kernel + "' (expected wendland_c2, cubic_spline or quadratic)");
  q.hOverDx = p.positive("h_over_dx", 2.0);
  q.alpha = p.number("alpha", 2e-3);
  if (q.alpha < 0.0) p.fail("alpha", "must not be negative (0: no damping, energy conserved)");
  q.cfl = p.positive("cfl", 1.0);
  if (q.cfl > 2.0)
    p.fail("cfl", "above 2 leapfrog is unstable for any oscillation it resolves; the paper uses 1");
  const double maxIt = p.positive("max_iterations", 10000);
  if (maxIt != std::floor(maxIt) || maxIt > 1e8)
    p.fail("max_iterations", "must be a whole number up to 1e8");
  q.maxIterations = static_cast<int>(maxIt);
  q.stopKineticEnergy = p.positive("stop_kinetic_energy", 1e-8);
  // beta = 2 p0 / rho0 (eq. 2.14) only sets the time unit: dt ~ 1/sqrt(beta) and zeta ~ sqrt(beta)
  // (eqs. 2.15, 2.17), so the iterates are the same for any beta. Default: beta = c0^2.
  const double packingPressure =
      p.positive("pressure", 0.5 * s.phase.rho0 * s.phase.c0 * s.phase.c0);
  q.beta = 2.0 * packingPressure / s.phase.rho0;
  p.rejectUnknown();

  SceneTable output = top.sub("output");
  const double every = output.positive("history_every", 1);
  if (every != std::floor(every)) output.fail("history_every", "must be a whole number");
  s.historyEvery = static_cast<int>(every);
  output.rejectUnknown();
  top.rejectUnknown();

  if (s.lengthScale == 0.0) {
    Region closed(s.container);
    Vec2 lo, hi;
    closed.bounds(lo, hi);
    s.lengthScale = (s.hasSurface ? std::min(s.surface, hi.y()) : hi.y()) - lo.y();
    if (!(s.lengthScale > 0.0))
      throw SceneError(file + ": key 'geometry.surface': lies below the container");
  }
  try {
    setUp(s);  // the geometry must give a region and particles
  } catch (const std::invalid_argument& e) {
    throw SceneError(file + ": key 'geometry': " + e.what());
  }
  return s;
}

PackingScene readPackingScene(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw SceneError(path + ": cannot open the scene file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parsePackingScene(ss.str(), path);
}

PackingSetup setUp(const PackingScene& s) {
  PackingSetup setup;
  setup.region = s.hasSurface ? belowSurface(s.container, s.surface) : Region(s.container);
  setup.fluid = latticeInside(setup.region, s.dx, s.latticeOrigin);
  if (setup.fluid.size() < 4)
    throw std::invalid_argument("the fluid region holds " + std::to_string(setup.fluid.size()) +
                                " lattice nodes at this dx; it needs at least 4");
  setup.V0 = setup.region.area() / static_cast<double>(setup.fluid.size());  // section 2
  // Solid layers to the kernel support lambda h (lambda = 2 for every kernel here).
  const int layers = static_cast<int>(std::ceil(2.0 * s.parameters.hOverDx - 1e-9));
  setup.solid = solidLayers(setup.region, s.dx, layers);
  setup.lengthScale = s.lengthScale;
  return setup;
}

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
      if (r.iteration % s.historyEvery != 0 && r.kinetic >= s.parameters.stopKineticEnergy) return;
      columns[0].values.push_back(r.iteration);
      columns[1].values.push_back(r.kinetic);
      columns[2].values.push_back(r.kineticMean);
      columns[3].values.push_back(r.potential - V0);
      columns[4].values.push_back(H * r.maxGradGamma);
      if (!options.quiet && r.iteration % 500 == 0)
        std::cerr << "iteration " << r.iteration << ": T/beta = " << r.kinetic
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
                << " iterations, T/beta = " << last.kinetic << ", H max|grad Gamma| " << gStart
                << " -> " << gEnd << " (" << wall << " s)\n";
    if (!(stopped && finite))
      std::cerr << "error: the packing "
                << (finite ? "did not reach" : "produced a non-finite value before") << " T/beta < "
                << s.parameters.stopKineticEnergy << " within " << s.parameters.maxIterations
                << " iterations\n";
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
