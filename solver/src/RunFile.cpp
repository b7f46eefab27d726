#include "sph/RunFile.hpp"

#include <hdf5.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sph {

namespace {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what + " failed");
}

hid_t openGroup(hid_t file, const std::string& group) {
  if (group == "/") return H5Gopen2(file, "/", H5P_DEFAULT);
  if (H5Lexists(file, group.c_str(), H5P_DEFAULT) > 0)
    return H5Gopen2(file, group.c_str(), H5P_DEFAULT);
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  hid_t g = H5Gcreate2(file, group.c_str(), lcpl, H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(lcpl);
  return g;
}

void writeAttribute(hid_t file, const std::string& group, const std::string& name, hid_t type,
                    const void* data) {
  hid_t g = openGroup(file, group);
  if (H5Aexists(g, name.c_str()) > 0) H5Adelete(g, name.c_str());
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate2(g, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  check(H5Awrite(a, type, data), "writing attribute " + name);
  H5Aclose(a), H5Sclose(space), H5Gclose(g);
}

hid_t stringType(std::size_t length) {
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, std::max<std::size_t>(length, 1));
  H5Tset_cset(t, H5T_CSET_UTF8);
  return t;
}

template <class T>
void writeArray(hid_t group, const std::string& name, hid_t type, const std::vector<T>& data,
                std::size_t columns) {
  hsize_t dims[2] = {data.size() / columns, columns};
  hid_t space = H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr);
  hid_t d = H5Dcreate2(group, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (!data.empty()) check(H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), name);
  H5Dclose(d), H5Sclose(space);
}

}  // namespace

namespace {

// <name>.h5 -> <name>.xdmf
std::string xdmfOf(const std::string& h5) {
  return std::filesystem::path(h5).replace_extension(".xdmf").string();
}

}  // namespace

RunFile::RunFile(const std::string& path) : path_(path), writing_(path + ".partial") {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = H5Fcreate(writing_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) throw std::runtime_error(writing_ + ": cannot create the run file");
  attribute("format", std::string("sph-run-1"));
}

void RunFile::finish() {
  namespace fs = std::filesystem;
  flush();
  const herr_t closed = H5Fclose(file_);
  file_ = -1;
  if (closed < 0) throw std::runtime_error(writing_ + ": HDF5: closing the run file failed");
  std::error_code e;
  fs::rename(writing_, path_, e);
  if (e) throw std::runtime_error(writing_ + ": cannot rename it to " + path_ + ": " + e.message());
  writeXdmf(xdmfOf(path_), path_);
  fs::remove(xdmfOf(path_) + ".partial", e);
}

RunFile::~RunFile() {
  if (file_ >= 0) H5Fclose(file_);
}

void RunFile::attribute(const std::string& name, const std::string& value,
                        const std::string& group) {
  hid_t t = stringType(value.size());
  writeAttribute(file_, group, name, t, value.c_str());
  H5Tclose(t);
}
void RunFile::attribute(const std::string& name, double value, const std::string& group) {
  writeAttribute(file_, group, name, H5T_NATIVE_DOUBLE, &value);
}
void RunFile::attribute(const std::string& name, std::int64_t value, const std::string& group) {
  writeAttribute(file_, group, name, H5T_NATIVE_INT64, &value);
}

void RunFile::text(const std::string& dataset, const std::string& value) {
  hid_t t = stringType(value.size());
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t d = H5Dcreate2(file_, dataset.c_str(), t, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  check(H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, value.c_str()), dataset);
  H5Dclose(d), H5Sclose(space), H5Tclose(t);
}

void RunFile::array(const std::string& group, const std::string& name,
                    const std::vector<double>& values) {
  hid_t g = openGroup(file_, group);
  writeArray(g, name, H5T_NATIVE_DOUBLE, values, 1);
  H5Gclose(g);
}

