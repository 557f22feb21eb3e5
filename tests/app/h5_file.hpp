#pragma once
// Reading result files in tests (docs/result-file.md), and scratch file names.
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace heavesim {

class H5File {
 public:
  /// Opens read-only; a file written in HDF5's SWMR mode and left open by a killed
  /// writer opens as a SWMR reader; a file this process writes (a ResultFile, which takes
  /// no file lock) opens without taking one either: HDF5 refuses a locking second open.
  explicit H5File(const std::string& path) {
    H5E_BEGIN_TRY {
      file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
      if (file_ < 0) {
        const hid_t unlocked = H5Pcreate(H5P_FILE_ACCESS);
        if (H5Pset_file_locking(unlocked, false, true) >= 0) file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, unlocked);
        H5Pclose(unlocked);
      }
    }
    H5E_END_TRY;
    if (file_ < 0) file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY | H5F_ACC_SWMR_READ, H5P_DEFAULT);
  }
  ~H5File() {
    if (file_ >= 0) H5Fclose(file_);
  }
  bool ok() const { return file_ >= 0; }
  bool exists(const std::string& path) const { return H5Lexists(file_, path.c_str(), H5P_DEFAULT) > 0; }
  bool has_attribute(const std::string& object, const std::string& name) const {
    return H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
  }
  long long_attribute(const std::string& object, const std::string& name) const {
    long value = -1;
    const hid_t attribute = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    H5Aread(attribute, H5T_NATIVE_LONG, &value);
    H5Aclose(attribute);
    return value;
  }
  double double_attribute(const std::string& object, const std::string& name) const {
    double value = NAN;
    const hid_t attribute = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    H5Aread(attribute, H5T_NATIVE_DOUBLE, &value);
    H5Aclose(attribute);
    return value;
  }
  /// A numeric attribute of any number of values (a scalar gives one; none if missing).
  std::vector<double> double_attributes(const std::string& object, const std::string& name) const {
    const hid_t attribute = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    if (attribute < 0) return {};
    const hid_t space = H5Aget_space(attribute);
    std::vector<double> values(static_cast<std::size_t>(std::max<hssize_t>(H5Sget_simple_extent_npoints(space), 0)));
    if (!values.empty()) H5Aread(attribute, H5T_NATIVE_DOUBLE, values.data());
    H5Sclose(space);
    H5Aclose(attribute);
    return values;
  }
  /// A variable-length string attribute (as ResultFile writes them).
  std::string string_attribute(const std::string& object, const std::string& name) const {
    const hid_t attribute = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    char* text = nullptr;
    H5Aread(attribute, type, &text);
    std::string value = text ? text : "";
    H5free_memory(text);
    H5Tclose(type);
    H5Aclose(attribute);
    return value;
  }
  std::vector<hsize_t> shape(const std::string& path) const {
    const hid_t dataset = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
    const hid_t space = H5Dget_space(dataset);
    std::vector<hsize_t> dims(H5Sget_simple_extent_ndims(space));
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    H5Sclose(space);
    H5Dclose(dataset);
    return dims;
  }
  std::vector<double> read(const std::string& path) const {
    std::vector<hsize_t> dims = shape(path);
    hsize_t size = 1;
    for (hsize_t d : dims) size *= d;
    std::vector<double> values(size);
    const hid_t dataset = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
    H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(dataset);
    return values;
  }

  /// Where a chunked dataset's chunks are in the file: (first row, address, bytes) for
  /// each allocated chunk, in HDF5's index order (H5Dget_chunk_info, HDF5 1.10.5).
  struct ChunkPlace {
    hsize_t first_row;
    haddr_t address;
    hsize_t bytes;
    bool operator==(const ChunkPlace&) const = default;
  };
  std::vector<ChunkPlace> chunk_places(const std::string& path) const {
    std::vector<ChunkPlace> places;
    const hid_t dataset = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
    const hid_t space = H5Dget_space(dataset);
    hsize_t chunks = 0;
    H5Dget_num_chunks(dataset, space, &chunks);
    for (hsize_t k = 0; k < chunks; ++k) {
      hsize_t offset[2] = {0, 0};
      unsigned filter_mask = 0;
      haddr_t address = HADDR_UNDEF;
      hsize_t bytes = 0;
      if (H5Dget_chunk_info(dataset, space, k, offset, &filter_mask, &address, &bytes) >= 0)
        places.push_back({offset[0], address, bytes});
    }
    H5Sclose(space);
    H5Dclose(dataset);
    return places;
  }

 private:
  hid_t file_ = -1;
};

inline std::string temporary(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("heavesim_" + std::to_string(::getpid()) + "_" + name)).string();
}

}  // namespace heavesim
