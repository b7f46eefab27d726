#include "sph/Simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sph/EquationOfState.hpp"
#include "sph/InitialParticles.hpp"
#include "sph/Parallel.hpp"
#include "sph/boundaries/NoSlipContinuity.hpp"
#include "sph/integrators/PositionVerlet.hpp"
#include "sph/integrators/PredictorCorrector.hpp"
#include "sph/integrators/VelocityVerlet.hpp"

namespace sph {

std::string_view name(FailureCause c) {
  switch (c) {
    case FailureCause::nan:
      return "nan";
    case FailureCause::density_band:
      return "density_band";
    case FailureCause::escaped_domain:
      return "escaped_domain";
    case FailureCause::wall_penetration:
      return "wall_penetration";
    case FailureCause::dt_collapse:
      return "dt_collapse";
    case FailureCause::energy_growth:
      return "energy_growth";
  }
  // No default: -Wswitch names an enumerator missing above, and any other value is a bug
  // (an error here), never the last case.
  throw std::logic_error("name(FailureCause): unknown value " +
                         std::to_string(static_cast<int>(c)));
}

std::string encode(const Failure& f) {
  std::ostringstream o;
  o.precision(17);
  o << static_cast<int>(f.cause) << ' ' << f.step << ' ' << f.time << ' ' << f.particle << ' '
    << f.message;
  return o.str();
}

Failure decodeFailure(const std::string& text) {
  std::istringstream in(text);
  int cause = 0;
  Failure f;
  in >> cause >> f.step >> f.time >> f.particle;
  std::getline(in >> std::ws, f.message);
  f.cause = static_cast<FailureCause>(cause);
  return f;
}

namespace {
// Whether a particle beyond a face of kind k leaves the run (removeDeparted) rather than fails.
bool leavesThrough(const Scene& scene, FaceKind k) {
  return k == FaceKind::open && scene.leaving == Scene::Leaving::removed;
}

template <int D>
Boundaries<D> boundariesOf(const Scene& s) {
  Boundaries<D> b;
  for (int a = 0; a < D; ++a) {
    b.lower[a] = s.lower[a], b.upper[a] = s.upper[a];
    for (int side = 0; side < 2; ++side) {
      b.face[a][side] = s.faces[a][side];
      for (int k = 0; k < D; ++k) b.wallVelocity[a][side][k] = s.wallVelocity[a][side][k];
    }
  }
  return b;
}
// A mirror ghost keeps its source's density (InteractionSet.hpp) while its hydrostatic pressure
// is its source's plus rho g . (x_g - x): a ghost below the floor has the density of a particle
// above it. Fourtakas et al.'s density diffusion (terms/DensityDiffusionFourtakas.hpp) reads that
// as a density deficit below the floor, which drains the bottom layer (a tank at rest, H/dx 20,
// Wendland: the bottom pressure 19 % low by t sqrt(g/H) = 20). With that form the ghost takes
// the density of its pressure through the inverse Tait EOS of its phase, as the fluid has; the
// paper's scenes, without it, keep the source's density.
template <int D>
void ghostDensitiesFromPressure(const std::vector<Phase>& phases, InteractionSet<D>& set) {
  for (std::size_t i = set.nFluid; i < set.size(); ++i)
    set.rho[i] = TaitEquationOfState::density(set.p[i], phases[set.phase[i]]);
}

// The terms' parameters: density diffusion takes c0 (and, in Fourtakas et al.'s form, the
// EOS and g) of the scene's one phase.
terms::TermParameters termParametersOf(const Scene& scene) {
  terms::TermParameters t{.beta = scene.beta,
                          .continuityByVolume = scene.continuityByVolume,
                          .pressureGradientByVolume = scene.continuityByVolume,
                          .diffusionDelta = scene.diffusionDelta};
  t.spacing = scene.dx;
  if (scene.phases.empty()) return t;
  const Phase& water = scene.phases[0];
  t.soundSpeed = water.c0, t.rho0 = water.rho0, t.bulkModulus = water.bulkModulus();
  t.gammaInteger = static_cast<int>(water.gamma);
  for (std::size_t a = 0; a < scene.bodyAcceleration.size() && a < 3; ++a)
    t.g[a] = scene.bodyAcceleration[a];
  return t;
}

// The scene's terms, and with particle shifting its pair sums (in the evaluations that ask)
// where the menu has them with the scene's terms (else the shifting pass gathers them itself).
TermSwitches termsOf(const Scene& scene) {
  TermSwitches t = scene.terms;
  t.concentrationGradient = scene.shifting.form != ShiftingForm::none;
  if (!onMenu(t)) t.concentrationGradient = false;
  return t;
}
}  // namespace

template <int D>
Simulation<D>::Simulation(const Scene& scene) : Simulation(scene, latticeParticles<D>(scene)) {}

template <int D>
Simulation<D>::Simulation(const Scene& scene, Particles<D> initial)
    : scene_(scene),
      bounds_(boundariesOf<D>(scene)),
      forces_(scene.kernel, termsOf(scene), termParametersOf(scene)),
      boundary_(makeBoundary<D>(scene, bounds_)),
      y_(std::move(initial)),
      skinFraction_(scene.neighbourSkin) {
  // (with wall particles the box's wall faces have no ghosts; obstacles keep the faces' ghosts)
  for (int a = 0; a < D; ++a)
    for (int side = 0; side < 2; ++side)
      noSlipGhosts_ |=
          bounds_.face[a][side] == FaceKind::no_slip && scene.wallModel == WallModel::mirror_ghosts;
  // The scene's word for each (name(TimeIntegrator), Scene.cpp) is the integrator's own.
  static_assert(integrators::PositionVerlet::name == "position_verlet" &&
                integrators::PredictorCorrector::name == "predictor_corrector" &&
                integrators::VelocityVerlet::name == "velocity_verlet");
  switch (scene.integrator) {
    case TimeIntegrator::predictor_corrector:
      advance_ = &Simulation::advanceWith<integrators::PredictorCorrector>;
      break;
    case TimeIntegrator::position_verlet:
      advance_ = &Simulation::advanceWith<integrators::PositionVerlet>;
      break;
    case TimeIntegrator::velocity_verlet:
      advance_ = &Simulation::advanceWith<integrators::VelocityVerlet>;
      ratesOfState_ = false;
      break;
  }
  // No default: -Wswitch names an enumerator missing above; any other value is a bug.
  if (!advance_)
    throw std::logic_error("Simulation: unknown time integrator " +
                           std::to_string(static_cast<int>(scene.integrator)));
  if (scene.shifting.form != ShiftingForm::none)
    shifting_ = std::make_unique<ParticleShifting<D>>(scene.kernel, scene.shifting, scene.dx);
  shiftingSums_ = forces_.terms().concentrationGradient;
  id_.resize(y_.size());
  std::iota(id_.begin(), id_.end(), 0);
  for (std::size_t i = 0; i < y_.size(); ++i)
    y_.p[i] = TaitEquationOfState::pressure(y_.rho[i], scene_.phases[y_.phase[i]]);
}

template <int D>
std::vector<std::string> Simulation<D>::termNames() const {
  auto names = forces_.termNames();
  double g = 0;
  for (double c : scene_.bodyAcceleration) g += std::abs(c);
  if (g > 0) names.push_back("body_force");
  boundary_->listTerms(names);
  if (noSlipGhosts_) names.push_back("no_slip_ghosts_free_slip_continuity");
  if (bounds_.anyPeriodic()) names.push_back("periodic");
  if (source_) names.push_back("source");
  if (shifting_) names.push_back("shifting_" + std::string(name(scene_.shifting.form)));
  return names;
}

template <int D>
inline void Simulation<D>::Motion::add(const Vec<D>& r, double h, std::int64_t i) {
  hMax = std::max(hMax, h);
  if (listed) {
    moved2 = std::max(moved2, (r - listedAt[i]).squaredNorm());
    grown = std::max(grown, h - listedH[i]);
  }
}

template <int D>
typename Simulation<D>::Motion Simulation<D>::motionStart(std::int64_t n) const {
  return {0.0,
          0.0,
          0.0,
          static_cast<std::int64_t>(listedAt_.size()) == n,
          listedAt_.data(),
          listedH_.data()};
}

template <int D>
void Simulation<D>::rates(const Particles<D>& state, double t, Derivatives<D>& out) {
  const std::int64_t n = static_cast<std::int64_t>(state.size());
  Motion m = motionStart(n);
  double hMax = 0, moved2 = 0, grown = 0;
#pragma omp parallel if (n >= parallelFrom()) reduction(max : hMax, moved2, grown)
  {
    Motion mine = m;
    walk(shareOf(n, omp_get_thread_num(), omp_get_num_threads()),
         [&](std::int64_t i) { mine.add(state.r[i], state.h[i], i); });
    hMax = mine.hMax, moved2 = mine.moved2, grown = mine.grown;
  }
  m.hMax = hMax, m.moved2 = moved2, m.grown = grown;
  rates(state, t, out, m);
}

template <int D>
void Simulation<D>::rates(const Particles<D>& state, double t, Derivatives<D>& out,
                          const Motion& motion, bool shiftingSums) {
  std::int64_t n = static_cast<std::int64_t>(state.size());
  // The lists of the last build serve while no particle has moved, and no h grown, enough to
  // bring a pair that was not listed inside the support (2 d + 2 dh below the skin:
  // ForceEvaluation.hpp). A boundary's entries after the halo (fixed wall particles) stand still,
  // in the same places of the set while the halo's members are the same. Over several
  // processes, the motion and h_max are the whole domain's, so that every process decides as one
  // would.
  const bool skinned = skinFraction_ > 0;
  bool kept = skinned && motion.listed && static_cast<std::int64_t>(listedAt_.size()) == n;
  double hMax = motion.hMax, moved2 = motion.moved2, grown = motion.grown;
  if (domain_) {
    double v[4] = {hMax, moved2, grown, kept ? 0.0 : 1.0};
    domain_->maxAll(v, 4);
    hMax = v[0], moved2 = v[1], grown = v[2], kept = v[3] == 0.0;
  }
  if (hMax == 0.0) {  // no particle is left anywhere (every one has departed): nothing acts
    out.resize(static_cast<std::size_t>(n));
    return;
  }
  const bool reuse = kept && 2.0 * std::sqrt(moved2) + 2.0 * grown < skin_;
  // New lists at an accepted state: the particles that left the slab go to its owner (in the
  // middle of a step y and y* keep the same particles).
  if (domain_ && !reuse && &state == &y_) {
    domain_->migrate(y_, id_, key_);
    n = static_cast<std::int64_t>(y_.size());
  } else if (domain_ && !reuse && !ratesOfState_ && &state == &yStar_) {
    // No accepted state is evaluated (VelocityVerlet.hpp): the trial state goes, and y and the
    // rates carried to this step ride along (the same particles, index by index).
    constexpr int width = 3 * D + 5;
    std::vector<double> riders(static_cast<std::size_t>(n) * width);
    forEachInShares(n, [&](std::int64_t i) {
      double* row = riders.data() + i * width;
      for (int a = 0; a < D; ++a)
        row[a] = y_.r[i][a], row[D + a] = y_.v[i][a], row[2 * D + a] = f_.dvdt[i][a];
      row[3 * D] = y_.rho[i], row[3 * D + 1] = y_.h[i], row[3 * D + 2] = y_.p[i];
      row[3 * D + 3] = f_.drhodt[i], row[3 * D + 4] = f_.dhdt[i];
    });
    domain_->migrate(yStar_, id_, key_, &riders, width);
    n = static_cast<std::int64_t>(yStar_.size());
    y_.resize(n), f_.resize(n);
    forEachInShares(n, [&](std::int64_t i) {
      const double* row = riders.data() + i * width;
      for (int a = 0; a < D; ++a)
        y_.r[i][a] = row[a], y_.v[i][a] = row[D + a], f_.dvdt[i][a] = row[2 * D + a];
      y_.rho[i] = row[3 * D], y_.h[i] = row[3 * D + 1], y_.p[i] = row[3 * D + 2];
      f_.drhodt[i] = row[3 * D + 3], f_.dhdt[i] = row[3 * D + 4];
      y_.m[i] = yStar_.m[i], y_.phase[i] = yStar_.phase[i];
    });
  }
  if (!reuse && skinned) {
    skin_ = skinFraction_ * 2.0 * hMax;
    listedAt_.resize(n), listedH_.resize(n);
    // Each thread its share, as in the scan above (not one thread the whole copy: the next scan
    // would then read half of it from the other core).
    forEachInShares(n,
                    [&](std::int64_t i) { listedAt_[i] = state.r[i], listedH_[i] = state.h[i]; });
  }
  Vec<D> g;
  for (int a = 0; a < D; ++a) g[a] = scene_.bodyAcceleration[a];
  // Over several processes the set is built from the owned particles and the halo within
  // the support plus the skin of them (every entry the owned particles' lists may hold).
  if (domain_) {
    // (and, with fixed wall particles, the fluid that gives those within it their state)
    const double width = 2.0 * hMax + skin_ + boundary_->fixedReach();
    domain_->exchangeHalo(state, key_, 1.01 * width, !reuse, halo_, haloKey_);
    placeHalo(!reuse);
  }
  const SetFluid<D> fluid = domain_ ? SetFluid<D>(state, halo_, placed_) : SetFluid<D>(state);
  // Ghosts within the support plus the skin: those the kept lists may need.
  buildSet(fluid, 2.0 * hMax + skin_, reuse ? HaloMembers::same : HaloMembers::rescan, set_);
  if (domain_ && !reuse) frameGrid(hMax);
  // (over several processes the rates of the owned particles only, in their order)
  forces_(set_, out, g, {skin_, reuse}, shiftingSums);  // with F/rho of eq. (12)
  if (noSlipGhosts_)
    noSlipGhostContinuity(set_, bounds_, scene_.kernel, scene_.continuityByVolume,
                          scene_.terms.variableH, out);
  if (source_) source_(t, state, out);
  ++evaluations_;
  if (reuse) ++reusedLists_;
}

template <int D>
void Simulation<D>::buildSet(const SetFluid<D>& fluid, double reach, HaloMembers members,
                             InteractionSet<D>& set) const {
  boundary_->build(fluid, scene_.phases, reach, members, set);
  // (hydrostatic ghost pressure comes with mirror ghosts only: Scene refuses it with wall
  // particles)
  if (scene_.hydrostaticGhosts &&
      (scene_.terms.densityDiffusion == DensityDiffusion::fourtakas ||
       scene_.terms.densityDiffusion == DensityDiffusion::fourtakasPhases ||
       scene_.terms.densityDiffusion == DensityDiffusion::antuono))
    ghostDensitiesFromPressure(scene_.phases, set);
}

template <int D>
void Simulation<D>::wholeSet(const Particles<D>& all, InteractionSet<D>& set) const {
  // Ghosts of every particle within the support of a wall: the kept set's members may be more
  // (within the support plus the skin when chosen), but those lie beyond the support of any
  // point inside the domain, where the kernel is 0.
  double hMax = 0;
  for (double h : all.h) hMax = std::max(hMax, h);
  buildSet(all, 2.0 * hMax + skin_, HaloMembers::rescan, set);
}

template <int D>
const InteractionSet<D>& Simulation<D>::stateSet(InteractionSet<D>& scratch) const {
  if (ratesOfState_) return set_;
  wholeSet(y_, scratch);
  return scratch;
}

template <int D>
void Simulation<D>::placeHalo(bool rescan) {
  const std::int64_t n = static_cast<std::int64_t>(key_.size());
  const std::int64_t nh = static_cast<std::int64_t>(haloKey_.size());
  if (!rescan && static_cast<std::int64_t>(placed_.size()) == n + nh) return;
  placed_.resize(n + nh);
  std::int64_t i = 0, j = 0;
  for (std::int64_t k = 0; k < n + nh; ++k) {
    const bool own = j == nh || (i < n && key_[i] < haloKey_[j]);
    placed_[k] = own ? static_cast<int>(i++) : static_cast<int>(-1 - j++);
  }
}

template <int D>
void Simulation<D>::frameGrid(double hMax) {
  // The whole set is every process's fluid and the halo entries of its own fluid (a halo copy's
  // ghosts are its owner's too), and every fixed wall particle (no source; each process holds
  // those within reach of its fluid and counts the others as left out), its box the union of
  // the processes' boxes.
  double box[2 * D];
  for (int a = 0; a < D; ++a) box[a] = -1e300, box[D + a] = -1e300;
  std::int64_t entries = 0, fixed = 0;
  for (std::size_t k = 0; k < set_.size(); ++k) {
    for (int a = 0; a < D; ++a)
      box[a] = std::max(box[a], -set_.x[k][a]), box[D + a] = std::max(box[D + a], set_.x[k][a]);
    const int source = set_.source[k];
    if (source < 0)
      ++fixed;
    else
      entries += placed_[source] >= 0;
  }
  // (and those left out of the set as in no pair: InteractionSet::leftOut)
  fixed += static_cast<std::int64_t>(set_.leftOut.count);
  for (int a = 0; a < D && set_.leftOut.count > 0; ++a)
    box[a] = std::max(box[a], -set_.leftOut.lo[a]),
    box[D + a] = std::max(box[D + a], set_.leftOut.hi[a]);
  domain_->maxAll(box, 2 * D);
  entries = domain_->sumAll(entries) + fixed;
  double lo[D], hi[D];
  for (int a = 0; a < D; ++a) lo[a] = -box[a], hi[a] = box[D + a];
  forces_.frameGrid(lo, hi, static_cast<std::size_t>(entries), hMax);
}

template <int D>
void Simulation<D>::distribute(std::shared_ptr<DomainDecomposition<D>> d) {
  if (source_) throw std::logic_error("Simulation::distribute: a source runs in one process");
  // (the shifts are summed over the set's fluid entries, owned and halo alike: not yet split)
  if (shifting_) throw std::logic_error("Simulation::distribute: shifting runs in one process");
  domain_ = std::move(d);
  if (!domain_) return;
  key_.resize(y_.size());
  std::iota(key_.begin(), key_.end(), std::int64_t{0});
  domain_->keepOwn(y_, id_, key_);
  ratesValid_ = false, listedAt_.clear();
}

template <int D>
void Simulation<D>::agree(std::optional<Failure>& failure) const {
  // The first failing particle by key, as one process takes the first by index.
  constexpr double huge = std::numeric_limits<double>::max();
  double first = huge;
  if (failure) {
    const auto at = std::find(id_.begin(), id_.end(), failure->particle);
    first = at == id_.end() ? 0.0 : static_cast<double>(key_[at - id_.begin()]);
    first = first * domain_->ranks() + domain_->rank();
  }
  double v = first;
  domain_->minAll(&v, 1);
  if (v == huge) return failure.reset();
  const int from = static_cast<int>(std::fmod(v, domain_->ranks()));
  std::string text = domain_->rank() == from ? encode(*failure) : std::string();
  domain_->broadcast(text, from);
  failure = decodeFailure(text);
}

template <int D>
double Simulation<D>::timeStep(TimeStepLimit& limit, int& particle) const {
  // Each extreme and the first particle that reaches it: every thread scans its share, keeping
  // the lower index among equal values (walk() does not go in index order), and the shares
  // combine the same way, so any thread count picks the particle one thread would.
  double hMin = std::numeric_limits<double>::max(), v2Max = 0, a2Max = 0, cMax = 0, nuMax = 0;
  int iH = -1, iV = -1, iA = -1;  // the particles that set each extreme
  const std::int64_t n = static_cast<std::int64_t>(y_.size());
  // Beyond the extreme so far, or at it with a lower index (an extreme of 0 with no particle
  // yet stays without one: v2 = a2 = 0 sets none).
  auto takes = [](double x, int i, double best, int bestI, bool larger) {
    return (larger ? x > best : x < best) || (x == best && bestI >= 0 && i < bestI);
  };
  // The same for combining the shares, each with or without its particle.
  auto better = [&](double x, int i, double best, int bestI, bool larger) {
    return i >= 0 && (bestI < 0 || takes(x, i, best, bestI, larger));
  };
#pragma omp parallel if (n >= parallelFrom())
  {
    double h = std::numeric_limits<double>::max(), v2 = 0, a2 = 0;
    int ih = -1, iv = -1, ia = -1;
    walk(shareOf(n, omp_get_thread_num(), omp_get_num_threads()), [&](std::int64_t i) {
      const int k = static_cast<int>(i);
      if (takes(y_.h[i], k, h, ih, false)) h = y_.h[i], ih = k;
      const double vi2 = y_.v[i].squaredNorm(), ai2 = f_.dvdt[i].squaredNorm();
      if (takes(vi2, k, v2, iv, true)) v2 = vi2, iv = k;
      if (takes(ai2, k, a2, ia, true)) a2 = ai2, ia = k;
    });
#pragma omp critical
    {
      if (better(h, ih, hMin, iH, false)) hMin = h, iH = ih;
      if (better(v2, iv, v2Max, iV, true)) v2Max = v2, iV = iv;
      if (better(a2, ia, a2Max, iA, true)) a2Max = a2, iA = ia;
    }
  }
  if (domain_) {  // the whole domain's extremes (the particle named is this process's)
    double v[3] = {-hMin, v2Max, a2Max};
    domain_->maxAll(v, 3);
    hMin = -v[0], v2Max = v[1], a2Max = v[2];
  }
  for (const auto& ph : scene_.phases) {
    cMax = std::max(cMax, ph.c0);
    if (scene_.terms.morrisViscosity) nuMax = std::max(nuMax, ph.mu / ph.rho0);
  }
  // Morris, Fox & Zhu (1997) eqs. (34)-(36), with the flow speed added to the sound speed.
  const double acoustic = scene_.cflAcoustic * hMin / (cMax + std::sqrt(v2Max));
  const double viscous = nuMax > 0 ? scene_.cflViscous * hMin * hMin / nuMax : 1e300;
  const double accel = a2Max > 0 ? scene_.cflForce * std::sqrt(hMin / std::sqrt(a2Max)) : 1e300;
  limit = TimeStepLimit::acoustic;
  particle = iV >= 0 ? iV : iH;
  double dt = acoustic;
  if (viscous < dt) dt = viscous, limit = TimeStepLimit::viscous, particle = iH;
  if (accel < dt) dt = accel, limit = TimeStepLimit::acceleration, particle = iA;
  return dt;
}

template <int D>
std::optional<Failure> Simulation<D>::checkParticle(const Particles<D>& s, std::size_t i, double t,
                                                    long step) const {
  auto fail = [&](FailureCause cause, const std::string& what) {
    std::ostringstream m;
    m << "step " << step << ", t = " << t << " s, particle " << id_[i] << ": " << what;
    return Failure{cause, step, t, id_[i], m.str()};
  };
  if (!s.r[i].allFinite()) return fail(FailureCause::nan, "position is not finite");
  if (!s.v[i].allFinite()) return fail(FailureCause::nan, "velocity is not finite");
  if (!std::isfinite(s.rho[i])) return fail(FailureCause::nan, "density is not finite");
  if (!std::isfinite(s.h[i]) || s.h[i] <= 0)
    return fail(FailureCause::nan, "smoothing length is not finite and positive");
  const Phase& ph = scene_.phases[s.phase[i]];
  const double ratio = s.rho[i] / ph.rho0;
  if (ratio < scene_.densityBand[0] || ratio > scene_.densityBand[1]) {
    std::ostringstream m;
    m << "density " << s.rho[i] << " kg/m^3 is outside the band [" << scene_.densityBand[0] << ", "
      << scene_.densityBand[1] << "] x rho0 = " << ph.rho0 << " of phase '" << ph.name << "'";
    return fail(FailureCause::density_band, m.str());
  }
  for (int a = 0; a < D; ++a) {
    for (int side = 0; side < 2; ++side) {
      const FaceKind k = bounds_.face[a][side];
      if (k == FaceKind::periodic || leavesThrough(scene_, k)) continue;
      const bool out = side == 0 ? s.r[i][a] < bounds_.lower[a] : s.r[i][a] > bounds_.upper[a];
      if (!out) continue;
      std::ostringstream m;
      const char* axis[3] = {"x", "y", "z"};
      m << "position " << axis[a] << " = " << s.r[i][a] << " m is beyond the "
        << (side == 0 ? "lower " : "upper ") << axis[a] << " face at "
        << (side == 0 ? bounds_.lower[a] : bounds_.upper[a]) << " m";
      if (Boundaries<D>::isWall(k))
        return fail(FailureCause::wall_penetration, m.str() + " (crossed the wall)");
      return fail(FailureCause::escaped_domain, m.str() + " (left the domain)");
    }
  }
  return std::nullopt;
}

namespace {
constexpr double huge = std::numeric_limits<double>::max();  // x <= huge: x is not inf or NaN

// What a particle's update needs of the box, by value: read through the Simulation, each of
// them would be loaded again after every store to a particle (which might have changed it).
template <int D>
struct BoxFaces {
  double tolerated;  // the deepest crossing of a wall that is reflected (dx / 2)
  bool periodic[D], wall[D][2];
  double lo[D], period[D], at[D][2], normalVelocity[D][2];
  BoxFaces(const Boundaries<D>& b, double dx) : tolerated(0.5 * dx) {
    for (int a = 0; a < D; ++a) {
      periodic[a] = b.face[a][0] == FaceKind::periodic;
      lo[a] = b.lower[a], period[a] = b.upper[a] - b.lower[a];
      for (int side = 0; side < 2; ++side) {
        wall[a][side] = Boundaries<D>::isWall(b.face[a][side]);
        at[a][side] = side == 0 ? b.lower[a] : b.upper[a];
        normalVelocity[a][side] = b.wallVelocity[a][side][a];
      }
    }
  }
  void wrap(Vec<D>& r) const {
    for (int a = 0; a < D; ++a)
      if (periodic[a])
        r[a] = lo[a] + (r[a] - lo[a]) - period[a] * std::floor((r[a] - lo[a]) / period[a]);
  }
  // A particle less than dx/2 beyond a wall is mirrored back (Simulation::wallReflections).
  void reflect(Vec<D>& r, Vec<D>& v, long& count, double& deepest) const {
    for (int a = 0; a < D; ++a)
      for (int side = 0; side < 2; ++side) {
        if (!wall[a][side]) continue;
        const double depth = side == 0 ? at[a][side] - r[a] : r[a] - at[a][side];
        if (depth <= 0 || depth > tolerated) continue;  // deeper: check() reports the failure
        deepest = std::max(deepest, depth);
        r[a] = 2 * at[a][side] - r[a];
        v[a] = 2 * normalVelocity[a][side] - v[a];
        ++count;
      }
  }
};

// A test without branches that every good particle passes (finite fields, density in its band,
// inside the box's non-periodic faces); only one that fails it gets checkParticle's, which finds
// and names the fault.
template <int D>
struct Plausible {
  double lo[D], hi[D], bandLow, bandHigh;
  const Phase* phases;
  Plausible(const Scene& scene, const Boundaries<D>& bounds)
      : bandLow(scene.densityBand[0]), bandHigh(scene.densityBand[1]), phases(scene.phases.data()) {
    for (int a = 0; a < D; ++a) {
      auto unbounded = [&](FaceKind k) {
        return k == FaceKind::periodic || leavesThrough(scene, k);
      };
      lo[a] = unbounded(bounds.face[a][0]) ? -huge : bounds.lower[a];
      hi[a] = unbounded(bounds.face[a][1]) ? huge : bounds.upper[a];
    }
  }
  bool operator()(const Vec<D>& r, const Vec<D>& v, double rho, double h, int phase) const {
    const double ratio = rho / phases[phase].rho0;
    bool ok = (ratio >= bandLow) & (ratio <= bandHigh) & (h > 0) & (h <= huge);
    for (int a = 0; a < D; ++a)
      ok &= (r[a] >= lo[a]) & (r[a] <= hi[a]) & (v[a] >= -huge) & (v[a] <= huge);
    return ok;
  }
};
}  // namespace

template <int D>
std::optional<Failure> Simulation<D>::check(const Particles<D>& s, double t, long step) const {
  // The first bad particle by index, whatever the thread count (a min over the shares).
  const std::int64_t n = static_cast<std::int64_t>(s.size());
  const Plausible<D> plausible(scene_, bounds_);
  std::int64_t first = n;
#pragma omp parallel if (n >= parallelFrom()) reduction(min : first)
  walk(shareOf(n, omp_get_thread_num(), omp_get_num_threads()), [&](std::int64_t i) {
    if (!plausible(s.r[i], s.v[i], s.rho[i], s.h[i], s.phase[i]) && i < first &&
        checkParticle(s, i, t, step))
      first = i;
  });
  return failureFrom(s, first, t, step);
}

template <int D>
std::optional<Failure> Simulation<D>::failureFrom(const Particles<D>& s, std::int64_t first,
                                                  double t, long step) const {
  if (first < static_cast<std::int64_t>(s.size())) return checkParticle(s, first, t, step);
  if (boundary_->hasInnerSolids())
    if (const SolidCrossing c = boundary_->firstInside(s); c.particle >= 0) {
      std::ostringstream m;
      m << "step " << step << ", t = " << t << " s, particle " << id_[c.particle] << ": " << c.depth
        << " m inside " << c.solid << " (crossed its wall)";
      return Failure{FailureCause::wall_penetration, step, t, id_[c.particle], m.str()};
    }
  return std::nullopt;
}

template <int D>
void Simulation<D>::prepare() {
  if (ratesValid_) return;
  rates(y_, t_, f_);
  ratesValid_ = true;
  TimeStepLimit l;
  int who;
  if (dtFloor_ == 0) dtFloor_ = scene_.dtFloor > 0 ? scene_.dtFloor : 1e-4 * timeStep(l, who);
}

// The integrator's view of one step (integrators/StateUpdate.hpp): y and f(y), the trial state
// y* and its rates, and each stage's pass over the particles. A stage's update is inlined into
// the pass that also does the stage's other work (periodic wrap, reflection, the checks, the
// lists' motion): a parallel region less each (0.6 us on two threads whose cores share a cache,
// more when not: issue 7). Each thread writes the particles it reads in every other loop of the
// step (a copy by one thread would have the other's share of m and phase cross the cores twice
// a step). y*.p is not read by the trial evaluation: rates() takes p from the EOS, and the final
// stage sets the accepted state's p (the same EOS, so the same p the set's fluid entries get).
template <int D>
struct Simulation<D>::Stepper {
  Simulation& sim;
  const double dt;
  std::int64_t count;  // the particles of this process (an evaluation may migrate some)
  bool parallel;
  const BoxFaces<D> box;  // by value (see BoxFaces)
  Motion motion;          // of y* in its last stage
  std::optional<Failure> failure;
  const bool shifts;  // particle shifting in this step (one in shifting.every)

