#include "sph/RunFile.hpp"

#include <hdf5.h>
#include <sys/resource.h>
#include <sys/statvfs.h>

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <utility>

#include "Hdf5Checked.hpp"
#include "XdmfSidecar.hpp"

namespace sph {

namespace {

using hdf5::check;
using hdf5::Handle;

// HDF5 closes what is left open at exit (atexit). A file whose close failed (a full disk) stays in
// its tables half closed, and closing it again there segfaulted: the library is told to leave it.
// Set before any other HDF5 call, at static initialisation.
[[maybe_unused]] const bool noCleanupAtExit = (H5dont_atexit(), true);

// Whether the absolute path `group` exists: H5Lexists fails (rather than says no) where a
// component above the last is missing, so each is asked in turn.
bool exists(hid_t file, const std::string& group, const std::string& path) {
  for (std::size_t end = group.find('/', 1);; end = group.find('/', end + 1)) {
    const std::string part = group.substr(0, end);
    const htri_t e = H5Lexists(file, part.c_str(), H5P_DEFAULT);
    if (e < 0) hdf5::fail(path, "looking up " + part);
    if (e == 0) return false;
    if (end == std::string::npos) return true;
  }
}

hid_t openGroup(hid_t file, const std::string& group, const std::string& path) {
  if (group == "/") return H5Gopen2(file, "/", H5P_DEFAULT);
  if (exists(file, group, path)) return H5Gopen2(file, group.c_str(), H5P_DEFAULT);
  Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose, path, "a property list");
  check(H5Pset_create_intermediate_group(lcpl, 1), path, "a property list");
  return H5Gcreate2(file, group.c_str(), lcpl, H5P_DEFAULT, H5P_DEFAULT);
}

void writeAttribute(hid_t object, const std::string& name, hid_t type, const void* data,
                    const std::string& path) {
  const htri_t exists = H5Aexists(object, name.c_str());
  if (exists < 0) hdf5::fail(path, "looking up attribute " + name);
  if (exists > 0) check(H5Adelete(object, name.c_str()), path, "replacing attribute " + name);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, path, "a dataspace");
  Handle a(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, path,
           "creating attribute " + name);
  check(H5Awrite(a, type, data), path, "writing attribute " + name);
}

template <class T>
void writeArray(hid_t group, const std::string& name, hid_t type, const std::vector<T>& data,
                std::size_t columns, const std::string& path) {
  hsize_t dims[2] = {data.size() / columns, columns};
  Handle space(H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr), H5Sclose, path,
               "a dataspace");
  Handle d(H5Dcreate2(group, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
           H5Dclose, path, "creating dataset " + name);
  if (!data.empty())
    check(H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), path, name);
}

// <name>.h5 -> <name>.xdmf
std::string xdmfOf(const std::string& h5) {
  return std::filesystem::path(h5).replace_extension(".xdmf").string();
}

// What a snapshot adds besides its arrays (groups, dataset headers, attributes) and what a series
// append may add (a new 1024-entry chunk of 8 bytes per column), with room to spare: 256 KiB.
constexpr double reserve = 256.0 * 1024.0;

}  // namespace

RunFile::RunFile(const std::string& path) : path_(path), writing_(path + ".partial") {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = H5Fcreate(writing_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) hdf5::fail(writing_, "creating the run file");
  std::string limit;
  const double left = room(limit);
  if (left < reserve) {  // no room to start: nothing is left behind
    H5Fclose(file_);
    file_ = -1;
    std::error_code ignored;
    std::filesystem::remove(writing_, ignored);
    std::ostringstream m;
    m.precision(3);
    m << writing_ << ": only " << left / 1048576.0 << " MiB left " << limit
      << ": the run cannot start";
    throw OutputError(m.str());
  }
  attribute("format", std::string("sph-run-1"));
}

RunFile::~RunFile() {
  if (file_ >= 0) H5Fclose(file_);  // a failure here has been reported, or the run is failing
}

template <class Write>
void RunFile::guarded(Write&& write) {
  if (broken_ || file_ < 0)
    throw OutputError(writing_ + ": the run file takes no more writes (an earlier one failed)");
  try {
    write();
  } catch (const OutputError& e) {
    markFailed(e.what());
    throw;
  }
}

