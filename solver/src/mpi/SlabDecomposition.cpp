// Slabs across the scene's longest axis, one an MPI rank, of equal particle counts (the work of
// a particle is about the same everywhere in a weakly compressible flow: its neighbours are as
// many). Slabs, not boxes or a space-filling curve: a rank's halo is then one number along one
// axis from each other rank (its owned particles' extent), the cut is recounted from one
// histogram, and the halo of a slab across the longest axis is the shortest a slab can have.
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <numeric>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "sph/DomainDecomposition.hpp"
#include "sph/Scene.hpp"

namespace sph {

namespace {

// A particle's fields as doubles, for the messages: r, v, rho, m, h, p, phase, id, key (ids and
// keys below 2^53 are exact as doubles).
template <int D>
constexpr int fieldsPerParticle = 2 * D + 7;

template <int D>
void pack(const Particles<D>& s, std::size_t i, int id, std::int64_t key,
          std::vector<double>& out) {
  for (int a = 0; a < D; ++a) out.push_back(s.r[i][a]);
  for (int a = 0; a < D; ++a) out.push_back(s.v[i][a]);
  out.insert(out.end(),
             {s.rho[i], s.m[i], s.h[i], s.p[i], double(s.phase[i]), double(id), double(key)});
}

template <int D>
void unpack(const double* f, Particles<D>& s, std::size_t i, int& id, std::int64_t& key) {
  for (int a = 0; a < D; ++a) s.r[i][a] = f[a], s.v[i][a] = f[D + a];
  s.rho[i] = f[2 * D], s.m[i] = f[2 * D + 1], s.h[i] = f[2 * D + 2], s.p[i] = f[2 * D + 3];
  s.phase[i] = static_cast<int>(f[2 * D + 4]);
  id = static_cast<int>(f[2 * D + 5]), key = static_cast<std::int64_t>(f[2 * D + 6]);
}

// The particles received, in key order; each packed with `width` riders after its fields, which
// go to `riders` (particle k's at k * width).
template <int D>
void unpackSorted(const std::vector<double>& in, Particles<D>& s, std::vector<int>& ids,
                  std::vector<std::int64_t>& keys, std::vector<double>* riders = nullptr,
                  int width = 0) {
  constexpr int P = fieldsPerParticle<D>;
  const int F = P + width;
  const std::size_t n = in.size() / F;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  auto keyOf = [&](std::size_t k) { return in[k * F + P - 1]; };
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return keyOf(a) < keyOf(b); });
  s.resize(n), ids.resize(n), keys.resize(n);
  for (std::size_t k = 0; k < n; ++k) unpack(in.data() + order[k] * F, s, k, ids[k], keys[k]);
  if (!riders) return;
  riders->resize(n * width);
  for (std::size_t k = 0; k < n; ++k)
    std::copy_n(in.data() + order[k] * F + P, width, riders->data() + k * width);
}

