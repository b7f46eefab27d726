#include "sph/Checkpoint.hpp"

#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <random>
#include <sstream>

#include "Hdf5Checked.hpp"
#include "sph/Run.hpp"

namespace sph {

namespace {

using hdf5::check;
using hdf5::Handle;
// The first format held a copy of the whole record under /record; the second lists segments.
constexpr const char* format = "sph-checkpoint-2";
constexpr const char* firstFormat = "sph-checkpoint-1";
constexpr const char* segmentFormat = "sph-checkpoint-record-1";

// Writing: every failure an OutputError naming the file (Hdf5Checked.hpp).
void putAttribute(hid_t object, const std::string& name, hid_t type, const void* value,
                  const std::string& path) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, path, "a dataspace");
  Handle a(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, path,
           "creating attribute " + name);
  check(H5Awrite(a, type, value), path, "writing attribute " + name);
}
void putNumber(hid_t object, const std::string& name, double value, const std::string& path) {
  putAttribute(object, name, H5T_NATIVE_DOUBLE, &value, path);
}
void putInteger(hid_t object, const std::string& name, std::int64_t value,
                const std::string& path) {
  putAttribute(object, name, H5T_NATIVE_INT64, &value, path);
}
void putText(hid_t object, const std::string& name, const std::string& value,
             const std::string& path) {
  Handle t(hdf5::stringType(value.size(), path), H5Tclose, path, "a string type");
  putAttribute(object, name, t, value.c_str(), path);
}

// A rows x columns dataset (1-D where columns is 1) of `type` from `data`.
void putArray(hid_t group, const std::string& name, hid_t type, const void* data, hsize_t rows,
              hsize_t columns, const std::string& path) {
  const hsize_t dims[2] = {rows, columns};
  Handle space(H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr), H5Sclose, path,
               "a dataspace");
  Handle d(H5Dcreate2(group, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
           H5Dclose, path, "creating dataset " + name);
  if (rows > 0) check(H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), path, name);
}
template <int D, class Vectors>
void putVectors(hid_t group, const std::string& name, const Vectors& v, const std::string& path) {
  static_assert(sizeof(Vec<D>) == D * sizeof(double));
  putArray(group, name, H5T_NATIVE_DOUBLE, v.data(), v.size(), D, path);
}
template <class Doubles>
void putDoubles(hid_t group, const std::string& name, const Doubles& v, const std::string& path) {
  putArray(group, name, H5T_NATIVE_DOUBLE, v.data(), v.size(), 1, path);
}
template <class Ints>
void putInts(hid_t group, const std::string& name, const Ints& v, const std::string& path) {
  static_assert(sizeof(v[0]) == 4);
  putArray(group, name, H5T_NATIVE_INT32, v.data(), v.size(), 1, path);
}

