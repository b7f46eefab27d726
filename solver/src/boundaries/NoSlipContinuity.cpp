#include "sph/boundaries/NoSlipContinuity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sph/Parallel.hpp"

namespace sph {

template <int D>
void noSlipGhostContinuity(const InteractionSet<D>& set, const Boundaries<D>& bounds,
                           KernelKind kernel, bool byVolume, bool variableH, Derivatives<D>& out) {
  const std::size_t nFluid = set.nFluid, end = set.haloEnd();
  // Each halo entry's free-slip velocity, built as buildInteractionSet builds the halo: axis by
  // axis, the images of the entries before them (InteractionSet::halo); a fluid entry's is its own.
  std::vector<Vec<D>> free(end - nFluid);
  auto freeOf = [&](std::size_t k) -> const Vec<D>& {
    return k < nFluid ? set.v[k] : free[k - nFluid];
  };
  std::size_t at = nFluid;
  for (int a = 0; a < D; ++a)
    for (const std::int64_t code : set.halo[a]) {
      const std::size_t k = static_cast<std::size_t>(code / 2);
      const int side = static_cast<int>(code % 2);
      Vec<D> v = freeOf(k);
      if (Boundaries<D>::isWall(bounds.face[a][side]))
        v[a] = 2.0 * bounds.wallVelocity[a][side][a] - v[a];
      free[at++ - nFluid] = v;
    }
  // The ghosts whose two velocities differ, with v_g - v_g^free, by cell (of side the largest
  // support, 2 h_max).
  struct Ghost {
    std::int64_t key;
    std::size_t entry;
    Vec<D> jump;
  };
  std::vector<Ghost> ghosts;
  double hMax = 0;
  for (std::size_t g = nFluid; g < end; ++g)
    if (set.v[g] != free[g - nFluid]) ghosts.push_back({0, g, set.v[g] - free[g - nFluid]});
  if (ghosts.empty()) return;
  for (std::size_t i = 0; i < end; ++i) hMax = std::max(hMax, set.h[i]);
  const double cell = 2.0 * hMax;
  Vec<D> origin;
  for (int a = 0; a < D; ++a) origin[a] = bounds.lower[a] - 4.0 * cell;  // below every ghost
  constexpr std::int64_t span = std::int64_t{1} << 20;  // cells an axis: keys of D x 20 bits
  auto cellOf = [&](const Vec<D>& x, int a) {
    return static_cast<std::int64_t>(std::floor((x[a] - origin[a]) / cell));
  };
  auto keyOf = [&](const std::array<std::int64_t, D>& c) {
    std::int64_t key = 0;
    for (int a = D - 1; a >= 0; --a) key = key * span + c[a];
    return key;
  };
  for (Ghost& q : ghosts) {
    std::array<std::int64_t, D> c;
    for (int a = 0; a < D; ++a) c[a] = cellOf(set.x[q.entry], a);
    q.key = keyOf(c);
  }
  // (by entry within a cell: each particle's sum in one order whatever the threads)
  std::sort(ghosts.begin(), ghosts.end(), [](const Ghost& p, const Ghost& q) {
    return p.key != q.key ? p.key < q.key : p.entry < q.entry;
  });
  // Only a particle within 2 h_max of a no-slip face has such a ghost in reach.
  auto nearNoSlip = [&](const Vec<D>& x) {
    for (int a = 0; a < D; ++a)
      for (int side = 0; side < 2; ++side)
        if (bounds.face[a][side] == FaceKind::no_slip &&
            std::abs(x[a] - (side == 0 ? bounds.lower[a] : bounds.upper[a])) < cell)
          return true;
    return false;
  };
  const bool owned = !set.ownedParticle.empty();
  forEachInShares(static_cast<std::int64_t>(nFluid), [&](std::int64_t i) {
    const int to = owned ? set.ownedParticle[i] : static_cast<int>(i);
    if (to < 0 || !nearNoSlip(set.x[i])) return;
    std::array<std::int64_t, D> c0, c;
    for (int a = 0; a < D; ++a) c0[a] = cellOf(set.x[i], a);
    double sum = 0, divergence = 0;  // the density's and h's (eq. 13: V_g in place of m_g)
    for (int n = 0; n < static_cast<int>(std::pow(3, D)); ++n) {
      for (int a = 0, m = n; a < D; ++a, m /= 3) c[a] = c0[a] + m % 3 - 1;
      const std::int64_t key = keyOf(c);
      auto it = std::lower_bound(ghosts.begin(), ghosts.end(), key,
                                 [](const Ghost& q, std::int64_t k) { return q.key < k; });
      for (; it != ghosts.end() && it->key == key; ++it) {
        const std::size_t g = it->entry;
        const Vec<D> r = set.x[i] - set.x[g];
        const double h = 0.5 * (set.h[i] + set.h[g]), r2 = r.squaredNorm();
        if (!(r2 < 4.0 * h * h) || r2 == 0.0) continue;
        const double rr = std::sqrt(r2), F = kernelSlope<D>(kernel, rr, h) / rr;
        const double vGradW = it->jump.dot(r) * F, V = set.m[g] / set.rho[g];
        sum += (byVolume ? set.rho[i] * V : set.m[g]) * vGradW;
        divergence += V * vGradW;
      }
    }
    out.drhodt[to] += sum;
    if (variableH) out.dhdt[to] += set.h[i] / D * divergence;
  });
}

template void noSlipGhostContinuity<1>(const InteractionSet<1>&, const Boundaries<1>&, KernelKind,
                                       bool, bool, Derivatives<1>&);
template void noSlipGhostContinuity<2>(const InteractionSet<2>&, const Boundaries<2>&, KernelKind,
                                       bool, bool, Derivatives<2>&);
template void noSlipGhostContinuity<3>(const InteractionSet<3>&, const Boundaries<3>&, KernelKind,
                                       bool, bool, Derivatives<3>&);

}  // namespace sph
