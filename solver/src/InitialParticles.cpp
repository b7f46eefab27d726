#include "sph/InitialParticles.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "sph/EquationOfState.hpp"
#include "sph/packing/Geometry.hpp"
#include "sph/packing/ParticlePacking.hpp"

namespace sph {

namespace {

// The block's nodes of the cell-centred Cartesian lattice (a circle's lattice is symmetric about
// its centre).
template <int D>
std::vector<Vec<D>> latticeNodes(const FluidBlock& b, double dx) {
  const bool circle = b.shape == FluidBlock::Shape::circle;
  Vec<D> lo, hi;
  std::array<long, D> count;
  for (int a = 0; a < D; ++a) {
    lo[a] = circle ? b.center[a] - b.radius : b.lower[a];
    hi[a] = circle ? b.center[a] + b.radius : b.upper[a];
    count[a] = latticeCount(hi[a] - lo[a], dx);
    if (circle) lo[a] = b.center[a] - 0.5 * dx * count[a];
  }
  std::vector<Vec<D>> out;
  // A rectangle thinner than dx/2 along an axis has no node along it: the loop below would still
  // place one at lo + dx/2, outside the block.
  for (int a = 0; a < D; ++a)
    if (count[a] == 0) return out;
  std::array<long, D> idx{};
  for (;;) {
    Vec<D> x;
    for (int a = 0; a < D; ++a) x[a] = lo[a] + (idx[a] + 0.5) * dx;
    bool inside = true;
    if (circle) {
      double d2 = 0;
      for (int a = 0; a < D; ++a) d2 += (x[a] - b.center[a]) * (x[a] - b.center[a]);
      inside = d2 < b.radius * b.radius;
    }
    if (inside) out.push_back(x);
    int a = 0;
    while (a < D && ++idx[a] >= count[a]) idx[a++] = 0;
    if (a == D) break;
  }
  return out;
}

// The sides of a rectangular block that lie on a free-slip or no-slip face of the domain: the run
// closes them with mirror ghosts (Boundaries), so the packing mirrors the fluid there too instead
// of using solid layers; packed against solid layers the block sat 0.35 dx from such a wall, and
// the run's ghosts pushed it off at once (measured, README: Cartesian against packed start).
template <int D>
std::vector<packing::MirrorWall> ghostWallSides(const FluidBlock& b, const Scene& scene) {
  std::vector<packing::MirrorWall> walls;
  if (b.shape != FluidBlock::Shape::rectangle) return walls;
  const double tol = 1e-9 * scene.dx;
  for (int a = 0; a < D; ++a)
    for (int side = 0; side < 2; ++side) {
      const FaceKind k = scene.faces[a][side];
      const double face = side ? scene.upper[a] : scene.lower[a];
      const double edge = side ? b.upper[a] : b.lower[a];
      if ((k == FaceKind::free_slip || k == FaceKind::no_slip) && std::abs(face - edge) < tol)
        walls.push_back({a, face, side ? -1 : 1});
    }
  return walls;
}

// Solid particles closing the other sides of a block (its free surface, section 2 of the paper):
// the nodes of the block's own lattice (latticeNodes, extended by `layers` along every axis) that
// are not fluid nodes, within `layers` dx of the block, on the fluid side of every wall, plus
// their mirror images across the walls (edges and corners: across each set of them), as the run's
// ghosts mirror the fluid. The lattice of a rectangle and its layers is then at rest
// (grad Gamma = 0); packing moves what a free-surface corner or an uneven edge disturbs.
template <int D>
std::vector<Vec<D>> solidAlongOpenSides(const FluidBlock& b,
                                        const std::vector<packing::MirrorWall>& walls, double dx,
                                        int layers) {
  const bool circle = b.shape == FluidBlock::Shape::circle;
  Vec<D> lo;
  std::array<long, D> count;
  for (int a = 0; a < D; ++a) {
    const double low = circle ? b.center[a] - b.radius : b.lower[a];
    const double high = circle ? b.center[a] + b.radius : b.upper[a];
    count[a] = latticeCount(high - low, dx);
    lo[a] = circle ? b.center[a] - 0.5 * dx * count[a] : low;
  }
  const double reach = layers * dx;
  // Not a node of the block (latticeNodes' test), and for a circle within `reach` of it: the index
  // box of a rectangle already is its nodes and `layers` more.
  const auto isSolidNode = [&](const std::array<long, D>& idx, const Vec<D>& y) {
    if (circle) {
      double d2 = 0;
      for (int a = 0; a < D; ++a) d2 += (y[a] - b.center[a]) * (y[a] - b.center[a]);
      return !(d2 < b.radius * b.radius) && std::sqrt(d2) < b.radius + reach;
    }
    for (int a = 0; a < D; ++a)
      if (idx[a] < 0 || idx[a] >= count[a]) return true;
    return false;
  };
  const auto fluidSide = [&](const Vec<D>& y) {
    for (const auto& w : walls)
      if (w.fluidSide * (y[w.axis] - w.at) <= 0.0) return false;
    return true;
  };
  std::vector<Vec<D>> out;
  for (int a = 0; a < D; ++a)
    if (count[a] == 0) return out;
  std::array<long, D> idx;
  idx.fill(-layers);
  for (;;) {  // the last axis varies fastest
    Vec<D> y;
    for (int a = 0; a < D; ++a) y[a] = lo[a] + (idx[a] + 0.5) * dx;
    if (isSolidNode(idx, y) && fluidSide(y)) {
      out.push_back(y);
      packing::appendMirrorImages<D>(y, walls, reach, out);
    }
    int a = D - 1;
    while (a >= 0 && ++idx[a] >= count[a] + layers) idx[a--] = -layers;
    if (a < 0) break;
  }
  return out;
}

// A 3-D block's volume that its N particles share: V0 = volume / N (2-D: packing::Region's area).
double blockVolume3(const FluidBlock& b) {
  if (b.shape == FluidBlock::Shape::circle)
    return 4.0 / 3.0 * std::numbers::pi * b.radius * b.radius * b.radius;
  return (b.upper[0] - b.lower[0]) * (b.upper[1] - b.lower[1]) * (b.upper[2] - b.lower[2]);
}

// In 2-D a circle away from the walls is closed by solid layers along its curve (packBlock); every
// other block's layers and mirror images continue its lattice.
template <int D>
bool layersFollowCurve(const FluidBlock& b, const std::vector<packing::MirrorWall>& walls) {
  return D == 2 && b.shape == FluidBlock::Shape::circle && walls.empty();
}

}  // namespace

template <int D>
bool packingLeavesLattice(const FluidBlock& b, const Scene& scene) {
  return b.packed && (b.packingNoise > 0.0 || layersFollowCurve<D>(b, ghostWallSides<D>(b, scene)));
}

namespace {

// Colagrossi et al. (2012) packing of a block from its lattice nodes: the block is closed by
// fixed solid layers (its free surface treated as a wall, section 2) or, on the domain's walls, by
// the mirror images of the fluid, V0 = volume / N, eq. (2.16) with the scene's kernel and h/dx,
// until T / (N beta) < the block's threshold. Returns V0. In 2-D a circle's solid layers follow
// its curve (packing::solidLayers); in 3-D every block's are nodes of its lattice.
template <int D>
double packBlock(const FluidBlock& b, const Scene& scene, std::vector<Vec<D>>& x,
                 PackedBlock& report) {
  using namespace packing;
  PackingParameters p;
  p.kernel = scene.kernel, p.hOverDx = scene.hOverDx;
  p.alpha = b.packingAlpha, p.maxIterations = b.packingMaxIterations;
  const int layers = static_cast<int>(std::ceil(2.0 * scene.hOverDx - 1e-9));
  const std::vector<MirrorWall> walls = ghostWallSides<D>(b, scene);
  double V0 = 0.0;
  std::vector<Vec<D>> solid;
  if constexpr (D == 2) {
    std::vector<Piece> path;
    if (b.shape == FluidBlock::Shape::circle) {
      const Vec2 c(b.center[0], b.center[1]), q = c + Vec2(b.radius, 0.0);
      path.push_back(arc(q, q, c, true));
    } else {
      const Vec2 lo(b.lower[0], b.lower[1]), hi(b.upper[0], b.upper[1]);
      path = {segment(lo, {hi.x(), lo.y()}), segment({hi.x(), lo.y()}, hi),
              segment(hi, {lo.x(), hi.y()}), segment({lo.x(), hi.y()}, lo)};
    }
    const Region region(path);
    V0 = region.area() / static_cast<double>(x.size());
    // (a rectangle's layers, on its sides' lattice, continue the block's: layersFollowCurve)
    solid = walls.empty() ? solidLayers(region, scene.dx, layers).position
                          : solidAlongOpenSides<2>(b, walls, scene.dx, layers);
  } else {
    V0 = blockVolume3(b) / static_cast<double>(x.size());
    solid = solidAlongOpenSides<D>(b, walls, scene.dx, layers);
  }
  if (b.packingNoise > 0.0) {
    std::mt19937 rng(2012);  // fixed: a scene packs the same every run
    std::uniform_real_distribution<double> noise(-b.packingNoise * scene.dx,
                                                 b.packingNoise * scene.dx);
    for (Vec<D>& y : x)
      for (int a = 0; a < D; ++a) y[a] += noise(rng);
  }
  ParticlePacking<D> packing(x, std::move(solid), V0, scene.dx, p);
  packing.setMirrorWalls(walls);
  // From rest T = 0: the test applies from the first iteration on.
  report.history.push_back(packing.record());
  while (packing.iteration() < p.maxIterations &&
         (packing.iteration() == 0 || report.history.back().kineticMean >= b.packingStop)) {
    packing.step();
    report.history.push_back(packing.record());
  }
  report.converged = packing.iteration() > 0 && report.history.back().kineticMean < b.packingStop;
  x = packing.positions();
  return V0;
}

// Q_max of initial_pressure = "stretching" (Scene.hpp): the largest (x - c)^T G G (x - c) over
// the block.
template <int D>
double stretchingQmax(const FluidBlock& b, const Eigen::Matrix<double, D, D>& GG, const Vec<D>& c) {
  const Eigen::Matrix<double, D, D> S = 0.5 * (GG + GG.transpose());
  if (b.shape == FluidBlock::Shape::circle) {
    const double lmax =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>>(S).eigenvalues().maxCoeff();
    return b.radius * b.radius * std::max(0.0, lmax);
  }
  double q = 0.0;  // the centre
  for (int corner = 0; corner < (1 << D); ++corner) {
    Vec<D> d;
    for (int a = 0; a < D; ++a) d[a] = ((corner >> a) & 1 ? b.upper[a] : b.lower[a]) - c[a];
    q = std::max(q, d.dot(S * d));
  }
  return q;
}

}  // namespace

long latticeCount(double width, double dx) {
  const double n = width / dx;
  // 2^53: beyond it a double no longer holds every whole number, and lround's long is reached
  // soon after; no block that fits in memory comes near (RunBudget refuses far earlier).
  if (!(n >= 0.0 && n < 9007199254740992.0))
    throw std::overflow_error("latticeCount: a block of width " + std::to_string(width) +
                              " m holds " + std::to_string(n) + " lattice spacings of " +
                              std::to_string(dx) + " m, too many to count");
  return std::lround(n);
}

template <int D>
Particles<D> latticeParticles(const Scene& scene, std::vector<PackedBlock>* packed) {
  Particles<D> out;
  const double dx = scene.dx;
  double g = 0;
  for (double c : scene.bodyAcceleration) g += c * c;
  g = std::sqrt(g);
  const std::vector<double> up = upward(scene);  // the hydrostatic start's heights
  for (std::size_t k = 0; k < scene.fluids.size(); ++k) {
    const FluidBlock& b = scene.fluids[k];
    std::vector<Vec<D>> nodes = latticeNodes<D>(b, dx);
    double volume = std::pow(dx, D);
    if constexpr (D >= 2)
      if (b.packed && !nodes.empty()) {
        PackedBlock report;
        report.block = k;
        volume = packBlock<D>(b, scene, nodes, report);
        if (packed) packed->push_back(std::move(report));
      }
    Eigen::Matrix<double, D, D> G = Eigen::Matrix<double, D, D>::Zero();
    Vec<D> c = Vec<D>::Zero();
    if (!b.velocityGradient.empty())
      for (int r = 0; r < D; ++r) {
        c[r] = b.gradientCenter[r];
        for (int k = 0; k < D; ++k) G(r, k) = b.velocityGradient[r * D + k];
      }
    const Eigen::Matrix<double, D, D> GG = G * G;
    const double Qmax = b.stretching ? stretchingQmax<D>(b, GG, c) : 0.0;
    const Phase& ph = scene.phases[b.phase];
    for (const Vec<D>& x : nodes) {
      double rho = ph.rho0;
      if (b.hydrostatic)
        rho = TaitEquationOfState::density(ph.p0 + ph.rho0 * g * (b.surface - height(up, x.data())),
                                           ph);
      if (b.stretching) {  // Scene.hpp: -grad p / rho0 = G G (x - c), p = p0 at Q = Q_max
        const Vec<D> d = x - c;
        rho = TaitEquationOfState::density(ph.p0 + 0.5 * ph.rho0 * (Qmax - d.dot(GG * d)), ph);
      }
      out.r.push_back(x);
      Vec<D> v = G * (x - c);
      for (int a = 0; a < D; ++a) v[a] += b.velocity[a];
      out.v.push_back(v);
      out.rho.push_back(rho);
      out.m.push_back(rho * volume);
      out.h.push_back(scene.h0());
      out.p.push_back(TaitEquationOfState::pressure(rho, ph));
      out.phase.push_back(b.phase);
    }
  }
  return out;
}

template bool packingLeavesLattice<1>(const FluidBlock&, const Scene&);
template bool packingLeavesLattice<2>(const FluidBlock&, const Scene&);
template bool packingLeavesLattice<3>(const FluidBlock&, const Scene&);
template Particles<1> latticeParticles<1>(const Scene&, std::vector<PackedBlock>*);
template Particles<2> latticeParticles<2>(const Scene&, std::vector<PackedBlock>*);
template Particles<3> latticeParticles<3>(const Scene&, std::vector<PackedBlock>*);

}  // namespace sph