void RunFile::appendSeries(std::vector<SeriesColumn>& columns) {
  hid_t g = openGroup(file_, "/series");
  for (auto& c : columns) {
    // step and dt_limiter are integers in the schema; everything else is double.
    const bool isStep = c.name == "step", isLimiter = c.name == "dt_limiter";
    const hid_t type = isStep ? H5T_NATIVE_INT64 : isLimiter ? H5T_NATIVE_INT32 : H5T_NATIVE_DOUBLE;
    hid_t d;
    if (H5Lexists(g, c.name.c_str(), H5P_DEFAULT) > 0) {
      d = H5Dopen2(g, c.name.c_str(), H5P_DEFAULT);
    } else {
      hsize_t zero = 0, unlimited = H5S_UNLIMITED, chunk = 1024;
      hid_t space = H5Screate_simple(1, &zero, &unlimited);
      hid_t plist = H5Pcreate(H5P_DATASET_CREATE);
      H5Pset_chunk(plist, 1, &chunk);
      d = H5Dcreate2(g, c.name.c_str(), type, space, H5P_DEFAULT, plist, H5P_DEFAULT);
      H5Pclose(plist), H5Sclose(space);
      for (const auto& [key, value] : c.text) {
        hid_t t = stringType(value.size()), s = H5Screate(H5S_SCALAR);
        hid_t a = H5Acreate2(d, key.c_str(), t, s, H5P_DEFAULT, H5P_DEFAULT);
        check(H5Awrite(a, t, value.c_str()), "attribute " + key);
        H5Aclose(a), H5Sclose(s), H5Tclose(t);
      }
      for (const auto& [key, value] : c.numbers) {
        hid_t s = H5Screate(H5S_SCALAR);
        hid_t a = H5Acreate2(d, key.c_str(), H5T_NATIVE_DOUBLE, s, H5P_DEFAULT, H5P_DEFAULT);
        check(H5Awrite(a, H5T_NATIVE_DOUBLE, &value), "attribute " + key);
        H5Aclose(a), H5Sclose(s);
      }
    }
    if (d < 0) throw std::runtime_error("HDF5: cannot open /series/" + c.name);
    hid_t space = H5Dget_space(d);
    hsize_t old = 0;
    H5Sget_simple_extent_dims(space, &old, nullptr);
    H5Sclose(space);
    hsize_t add = c.values.size(), total = old + add;
    if (add > 0) {
      check(H5Dset_extent(d, &total), "extending /series/" + c.name);
      hid_t file = H5Dget_space(d);
      H5Sselect_hyperslab(file, H5S_SELECT_SET, &old, nullptr, &add, nullptr);
      hid_t mem = H5Screate_simple(1, &add, nullptr);
      if (isStep || isLimiter) {
        std::vector<std::int64_t> v(c.values.begin(), c.values.end());
        std::vector<std::int32_t> w(c.values.begin(), c.values.end());
        check(isStep ? H5Dwrite(d, H5T_NATIVE_INT64, mem, file, H5P_DEFAULT, v.data())
                     : H5Dwrite(d, H5T_NATIVE_INT32, mem, file, H5P_DEFAULT, w.data()),
              "/series/" + c.name);
      } else {
        check(H5Dwrite(d, H5T_NATIVE_DOUBLE, mem, file, H5P_DEFAULT, c.values.data()),
              "/series/" + c.name);
      }
      H5Sclose(mem), H5Sclose(file);
    }
    H5Dclose(d);
    c.values.clear();
  }
  H5Gclose(g);
}

void RunFile::snapshot(double time, std::int64_t step, const SnapshotFields& f, bool lastGood) {
  char name[32];
  std::snprintf(name, sizeof name, "/snapshots/%05zu", snapshots_.size());
  hid_t g = openGroup(file_, name);
  writeArray(g, "position", H5T_NATIVE_DOUBLE, f.position, 3);
  writeArray(g, "velocity", H5T_NATIVE_DOUBLE, f.velocity, 3);
  writeArray(g, "density", H5T_NATIVE_DOUBLE, f.density, 1);
  writeArray(g, "pressure", H5T_NATIVE_DOUBLE, f.pressure, 1);
  writeArray(g, "h", H5T_NATIVE_DOUBLE, f.h, 1);
  writeArray(g, "mass", H5T_NATIVE_DOUBLE, f.mass, 1);
  writeArray(g, "phase", H5T_NATIVE_INT32, f.phase, 1);
  H5Gclose(g);
  attribute("time", time, name);
  attribute("step", step, name);
  if (lastGood) attribute("last_good", std::int64_t{1}, name);
  snapshots_.push_back({name, time, f.density.size()});
  flush();
  writeXdmf(xdmfOf(path_) + ".partial", writing_);
}

void RunFile::flush() {
  H5Fflush(file_, H5F_SCOPE_GLOBAL);
}

// XDMF 3 temporal collection of polyvertex grids pointing into the HDF5 file `h5` (named
// relative to the XDMF, which lies beside it). Written to a temporary file and renamed, so a reader
// never sees half of it.
void RunFile::writeXdmf(const std::string& xdmf, const std::string& h5) const {
  namespace fs = std::filesystem;
  const std::string file = fs::path(h5).filename().string();
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
    << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  auto item = [&](const Entry& e, const std::string& field, int cols, const char* type, int bytes) {
    x << "      <DataItem Dimensions=\"" << e.n << (cols > 1 ? " 3" : "") << "\" NumberType=\""
      << type << "\" Precision=\"" << bytes << "\" Format=\"HDF\">" << file << ":" << e.group << "/"
      << field << "</DataItem>\n";
  };
  for (const Entry& e : snapshots_) {
    x << "   <Grid Name=\"" << e.group.substr(e.group.rfind('/') + 1)
      << "\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << e.time << "\"/>\n"
      << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << e.n
      << "\" NodesPerElement=\"1\"/>\n    <Geometry GeometryType=\"XYZ\">\n";
    item(e, "position", 3, "Float", 8);
    x << "    </Geometry>\n";
    x << "    <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n";
    item(e, "velocity", 3, "Float", 8);
    x << "    </Attribute>\n";
    for (const char* s : {"density", "pressure", "h", "mass"}) {
      x << "    <Attribute Name=\"" << s << "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
      item(e, s, 1, "Float", 8);
      x << "    </Attribute>\n";
    }
    x << "    <Attribute Name=\"phase\" AttributeType=\"Scalar\" Center=\"Node\">\n";
    item(e, "phase", 1, "Int", 4);
    x << "    </Attribute>\n   </Grid>\n";
  }
  x << "  </Grid>\n </Domain>\n</Xdmf>\n";
  const fs::path tmp = fs::path(xdmf).concat(".tmp");
  {
    std::ofstream out(tmp);
    out << x.str();
  }
  fs::rename(tmp, xdmf);
}

}  // namespace sph