void RunFile::markFailed(const std::string& why) {
  if (broken_) return;
  broken_ = true;
  // Best effort: after a failed HDF5 write these fail too, after a failed XDMF write they hold.
  try {
    Handle root(H5Gopen2(file_, "/", H5P_DEFAULT), H5Gclose, writing_, "opening /");
    const std::string status = "output_error";
    for (const auto& [name, value] : {std::pair{"status", status}, std::pair{"failure", why}}) {
      Handle t(hdf5::stringType(value.size(), writing_), H5Tclose, writing_, "a string type");
      writeAttribute(root, name, t, value.c_str(), writing_);
    }
    check(H5Fflush(file_, H5F_SCOPE_GLOBAL), writing_, "flushing the run file");
  } catch (const OutputError&) {
  }
}

void RunFile::finish() {
  namespace fs = std::filesystem;
  ensureRoom(0.0);
  flush();
  const herr_t closed = H5Fclose(file_);
  file_ = -1;
  broken_ = true;  // no more writes
  if (closed < 0) hdf5::fail(writing_, "closing the run file");
  // The final sidecar (naming <name>.h5) first, as the partial one, so that a failure to write it
  // leaves the earlier run's pair in place; then both renamed.
  std::vector<XdmfSnapshot> entries;
  for (const Entry& s : snapshots_) entries.push_back({s.group, s.time, s.n});
  const std::string xdmf = xdmfOf(path_);
  writeXdmf(xdmf + ".partial", path_, entries);
  for (const auto& [from, to] : {std::pair{writing_, path_}, std::pair{xdmf + ".partial", xdmf}}) {
    std::error_code e;
    fs::rename(from, to, e);
    if (e) throw OutputError(from + ": cannot rename it to " + to + " (" + e.message() + ")");
  }
}

double RunFile::room(std::string& limit) const {
  namespace fs = std::filesystem;
  double room = 1e300;
  struct statvfs v {};
  if (statvfs(fs::absolute(writing_).parent_path().c_str(), &v) == 0) {
    room = static_cast<double>(v.f_bavail) * static_cast<double>(v.f_frsize);
    limit = "free on its file system";
  }
  // ulimit -f applies to each file: the HDF5 file, and the XDMF sidecar, which grows by
  // some 1.7 kB a snapshot.
  rlimit fsize{};
  if (getrlimit(RLIMIT_FSIZE, &fsize) == 0 && fsize.rlim_cur != RLIM_INFINITY) {
    std::error_code e;
    const double size = static_cast<double>(fs::file_size(writing_, e));
    const double cap = static_cast<double>(fsize.rlim_cur);
    const double left = std::min(cap - (e ? 0.0 : size), cap - 1700.0 * (snapshots_.size() + 2));
    if (left < room) room = left, limit = "below the file size limit (ulimit -f)";
  }
  return std::max(room, 0.0);
}

void RunFile::ensureRoom(double bytes) {
  const double need = 2.0 * bytes + reserve;
  std::string limit;
  const double room = this->room(limit);
  if (room >= need) return;
  std::ostringstream m;
  m.precision(3);
  m << writing_ << ": only " << room / 1048576.0 << " MiB left " << limit << ", and the next "
    << (bytes > 0 ? "snapshot needs" : "writes need") << " about " << need / 1048576.0
    << " MiB: the run stops here; the file holds the run to ";
  if (snapshots_.empty())
    m << "its start";
  else
    m << "t = " << snapshots_.back().time << " s (its last snapshot), status output_error";
  markFailed(m.str());  // within the reserve
  throw OutputError(m.str());
}

void RunFile::attribute(const std::string& name, const std::string& value,
                        const std::string& group) {
  guarded([&] {
    Handle t(hdf5::stringType(value.size(), writing_), H5Tclose, writing_, "a string type");
    Handle g(openGroup(file_, group, writing_), H5Gclose, writing_, "opening " + group);
    writeAttribute(g, name, t, value.c_str(), writing_);
  });
}
void RunFile::attribute(const std::string& name, double value, const std::string& group) {
  guarded([&] {
    Handle g(openGroup(file_, group, writing_), H5Gclose, writing_, "opening " + group);
    writeAttribute(g, name, H5T_NATIVE_DOUBLE, &value, writing_);
  });
}
void RunFile::attribute(const std::string& name, std::int64_t value, const std::string& group) {
  guarded([&] {
    Handle g(openGroup(file_, group, writing_), H5Gclose, writing_, "opening " + group);
    writeAttribute(g, name, H5T_NATIVE_INT64, &value, writing_);
  });
}

