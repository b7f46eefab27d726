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
  // Each particle's id (its index at the start), ascending; empty where none has left the run
  // (Simulation::departures), so that particle k is id k.
  std::vector<std::int32_t> id;
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

  // A checkpoint's share of the record (Checkpoint.cpp): what was added to it since the last
  // segment, so that each snapshot and series value is written to the checkpoints once. The
  // first segment is the record so far (/series, /snapshots and /packing, those that exist); each
  // later one the snapshots since and each series column's rows since, with the attribute
  // `rows_from` (the rows before them). Written into the open HDF5 file `into`; failures throw
  // OutputError naming `intoPath`. Buffered series values are not copied: append them first.
  // Returns where the record then ends; segmented() takes it once the segment is kept.
  struct RecordEnd {
    bool any = false;  // a segment has been kept (else the next one starts the record)
    std::size_t snapshots = 0;
    std::vector<std::pair<std::string, std::uint64_t>> rows;  // series column, its rows
  };
  RecordEnd writeRecordSegment(std::int64_t into, const std::string& intoPath);
  void segmented(RecordEnd end) { segmented_ = std::move(end); }
  // Segments (their open HDF5 files, in order; the first starts the record) copied into this
  // file, which continues the record: their snapshots become this file's first, its XDMF lists
  // them, and the next segment starts after them. A segment that does not continue the ones
  // before it is an OutputError naming `fromPaths`' entry.
  void adoptRecordSegments(const std::vector<std::int64_t>& from,
                           const std::vector<std::string>& fromPaths);
  // The record of the open HDF5 file `from` under the group `under` (a checkpoint of the first
  // format, which held the whole record) adopted as a first segment.
  void adoptRecord(std::int64_t from, const std::string& under);

  // A write beside the file failed (a checkpoint): marks it status "output_error" with `why`
  // where it still can; it takes no more writes.
  void outputFailedBeside(const std::string& why) { markFailed(why); }

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
  RecordEnd segmented_;       // where the last kept segment ends
  void adoptedSnapshots();    // snapshots_, segmented_ and the XDMF from the adopted record
  bool xdmfWritten_ = false;  // the partial sidecar holds snapshots_ (appended to from then on)
};

}  // namespace sph
