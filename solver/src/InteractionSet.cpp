#include "sph/InteractionSet.hpp"

#include <omp.h>

#include "sph/EquationOfState.hpp"
#include "sph/Parallel.hpp"

namespace sph {

template <int D>
void buildInteractionSet(const Particles<D>& fluid, const std::vector<Phase>& phases,
                         const Boundaries<D>& bounds, double reach, const Vec<D>& ghostGravity,
                         InteractionSet<D>& set) {
  const std::size_t n = fluid.size();
  set.resize(n);  // the fluid entries; the halo is appended below
  set.nFluid = n;
  const std::int64_t count = static_cast<std::int64_t>(n);
#pragma omp parallel for if (count >= parallelFrom())
  for (std::int64_t i = 0; i < count; ++i) {
    set.x[i] = fluid.r[i], set.v[i] = fluid.v[i], set.rho[i] = fluid.rho[i];
    set.m[i] = fluid.m[i], set.h[i] = fluid.h[i];
    const Phase& ph = phases[fluid.phase[i]];
    set.p[i] = TaitEquationOfState::pressure(fluid.rho[i], ph);
    set.mu[i] = ph.mu;
    set.source[i] = static_cast<int>(i);
  }
  // Per axis: the entries within reach of a face, found in parallel (each thread a contiguous
  // share, listed in thread order: the serial order), then their images written after the
  // entries so far, each thread's at its list's offset.
  const int threads = omp_get_max_threads();
  if (static_cast<int>(set.nearFace.size()) < threads) set.nearFace.resize(threads);
  for (int a = 0; a < D; ++a) {
    const double lo = bounds.lower[a], hi = bounds.upper[a], period = hi - lo;
    const std::int64_t scanned = static_cast<std::int64_t>(set.size());
#pragma omp parallel if (scanned >= parallelFrom())
    {
      const int t = omp_get_thread_num(), nt = omp_get_num_threads();
      auto& mine = set.nearFace[t];
      mine.clear();
      for (std::int64_t k = scanned * t / nt; k < scanned * (t + 1) / nt; ++k)
        for (int side = 0; side < 2; ++side) {
          if (bounds.face[a][side] == FaceKind::open) continue;
          const double xa = set.x[k][a];
          if ((side == 0 ? xa - lo : hi - xa) < reach) mine.push_back(2 * k + side);
        }
#pragma omp barrier
#pragma omp single
      {
        std::size_t total = static_cast<std::size_t>(scanned);
        for (int u = 0; u < nt; ++u) total += set.nearFace[u].size();
        set.resize(total);
      }
      std::size_t g = static_cast<std::size_t>(scanned);  // this thread's first image
      for (int u = 0; u < t; ++u) g += set.nearFace[u].size();
      for (const std::int64_t code : mine) {
        const std::size_t k = static_cast<std::size_t>(code / 2);
        const int side = static_cast<int>(code % 2);
        const FaceKind kind = bounds.face[a][side];
        const double xa = set.x[k][a];
        Vec<D> xg = set.x[k], vg = set.v[k];
        double pg = set.p[k];
        if (kind == FaceKind::periodic) {
          xg[a] += side == 0 ? period : -period;
        } else {
          pg += set.rho[k] * ghostGravity[a] * (2.0 * (side == 0 ? lo : hi) - 2.0 * xa);
          const double wall = side == 0 ? lo : hi;
          const Vec<D>& vw = bounds.wallVelocity[a][side];
          xg[a] = 2.0 * wall - xa;
          if (kind == FaceKind::no_slip) {
            vg = 2.0 * vw - vg;
          } else {
            vg[a] = 2.0 * vw[a] - vg[a];
          }
        }
        set.x[g] = xg, set.v[g] = vg, set.p[g] = pg;
        set.rho[g] = set.rho[k], set.m[g] = set.m[k], set.h[g] = set.h[k], set.mu[g] = set.mu[k];
        set.source[g] = set.source[k];
        ++g;
      }
    }
  }
}

template void buildInteractionSet<1>(const Particles<1>&, const std::vector<Phase>&,
                                     const Boundaries<1>&, double, const Vec<1>&,
                                     InteractionSet<1>&);
template void buildInteractionSet<2>(const Particles<2>&, const std::vector<Phase>&,
                                     const Boundaries<2>&, double, const Vec<2>&,
                                     InteractionSet<2>&);
template void buildInteractionSet<3>(const Particles<3>&, const std::vector<Phase>&,
                                     const Boundaries<3>&, double, const Vec<3>&,
                                     InteractionSet<3>&);

}  // namespace sph