void RunFile::text(const std::string& dataset, const std::string& value) {
  guarded([&] {
    Handle t(hdf5::stringType(value.size(), writing_), H5Tclose, writing_, "a string type");
    Handle space(H5Screate(H5S_SCALAR), H5Sclose, writing_, "a dataspace");
    Handle d(H5Dcreate2(file_, dataset.c_str(), t, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose, writing_, "creating " + dataset);
    check(H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, value.c_str()), writing_, dataset);
  });
}

void RunFile::array(const std::string& group, const std::string& name,
                    const std::vector<double>& values) {
  guarded([&] {
    Handle g(openGroup(file_, group, writing_), H5Gclose, writing_, "opening " + group);
    writeArray(g, name, H5T_NATIVE_DOUBLE, values, 1, writing_);
  });
}

namespace {

// /series/<name>: opened, or made (chunked, extendable) with its attributes.
hid_t seriesColumn(hid_t g, const SeriesColumn& c, hid_t type, const std::string& path) {
  const std::string where = "/series/" + c.name;
  const htri_t exists = H5Lexists(g, c.name.c_str(), H5P_DEFAULT);
  if (exists < 0) hdf5::fail(path, "looking up " + where);
  if (exists > 0) return H5Dopen2(g, c.name.c_str(), H5P_DEFAULT);
  hsize_t zero = 0, unlimited = H5S_UNLIMITED, chunk = 1024;
  Handle space(H5Screate_simple(1, &zero, &unlimited), H5Sclose, path, "a dataspace");
  Handle plist(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, path, "a property list");
  check(H5Pset_chunk(plist, 1, &chunk), path, "chunking " + where);
  const hid_t d = H5Dcreate2(g, c.name.c_str(), type, space, H5P_DEFAULT, plist, H5P_DEFAULT);
  if (d < 0) hdf5::fail(path, "creating " + where);
  try {
    for (const auto& [key, value] : c.text) {
      Handle t(hdf5::stringType(value.size(), path), H5Tclose, path, "a string type");
      writeAttribute(d, key, t, value.c_str(), path);
    }
    for (const auto& [key, value] : c.numbers)
      writeAttribute(d, key, H5T_NATIVE_DOUBLE, &value, path);
  } catch (...) {
    H5Dclose(d);
    throw;
  }
  return d;
}

// Rows [old, old + add) of the one-dimensional dataset `d` (at `where` in the file at `path`),
// extended to hold them, written from `rows` of the memory type `type`.
void appendRows(hid_t d, hid_t type, hsize_t old, hsize_t add, const void* rows,
                const std::string& path, const std::string& where) {
  hsize_t total = old + add;
  check(H5Dset_extent(d, &total), path, "extending " + where);
  Handle file(H5Dget_space(d), H5Sclose, path, "the extent of " + where);
  check(H5Sselect_hyperslab(file, H5S_SELECT_SET, &old, nullptr, &add, nullptr), path,
        "selecting in " + where);
  Handle mem(H5Screate_simple(1, &add, nullptr), H5Sclose, path, "a dataspace");
  check(H5Dwrite(d, type, mem, file, H5P_DEFAULT, rows), path, where);
}

}  // namespace

void RunFile::appendSeries(std::vector<SeriesColumn>& columns) {
  guarded([&] {
    Handle g(openGroup(file_, "/series", writing_), H5Gclose, writing_, "opening /series");
    for (auto& c : columns) {
      // step and dt_limiter are integers in the schema; everything else is double.
      const bool isStep = c.name == "step", isLimiter = c.name == "dt_limiter";
      const hid_t type = isStep      ? H5T_NATIVE_INT64
                         : isLimiter ? H5T_NATIVE_INT32
                                     : H5T_NATIVE_DOUBLE;
      const std::string where = "/series/" + c.name;
      Handle d(seriesColumn(g, c, type, writing_), H5Dclose, writing_, "opening " + where);
      Handle space(H5Dget_space(d), H5Sclose, writing_, "the extent of " + where);
      hsize_t old = 0;
      if (H5Sget_simple_extent_dims(space, &old, nullptr) < 0)
        hdf5::fail(writing_, "the extent of " + where);
      const hsize_t add = c.values.size();
      if (add > 0) {
        if (isStep) {
          std::vector<std::int64_t> v(c.values.begin(), c.values.end());
          appendRows(d, type, old, add, v.data(), writing_, where);
        } else if (isLimiter) {
          std::vector<std::int32_t> w(c.values.begin(), c.values.end());
          appendRows(d, type, old, add, w.data(), writing_, where);
        } else {
          appendRows(d, type, old, add, c.values.data(), writing_, where);
        }
      }
      c.values.clear();
    }
  });
}