  Stepper(Simulation& s, double step)
      : sim(s),
        dt(step),
        count(static_cast<std::int64_t>(s.y_.size())),
        parallel(count >= parallelFrom()),
        box(s.bounds_, s.scene_.dx),
        shifts(s.shifting_ && s.step_ % s.scene_.shifting.every == 0) {
    sim.yStar_.resize(s.y_.size());
  }
  integrators::StateFields<D, false> state() const {
    const Particles<D>& y = sim.y_;
    return {y.r.data(), y.v.data(), y.rho.data(), y.h.data(), y.m.data(), y.phase.data()};
  }
  integrators::StateFields<D, true> trial() {
    Particles<D>& y = sim.yStar_;
    return {y.r.data(), y.v.data(), y.rho.data(), y.h.data(), y.m.data(), y.phase.data()};
  }
  integrators::RateFields<D> rates() const { return fieldsOf(sim.f_); }
  integrators::RateFields<D> trialRates() const { return fieldsOf(sim.fStar_); }
  static integrators::RateFields<D> fieldsOf(const Derivatives<D>& f) {
    return {f.dvdt.data(), f.drhodt.data(), f.dhdt.data()};
  }
  // f(y*) at t + `after` (sized by the evaluation), and with particle shifting the shifts the
  // final stage adds, from the interaction set of y* (the step's trial state) just built.
  // Over several processes with velocity Verlet, particles may move to other processes on the
  // way (rates()): state(), rates() and trial() are to be taken again after it.
  void evaluate(double after) {
    sim.rates(sim.yStar_, sim.t_ + after, sim.fStar_, motion, shifts && sim.shiftingSums_);
    count = static_cast<std::int64_t>(sim.y_.size()), parallel = count >= parallelFrom();
    if (!shifts) return;
    const double span = dt * sim.scene_.shifting.every;  // the steps the shift stands for
    if (sim.shiftingSums_)
      (*sim.shifting_)(sim.set_, span, sim.fStar_, sim.forces_, sim.shift_);
    else
      (*sim.shifting_)(sim.set_, span, sim.shift_);
  }

