#pragma once
// Every HDF5 call of the run file checked (RunFile.cpp): an identifier that closes itself, so that
// a failure part way leaks nothing, and statuses that throw OutputError naming the file, what was
// being done and HDF5's innermost reason (for a full disk "No space left on device", for a file
// above ulimit -f "File too large"). Internal to the solver library.
#include <hdf5.h>

#include <algorithm>
#include <string>

#include "sph/RunFile.hpp"  // OutputError

namespace sph::hdf5 {

// The innermost description on HDF5's error stack, e.g. "file write failed: ..., errno = 28,
// error message = 'No space left on device'", shortened to that message where it has one.
inline std::string reason() {
  std::string out;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned n, const H5E_error2_t* e, void* data) -> herr_t {
        auto& s = *static_cast<std::string*>(data);
        if (n == 0 && e->desc) s = e->desc;
        return 0;
      },
      &out);
  const auto at = out.find("error message = '");
  if (at != std::string::npos) {
    const auto from = at + 17, to = out.find('\'', from);
    out = out.substr(from, to == std::string::npos ? std::string::npos : to - from);
  }
  return out;
}

[[noreturn]] inline void fail(const std::string& file, const std::string& what) {
  const std::string why = reason();
  throw OutputError(file + ": HDF5: " + what + " failed" + (why.empty() ? "" : " (" + why + ")"));
}

inline void check(herr_t status, const std::string& file, const std::string& what) {
  if (status < 0) fail(file, what);
}

// An HDF5 identifier, checked on creation and closed on destruction.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t), const std::string& file, const std::string& what)
      : id_(id), close_(close) {
    if (id_ < 0) fail(file, what);
  }
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  operator hid_t() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// A UTF-8 string type of `length` bytes (at least 1, HDF5's minimum), for attributes and text.
inline hid_t stringType(std::size_t length, const std::string& file) {
  const hid_t t = H5Tcopy(H5T_C_S1);
  if (t < 0) fail(file, "a string type");
  if (H5Tset_size(t, std::max<std::size_t>(length, 1)) < 0 || H5Tset_cset(t, H5T_CSET_UTF8) < 0) {
    H5Tclose(t);
    fail(file, "a string type");
  }
  return t;
}

}  // namespace sph::hdf5
