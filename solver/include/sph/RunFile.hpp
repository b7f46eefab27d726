#pragma once
// One HDF5 file per run (layout: reports/SCHEMA.md) and an XDMF sidecar so that ParaView opens
// the snapshots as a time series. Flushed at every snapshot so that a killed run keeps what it
// wrote. Both are written as <path>.partial (the XDMF naming the partial HDF5 file) and renamed
// into place by finish(): the run file of an earlier run into the same place stays whole until a
// rerun has finished, whether the rerun is killed, runs out of disk or fails.
//
// Every HDF5 call and every write is checked: a failure throws OutputError naming the path, and
// the file takes no more writes. Before each snapshot the room left (free space, and ulimit -f
// less the file's size) is compared with what the snapshot needs, twice over, plus a reserve:
// where it falls short the run stops before writing, with status "output_error", and the file
// stays readable as of its last snapshot. A write that fails all the same (another process filled
// the disk) may leave the part written since that snapshot unreadable.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace sph {

struct SeriesColumn {
  std::string name;
  std::vector<double> values;                             // buffered until the next flush
  std::vector<std::pair<std::string, std::string>> text;  // attributes, written once
  std::vector<std::pair<std::string, double>> numbers;    // attributes, written once
};

struct SnapshotFields {
  std::vector<double> position, velocity;  // N x 3, unused axes zero
  std::vector<double> density, pressure, h, mass;
  std::vector<std::int32_t> phase;
};

// The run file or its directory cannot be written (exit 4, Run.hpp); the message names the path.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class RunFile {
 public:
  explicit RunFile(const std::string& path);  // creates or truncates <path>.partial
  ~RunFile();  // without finish(): closes <path>.partial and leaves it there
  RunFile(const RunFile&) = delete;
  RunFile& operator=(const RunFile&) = delete;

  void attribute(const std::string& name, const std::string& value, const std::string& group = "/");
  void attribute(const std::string& name, double value, const std::string& group = "/");
  void attribute(const std::string& name, std::int64_t value, const std::string& group = "/");
  void text(const std::string& dataset, const std::string& value);
  // A fixed 1-D dataset <group>/<name> (the group is made when missing).
  void array(const std::string& group, const std::string& name, const std::vector<double>& values);

  // Appends the buffered values of each column to /series/<name> and empties the buffers.
  void appendSeries(std::vector<SeriesColumn>& columns);
  void snapshot(double time, std::int64_t step, const SnapshotFields& f, bool lastGood = false);
  void flush();
  // Closes the file and renames it to path(), then writes path()'s XDMF sidecar and removes the
  // partial one. The file takes no more writes.
  void finish();

  // The record so far (/series, /snapshots and /packing, those that exist) copied into the open
  // HDF5 file `into` under the group `under` (a checkpoint: Checkpoint.cpp); failures throw
  // OutputError naming `intoPath`. Buffered series values are not copied: append them first.
  void copyRecordTo(std::int64_t into, const std::string& under, const std::string& intoPath);
  // The record under `under` of the open HDF5 file `from` (a checkpoint) copied into this file,
  // which continues it: its snapshots become this file's first, and its XDMF lists them.
  void adoptRecord(std::int64_t from, const std::string& under);

  const std::string& path() const { return path_; }            // where finish() puts it
  const std::string& writingPath() const { return writing_; }  // <path>.partial until then

 private:
  // Runs a write; a failure marks the file broken (no more writes) and is rethrown.
  template <class Write>
  void guarded(Write&& write);
  // Throws OutputError, after marking the file output_error, where less than `bytes` twice over
  // plus a reserve is left to write.
  void ensureRoom(double bytes);
  double room(std::string& limit) const;  // bytes left to write; `limit` says which limit
  // Marks the file broken and, where it still can, writes status "output_error" and `why`.
  void markFailed(const std::string& why);
  std::string path_, writing_;
  std::int64_t file_ = -1;
  bool broken_ = false;
  struct Entry {
    std::string group;
    double time;
    std::size_t n;
  };
  std::vector<Entry> snapshots_;
  bool xdmfWritten_ = false;  // the partial sidecar holds snapshots_ (appended to from then on)
};

}  // namespace sph
