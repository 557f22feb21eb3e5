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

 private:
  hid_t id_ = -1;
};

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
