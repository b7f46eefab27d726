#include "sph/InteractionSet.hpp"

#include <omp.h>

#include <algorithm>
#include <stdexcept>

#include "sph/EquationOfState.hpp"
#include "sph/Parallel.hpp"

namespace sph {

template <int D>
void buildInteractionSet(const Particles<D>& fluid, const std::vector<Phase>& phases,
                         const Boundaries<D>& bounds, double reach, const Vec<D>& ghostGravity,
                         InteractionSet<D>& set, HaloMembers members) {
  const std::size_t n = fluid.size();
  const std::int64_t count = static_cast<std::int64_t>(n);
  const bool same = members == HaloMembers::same;
  if (same && set.nFluid != n) throw std::logic_error("buildInteractionSet: the fluid changed");
  if (!same) set.resize(n);  // the fluid entries; the halo is appended below
  set.nFluid = n;
  // One team for the fluid copy and every axis's halo (a team costs 0.6 us or more to
  // gather on the 2-core machine; the whole set about 10 us at 1,700 entries on one thread). Each
  // thread copies a contiguous share of the fluid and, per axis, lists the entries within reach of
  // a face in its share of the entries so far; the images are then written after those entries,
  // each thread's at its list's offset, so the order is the serial one whatever the thread count.
  const int threads = count >= parallelFrom() ? omp_get_max_threads() : 1;
  if (static_cast<int>(set.nearFace.size()) < threads) set.nearFace.resize(threads);
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    const int t = omp_get_thread_num(), nt = omp_get_num_threads();
    {
      // Through pointers held in registers: a store through an Eigen vector may alias anything,
      // so the vectors' own data pointers would be loaded again after each (13.0 against 14.3 us
      // for the dam break's set at 1,250 particles, one thread, best of 5,000).
      const Vec<D>* r = fluid.r.data();
      const Vec<D>* v = fluid.v.data();
      const double *rho = fluid.rho.data(), *m = fluid.m.data(), *h = fluid.h.data();
      const int* phase = fluid.phase.data();
      const Phase* ph = phases.data();
      Vec<D>* X = set.x.data();
      Vec<D>* V = set.v.data();
      double *Rho = set.rho.data(), *M = set.m.data(), *H = set.h.data(), *P = set.p.data(),
             *Mu = set.mu.data();
      int* source = set.source.data();
      walk(shareOf(count, t, nt), [=](std::int64_t i) {
        X[i] = r[i], V[i] = v[i], Rho[i] = rho[i], M[i] = m[i], H[i] = h[i];
        P[i] = TaitEquationOfState::pressure(rho[i], ph[phase[i]]);
        Mu[i] = ph[phase[i]].mu;
        source[i] = static_cast<int>(i);
      });
    }
    auto& mine = set.nearFace[t].entries;
    for (int a = 0; a < D; ++a) {
      const double lo = bounds.lower[a], hi = bounds.upper[a], period = hi - lo;
      const bool lower = bounds.face[a][0] != FaceKind::open;
      const bool upper = bounds.face[a][1] != FaceKind::open;
      // Axis 0 scans (or, with the last build's codes, images) the fluid, each thread the share
      // it copied: no barrier before it.
      if (a > 0) {
#pragma omp barrier
      }
      // The entries before this axis's images: the fluid and the earlier axes' halo. Thread t
      // takes the fluid it copied, the last thread also the earlier axes' halo (images of images
      // at the box's edges and corners, few): the codes stay in ascending order, and a thread
      // images the entries it wrote. (Half of all the entries so far had thread 0 image the floor's
      // ghosts of some of thread 1's fluid, which thread 1's pair loop then reads.)
      std::size_t scanned = n;
      for (int b = 0; b < a; ++b) scanned += set.halo[b].size();
      const auto [from, to] = shareOf(static_cast<std::int64_t>(scanned), count, t, nt);
      // Codes 2 k + side: entry k's image across the lower (0) or upper (1) face of axis a.
      std::vector<std::int64_t>& codes = set.halo[a];
      const std::int64_t* first;  // this thread's codes, and its first image
      std::size_t g, many;
      if (same) {
        // The last build's codes (ascending in k), split as a rescan splits them: a thread takes
        // the images of its share of the entries so far, whose records it wrote, so that no
        // record crosses to the other core (an equal share of the codes gave one thread the
        // images of the other's entries: the floor's, when the rows are the sorted order's).
        auto split = [&](std::int64_t k) {
          return static_cast<std::size_t>(std::lower_bound(codes.begin(), codes.end(), 2 * k) -
                                          codes.begin());
        };
        const std::size_t begin = split(from), end = t + 1 < nt ? split(to) : codes.size();
        first = codes.data() + begin, many = end - begin;
        g = scanned + begin;
      } else {
        mine.clear();
        const Vec<D>* x = set.x.data();
        for (std::int64_t k = from; k < to; ++k) {
          const double xa = x[k][a];
          if (lower && xa - lo < reach) mine.push_back(2 * k);
          if (upper && hi - xa < reach) mine.push_back(2 * k + 1);
        }
#pragma omp barrier
#pragma omp single
        {
          std::size_t total = scanned;
          for (int u = 0; u < nt; ++u) total += set.nearFace[u].entries.size();
          set.resize(total);
          codes.resize(total - scanned);
        }
        g = scanned;
        for (int u = 0; u < t; ++u) g += set.nearFace[u].entries.size();
        std::copy(mine.begin(), mine.end(), codes.begin() + (g - scanned));
        first = mine.data(), many = mine.size();
      }
      Vec<D>* X = set.x.data();
      Vec<D>* V = set.v.data();
      double *rho = set.rho.data(), *p = set.p.data(), *m = set.m.data(), *h = set.h.data(),
             *mu = set.mu.data();
      int* source = set.source.data();
      // The images in this thread's run of the halo (its last ones walked down: see walk()).
      walk(Share{0, static_cast<std::int64_t>(many)}, [&](std::int64_t c) {
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
        p[i] = periodic ? p[k] : p[k] + rho[k] * ghostGravity[a] * (2.0 * wall - 2.0 * xa);
        rho[i] = rho[k], m[i] = m[k], h[i] = h[k], mu[i] = mu[k], source[i] = source[k];
      });
    }
  }
}

template void buildInteractionSet<1>(const Particles<1>&, const std::vector<Phase>&,
                                     const Boundaries<1>&, double, const Vec<1>&,
                                     InteractionSet<1>&, HaloMembers);
template void buildInteractionSet<2>(const Particles<2>&, const std::vector<Phase>&,
                                     const Boundaries<2>&, double, const Vec<2>&,
                                     InteractionSet<2>&, HaloMembers);
template void buildInteractionSet<3>(const Particles<3>&, const std::vector<Phase>&,
                                     const Boundaries<3>&, double, const Vec<3>&,
                                     InteractionSet<3>&, HaloMembers);

}  // namespace sph