  // Stage::trial: update, wrap, motion. Returns true.
  template <class Update>
  bool move(Update update, integrators::StageTag<integrators::Stage::trial>) {
    Vec<D>* rS = sim.yStar_.r.data();
    const double* hS = sim.yStar_.h.data();
    motion = sim.motionStart(count);
    double hMax = 0, moved2 = 0, grown = 0;
    const BoxFaces<D> faces = box;
#pragma omp parallel if (parallel) reduction(max : hMax, moved2, grown)
    {
      Motion mine = motion;
      walk(shareOf(count, omp_get_thread_num(), omp_get_num_threads()),
           [&mine, faces, update, rS, hS](std::int64_t i) {
             update(i);
             faces.wrap(rS[i]);
             mine.add(rS[i], hS[i], i);
           });
      hMax = mine.hMax, moved2 = mine.moved2, grown = mine.grown;
    }
    motion.hMax = hMax, motion.moved2 = moved2, motion.grown = grown;
    return true;
  }

  // Stage::final: update, the pressure of the new density, wrap, the walls' reflection, then
  // the checks and the motion (after a custom reflection, which moves particles after this
  // pass, the checks wait for it). Returns false with `failure` set if a check fails.
  template <class Update>
  bool move(Update update, integrators::StageTag<integrators::Stage::final>) {
    Particles<D>& ys = sim.yStar_;
    Vec<D>* rS = ys.r.data();
    Vec<D>* vS = ys.v.data();
    const double *rhoS = ys.rho.data(), *hS = ys.h.data();
    double* pS = ys.p.data();
    const int* phaseS = ys.phase.data();
    const bool ownReflection = sim.reflectsItself();
    const Plausible<D> plausible(sim.scene_, sim.bounds_);
    const Phase* phases = sim.scene_.phases.data();
    const BoxFaces<D> faces = box;
    motion = sim.motionStart(count);
    long reflected = 0;
    double deepest = sim.reflectionDepth_, hMax = 0, moved2 = 0, grown = 0;
    std::int64_t first = count;
    const double t = sim.t_ + dt;
    const long step = sim.step_ + 1;
    const Simulation& checker = sim;
    const Vec<D>* shift = shifts ? sim.shift_.data() : nullptr;  // after the update
#pragma omp parallel if (parallel) reduction(+ : reflected) \
    reduction(max : deepest, hMax, moved2, grown) reduction(min : first)
    {
      Motion mine = motion;
      walk(
          shareOf(count, omp_get_thread_num(), omp_get_num_threads()), [
            &mine, &reflected, &deepest, &first, &checker, &ys, update, faces, plausible, phases,
            ownReflection, t, step, rS, vS, rhoS, hS, pS, phaseS, shift
          ](std::int64_t i) __attribute__((always_inline)) {
            update(i);
            if (shift) rS[i] += shift[i];
            pS[i] = TaitEquationOfState::pressure(rhoS[i], phases[phaseS[i]]);
            faces.wrap(rS[i]);
            faces.reflect(rS[i], vS[i], reflected, deepest);
            if (ownReflection) return;
            if (!plausible(rS[i], vS[i], rhoS[i], hS[i], phaseS[i]) && i < first &&
                checker.checkParticle(ys, i, t, step))
              first = i;
            mine.add(rS[i], hS[i], i);
          });
      hMax = mine.hMax, moved2 = mine.moved2, grown = mine.grown;
    }
    sim.reflections_ += reflected, sim.reflectionDepth_ = deepest;
    motion.hMax = hMax, motion.moved2 = moved2, motion.grown = grown;
    if (ownReflection) {
      if (sim.boundary_->hasInnerSolids()) {
        long put = 0;
        sim.boundary_->putBack(ys, faces.tolerated, put, sim.reflectionDepth_);
        sim.reflections_ += put;
      }
      if (sim.reflection_) sim.reflection_(ys);
      failure = sim.check(ys, t, step);
    } else {
      failure = sim.failureFrom(ys, first, t, step);
    }
    if (sim.domain_) sim.agree(failure);
    if (!failure && sim.check_) failure = sim.check_(ys, t, step);
    return !failure;
  }
};

template <int D>
template <class Integrator>
std::optional<Failure> Simulation<D>::advanceWith(double dtMax) {
  prepare();
  TimeStepLimit limit;
  int limiting = -1;
  const double dtStable = timeStep(limit, limiting);
  if (limiting >= 0) limiting = id_[limiting];
  if (!(dtStable >= dtFloor_)) {
    std::ostringstream m;
    m << "step " << step_ + 1 << ", t = " << t_ << " s, particle " << limiting << ": time step "
      << dtStable << " s collapsed below the floor " << dtFloor_ << " s ("
      << (limit == TimeStepLimit::acoustic  ? "acoustic"
          : limit == TimeStepLimit::viscous ? "viscous"
                                            : "acceleration")
      << " limit, set by this particle)";
    return Failure{FailureCause::dt_collapse, step_ + 1, t_, limiting, m.str()};
  }
  const double dt = std::min(dtStable, dtMax);
  Stepper step(*this, dt);
  if (!Integrator::advance(step, dt)) return step.failure;
  const bool ownReflection = reflectsItself();
  const Motion motion = step.motion;
  std::swap(y_, yStar_);
  t_ += dt, dt_ = dt, limit_ = limit;
  ++step_;
  const std::size_t before = y_.size();
  if constexpr (Integrator::evaluationsPerStep == 1) {
    // The trial state's rates are the new state's (the integrator says why).
    std::swap(f_, fStar_);
    if (cellOrderEvery_ > 0 && step_ % cellOrderEvery_ == 0) storeInCellOrder();
    if (scene_.leaving == Scene::Leaving::removed) removeDeparted();
    return std::nullopt;
  }
  if (cellOrderEvery_ > 0 && step_ % cellOrderEvery_ == 0) storeInCellOrder();
  if (scene_.leaving == Scene::Leaving::removed) removeDeparted();
  // The motion is of y's particles whatever their order (h_max does not depend on it); new
  // lists follow a new order (storeInCellOrder clears the positions they were built at), and so
  // do fewer particles.
  if (ownReflection || y_.size() != before)
    rates(y_, t_, f_);
  else
    rates(y_, t_, f_, motion);
  return std::nullopt;
}

template <int D>
void Simulation<D>::storeInCellOrder() {
  // The last evaluation was of the corrector's y*, whose particles have y's indices.
  const std::int64_t n = static_cast<std::int64_t>(y_.size());
  if (domain_) {
    // The owned entries of the set's fluid (placed_: the same particles as y's) in cell order,
    // numbered anew together with every other process's.
    forces_.cellOrder(placed_.size(), order_, &cells_);
    if (order_.size() != placed_.size()) return;
    std::vector<std::int64_t> cells, keys;
    std::size_t placed = 0;
    for (std::size_t k = 0; k < order_.size(); ++k)
      if (const int i = placed_[order_[k]]; i >= 0) {
        order_[placed++] = i;
        cells.push_back(cells_[k]), keys.push_back(key_[i]);
      }
    order_.resize(placed);
    domain_->renumber(cells, keys);
    key_ = std::move(keys);
  } else {
    forces_.cellOrder(y_.size(), order_);
  }
  if (static_cast<std::int64_t>(order_.size()) != n) return;
  Particles<D>& to = yStar_;  // free until the next step's predictor
  to.resize(n);
  idScratch_.resize(n);
  forEachInShares(n, [&](std::int64_t k) {
    const int i = order_[k];
    to.r[k] = y_.r[i], to.v[k] = y_.v[i], to.rho[k] = y_.rho[i], to.m[k] = y_.m[i];
    to.h[k] = y_.h[i], to.p[k] = y_.p[i], to.phase[k] = y_.phase[i];
    idScratch_[k] = id_[i];
  });
  std::swap(y_, to);
  std::swap(id_, idScratch_);
  listedAt_.clear();           // the lists were of the old order
  if (ratesOfState_) return;   // the next evaluation is of y
  Derivatives<D>& g = fStar_;  // free until the next step's evaluation
  g.resize(n);
  forEachInShares(n, [&](std::int64_t k) {
    const int i = order_[k];
    g.dvdt[k] = f_.dvdt[i], g.drhodt[k] = f_.drhodt[i], g.dhdt[k] = f_.dhdt[i];
  });
  std::swap(f_, g);
}

template <int D>
void Simulation<D>::Departure::appendTo(std::vector<double>& rows) const {
  rows.insert(rows.end(), {double(id), double(step), time});
  for (int a = 0; a < D; ++a) rows.push_back(r[a]);
  for (int a = 0; a < D; ++a) rows.push_back(v[a]);
  rows.insert(rows.end(), {m, rho, double(phase)});
}

template <int D>
typename Simulation<D>::Departure Simulation<D>::Departure::ofRow(const double* row) {
  Departure d{int(row[0]), long(row[1]),   row[2],         {},
              {},          row[3 + 2 * D], row[4 + 2 * D], int(row[5 + 2 * D])};
  for (int a = 0; a < D; ++a) d.r[a] = row[3 + a], d.v[a] = row[3 + D + a];
  return d;
}

template <int D>
void Simulation<D>::removeDeparted() {
  const std::int64_t n = static_cast<std::int64_t>(y_.size());
  Vec<D> lo, hi;  // beyond them a particle leaves (the other faces: never)
  for (int a = 0; a < D; ++a) {
    lo[a] = leavesThrough(scene_, bounds_.face[a][0]) ? bounds_.lower[a] : -huge;
    hi[a] = leavesThrough(scene_, bounds_.face[a][1]) ? bounds_.upper[a] : huge;
  }
  std::vector<int> gone;
  for (std::int64_t i = 0; i < n; ++i)
    for (int a = 0; a < D; ++a)
      if (y_.r[i][a] < lo[a] || y_.r[i][a] > hi[a]) {
        gone.push_back(static_cast<int>(i));
        break;
      }
  double any = gone.empty() ? 0.0 : 1.0;
  if (domain_) domain_->maxAll(&any, 1);
  if (any == 0.0) return;
  auto departure = [&](int i) {
    return Departure{id_[i], step_, t_, y_.r[i], y_.v[i], y_.m[i], y_.rho[i], y_.phase[i]};
  };
  if (!domain_) {
    for (const int i : gone) departures_.push_back(departure(i));
  } else {
    // In one process's order on process 0: the departed numbered together by key.
    std::vector<std::int64_t> place(gone.size()), zero(gone.size(), 0);
    std::vector<double> rows;
    for (std::size_t k = 0; k < gone.size(); ++k) {
      place[k] = key_[gone[k]];
      departure(gone[k]).appendTo(rows);
    }
    domain_->renumber(zero, place);
    std::vector<double> all;
    domain_->gather(rows, Departure::width, place, all);
    for (std::size_t k = 0; k < all.size() / Departure::width; ++k)
      departures_.push_back(Departure::ofRow(all.data() + k * Departure::width));
  }
  // The others close up, in their order.
  std::size_t kept = 0, next = 0;
  const bool rates = f_.drhodt.size() == y_.size();
  for (std::int64_t i = 0; i < n; ++i) {
    if (next < gone.size() && gone[next] == i) {
      ++next;
      continue;
    }
    y_.r[kept] = y_.r[i], y_.v[kept] = y_.v[i], y_.rho[kept] = y_.rho[i], y_.m[kept] = y_.m[i];
    y_.h[kept] = y_.h[i], y_.p[kept] = y_.p[i], y_.phase[kept] = y_.phase[i];
    id_[kept] = id_[i];
    if (domain_) key_[kept] = key_[i];
    if (rates)
      f_.dvdt[kept] = f_.dvdt[i], f_.drhodt[kept] = f_.drhodt[i], f_.dhdt[kept] = f_.dhdt[i];
    ++kept;
  }
  y_.resize(kept), id_.resize(kept);
  if (rates) f_.resize(kept);
  if (domain_) {
    key_.resize(kept);
    domain_->renumber(std::vector<std::int64_t>(kept, 0), key_);  // keys 0, 1, ... again
  }
  listedAt_.clear();  // the lists, cells and halo are made anew
}

template <int D>
std::vector<double> Simulation<D>::departedVolume() const {
  std::vector<double> v(scene_.phases.size(), 0.0);
  for (const Departure& d : departures_) v[d.phase] += d.m / d.rho;
  return v;
}

template <int D>
typename Simulation<D>::Resumable Simulation<D>::resumable() const {
  Resumable r;
  r.ids = id_;
  r.time = t_, r.lastDt = dt_, r.dtFloor = dtFloor_, r.reflectionDepth = reflectionDepth_;
  r.skin = skin_, r.limit = limit_;
  r.step = step_, r.evaluations = evaluations_, r.reflections = reflections_;
  r.reusedLists = reusedLists_;
  r.listedAt = listedAt_, r.listedH = listedH_;
  r.departures = departures_;
  return r;
}

template <int D>
void Simulation<D>::gatherWhole(Whole& w) const {
  w.state = resumable();
  if (!domain_) {
    w.particles = y_, w.rates = f_;
    return;
  }
  domain_->gather(y_, id_, key_, w.particles, w.state.ids);
  // Rates and listed state as rows: dv/dt, drho/dt, dh/dt, then the listed r and h if listed.
  const std::size_t n = y_.size();
  const bool listed = listedAt_.size() == n && n > 0;
  double anyListed = listed ? 1.0 : 0.0;
  domain_->maxAll(&anyListed, 1);
  const int width = D + 2 + (anyListed > 0 ? D + 1 : 0);
  std::vector<double> rows;
  rows.reserve(n * width);
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < D; ++a) rows.push_back(f_.dvdt[i][a]);
    rows.push_back(f_.drhodt[i]), rows.push_back(f_.dhdt[i]);
    if (anyListed > 0) {
      for (int a = 0; a < D; ++a) rows.push_back(listedAt_[i][a]);
      rows.push_back(listedH_[i]);
    }
  }
  std::vector<double> all;
  domain_->gather(rows, width, key_, all);
  double extremes[1] = {reflectionDepth_};
  domain_->maxAll(extremes, 1);
  w.state.reflectionDepth = extremes[0];
  w.state.reflections = domain_->sumAll(reflections_);
  if (domain_->rank() != 0) {
    w.state.listedAt.clear(), w.state.listedH.clear();
    return;
  }
  const std::size_t total = all.size() / width;
  w.rates.resize(total);
  w.state.listedAt.resize(anyListed > 0 ? total : 0),
      w.state.listedH.resize(w.state.listedAt.size());
  for (std::size_t k = 0; k < total; ++k) {
    const double* row = all.data() + k * width;
    for (int a = 0; a < D; ++a) w.rates.dvdt[k][a] = row[a];
    w.rates.drhodt[k] = row[D], w.rates.dhdt[k] = row[D + 1];
    if (anyListed > 0) {
      for (int a = 0; a < D; ++a) w.state.listedAt[k][a] = row[D + 2 + a];
      w.state.listedH[k] = row[2 * D + 2];
    }
  }
}