void RunFile::snapshot(double time, std::int64_t step, const SnapshotFields& f, bool lastGood) {
  const double bytes = 8.0 * (f.position.size() + f.velocity.size() + f.density.size() +
                              f.pressure.size() + f.h.size() + f.mass.size()) +
                       4.0 * (f.phase.size() + f.id.size());
  ensureRoom(bytes);
  char name[32];
  std::snprintf(name, sizeof name, "/snapshots/%05zu", snapshots_.size());
  guarded([&] {
    Handle g(openGroup(file_, name, writing_), H5Gclose, writing_, std::string("creating ") + name);
    writeArray(g, "position", H5T_NATIVE_DOUBLE, f.position, 3, writing_);
    writeArray(g, "velocity", H5T_NATIVE_DOUBLE, f.velocity, 3, writing_);
    writeArray(g, "density", H5T_NATIVE_DOUBLE, f.density, 1, writing_);
    writeArray(g, "pressure", H5T_NATIVE_DOUBLE, f.pressure, 1, writing_);
    writeArray(g, "h", H5T_NATIVE_DOUBLE, f.h, 1, writing_);
    writeArray(g, "mass", H5T_NATIVE_DOUBLE, f.mass, 1, writing_);
    writeArray(g, "phase", H5T_NATIVE_INT32, f.phase, 1, writing_);
    if (!f.id.empty()) writeArray(g, "id", H5T_NATIVE_INT32, f.id, 1, writing_);
    writeAttribute(g, "time", H5T_NATIVE_DOUBLE, &time, writing_);
    writeAttribute(g, "step", H5T_NATIVE_INT64, &step, writing_);
    const std::int64_t one = 1;
    if (lastGood) writeAttribute(g, "last_good", H5T_NATIVE_INT64, &one, writing_);
  });
  flush();
  snapshots_.push_back({name, time, f.density.size()});
  const std::string xdmf = xdmfOf(path_) + ".partial";
  if (snapshots_.size() > 1 && xdmfWritten_) {
    guarded([&] { appendXdmf(xdmf, writing_, {name, time, f.density.size()}); });
    return;
  }
  std::vector<XdmfSnapshot> entries;
  for (const Entry& s : snapshots_) entries.push_back({s.group, s.time, s.n});
  guarded([&] { writeXdmf(xdmf, writing_, entries); });
  xdmfWritten_ = true;
}

namespace {
constexpr const char* recordGroups[] = {"series", "snapshots", "packing"};

// Copies `from`/<name> to `to`/<name> for each record group that `from` holds.
void copyRecord(hid_t from, const std::string& fromGroup, hid_t to, const std::string& toGroup,
                const std::string& path) {
  Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose, path, "a property list");
  check(H5Pset_create_intermediate_group(lcpl, 1), path, "a property list");
  for (const char* name : recordGroups) {
    const std::string source = fromGroup + name, target = toGroup + name;
    if (!exists(from, source, path)) continue;
    check(H5Ocopy(from, source.c_str(), to, target.c_str(), H5P_DEFAULT, lcpl), path,
          "copying " + source + " to " + target);
  }
}

std::string asGroupPrefix(const std::string& group) {
  return group.empty() || group.back() != '/' ? group + "/" : group;
}
}  // namespace

namespace {
// The names of group `group`'s members, in HDF5's name order (the snapshots' %05zu names sort as
// their numbers).
std::vector<std::string> members(hid_t file, const std::string& group, const std::string& path) {
  std::vector<std::string> names;
  if (!exists(file, group, path)) return names;
  Handle g(H5Gopen2(file, group.c_str(), H5P_DEFAULT), H5Gclose, path, "opening " + group);
  H5G_info_t info{};
  check(H5Gget_info(g, &info), path, "listing " + group);
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    const ssize_t size =
        H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, k, nullptr, 0, H5P_DEFAULT);
    if (size < 0) hdf5::fail(path, "listing " + group);
    std::string name(static_cast<std::size_t>(size) + 1, '\0');
    if (H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(), name.size(),
                           H5P_DEFAULT) < 0)
      hdf5::fail(path, "listing " + group);
    name.resize(static_cast<std::size_t>(size));
    names.push_back(name);
  }
  return names;
}

hsize_t rowsOf(hid_t d, const std::string& path, const std::string& where) {
  Handle space(H5Dget_space(d), H5Sclose, path, "the extent of " + where);
  hsize_t n = 0;
  if (H5Sget_simple_extent_dims(space, &n, nullptr) < 0) hdf5::fail(path, "the extent of " + where);
  return n;
}

