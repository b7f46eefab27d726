#include "XdmfSidecar.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>

#include "sph/RunFile.hpp"  // OutputError

namespace sph {

namespace {

// The polyvertex cells' connectivity, "0 1 ... n-1": each particle one vertex cell. ParaView's
// default reader (Xdmf3ReaderS, ParaView 5.11) makes cells only from an explicit connectivity
// item: with NumberOfElements alone it gives the points and no cells, which draw nothing. The
// item is written inline in every grid: an item shared between grids (by xi:include) the Xdmf 3
// library moves into the first topology that reads it, and the other steps get no cells (tried
// with ParaView 5.11). It costs at most 8 bytes a particle a snapshot (up to 10^7 particles),
// against the run file's 84.
std::string vertexIndices(std::size_t n) {
  std::string s;
  s.reserve(n * 8);
  for (std::size_t i = 0; i < n; ++i) {
    if (i) s += ' ';
    s += std::to_string(i);
  }
  return s;
}

constexpr std::string_view footer = "  </Grid>\n </Domain>\n</Xdmf>\n";

std::string header() {
  return "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
         "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
}

// One snapshot's grid; `indices` is its vertex cells' connectivity.
void grid(std::ostream& x, const std::string& file, const XdmfSnapshot& e,
          const std::string& indices) {
  auto item = [&](const std::string& field, int cols, const char* type, int bytes) {
    x << "      <DataItem Dimensions=\"" << e.n << (cols > 1 ? " 3" : "") << "\" NumberType=\""
      << type << "\" Precision=\"" << bytes << "\" Format=\"HDF\">" << file << ":" << e.group << "/"
      << field << "</DataItem>\n";
  };
  x << "   <Grid Name=\"" << e.group.substr(e.group.rfind('/') + 1) << "\" GridType=\"Uniform\">\n"
    << "    <Time Value=\"" << e.time << "\"/>\n"
    << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << e.n
    << "\" NodesPerElement=\"1\">\n"
    << "      <DataItem Dimensions=\"" << e.n
    << "\" NumberType=\"Int\" Precision=\"8\" Format=\"XML\">" << indices << "</DataItem>\n"
    << "    </Topology>\n    <Geometry GeometryType=\"XYZ\">\n";
  item("position", 3, "Float", 8);
  x << "    </Geometry>\n";
  x << "    <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n";
  item("velocity", 3, "Float", 8);
  x << "    </Attribute>\n";
  for (const char* s : {"density", "pressure", "h", "mass"}) {
    x << "    <Attribute Name=\"" << s << "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
    item(s, 1, "Float", 8);
    x << "    </Attribute>\n";
  }
  x << "    <Attribute Name=\"phase\" AttributeType=\"Scalar\" Center=\"Node\">\n";
  item("phase", 1, "Int", 4);
  x << "    </Attribute>\n   </Grid>\n";
}

std::string fileName(const std::string& h5) {
  return std::filesystem::path(h5).filename().string();
}

std::string text(const std::string& h5, const std::vector<XdmfSnapshot>& snapshots) {
  std::ostringstream x;
  x << header();
  std::map<std::size_t, std::string> indices;  // by particle count: one string for a run's steps
  for (const XdmfSnapshot& e : snapshots) {
    auto [at, added] = indices.try_emplace(e.n);
    if (added) at->second = vertexIndices(e.n);
    grid(x, fileName(h5), e, at->second);
  }
  x << footer;
  return x.str();
}

std::string reason() {
  return errno ? std::strerror(errno) : "the write failed";
}

}  // namespace

void writeXdmf(const std::string& xdmf, const std::string& h5,
               const std::vector<XdmfSnapshot>& snapshots) {
  namespace fs = std::filesystem;
  const fs::path tmp = fs::path(xdmf).concat(".tmp");
  const std::string content = text(h5, snapshots);
  errno = 0;
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  out.close();  // the last bytes reach the file here: a full disk shows now or never
  if (!out) {
    const std::string why = reason();
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw OutputError(tmp.string() + ": cannot write the XDMF sidecar (" + why + ")");
  }
  std::error_code e;
  fs::rename(tmp, xdmf, e);
  if (e) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw OutputError(xdmf + ": cannot rename " + tmp.string() + " to it (" + e.message() + ")");
  }
}

void appendXdmf(const std::string& xdmf, const std::string& h5, const XdmfSnapshot& snapshot) {
  namespace fs = std::filesystem;
  std::error_code e;
  const auto size = fs::file_size(xdmf, e);
  std::fstream io(xdmf, std::ios::binary | std::ios::in | std::ios::out);
  std::string tail(footer.size(), '\0');
  if (!e && size >= footer.size()) {
    io.seekg(static_cast<std::streamoff>(size - footer.size()));
    io.read(tail.data(), static_cast<std::streamsize>(tail.size()));
  }
  if (e || !io || tail != footer)
    throw OutputError(xdmf +
                      ": cannot add a snapshot to the XDMF sidecar (it is not the one this " +
                      "run wrote, or it cannot be read)");
  const auto at = size - footer.size();
  std::ostringstream x;
  grid(x, fileName(h5), snapshot, vertexIndices(snapshot.n));
  x << footer;
  const std::string added = x.str();
  errno = 0;
  io.seekp(static_cast<std::streamoff>(at));
  io.write(added.data(), static_cast<std::streamsize>(added.size()));
  io.close();
  if (io) return;
  // Cut back to the earlier snapshots and close them again: the bytes of the old closing lines
  // fit where they were, so the sidecar stays whole up to its last snapshot on a full disk too.
  const std::string why = reason();
  std::error_code ignored;
  fs::resize_file(xdmf, at, ignored);
  std::ofstream restore(xdmf, std::ios::binary | std::ios::app);
  restore.write(footer.data(), static_cast<std::streamsize>(footer.size()));
  throw OutputError(xdmf + ": cannot add a snapshot to the XDMF sidecar (" + why + ")");
}

}  // namespace sph
