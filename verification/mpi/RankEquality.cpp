// rank_equality SCENE STEPS [INTEGRATOR]: STEPS steps of SCENE (with [numerics] integrator =
// INTEGRATOR if given) over every rank of MPI_COMM_WORLD (slabs,
// sph/DomainDecomposition.hpp) and, on rank 0, in one process; exit 0 when the two final states
// are the same to the bit (every field of every particle, in the one process's storage order,
// and the particles' ids), 1 naming the first difference, 2 on bad arguments.
// SCENE is a scene file, or "channel": a periodic channel (Poiseuille flow between no-slip walls,
// periodic along its length, the cut axis) built here.
#include <mpi.h>

#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sph/DomainDecomposition.hpp"
#include "sph/Scene.hpp"
#include "sph/Simulation.hpp"

namespace {

using namespace sph;

std::string channel() {
  std::ostringstream s;
  s << "name = \"channel\"\ndimension = 2\n[domain]\nlower = [0.0, 0.0]\nupper = [0.3, 0.1]\n"
    << "x_lower = \"periodic\"\nx_upper = \"periodic\"\ny_lower = \"no_slip\"\n"
    << "y_upper = \"no_slip\"\n[[phase]]\nname = \"w\"\nrho0 = 1000.0\nc0 = 1.0\nmu = 1.0\n"
    << "p0 = 100.0\n[[fluid]]\nlower = [0.0, 0.0]\nupper = [0.3, 0.1]\n"
    << "[physics]\ngravity = [0.5, 0.0]\nartificial_viscosity = 0.0\nmorris_viscosity = true\n"
    << "variable_h = true\n[numerics]\ndx = 0.005\nend_time = 1.0\n";
  return s.str();
}

// The scene's text with its [numerics] integrator set.
std::string withIntegrator(std::string text, const std::string& integrator) {
  const std::string table = "\n[numerics]\n";
  const std::size_t at = text.find(table);
  if (at == std::string::npos) throw std::invalid_argument("the scene has no [numerics] table");
  return text.insert(at + table.size(), "integrator = \"" + integrator + "\"\n");
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("cannot read " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// One process's run of `steps` steps (keepCellOrder as sph run keeps it: Run.cpp).
constexpr int cellOrderSteps = 10;

template <int D>
int compare(const Scene& scene, long steps) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  Simulation<D> spread(scene);
  spread.keepCellOrder(cellOrderSteps);
  spread.distribute(slabDecomposition<D>(scene));
  std::string why;
  for (long s = 0; s < steps && why.empty(); ++s)
    if (auto f = spread.advance()) why = "the spread run failed: " + f->message;
  Particles<D> all;
  std::vector<int> ids;
  if (const auto* d = spread.decomposition())
    d->gather(spread.particles(), spread.ids(), spread.keys(), all, ids);
  else
    all = spread.particles(), ids = spread.ids();
  int code = why.empty() ? 0 : 1;
  if (rank == 0 && code == 0) {
    Simulation<D> one(scene);
    one.keepCellOrder(cellOrderSteps);
    for (long s = 0; s < steps && why.empty(); ++s)
      if (auto f = one.advance()) why = "the one-process run failed: " + f->message;
    const Particles<D>& p = one.particles();
    auto same = [](const auto& a, const auto& b) {
      return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
    };
    if (why.empty() && p.size() != all.size())
      why = std::to_string(all.size()) + " particles against " + std::to_string(p.size());
    else if (why.empty()) {
      const char* names[] = {"r", "v", "rho", "m", "h", "p", "phase", "ids"};
      const bool equal[] = {same(p.r, all.r),         same(p.v, all.v),    same(p.rho, all.rho),
                            same(p.m, all.m),         same(p.h, all.h),    same(p.p, all.p),
                            same(p.phase, all.phase), same(one.ids(), ids)};
      for (int k = 0; k < 8; ++k)
        if (!equal[k]) why += std::string(why.empty() ? "" : ", ") + names[k] + " differ";
      if (why.empty())
        std::cout << scene.name << ": " << steps << " steps (t = " << one.time() << " s, "
                  << one.forceEvaluations() << " evaluations, " << one.reusedNeighbourLists()
                  << " with kept lists), " << p.size() << " particles: the same to the bit\n";
    }
    code = why.empty() ? 0 : 1;
  }
  MPI_Bcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (!why.empty()) std::cerr << "rank " << rank << ": " << scene.name << ": " << why << "\n";
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int code = 2;
  if (argc != 3 && argc != 4) {
    std::cerr << "usage: rank_equality SCENE|channel STEPS [INTEGRATOR]\n";
  } else {
    try {
      const std::string which = argv[1];
      std::string text = which == "channel" ? channel() : readText(which);
      if (argc == 4) text = withIntegrator(text, argv[3]);
      const Scene scene = parseScene(text, which);
      const long steps = std::stol(argv[2]);
      code = scene.dimension == 2   ? compare<2>(scene, steps)
             : scene.dimension == 3 ? compare<3>(scene, steps)
                                    : compare<1>(scene, steps);
    } catch (const std::exception& e) {
      std::cerr << "rank_equality: " << e.what() << "\n";
      code = 2;
    }
  }
  MPI_Finalize();
  return code;
}