// Rows [from, from + count) of 1-D dataset `d` (of `type`) as bytes.
std::vector<char> readRows(hid_t d, hid_t type, hsize_t from, hsize_t count,
                           const std::string& path, const std::string& where) {
  std::vector<char> bytes(count * H5Tget_size(type));
  if (count == 0) return bytes;
  Handle file(H5Dget_space(d), H5Sclose, path, "the extent of " + where);
  check(H5Sselect_hyperslab(file, H5S_SELECT_SET, &from, nullptr, &count, nullptr), path,
        "selecting in " + where);
  Handle mem(H5Screate_simple(1, &count, nullptr), H5Sclose, path, "a dataspace");
  check(H5Dread(d, type, mem, file, H5P_DEFAULT, bytes.data()), path, "reading " + where);
  return bytes;
}

std::uint64_t integerAttribute(hid_t object, const char* name, const std::string& path,
                               const std::string& where) {
  std::uint64_t v = 0;
  Handle a(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, path, where + " attribute " + name);
  check(H5Aread(a, H5T_NATIVE_UINT64, &v), path, where + " attribute " + name);
  return v;
}
}  // namespace

RunFile::RecordEnd RunFile::writeRecordSegment(std::int64_t into, const std::string& intoPath) {
  if (broken_ || file_ < 0)
    throw OutputError(writing_ + ": the run file takes no more writes (an earlier one failed)");
  RecordEnd end;
  end.any = true, end.snapshots = snapshots_.size();
  for (const std::string& c : members(file_, "/series", writing_)) {
    Handle d(H5Dopen2(file_, ("/series/" + c).c_str(), H5P_DEFAULT), H5Dclose, writing_,
             "opening /series/" + c);
    end.rows.emplace_back(c, rowsOf(d, writing_, "/series/" + c));
  }
  if (!segmented_.any) {
    copyRecord(file_, "/", into, "/", intoPath);
    return end;
  }
  Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose, intoPath, "a property list");
  check(H5Pset_create_intermediate_group(lcpl, 1), intoPath, "a property list");
  for (std::size_t k = segmented_.snapshots; k < snapshots_.size(); ++k) {
    const std::string& g = snapshots_[k].group;
    check(H5Ocopy(file_, g.c_str(), into, g.c_str(), H5P_DEFAULT, lcpl), intoPath, "copying " + g);
  }
  Handle series(H5Gcreate2(into, "/series", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                intoPath, "creating /series");
  for (const auto& [c, rows] : end.rows) {
    const std::string where = "/series/" + c;
    std::uint64_t from = 0;
    for (const auto& [name, before] : segmented_.rows)
      if (name == c) from = before;
    if (from == 0) {  // a column new since the last segment, whole with its attributes
      check(H5Ocopy(file_, where.c_str(), into, where.c_str(), H5P_DEFAULT, H5P_DEFAULT), intoPath,
            "copying " + where);
      continue;
    }
    Handle d(H5Dopen2(file_, where.c_str(), H5P_DEFAULT), H5Dclose, writing_, "opening " + where);
    Handle type(H5Dget_type(d), H5Tclose, writing_, "the type of " + where);
    const hsize_t count = rows - from;
    const std::vector<char> bytes = readRows(d, type, from, count, writing_, where);
    Handle space(H5Screate_simple(1, &count, nullptr), H5Sclose, intoPath, "a dataspace");
    Handle out(H5Dcreate2(into, where.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
               H5Dclose, intoPath, "creating " + where);
    if (count > 0)
      check(H5Dwrite(out, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()), intoPath, where);
    writeAttribute(out, "rows_from", H5T_NATIVE_UINT64, &from, intoPath);
  }
  return end;
}

void RunFile::adoptRecordSegments(const std::vector<std::int64_t>& from,
                                  const std::vector<std::string>& fromPaths) {
  guarded([&] {
    for (std::size_t s = 0; s < from.size(); ++s) {
      const hid_t segment = from[s];
      const std::string& path = fromPaths[s];
      if (s == 0) {
        copyRecord(segment, "/", file_, "/", writing_);
        continue;
      }
      Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose, writing_, "a property list");
      check(H5Pset_create_intermediate_group(lcpl, 1), writing_, "a property list");
      const std::vector<std::string> had = members(file_, "/snapshots", writing_);
      const std::vector<std::string> added = members(segment, "/snapshots", path);
      for (std::size_t k = 0; k < added.size(); ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "%05zu", had.size() + k);
        if (added[k] != name)
          throw OutputError(path + ": snapshot " + added[k] + " does not follow the record's " +
                            std::to_string(had.size()) + " snapshots");
        const std::string g = "/snapshots/" + added[k];
        check(H5Ocopy(segment, g.c_str(), file_, g.c_str(), H5P_DEFAULT, lcpl), writing_,
              "copying " + g + " from " + path);
      }
      for (const std::string& c : members(segment, "/series", path)) {
        const std::string where = "/series/" + c;
        Handle d(H5Dopen2(segment, where.c_str(), H5P_DEFAULT), H5Dclose, path, "opening " + where);
        const htri_t hasFrom = H5Aexists(d, "rows_from");
        if (hasFrom < 0) hdf5::fail(path, "looking up " + where + " rows_from");
        const bool known = exists(file_, where, writing_);
        if (!hasFrom) {  // a whole column, new in this segment
          if (known)
            throw OutputError(path + ": " + where + " is whole but the record already has it");
          check(H5Ocopy(segment, where.c_str(), file_, where.c_str(), H5P_DEFAULT, lcpl), writing_,
                "copying " + where + " from " + path);
          continue;
        }
        const std::uint64_t rowsFrom = integerAttribute(d, "rows_from", path, where);
        if (!known) throw OutputError(path + ": " + where + " continues a column the record lacks");
        Handle target(H5Dopen2(file_, where.c_str(), H5P_DEFAULT), H5Dclose, writing_,
                      "opening " + where);
        hsize_t old = rowsOf(target, writing_, where);
        if (old != rowsFrom)
          throw OutputError(path + ": " + where + " continues row " + std::to_string(rowsFrom) +
                            " but the record has " + std::to_string(old));
        Handle type(H5Dget_type(d), H5Tclose, path, "the type of " + where);
        const hsize_t add = rowsOf(d, path, where);
        if (add == 0) continue;
        const std::vector<char> bytes = readRows(d, type, 0, add, path, where);
        appendRows(target, type, old, add, bytes.data(), writing_, where);
      }
    }
  });
  adoptedSnapshots();
}