template <int D>
class SlabDecomposition final : public DomainDecomposition<D> {
 public:
  explicit SlabDecomposition(const Scene& scene) {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
    axis_ = 0;
    for (int a = 1; a < D; ++a)
      if (scene.upper[a] - scene.lower[a] > scene.upper[axis_] - scene.lower[axis_]) axis_ = a;
    lo_ = scene.lower[axis_], period_ = scene.upper[axis_] - scene.lower[axis_];
    periodic_ = scene.faces[axis_][0] == FaceKind::periodic;
  }
  int rank() const override { return rank_; }
  int ranks() const override { return ranks_; }
  void maxAll(double* v, int n) const override {
    MPI_Allreduce(MPI_IN_PLACE, v, n, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  }
  void minAll(double* v, int n) const override {
    MPI_Allreduce(MPI_IN_PLACE, v, n, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  }
  std::int64_t sumAll(std::int64_t x) const override {
    MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
    return x;
  }
  void broadcast(std::string& s, int from) const override {
    std::int64_t n = static_cast<std::int64_t>(s.size());
    MPI_Bcast(&n, 1, MPI_INT64_T, from, MPI_COMM_WORLD);
    s.resize(static_cast<std::size_t>(n));
    MPI_Bcast(s.data(), static_cast<int>(n), MPI_CHAR, from, MPI_COMM_WORLD);
  }

  void keepOwn(Particles<D>& all, std::vector<int>& ids, std::vector<std::int64_t>& keys) override {
    cut(all);
    std::vector<std::size_t> mine;
    for (std::size_t i = 0; i < all.size(); ++i)
      if (owner(all.r[i][axis_]) == rank_) mine.push_back(i);
    Particles<D> own;
    own.resize(mine.size());
    std::vector<int> ownIds(mine.size());
    std::vector<std::int64_t> ownKeys(mine.size());
    for (std::size_t k = 0; k < mine.size(); ++k) {
      const std::size_t i = mine[k];
      own.r[k] = all.r[i], own.v[k] = all.v[i], own.rho[k] = all.rho[i], own.m[k] = all.m[i];
      own.h[k] = all.h[i], own.p[k] = all.p[i], own.phase[k] = all.phase[i];
      ownIds[k] = ids[i], ownKeys[k] = keys[i];
    }
    all = std::move(own), ids = std::move(ownIds), keys = std::move(ownKeys);
  }

  void migrate(Particles<D>& owned, std::vector<int>& ids, std::vector<std::int64_t>& keys,
               std::vector<double>* riders = nullptr, int width = 0) override {
    // New cuts when the largest slab holds 10 % more than the mean (the step waits for it).
    const double began = MPI_Wtime();
    const std::int64_t mine = static_cast<std::int64_t>(owned.size());
    std::int64_t largest = mine;
    MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_INT64_T, MPI_MAX, MPI_COMM_WORLD);
    const std::int64_t total = sumAll(mine);
    if (largest * ranks_ > total * 11 / 10) cutAcross(owned), ++traffic_.rebalances;
    std::vector<std::vector<double>> out(ranks_);
    std::vector<std::size_t> stay;
    if (!riders) width = 0;
    auto packWith = [&](std::size_t i, std::vector<double>& to) {
      pack(owned, i, ids[i], keys[i], to);
      if (width > 0)
        to.insert(to.end(), riders->begin() + i * width, riders->begin() + (i + 1) * width);
    };
    for (std::size_t i = 0; i < owned.size(); ++i) {
      const int k = owner(owned.r[i][axis_]);
      if (k == rank_)
        stay.push_back(i);
      else
        packWith(i, out[k]);
    }
    traffic_.migrated += static_cast<std::int64_t>(owned.size() - stay.size());
    std::vector<double> in = exchange(out);
    if (in.empty() && stay.size() == owned.size()) {  // none left, none came: as they were
      traffic_.migrationSeconds += MPI_Wtime() - began;
      return;
    }
    for (std::size_t i : stay) packWith(i, in);
    unpackSorted(in, owned, ids, keys, width > 0 ? riders : nullptr, width);
    traffic_.migrationSeconds += MPI_Wtime() - began;
  }

  void exchangeHalo(const Particles<D>& owned, const std::vector<std::int64_t>& keys, double width,
                    bool rescan, Particles<D>& halo, std::vector<std::int64_t>& haloKeys) override {
    const double began = MPI_Wtime();
    if (rescan) {
      // Every rank's owned extent along the axis (an empty one takes nothing).
      std::vector<double> extent(2 * ranks_);
      double mine[2] = {1e300, -1e300};
      for (std::size_t i = 0; i < owned.size(); ++i)
        mine[0] = std::min(mine[0], owned.r[i][axis_]),
        mine[1] = std::max(mine[1], owned.r[i][axis_]);
      MPI_Allgather(mine, 2, MPI_DOUBLE, extent.data(), 2, MPI_DOUBLE, MPI_COMM_WORLD);
      sendTo_.assign(ranks_, {});
      for (int k = 0; k < ranks_; ++k) {
        if (k == rank_ || extent[2 * k] > extent[2 * k + 1]) continue;
        const double lo = extent[2 * k] - width, hi = extent[2 * k + 1] + width;
        for (std::size_t i = 0; i < owned.size(); ++i) {
          const double x = owned.r[i][axis_];
          bool near = x >= lo && x <= hi;
          if (periodic_)
            near |= (x + period_ >= lo && x + period_ <= hi) ||
                    (x - period_ >= lo && x - period_ <= hi);
          if (near) sendTo_[k].push_back(i);
        }
      }
    }
    std::vector<std::vector<double>> out(ranks_);
    for (int k = 0; k < ranks_; ++k) {
      for (std::size_t i : sendTo_[k]) pack(owned, i, 0, keys[i], out[k]);
      traffic_.haloSent += static_cast<std::int64_t>(sendTo_[k].size());
    }
    std::vector<int> ids;
    unpackSorted(exchange(out), halo, ids, haloKeys);
    traffic_.haloSeconds += MPI_Wtime() - began;
  }
  typename DomainDecomposition<D>::Traffic traffic() const override { return traffic_; }

  void renumber(const std::vector<std::int64_t>& cells,
                std::vector<std::int64_t>& keys) const override {
    // Rank 0 orders every (cell, key) and hands each rank its particles' places: O(N) there,
    // every keepCellOrder steps (DESIGN-MPI.md: keys by prefix sums instead).
    const int n = static_cast<int>(keys.size());
    std::vector<std::int64_t> pairs(2 * n);
    for (int i = 0; i < n; ++i) pairs[2 * i] = cells[i], pairs[2 * i + 1] = keys[i];
    std::vector<int> counts, offsets;
    const std::vector<std::int64_t> all = gatherTo0(pairs, counts, offsets);
    std::vector<std::int64_t> places;
    std::vector<int> halfCounts(ranks_), halfOffsets(ranks_);
    if (rank_ == 0) {
      const std::size_t total = all.size() / 2;
      std::vector<std::size_t> order(total);
      std::iota(order.begin(), order.end(), std::size_t{0});
      auto before = [&](std::size_t a, std::size_t b) {
        return all[2 * a] != all[2 * b] ? all[2 * a] < all[2 * b] : all[2 * a + 1] < all[2 * b + 1];
      };
      // Each process's pairs come in its cell order, itself (cell, key) ascending: merged run by
      // run (a sort where a run is not in order).
      bool runsInOrder = true;
      for (int r = 0; r < ranks_ && runsInOrder; ++r)
        runsInOrder = std::is_sorted(order.begin() + offsets[r] / 2,
                                     order.begin() + (offsets[r] + counts[r]) / 2, before);
      if (runsInOrder)
        for (int r = 1; r < ranks_; ++r)
          std::inplace_merge(order.begin(), order.begin() + offsets[r] / 2,
                             order.begin() + (offsets[r] + counts[r]) / 2, before);
      else
        std::sort(order.begin(), order.end(), before);
      places.resize(total);
      for (std::size_t k = 0; k < total; ++k) places[order[k]] = static_cast<std::int64_t>(k);
      for (int r = 0; r < ranks_; ++r)
        halfCounts[r] = counts[r] / 2, halfOffsets[r] = offsets[r] / 2;
    }
    MPI_Scatterv(places.data(), halfCounts.data(), halfOffsets.data(), MPI_INT64_T, keys.data(), n,
                 MPI_INT64_T, 0, MPI_COMM_WORLD);
  }

  void gather(const Particles<D>& owned, const std::vector<int>& ids,
              const std::vector<std::int64_t>& keys, Particles<D>& all,
              std::vector<int>& allIds) const override {
    std::vector<double> mine;
    for (std::size_t i = 0; i < owned.size(); ++i) pack(owned, i, ids[i], keys[i], mine);
    std::vector<int> counts, offsets;
    const std::vector<double> every = gatherTo0(mine, counts, offsets);
    std::vector<std::int64_t> allKeys;
    if (rank_ == 0)
      unpackSorted(every, all, allIds, allKeys);
    else
      all.resize(0), allIds.clear();
  }

  void gather(const std::vector<double>& rows, int width, const std::vector<std::int64_t>& keys,
              std::vector<double>& all) const override {
    std::vector<double> mine;  // each row led by its key (exact as a double below 2^53)
    mine.reserve(keys.size() * (width + 1));
    for (std::size_t i = 0; i < keys.size(); ++i) {
      mine.push_back(static_cast<double>(keys[i]));
      mine.insert(mine.end(), rows.begin() + i * width, rows.begin() + (i + 1) * width);
    }
    std::vector<int> counts, offsets;
    const std::vector<double> every = gatherTo0(mine, counts, offsets);
    all.clear();
    if (rank_ != 0) return;
    const std::size_t n = every.size() / (width + 1);
    all.resize(n * width);
    for (std::size_t k = 0; k < n; ++k) {
      const double* row = every.data() + k * (width + 1);
      std::copy(row + 1, row + 1 + width, all.begin() + static_cast<std::int64_t>(row[0]) * width);
    }
  }

 private:
  int owner(double x) const {
    if (periodic_) x = lo_ + (x - lo_) - period_ * std::floor((x - lo_) / period_);
    return static_cast<int>(std::upper_bound(cuts_.begin(), cuts_.end(), x) - cuts_.begin());
  }
  // Cuts at equal counts of `all` (every rank the same particles).
  void cut(const Particles<D>& all) {
    std::vector<double> x(all.size());
    for (std::size_t i = 0; i < all.size(); ++i) x[i] = all.r[i][axis_];
    cutAt(x);
  }
  // The same for particles spread over the ranks (all positions gathered: a rebalance is rare).
  void cutAcross(const Particles<D>& owned) {
    std::vector<double> mine(owned.size());
    for (std::size_t i = 0; i < owned.size(); ++i) mine[i] = owned.r[i][axis_];
    int n = static_cast<int>(mine.size());
    std::vector<int> counts(ranks_), offsets(ranks_);
    MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    std::partial_sum(counts.begin(), counts.end() - 1, offsets.begin() + 1);
    std::vector<double> x(offsets.back() + counts.back());
    MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, x.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                   MPI_COMM_WORLD);
    cutAt(x);
  }
  // cuts_[k - 1]: where slab k begins (slab 0 from -inf, the last to +inf).
  void cutAt(std::vector<double> x) {
    std::sort(x.begin(), x.end());
    cuts_.assign(ranks_ - 1, 0.0);
    for (int k = 1; k < ranks_; ++k)
      cuts_[k - 1] = x.empty() ? lo_ + period_ * k / ranks_ : x[x.size() * k / ranks_];
  }
  // Each rank's message to each other; returns what this rank received, in rank order.
  std::vector<double> exchange(const std::vector<std::vector<double>>& out) const {
    std::vector<int> sendCounts(ranks_), recvCounts(ranks_), sendOffsets(ranks_),
        recvOffsets(ranks_);
    std::vector<double> send;
    for (int k = 0; k < ranks_; ++k) {
      sendOffsets[k] = static_cast<int>(send.size());
      sendCounts[k] = static_cast<int>(out[k].size());
      send.insert(send.end(), out[k].begin(), out[k].end());
    }
    MPI_Alltoall(sendCounts.data(), 1, MPI_INT, recvCounts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    std::partial_sum(recvCounts.begin(), recvCounts.end() - 1, recvOffsets.begin() + 1);
    std::vector<double> in(recvOffsets.back() + recvCounts.back());
    MPI_Alltoallv(send.data(), sendCounts.data(), sendOffsets.data(), MPI_DOUBLE, in.data(),
                  recvCounts.data(), recvOffsets.data(), MPI_DOUBLE, MPI_COMM_WORLD);
    return in;
  }
  // Every rank's `mine` on rank 0, in rank order; `counts` and `offsets` (rank 0's) say where.
  template <class T>
  std::vector<T> gatherTo0(const std::vector<T>& mine, std::vector<int>& counts,
                           std::vector<int>& offsets) const {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, std::int64_t>);
    const MPI_Datatype type = std::is_same_v<T, double> ? MPI_DOUBLE : MPI_INT64_T;
    int n = static_cast<int>(mine.size());
    counts.assign(ranks_, 0), offsets.assign(ranks_, 0);
    MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<T> all;
    if (rank_ == 0) {
      std::partial_sum(counts.begin(), counts.end() - 1, offsets.begin() + 1);
      all.resize(offsets.back() + counts.back());
    }
    MPI_Gatherv(mine.data(), n, type, all.data(), counts.data(), offsets.data(), type, 0,
                MPI_COMM_WORLD);
    return all;
  }