template <int D>
bool Simulation<D>::resume(const Resumable& whole, const Derivatives<D>& wholeRates, bool verify) {
  // Over several processes, this process's part: its particles' entries by key.
  Resumable own;
  Derivatives<D> ownRates;
  if (domain_) {
    const std::size_t total = whole.ids.size();
    for (const std::int64_t k : key_)
      if (k < 0 || static_cast<std::size_t>(k) >= total || wholeRates.drhodt.size() != total)
        throw std::invalid_argument("the particle ids or rates are not of the " +
                                    std::to_string(total) + " particles of the whole domain");
    own = whole;
    const std::size_t n = y_.size();
    own.ids.resize(n), ownRates.resize(n);
    const bool listed = whole.listedAt.size() == total;
    own.listedAt.resize(listed ? n : 0), own.listedH.resize(listed ? n : 0);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = static_cast<std::size_t>(key_[i]);
      own.ids[i] = whole.ids[k];
      ownRates.dvdt[i] = wholeRates.dvdt[k], ownRates.drhodt[i] = wholeRates.drhodt[k];
      ownRates.dhdt[i] = wholeRates.dhdt[k];
      if (listed) own.listedAt[i] = whole.listedAt[k], own.listedH[i] = whole.listedH[k];
    }
    // (the count is the whole domain's: process 0 carries it, the others none, as summed)
    if (domain_->rank() != 0) own.reflections = 0, own.departures.clear();
  }
  const Resumable& r = domain_ ? own : whole;
  const Derivatives<D>& rates = domain_ ? ownRates : wholeRates;
  const std::size_t n = y_.size();
  if (r.ids.size() != n || (!r.listedAt.empty() && r.listedAt.size() != n) ||
      r.listedH.size() != r.listedAt.size() || rates.drhodt.size() != n)
    throw std::invalid_argument("the particle ids, rates or neighbour lists are not of the " +
                                std::to_string(n) + " particles");
  id_ = r.ids;
  t_ = r.time, dt_ = r.lastDt, dtFloor_ = r.dtFloor, reflectionDepth_ = r.reflectionDepth;
  limit_ = r.limit, step_ = r.step, reflections_ = r.reflections;
  departures_ = r.departures;
  // The lists' build from the listed state: a rescan of the halo and the cell list of its
  // positions and h (the other fields set no list, no cell and no halo member).
  listedAt_.clear();
  const bool skinned = skinFraction_ > 0;  // as rates() decides it
  if (skinned && !r.listedAt.empty()) {
    Particles<D> listed = y_;
    listed.r = r.listedAt, listed.h = r.listedH;
    this->rates(listed, t_, fStar_);
  }
  bool same = true;
  // (rates carried from the step before, not of the state: nothing to evaluate them against)
  if (verify && ratesOfState_) {
    this->rates(y_, t_, f_);
    auto equal = [](const auto& a, const auto& b) {
      return std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
    };
    same = equal(f_.dvdt, rates.dvdt) && equal(f_.drhodt, rates.drhodt) &&
           equal(f_.dhdt, rates.dhdt) && (!skinned || skin_ == r.skin);
  } else {
    f_ = rates;
  }
  if (domain_) {  // the same on every process
    double differs = same ? 0.0 : 1.0;
    domain_->maxAll(&differs, 1);
    same = differs == 0.0;
  }
  ratesValid_ = true;
  evaluations_ = r.evaluations, reusedLists_ = r.reusedLists;  // the run's, not these
  return same;
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

}  // namespace sph