// Reading: every failure a CheckpointError naming the file and the item.
class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    if (!std::filesystem::exists(path)) fail("no such file");
    file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file_ < 0) fail("not an HDF5 file, or damaged (" + hdf5::reason() + ")");
    if (!has("/", "format") ||
        (text("/", "format") != format && text("/", "format") != firstFormat))
      fail(std::string("not a checkpoint of sph run (its root attribute format is not ") + format +
           ")");
  }
  // A record segment (Checkpoint.hpp) instead of a checkpoint.
  Reader(const std::string& path, const char* expected) : path_(path) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    if (!std::filesystem::exists(path)) fail("no such file");
    file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file_ < 0) fail("not an HDF5 file, or damaged (" + hdf5::reason() + ")");
    if (!has("/", "format") || text("/", "format") != expected)
      fail(std::string("its root attribute format is not ") + expected);
  }
  ~Reader() {
    if (file_ >= 0) H5Fclose(file_);
  }
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;
  hid_t file() const { return file_; }

  [[noreturn]] void fail(const std::string& what) const {
    throw CheckpointError(path_ + ": " + what);
  }
  bool has(const std::string& object, const std::string& attribute) const {
    const hid_t o = H5Oopen(file_, object.c_str(), H5P_DEFAULT);
    if (o < 0) return false;
    const htri_t e = H5Aexists(o, attribute.c_str());
    H5Oclose(o);
    return e > 0;
  }
  std::string text(const std::string& object, const std::string& attribute) const {
    const Object o(*this, object);
    const hid_t a = H5Aopen(o.id, attribute.c_str(), H5P_DEFAULT);
    if (a < 0) fail("missing attribute " + attribute + " of " + object);
    const hid_t t = H5Aget_type(a);
    std::string value;
    if (t >= 0 && H5Tget_class(t) == H5T_STRING && !H5Tis_variable_str(t)) {
      value.assign(H5Tget_size(t), '\0');
      if (H5Aread(a, t, value.data()) < 0) value.clear();
    }
    if (t >= 0) H5Tclose(t);
    H5Aclose(a);
    return value.substr(0, value.find('\0'));
  }
  double number(const std::string& object, const std::string& attribute) const {
    double v = 0;
    read(object, attribute, H5T_NATIVE_DOUBLE, &v);
    return v;
  }
  std::int64_t integer(const std::string& object, const std::string& attribute) const {
    std::int64_t v = 0;
    read(object, attribute, H5T_NATIVE_INT64, &v);
    return v;
  }
  std::uint64_t unsignedInteger(const std::string& object, const std::string& attribute) const {
    std::uint64_t v = 0;
    read(object, attribute, H5T_NATIVE_UINT64, &v);
    return v;
  }
  // The string dataset `name`.
  std::string textDataset(const std::string& name) const {
    const hid_t d = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
    if (d < 0) fail("missing dataset " + name);
    const hid_t t = H5Dget_type(d);
    std::string value;
    bool ok = t >= 0 && H5Tget_class(t) == H5T_STRING && !H5Tis_variable_str(t);
    if (ok) {
      value.assign(H5Tget_size(t), '\0');
      ok = H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, value.data()) >= 0;
    }
    if (t >= 0) H5Tclose(t);
    H5Dclose(d);
    if (!ok) fail("dataset " + name + " is not a readable string");
    return value.substr(0, value.find('\0'));
  }
  // Dataset `name` of `rows` x `columns` entries (1-D where columns is 1) into `out`, as `type`.
  void array(const std::string& name, hid_t type, void* out, std::size_t rows,
             std::size_t columns) const {
    const hid_t d = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
    if (d < 0) fail("missing dataset " + name);
    const hid_t space = H5Dget_space(d);
    hsize_t dims[2] = {0, 1};
    const int rank = space < 0 ? -1 : H5Sget_simple_extent_ndims(space);
    if (rank == 1 || rank == 2) H5Sget_simple_extent_dims(space, dims, nullptr);
    if (space >= 0) H5Sclose(space);
    const bool shape =
        rank == (columns == 1 ? 1 : 2) && dims[0] == rows && (columns == 1 || dims[1] == columns);
    const bool read =
        shape && (rows == 0 || H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out) >= 0);
    H5Dclose(d);
    if (!shape) {
      std::ostringstream m;
      m << "dataset " << name << " is not of " << rows << " x " << columns << " entries";
      fail(m.str());
    }
    if (!read) fail("dataset " + name + " cannot be read (" + hdf5::reason() + ")");
  }
  bool has(const std::string& name) const {
    return H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0;
  }
  // The length of dataset `name` along its first axis (its rows, for a table).
  std::size_t length(const std::string& name) const {
    const hid_t d = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
    if (d < 0) fail("missing dataset " + name);
    const hid_t space = H5Dget_space(d);
    hsize_t dims[H5S_MAX_RANK] = {};
    const bool ok = space >= 0 && H5Sget_simple_extent_ndims(space) >= 1 &&
                    H5Sget_simple_extent_dims(space, dims, nullptr) >= 0;
    if (space >= 0) H5Sclose(space);
    H5Dclose(d);
    if (!ok) fail("dataset " + name + " has no extent");
    return dims[0];
  }

 private:
  struct Object {
    Object(const Reader& r, const std::string& name)
        : id(H5Oopen(r.file_, name.c_str(), H5P_DEFAULT)) {
      if (id < 0) r.fail("missing " + name);
    }
    ~Object() { H5Oclose(id); }
    hid_t id;
  };
  void read(const std::string& object, const std::string& attribute, hid_t type, void* out) const {
    const Object o(*this, object);
    const hid_t a = H5Aopen(o.id, attribute.c_str(), H5P_DEFAULT);
    if (a < 0) fail("missing attribute " + attribute + " of " + object);
    const bool ok = H5Aread(a, type, out) >= 0;
    H5Aclose(a);
    if (!ok) fail("attribute " + attribute + " of " + object + " cannot be read as a number");
  }
  std::string path_;
  hid_t file_ = -1;
};

