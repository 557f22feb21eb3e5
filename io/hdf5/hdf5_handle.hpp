#pragma once
// One RAII layer over the HDF5 C API for every reader and writer of the project: a
// handle of any kind (file, group, dataset, dataspace, datatype, attribute, property
// list) that releases itself when it goes out of scope, so no code path (an early
// return, an exception) leaves an identifier open. H5Idec_ref closes an identifier of
// any type when its reference count reaches zero (HDF5 Reference Manual, H5I).
#include <hdf5.h>

#include <utility>

namespace heavesim::hdf5 {

class Handle {
 public:
  Handle() = default;
  /// Takes ownership of `id` (a negative id is an HDF5 failure: nothing to release).
  explicit Handle(hid_t id) : id_(id) {}
  ~Handle() { reset(); }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, -1)) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, -1);
    }
    return *this;
  }

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  /// Releases the identifier now (its errors, if any, are reported by HDF5's return code).
  void reset() {
    if (id_ >= 0) H5Idec_ref(id_);
    id_ = -1;
  }
  /// Releases the identifier now and says whether HDF5 managed to (closing a file or a
  /// dataset writes what it still holds, and that write can fail).
  bool close() {
    const bool closed = id_ < 0 || H5Idec_ref(id_) >= 0;
    id_ = -1;
    return closed;
  }
  /// Forgets the identifier without releasing it: for a file whose writes have failed,
  /// where closing would retry them (and could half-write what the disk refused). The
  /// process exits without HDF5's at-exit clean-up (skip_library_exit_cleanup).
  void abandon() { id_ = -1; }

 private:
  hid_t id_ = -1;
};

/// Stops HDF5 from closing, at process exit, what the program left open. After a failed
/// write the library's own clean-up (H5_term_library, registered with atexit) retries the
/// flush of datasets it could not close and crashes on them (HDF5 1.10: a dataset whose
/// close failed stays registered after its memory is freed; exit code 139 on a full
/// disk). Writers close everything themselves, in order, and check each close. Effective
/// only before the first other HDF5 call (HDF5 Reference Manual, H5dont_atexit).
inline void skip_library_exit_cleanup() { H5dont_atexit(); }

/// A variable-length UTF-8 string type, for text datasets and attributes.
inline Handle variable_text_type() {
  Handle type(H5Tcopy(H5T_C_S1));
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  return type;
}

/// Link-creation properties that create missing intermediate groups ("/a/b/c" creates /a and /a/b).
inline Handle intermediate_group_links() {
  Handle properties(H5Pcreate(H5P_LINK_CREATE));
  H5Pset_create_intermediate_group(properties.get(), 1);
  return properties;
}

}  // namespace heavesim::hdf5
