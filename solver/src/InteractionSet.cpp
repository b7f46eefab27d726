#include "sph/InteractionSet.hpp"

#include <omp.h>

#include <algorithm>
#include <stdexcept>

#include "sph/EquationOfState.hpp"
#include "sph/Parallel.hpp"

namespace sph {

template <int D>
void buildInteractionSet(const SetFluid<D>& fluid, const std::vector<Phase>& phases,
                         const Boundaries<D>& bounds, double reach,
                         const std::type_identity_t<GhostPressure<D>>& ghost,
                         InteractionSet<D>& set, HaloMembers members) {
  const std::size_t n = fluid.size();
  const std::int64_t count = static_cast<std::int64_t>(n);
  const bool same = members == HaloMembers::same;
  if (same && set.nFluid != n) throw std::logic_error("buildInteractionSet: the fluid changed");
  if (!same) {
    set.resize(n);  // the fluid entries; the halo is appended below
    set.ownedParticle.resize(fluid.halo ? n : 0);
    set.nOwned = fluid.owned.size();
  }
  set.nFluid = n;
  // One team for the fluid copy and every axis's halo (a team costs 0.6 us or more to
  // gather on the 2-core machine; the whole set about 10 us at 1,700 entries on one thread). Each
  // thread copies a contiguous share of the fluid and, per axis, lists the entries within reach of
  // a face among the entries it wrote (its runs, below); the images are then written after all
  // the entries so far, each run's at its offset, so the order is the serial one whatever the
  // thread count.
  const int threads = count >= parallelFrom() ? omp_get_max_threads() : 1;
  if (static_cast<int>(set.nearFace.size()) < threads) set.nearFace.resize(threads);
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    const int t = omp_get_thread_num(), nt = omp_get_num_threads();
    {
      // Through pointers held in registers: a store through an Eigen vector may alias anything,
      // so the vectors' own data pointers would be loaded again after each (13.0 against 14.3 us
      // for the dam break's set at 1,250 particles, one thread, best of 5,000).
      struct Fields {
        const Vec<D>*r, *v;
        const double *rho, *m, *h;
        const int* phase;
      };
      auto fieldsOf = [](const Particles<D>& p) {
        return Fields{p.r.data(), p.v.data(), p.rho.data(), p.m.data(), p.h.data(), p.phase.data()};
      };
      const Fields own = fieldsOf(fluid.owned);
      const Fields received = fluid.halo ? fieldsOf(*fluid.halo) : own;
      const Phase* ph = phases.data();
      Vec<D>* X = set.x.data();
      Vec<D>* V = set.v.data();
      double *Rho = set.rho.data(), *M = set.m.data(), *H = set.h.data(), *P = set.p.data(),
             *Mu = set.mu.data(), *Rho0 = set.rho0.data();
      int *PhaseOf = set.phase.data(), *source = set.source.data();
      const auto copy = [=](const Fields& f, std::int64_t s, std::int64_t i) {
        X[i] = f.r[s], V[i] = f.v[s], Rho[i] = f.rho[s], M[i] = f.m[s], H[i] = f.h[s];
        P[i] = TaitEquationOfState::pressure(f.rho[s], ph[f.phase[s]]);
        Mu[i] = ph[f.phase[s]].mu, Rho0[i] = ph[f.phase[s]].rho0, PhaseOf[i] = f.phase[s];
        source[i] = static_cast<int>(i);
      };
      if (!fluid.halo) {
        walk(shareOf(count, t, nt), [=](std::int64_t i) { copy(own, i, i); });
      } else {
        const int* from = fluid.from;
        int* ownedParticle = same ? nullptr : set.ownedParticle.data();
        walk(shareOf(count, t, nt), [=](std::int64_t i) {
          const int f = from[i];
          if (f >= 0)
            copy(own, f, i);
          else
            copy(received, -1 - f, i);
          if (ownedParticle) ownedParticle[i] = std::max(f, -1);
        });
      }
    }
    auto& near = set.nearFace[t];
    auto& mine = near.entries;
    // The runs of entries this thread wrote, in ascending order: its share of the fluid, then,
    // after each axis, the images it wrote of each run before. The images across the next axis of
    // those entries are its too: an entry's record does not cross to the other core to be imaged.
    // (Were the earlier axes' halo imaged by the last thread, thread 1 would image, across the
    // floor, thread 0's images of the walls at the two bottom corners, at every evaluation.)
    std::array<Share, 8> runs{};
    static_assert(D <= 3, "runs: 2^D at most");
    int nRuns = 1;
    runs[0] = shareOf(count, t, nt);
    for (int a = 0; a < D; ++a) {
      const double lo = bounds.lower[a], hi = bounds.upper[a], period = hi - lo;
      const bool lower = bounds.face[a][0] != FaceKind::open;
      const bool upper = bounds.face[a][1] != FaceKind::open;
      // Axis 0 scans (or, with the last build's codes, images) the fluid, each thread the share
      // it copied: no barrier before it.
      if (a > 0) {
#pragma omp barrier
      }
      // The entries before this axis's images: the fluid and the earlier axes' halo.
      std::size_t scanned = n;
      for (int b = 0; b < a; ++b) scanned += set.halo[b].size();
      // Codes 2 k + side: entry k's image across the lower (0) or upper (1) face of axis a,
      // ascending in k. The images of a run of entries follow those of the runs before it, all
      // threads' runs taken together in entry order: the order is the serial one whatever the
      // thread count. `block[r]`: where run r's images begin in the halo of this axis, and how
      // many; `from[r]`: their codes.
      std::vector<std::int64_t>& codes = set.halo[a];
      std::array<Share, 8> block{};
      std::array<const std::int64_t*, 8> from{};
      if (same) {
        // The last build's codes, split at the runs' ends.
        auto split = [&](std::int64_t k) {
          return static_cast<std::int64_t>(std::lower_bound(codes.begin(), codes.end(), 2 * k) -
                                           codes.begin());
        };
        for (int r = 0; r < nRuns; ++r) {
          block[r] = {split(runs[r].begin), split(runs[r].end)};
          from[r] = codes.data() + block[r].begin;
        }
      } else {
        mine.clear();
        const Vec<D>* x = set.x.data();
        near.runs = nRuns;
        for (int r = 0; r < nRuns; ++r) {
          const std::size_t before = mine.size();
          for (std::int64_t k = runs[r].begin; k < runs[r].end; ++k) {
            const double xa = x[k][a];
            if (lower && xa - lo < reach) mine.push_back(2 * k);
            if (upper && hi - xa < reach) mine.push_back(2 * k + 1);
          }
          near.runBegin[r] = runs[r].begin;
          near.runCount[r] = static_cast<std::int64_t>(mine.size() - before);
        }
#pragma omp barrier
#pragma omp single
        {
          std::size_t total = scanned;
          for (int u = 0; u < nt; ++u) total += set.nearFace[u].entries.size();
          set.resize(total);
          codes.resize(total - scanned);
        }
        std::size_t listed = 0;
        for (int r = 0; r < nRuns; ++r) {
          // Every thread's images of the entries before this run come first.
          std::int64_t offset = 0;
          for (int u = 0; u < nt; ++u) {
            const auto& other = set.nearFace[u];
            for (int q = 0; q < other.runs; ++q)
              if (other.runBegin[q] < runs[r].begin) offset += other.runCount[q];
          }
          block[r] = {offset, offset + near.runCount[r]};
          from[r] = mine.data() + listed;
          std::copy(from[r], from[r] + near.runCount[r], codes.begin() + offset);
          listed += static_cast<std::size_t>(near.runCount[r]);
        }
      }
      Vec<D>* X = set.x.data();
      Vec<D>* V = set.v.data();
      double *rho = set.rho.data(), *p = set.p.data(), *m = set.m.data(), *h = set.h.data(),
             *mu = set.mu.data(), *rho0 = set.rho0.data();
      int *phase = set.phase.data(), *source = set.source.data();
      // The images of each run (its last ones walked down: see walk()); a run's images are a run
      // of this thread's for the next axis.
      const int sourceRuns = nRuns;
      for (int r = 0; r < sourceRuns; ++r) {
        const std::size_t g = scanned + static_cast<std::size_t>(block[r].begin);
        const std::int64_t* first = from[r];
        if (block[r].end > block[r].begin)
          runs[nRuns++] = {static_cast<std::int64_t>(g),
                           static_cast<std::int64_t>(scanned) + block[r].end};
        walk(Share{0, block[r].end - block[r].begin}, [&](std::int64_t c) {
          const std::size_t i = g + static_cast<std::size_t>(c);  // the image's entry
          const std::int64_t code = first[c];
          const std::size_t k = static_cast<std::size_t>(code / 2);
          const int side = static_cast<int>(code % 2);
          const FaceKind kind = bounds.face[a][side];
          const bool periodic = kind == FaceKind::periodic, noSlip = kind == FaceKind::no_slip;
          const double wall = side == 0 ? lo : hi, shift = side == 0 ? period : -period;
          const Vec<D>& vw = bounds.wallVelocity[a][side];
          // Component by component: a vector built on the stack and changed in one component
          // was read back before its store had landed, a stall a ghost (the dam break's set at
          // 1,250 particles, one thread, best of 5,000: 13.0 -> 10.0 us).
          for (int b = 0; b < D; ++b) {
            const double xb = X[k][b], vb = V[k][b];
            if (b == a) {
              X[i][b] = periodic ? xb + shift : 2.0 * wall - xb;
              V[i][b] = periodic ? vb : 2.0 * vw[b] - vb;
            } else {
              X[i][b] = xb;
              V[i][b] = noSlip ? 2.0 * vw[b] - vb : vb;
            }
          }
          const double xa = X[k][a];
          p[i] = periodic ? p[k]
                          : std::max(p[k] + rho[k] * ghost.gravity[a] * (2.0 * wall - 2.0 * xa),
                                     ghost.floor);  // NaN stays NaN
          rho[i] = rho[k], m[i] = m[k], h[i] = h[k], mu[i] = mu[k], rho0[i] = rho0[k];
          phase[i] = phase[k], source[i] = source[k];
        });
      }
    }
  }
}

template void buildInteractionSet<1>(const SetFluid<1>&, const std::vector<Phase>&,
                                     const Boundaries<1>&, double, const GhostPressure<1>&,
                                     InteractionSet<1>&, HaloMembers);
template void buildInteractionSet<2>(const SetFluid<2>&, const std::vector<Phase>&,
                                     const Boundaries<2>&, double, const GhostPressure<2>&,
                                     InteractionSet<2>&, HaloMembers);
template void buildInteractionSet<3>(const SetFluid<3>&, const std::vector<Phase>&,
                                     const Boundaries<3>&, double, const GhostPressure<3>&,
                                     InteractionSet<3>&, HaloMembers);

}  // namespace sph