// fsync of a file or directory, so that the rename below never names a file whose data is not
// yet on the disk (a power cut after the rename would otherwise leave an empty checkpoint).
void sync(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) throw OutputError(path + ": cannot open it to sync (" + std::strerror(errno) + ")");
  const int synced = ::fsync(fd);
  ::close(fd);
  if (synced != 0)
    throw OutputError(path + ": cannot sync it to the disk (" + std::strerror(errno) + ")");
}

// The segments' directory of checkpoint `path` and run `run`, relative to the checkpoint's
// directory: <name>.checkpoint.record/<run> for <name>.checkpoint.h5.
std::string recordDirectory(const std::string& path, const std::string& run) {
  return (std::filesystem::path(path).stem().string() + ".record/") + run;
}
std::string segmentName(std::size_t k) {
  char name[32];
  std::snprintf(name, sizeof name, "%05zu.h5", k);
  return name;
}
std::uint64_t randomWord() {
  std::random_device device;
  std::uint64_t w = 0;
  while (w == 0) w = (std::uint64_t{device()} << 32) ^ device();
  return w;
}

// Segment `index` of `chain`: what the record of `runFile` gained since the last segment, written
// as <segment>.partial, synced and renamed to `segment`. Returns where the record then ends.
RunFile::RecordEnd writeSegment(const std::string& segment, const RecordChain& chain,
                                std::size_t index, std::uint64_t token, RunFile& runFile) {
  namespace fs = std::filesystem;
  const fs::path directory = fs::path(segment).parent_path();
  std::error_code e;
  fs::create_directories(directory, e);
  if (e) throw OutputError(directory.string() + ": cannot create it (" + e.message() + ")");
  const std::string writing = segment + ".partial";
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fcreate(writing.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file < 0) hdf5::fail(writing, "creating the record segment");
  RunFile::RecordEnd end;
  try {
    Handle root(H5Gopen2(file, "/", H5P_DEFAULT), H5Gclose, writing, "opening /");
    putText(root, "format", segmentFormat, writing);
    putText(root, "run", chain.run, writing);
    putInteger(root, "index", static_cast<std::int64_t>(index), writing);
    putAttribute(root, "token", H5T_NATIVE_UINT64, &token, writing);
    end = runFile.writeRecordSegment(file, writing);
  } catch (...) {
    H5Fclose(file);
    fs::remove(writing, e);
    throw;
  }
  if (H5Fclose(file) < 0) {
    fs::remove(writing, e);
    hdf5::fail(writing, "closing the record segment");
  }
  sync(writing);
  fs::rename(writing, segment, e);
  if (e) throw OutputError(writing + ": cannot rename it to " + segment + " (" + e.message() + ")");
  sync(directory.string());
  return end;
}

}  // namespace

RecordChain newRecordChain() {
  char run[17];
  std::snprintf(run, sizeof run, "%016llx", static_cast<unsigned long long>(randomWord()));
  return {run, {}};
}

void removeCheckpoint(const std::string& path) {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
  const std::filesystem::path p(path);
  std::filesystem::remove_all(p.parent_path() / (p.stem().string() + ".record"), ignored);
}

std::string checkpointPath(const std::string& outDir, const Scene& scene) {
  return (std::filesystem::path(outDir) / (scene.name + ".checkpoint.h5")).string();
}