void RunFile::adoptRecord(std::int64_t from, const std::string& under) {
  guarded([&] { copyRecord(from, asGroupPrefix(under), file_, "/", writing_); });
  adoptedSnapshots();
}

void RunFile::adoptedSnapshots() {
  guarded([&] {
    snapshots_.clear();
    segmented_ = RecordEnd{};
    segmented_.any = true;
    for (const std::string& c : members(file_, "/series", writing_)) {
      Handle d(H5Dopen2(file_, ("/series/" + c).c_str(), H5P_DEFAULT), H5Dclose, writing_,
               "opening /series/" + c);
      segmented_.rows.emplace_back(c, rowsOf(d, writing_, "/series/" + c));
    }
    const std::vector<std::string> names = members(file_, "/snapshots", writing_);
    for (std::size_t k = 0; k < names.size(); ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "/snapshots/%05zu", k);
      if (names[k] != name + 11)
        throw OutputError(writing_ + ": the adopted snapshots are not numbered 0 to " +
                          std::to_string(names.size() - 1));
      Handle s(H5Gopen2(file_, name, H5P_DEFAULT), H5Gclose, writing_,
               std::string("opening ") + name);
      double time = 0;
      Handle a(H5Aopen(s, "time", H5P_DEFAULT), H5Aclose, writing_, std::string(name) + " time");
      check(H5Aread(a, H5T_NATIVE_DOUBLE, &time), writing_, std::string(name) + " time");
      Handle d(H5Dopen2(s, "density", H5P_DEFAULT), H5Dclose, writing_,
               std::string(name) + " density");
      snapshots_.push_back({name, time, static_cast<std::size_t>(rowsOf(d, writing_, name))});
    }
    segmented_.snapshots = snapshots_.size();
  });
  flush();
  std::vector<XdmfSnapshot> entries;
  for (const Entry& s : snapshots_) entries.push_back({s.group, s.time, s.n});
  guarded([&] { writeXdmf(xdmfOf(path_) + ".partial", writing_, entries); });
  xdmfWritten_ = true;
}

void RunFile::flush() {
  guarded([&] { check(H5Fflush(file_, H5F_SCOPE_GLOBAL), writing_, "flushing the run file"); });
}

}  // namespace sph