  int rank_ = 0, ranks_ = 1, axis_ = 0;
  double lo_ = 0, period_ = 1;
  bool periodic_ = false;
  std::vector<double> cuts_;
  std::vector<std::vector<std::size_t>> sendTo_;  // the halo members each rank gets
  typename DomainDecomposition<D>::Traffic traffic_;
};

}  // namespace

template <int D>
std::shared_ptr<DomainDecomposition<D>> slabDecomposition(const Scene& scene) {
  int started = 0, ranks = 1;
  MPI_Initialized(&started);
  if (!started) return nullptr;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (ranks == 1) return nullptr;
  return std::make_shared<SlabDecomposition<D>>(scene);
}

template std::shared_ptr<DomainDecomposition<1>> slabDecomposition<1>(const Scene&);
template std::shared_ptr<DomainDecomposition<2>> slabDecomposition<2>(const Scene&);
template std::shared_ptr<DomainDecomposition<3>> slabDecomposition<3>(const Scene&);

Processes::Processes() {
  int started = 0;
  MPI_Initialized(&started);
  if (launchedProcesses() > 1 && !started) {
    MPI_Init(nullptr, nullptr);
    started_ = true;
  }
}
Processes::~Processes() {
  // Not while an error unwinds: the other processes may wait in a collective call, and a process
  // that exits unfinalized makes the launcher end them all.
  int finished = 0;
  MPI_Finalized(&finished);
  if (started_ && !finished && std::uncaught_exceptions() == 0) MPI_Finalize();
}

}  // namespace sph