namespace {

template <int D>
void writeState(const std::string& path, const Scene& scene, const Particles<D>& y,
                typename Simulation<D>::Resumable state, const Derivatives<D>& f,
                const RunProgress& progress, RunFile& runFile, std::vector<SeriesColumn>& series,
                RecordChain& chain, const StepCounters* failedStep) {
  namespace fs = std::filesystem;
  runFile.appendSeries(series);
  // The record's new segment, in place before the checkpoint that lists it.
  const std::string directory = recordDirectory(path, chain.run);
  const fs::path segments = fs::absolute(path).parent_path() / directory;
  const std::size_t index = chain.tokens.size();
  const std::uint64_t token = randomWord();
  const std::string segment = (segments / segmentName(index)).string();
  RunFile::RecordEnd recordEnd = writeSegment(segment, chain, index, token, runFile);
  std::vector<std::uint64_t> tokens = chain.tokens;
  tokens.push_back(token);
  const std::string writing = path + ".partial";
  if (failedStep) {
    state.evaluations = failedStep->evaluations, state.reusedLists = failedStep->reusedLists;
    state.reflections = failedStep->reflections;
    state.reflectionDepth = failedStep->reflectionDepth;
  }
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fcreate(writing.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file < 0) hdf5::fail(writing, "creating the checkpoint");
  // The writes, each object closed before the file is: a failed close of the file (a full disk)
  // is then seen.
  auto write = [&] {
    Handle root(H5Gopen2(file, "/", H5P_DEFAULT), H5Gclose, writing, "opening /");
    putText(root, "format", format, writing);
    putInteger(root, "dimension", D, writing);
    putText(root, "scene_file", scene.file, writing);
    putText(root, "run_file", fs::path(runFile.path()).filename().string(), writing);
    putText(root, "git_commit", provenance().commit, writing);
    putNumber(root, "time", state.time, writing);
    putInteger(root, "step", state.step, writing);
    putInteger(root, "after_failure", failedStep ? 1 : 0, writing);
    {
      Handle t(hdf5::stringType(scene.text.size(), writing), H5Tclose, writing, "a string type");
      Handle space(H5Screate(H5S_SCALAR), H5Sclose, writing, "a dataspace");
      Handle d(H5Dcreate2(file, "/scene", t, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
               H5Dclose, writing, "creating /scene");
      check(H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, scene.text.c_str()), writing, "/scene");
    }
    Handle g(H5Gcreate2(file, "/state", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, writing,
             "creating /state");
    putVectors<D>(g, "position", y.r, writing), putVectors<D>(g, "velocity", y.v, writing);
    putDoubles(g, "density", y.rho, writing), putDoubles(g, "mass", y.m, writing);
    putDoubles(g, "h", y.h, writing), putDoubles(g, "pressure", y.p, writing);
    putInts(g, "phase", y.phase, writing), putInts(g, "id", state.ids, writing);
    putVectors<D>(g, "dvdt", f.dvdt, writing), putDoubles(g, "drhodt", f.drhodt, writing);
    putDoubles(g, "dhdt", f.dhdt, writing);
    putVectors<D>(g, "listed_position", state.listedAt, writing);
    putDoubles(g, "listed_h", state.listedH, writing);
    std::vector<double> departed;  // a row a departure (Simulation::Departure::appendTo)
    for (const auto& d : state.departures) d.appendTo(departed);
    putArray(g, "departures", H5T_NATIVE_DOUBLE, departed.data(), state.departures.size(),
             Simulation<D>::Departure::width, writing);
    putNumber(g, "time", state.time, writing), putNumber(g, "last_dt", state.lastDt, writing);
    putNumber(g, "dt_floor", state.dtFloor, writing);
    putNumber(g, "reflection_depth", state.reflectionDepth, writing);
    putNumber(g, "skin", state.skin, writing);
    putInteger(g, "dt_limiter", static_cast<std::int64_t>(state.limit), writing);
    putInteger(g, "step", state.step, writing);
    putInteger(g, "force_evaluations", state.evaluations, writing);
    putInteger(g, "kept_neighbour_lists", state.reusedLists, writing);
    putInteger(g, "wall_reflections", state.reflections, writing);
    Handle p(H5Gcreate2(file, "/progress", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
             writing, "creating /progress");
    putNumber(p, "next_snapshot", progress.nextSnapshot, writing);
    putNumber(p, "next_checkpoint", progress.nextCheckpoint, writing);
    putInteger(p, "recorded", progress.recorded, writing);
    putInteger(p, "snapshotted", progress.snapshotted, writing);
    putNumber(p, "total_volume0", progress.total0, writing);
    putNumber(p, "energy_kinetic", progress.energyKinetic, writing);
    putNumber(p, "energy_internal", progress.energyInternal, writing);
    putNumber(p, "energy_potential", progress.energyPotential, writing);
    putNumber(p, "energy_round_off", progress.energyRoundOff, writing);
    putDoubles(p, "volume0", progress.volume0, writing);
    putDoubles(p, "max_variation", progress.maxVariation, writing);
    putText(root, "record_directory", directory, writing);
    putText(root, "record_run", chain.run, writing);
    Handle r(H5Gcreate2(file, "/record", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, writing,
             "creating /record");
    putArray(r, "tokens", H5T_NATIVE_UINT64, tokens.data(), tokens.size(), 1, writing);
  };
  try {
    write();
  } catch (...) {
    H5Fclose(file);
    std::error_code ignored;
    fs::remove(writing, ignored);
    throw;
  }
  if (H5Fclose(file) < 0) {
    std::error_code ignored;
    fs::remove(writing, ignored);
    hdf5::fail(writing, "closing the checkpoint");
  }
  sync(writing);
  std::error_code e;
  fs::rename(writing, path, e);
  if (e) throw OutputError(writing + ": cannot rename it to " + path + " (" + e.message() + ")");
  sync(fs::absolute(path).parent_path().string());
  runFile.segmented(std::move(recordEnd));
  chain.tokens = std::move(tokens);
  // What no checkpoint lists any more: other runs' chains, and this chain's segments past the
  // new one (written for a checkpoint that was cut short).
  std::vector<fs::path> stale;
  for (auto it = fs::directory_iterator(segments.parent_path(), e);
       !e && it != fs::directory_iterator(); it.increment(e))
    if (it->path().filename() != chain.run) stale.push_back(it->path());
  for (const fs::path& other : stale) fs::remove_all(other, e);
  for (std::size_t k = index + 1; fs::exists(segments / segmentName(k), e); ++k)
    fs::remove(segments / segmentName(k), e);
}

}  // namespace

Scene checkpointScene(const std::string& path) {
  const Reader r(path);
  const std::string text = r.textDataset("/scene");
  const std::string file = r.text("/", "scene_file");
  try {
    return parseScene(text, file);
  } catch (const SceneError& e) {
    r.fail(std::string("its scene does not read: ") + e.what());
  }
}

template <int D>
void writeCheckpoint(const std::string& path, const Simulation<D>& sim, const RunProgress& progress,
                     RunFile& runFile, std::vector<SeriesColumn>& series, RecordChain& chain,
                     const StepCounters* failedStep) {
  writeState<D>(path, sim.scene(), sim.particles(), sim.resumable(), sim.currentRates(), progress,
                runFile, series, chain, failedStep);
}

template <int D>
void writeCheckpoint(const std::string& path, const Scene& scene,
                     const typename Simulation<D>::Whole& whole, const RunProgress& progress,
                     RunFile& runFile, std::vector<SeriesColumn>& series, RecordChain& chain,
                     const StepCounters* failedStep) {
  writeState<D>(path, scene, whole.particles, whole.state, whole.rates, progress, runFile, series,
                chain, failedStep);
}

template <int D>
CheckpointState<D> readCheckpoint(const std::string& path, const Scene& scene) {
  const Reader r(path);
  if (r.integer("/", "dimension") != D || scene.dimension != D)
    r.fail("its dimension is not the scene's");
  CheckpointState<D> c;
  const std::size_t n = r.length("/state/density");
  if (n == 0) r.fail("no particles in /state");
  Particles<D>& y = c.particles;
  y.resize(n);
  auto& s = c.simulation;
  s.ids.resize(n);
  r.array("/state/position", H5T_NATIVE_DOUBLE, y.r.data(), n, D);
  r.array("/state/velocity", H5T_NATIVE_DOUBLE, y.v.data(), n, D);
  r.array("/state/density", H5T_NATIVE_DOUBLE, y.rho.data(), n, 1);
  r.array("/state/mass", H5T_NATIVE_DOUBLE, y.m.data(), n, 1);
  r.array("/state/h", H5T_NATIVE_DOUBLE, y.h.data(), n, 1);
  r.array("/state/pressure", H5T_NATIVE_DOUBLE, y.p.data(), n, 1);
  r.array("/state/phase", H5T_NATIVE_INT32, y.phase.data(), n, 1);
  r.array("/state/id", H5T_NATIVE_INT32, s.ids.data(), n, 1);
  c.rates.resize(n);
  r.array("/state/dvdt", H5T_NATIVE_DOUBLE, c.rates.dvdt.data(), n, D);
  r.array("/state/drhodt", H5T_NATIVE_DOUBLE, c.rates.drhodt.data(), n, 1);
  r.array("/state/dhdt", H5T_NATIVE_DOUBLE, c.rates.dhdt.data(), n, 1);
  const std::size_t listed = r.length("/state/listed_h");
  if (listed != 0 && listed != n) r.fail("/state/listed_h is neither empty nor of every particle");
  s.listedAt.resize(listed), s.listedH.resize(listed);
  r.array("/state/listed_position", H5T_NATIVE_DOUBLE, s.listedAt.data(), listed, D);
  r.array("/state/listed_h", H5T_NATIVE_DOUBLE, s.listedH.data(), listed, 1);
  // The particles that left the run (none in a checkpoint written before they could).
  if (r.has("/state/departures")) {
    using Departure = typename Simulation<D>::Departure;
    const std::size_t rows = r.length("/state/departures");
    std::vector<double> all(rows * Departure::width);
    r.array("/state/departures", H5T_NATIVE_DOUBLE, all.data(), rows, Departure::width);
    for (std::size_t k = 0; k < rows; ++k) {
      const Departure d = Departure::ofRow(all.data() + k * Departure::width);
      if (d.phase < 0 || static_cast<std::size_t>(d.phase) >= scene.phases.size())
        r.fail("/state/departures names a phase the scene does not have");
      s.departures.push_back(d);
    }
  }
  // Every id once, among the particles and those that left, and every phase the scene's: else
  // the state is not of this scene.
  const std::size_t ever = n + s.departures.size();
  std::vector<char> seen(ever, 0);
  for (const auto& d : s.departures)
    if (d.id < 0 || static_cast<std::size_t>(d.id) >= ever || seen[d.id]++)
      r.fail("/state/departures and /state/id do not number the particles once each");
  for (std::size_t k = 0; k < n; ++k) {
    const int id = s.ids[k];
    if (id < 0 || static_cast<std::size_t>(id) >= ever || seen[id]++)
      r.fail("/state/id and /state/departures do not number the particles once each");
    if (y.phase[k] < 0 || static_cast<std::size_t>(y.phase[k]) >= scene.phases.size())
      r.fail("/state/phase names a phase the scene does not have");
  }
  s.time = r.number("/state", "time"), s.lastDt = r.number("/state", "last_dt");
  s.dtFloor = r.number("/state", "dt_floor");
  s.reflectionDepth = r.number("/state", "reflection_depth");
  s.skin = r.number("/state", "skin");
  const std::int64_t limit = r.integer("/state", "dt_limiter");
  if (limit < 0 || limit > 2) r.fail("/state dt_limiter is not 0, 1 or 2");
  s.limit = static_cast<TimeStepLimit>(limit);
  s.step = r.integer("/state", "step");
  s.evaluations = r.integer("/state", "force_evaluations");
  s.reusedLists = r.integer("/state", "kept_neighbour_lists");
  s.reflections = r.integer("/state", "wall_reflections");
  RunProgress& p = c.progress;
  p.nextSnapshot = r.number("/progress", "next_snapshot");
  p.nextCheckpoint = r.number("/progress", "next_checkpoint");
  p.recorded = r.integer("/progress", "recorded");
  p.snapshotted = r.integer("/progress", "snapshotted");
  p.total0 = r.number("/progress", "total_volume0");
  p.energyKinetic = r.number("/progress", "energy_kinetic");
  p.energyInternal = r.number("/progress", "energy_internal");
  p.energyPotential = r.number("/progress", "energy_potential");
  p.energyRoundOff = r.number("/progress", "energy_round_off");
  const std::size_t phases = scene.phases.size();
  p.volume0.resize(r.length("/progress/volume0"));
  if (p.volume0.size() != phases && !p.volume0.empty())
    r.fail("/progress/volume0 is not of the scene's phases");
  r.array("/progress/volume0", H5T_NATIVE_DOUBLE, p.volume0.data(), p.volume0.size(), 1);
  p.maxVariation.resize(phases + 1);
  r.array("/progress/max_variation", H5T_NATIVE_DOUBLE, p.maxVariation.data(), phases + 1, 1);
  c.runFile = r.text("/", "run_file");
  c.commit = r.text("/", "git_commit");
  c.afterFailure = r.integer("/", "after_failure") != 0;
  return c;
}

namespace {
// The segments checkpoint `r` (of the second format) lists, open and checked: each there, of
// its chain and index, with the token the checkpoint gave it.
struct Segments {
  RecordChain chain;
  std::vector<std::unique_ptr<Reader>> open;
  std::vector<std::int64_t> files;
  std::vector<std::string> paths;
};
Segments openSegments(const Reader& r, const std::string& path) {
  Segments s;
  s.chain.run = r.text("/", "record_run");
  s.chain.tokens.resize(r.length("/record/tokens"));
  if (s.chain.tokens.empty()) r.fail("/record/tokens lists no segment");
  r.array("/record/tokens", H5T_NATIVE_UINT64, s.chain.tokens.data(), s.chain.tokens.size(), 1);
  const std::filesystem::path directory =
      std::filesystem::absolute(path).parent_path() / r.text("/", "record_directory");
  for (std::size_t k = 0; k < s.chain.tokens.size(); ++k) {
    const std::string segment = (directory / segmentName(k)).string();
    try {
      s.open.push_back(std::make_unique<Reader>(segment, segmentFormat));
    } catch (const CheckpointError& e) {
      r.fail(std::string("its record segment ") + e.what());
    }
    const Reader& g = *s.open.back();
    if (g.text("/", "run") != s.chain.run ||
        g.integer("/", "index") != static_cast<std::int64_t>(k) ||
        g.unsignedInteger("/", "token") != s.chain.tokens[k])
      r.fail("its record segment " + segment +
             " is not the one it wrote (of another run, or written again since)");
    s.files.push_back(g.file()), s.paths.push_back(segment);
  }
  return s;
}
}  // namespace

void checkCheckpointRecord(const std::string& path) {
  const Reader r(path);
  if (r.text("/", "format") != firstFormat) openSegments(r, path);
}

RecordChain adoptCheckpointRecord(const std::string& path, RunFile& runFile) {
  const Reader r(path);
  if (r.text("/", "format") == firstFormat) {
    runFile.adoptRecord(r.file(), "/record");
    return {};
  }
  Segments s = openSegments(r, path);
  runFile.adoptRecordSegments(s.files, s.paths);
  return std::move(s.chain);
}

template void writeCheckpoint<1>(const std::string&, const Simulation<1>&, const RunProgress&,
                                 RunFile&, std::vector<SeriesColumn>&, RecordChain&,
                                 const StepCounters*);
template void writeCheckpoint<1>(const std::string&, const Scene&,
                                 const typename Simulation<1>::Whole&, const RunProgress&, RunFile&,
                                 std::vector<SeriesColumn>&, RecordChain&, const StepCounters*);
template void writeCheckpoint<2>(const std::string&, const Simulation<2>&, const RunProgress&,
                                 RunFile&, std::vector<SeriesColumn>&, RecordChain&,
                                 const StepCounters*);
template void writeCheckpoint<2>(const std::string&, const Scene&,
                                 const typename Simulation<2>::Whole&, const RunProgress&, RunFile&,
                                 std::vector<SeriesColumn>&, RecordChain&, const StepCounters*);
template void writeCheckpoint<3>(const std::string&, const Simulation<3>&, const RunProgress&,
                                 RunFile&, std::vector<SeriesColumn>&, RecordChain&,
                                 const StepCounters*);
template void writeCheckpoint<3>(const std::string&, const Scene&,
                                 const typename Simulation<3>::Whole&, const RunProgress&, RunFile&,
                                 std::vector<SeriesColumn>&, RecordChain&, const StepCounters*);
template CheckpointState<1> readCheckpoint<1>(const std::string&, const Scene&);
template CheckpointState<2> readCheckpoint<2>(const std::string&, const Scene&);
template CheckpointState<3> readCheckpoint<3>(const std::string&, const Scene&);

}  // namespace sph
