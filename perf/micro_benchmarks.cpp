// Issue 7 micro-benchmarks (Google Benchmark): the neighbour search, each term combination of the
// menu alone, and the whole force evaluation from 1e3 to 1e6 particles at 1 and 2 threads, on the
// 2-D perturbed-lattice block of Workload.hpp. items_per_second is fluid particles evaluated per
// second; the counter ns_per_particle is its inverse.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <map>
#include <memory>
#include <string>

#include "CoreRoundTrip.hpp"
#include "Workload.hpp"

namespace {

using sph::perf::Block2D;

// Blocks are built once per size and shared by the benchmarks (building 1e6 takes a while).
Block2D& block(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<Block2D>> cache;
  auto& b = cache[n];
  if (!b) b = std::make_unique<Block2D>(sph::perf::makeBlock(n));
  return *b;
}

void setCounters(benchmark::State& state, std::size_t particles) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * particles));
  state.counters["ns_per_particle"] = benchmark::Counter(
      1e-9 * static_cast<double>(particles),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Neighbour search: the cell list build over fluid and ghosts.
void BM_CellListBuild(benchmark::State& state) {
  Block2D& b = block(static_cast<std::size_t>(state.range(0)));
  sph::CellList<2> cells;
  for (auto _ : state) {
    cells.build(b.set.x, 2.0 * b.hMax);
    benchmark::DoNotOptimize(cells.order().data());
  }
  setCounters(state, b.set.size());
}
BENCHMARK(BM_CellListBuild)
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMicrosecond);

// One term combination alone (quadratic kernel, 1 thread, 2e4 particles): range(0) is the menu
// entry of sph_bench's table (Workload.hpp: menuEntry); range(1) 1: with the neighbour lists of a
// build with the scenes' default skin reused, as most of a run's evaluations are (below), else
// built at each evaluation. Every entry with lists built; the paper's terms with each density
// diffusion form (entries 7 + 8 x form: none, Molteni & Colagrossi, Fourtakas et al., theirs
// within each phase, Antuono et al. with its gradient pass) with lists kept too.
void BM_Terms(benchmark::State& state) {
  const sph::TermSwitches terms = sph::perf::menuEntry(static_cast<int>(state.range(0)));
  Block2D& b = block(20000);
  sph::ForceEvaluation<2> force(sph::KernelKind::quadratic, terms, sph::perf::termParameters(b));
  omp_set_num_threads(1);
  const bool keep = state.range(1) != 0;
  const sph::NeighbourLists build{keep ? 0.1 * 2.0 * b.hMax : 0.0, false}, kept{build.skin, keep};
  force(b.set, b.out, sph::Vec<2>::Zero(), build);
  for (auto _ : state) {
    force(b.set, b.out, sph::Vec<2>::Zero(), kept);
    benchmark::DoNotOptimize(b.out.drhodt.data());
  }
  std::string label;
  for (const auto& n : force.termNames()) label += (label.empty() ? "" : "+") + n;
  if (terms.concentrationGradient) label += (label.empty() ? "" : "+") + std::string("shifting");
  state.SetLabel(label);
  setCounters(state, b.set.nFluid);
}
BENCHMARK(BM_Terms)
    ->Apply([](benchmark::internal::Benchmark* b) {
      for (int t = 0; t < static_cast<int>(sph::terms::menuSize); ++t) b->Args({t, 0});
      for (int form = 0; form <= sph::terms::DensityDiffusionForms::size; ++form)
        b->Args({7 + 8 * form, 1});
    })
    ->Unit(benchmark::kMicrosecond);

// Each kernel with every term (the dam break's menu entry), 1 thread, 2e4 particles.
void BM_Kernels(benchmark::State& state) {
  const auto kind = static_cast<sph::KernelKind>(state.range(0));
  Block2D& b = block(20000);
  sph::ForceEvaluation<2> force(kind, {true, true, true}, 1.0);
  omp_set_num_threads(1);
  for (auto _ : state) {
    force(b.set, b.out);
    benchmark::DoNotOptimize(b.out.drhodt.data());
  }
  state.SetLabel(std::string(sph::name(kind)));
  setCounters(state, b.set.nFluid);
}
BENCHMARK(BM_Kernels)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

// The whole force evaluation (quadratic kernel, all terms): range(0) particles, range(1) threads.
void BM_ForceEvaluation(benchmark::State& state) {
  Block2D& b = block(static_cast<std::size_t>(state.range(0)));
  sph::ForceEvaluation<2> force(sph::KernelKind::quadratic, {true, true, true}, 1.0);
  omp_set_num_threads(static_cast<int>(state.range(1)));
  for (auto _ : state) {
    force(b.set, b.out);
    benchmark::DoNotOptimize(b.out.drhodt.data());
  }
  setCounters(state, b.set.nFluid);
}
BENCHMARK(BM_ForceEvaluation)
    ->ArgsProduct({{1000, 10000, 100000, 1000000}, {1, 2}})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

// The same with the neighbour lists of a build with the scenes' default skin (0.1 of the support)
// reused, as most of a run's evaluations are (Simulation::keepNeighbourLists).
void BM_ForceEvaluationKeptLists(benchmark::State& state) {
  Block2D& b = block(static_cast<std::size_t>(state.range(0)));
  sph::ForceEvaluation<2> force(sph::KernelKind::quadratic, {true, true, true}, 1.0);
  omp_set_num_threads(static_cast<int>(state.range(1)));
  const sph::NeighbourLists build{0.1 * 2.0 * b.hMax, false}, kept{build.skin, true};
  force(b.set, b.out, sph::Vec<2>::Zero(), build);
  for (auto _ : state) {
    force(b.set, b.out, sph::Vec<2>::Zero(), kept);
    benchmark::DoNotOptimize(b.out.drhodt.data());
  }
  setCounters(state, b.set.nFluid);
}
BENCHMARK(BM_ForceEvaluationKeptLists)
    ->ArgsProduct({{1000, 10000, 100000, 1000000}, {1, 2}})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

}  // namespace

// Google Benchmark's main, with the core-to-core round trip at the start in the output's context
// (CoreRoundTrip.hpp: the 2-thread figures depend on it).
int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("core_round_trip_ns",
                              std::to_string(static_cast<int>(sph::perf::coreRoundTrip() + 0.5)));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
