#include "io/hdf5/hdf5_reader.hpp"

#include <hdf5_hl.h>

#include <algorithm>

#include <fmt/format.h>

#include "hydro/data_file.hpp"
#include "io/hdf5/hdf5_error.hpp"

namespace heavesim::hdf5 {
namespace {

std::vector<hsize_t> dataspace_shape(hid_t dataset) {
  const Handle space(H5Dget_space(dataset));
  const int rank = H5Sget_simple_extent_ndims(space.get());
  std::vector<hsize_t> shape(std::max(rank, 0));
  if (rank > 0) H5Sget_simple_extent_dims(space.get(), shape.data(), nullptr);
  return shape;
}

/// The most bytes one dataset or attribute may need in memory: far more than any BEM
/// file's largest array (6 x 6 Nb x Nf numbers, some 10^5), far less than what the
/// dimensions or type size of a damaged header (up to 2^64) would allocate.
constexpr std::size_t largest_object_bytes = std::size_t{1} << 27;  // 128 MiB

/// The element count of `shape`, checked before anything is allocated for it: fails
/// (naming `object`) when count x element_bytes exceeds largest_object_bytes.
std::size_t checked_element_count(const Reader& reader, const std::string& object, const std::vector<hsize_t>& shape,
                                  std::size_t element_bytes) {
  const std::size_t limit = largest_object_bytes / std::max<std::size_t>(element_bytes, 1);
  std::size_t count = 1;
  for (hsize_t extent : shape) {
    if (extent != 0 && count > limit / extent)
      reader.fail(object, fmt::format("shape {} of {}-byte elements", shape_text(shape), element_bytes),
                  fmt::format("at most {} MiB in one dataset (a damaged header gives such sizes)",
                              largest_object_bytes >> 20));
    count *= extent;
  }
  return count;
}

/// Strings of a dataset or attribute of string type `stored` (fixed or variable
/// length); `read(memory_type, buffer)` reads it.
template <class Read>
std::vector<std::string> read_string_elements(hid_t stored, std::size_t count, Read read) {
  std::vector<std::string> texts;
  if (H5Tis_variable_str(stored) > 0) {
    const Handle memory(H5Tcopy(H5T_C_S1));
    H5Tset_size(memory.get(), H5T_VARIABLE);
    H5Tset_cset(memory.get(), H5Tget_cset(stored));
    std::vector<char*> pointers(count, nullptr);
    if (read(memory.get(), pointers.data()) < 0) return {};
    for (char* p : pointers) {
      texts.emplace_back(p ? p : "");
      H5free_memory(p);
    }
    return texts;
  }
  const std::size_t size = H5Tget_size(stored);
  const Handle memory(H5Tcopy(H5T_C_S1));
  H5Tset_size(memory.get(), size);
  H5Tset_strpad(memory.get(), H5T_STR_NULLPAD);
  std::vector<char> buffer(size * count + 1, '\0');
  if (read(memory.get(), buffer.data()) < 0) return {};
  for (std::size_t k = 0; k < count; ++k) {
    const char* begin = buffer.data() + k * size;
    texts.emplace_back(begin, std::find(begin, begin + size, '\0'));
  }
  return texts;
}

/// Bytes per element of a string type in memory: the fixed length, or a pointer.
std::size_t string_element_bytes(hid_t type) {
  return H5Tis_variable_str(type) > 0 ? sizeof(char*) : H5Tget_size(type);
}

herr_t record_scale_name(hid_t /*dataset*/, unsigned /*axis*/, hid_t scale, void* name) {
  // The scale's own dataset name: netCDF4 names a dimension after its coordinate
  // variable (the NAME attribute of a dimension without one is a placeholder text).
  const ssize_t length = H5Iget_name(scale, nullptr, 0);
  std::string path(static_cast<std::size_t>(std::max<ssize_t>(length, 0)), '\0');
  if (length > 0) H5Iget_name(scale, path.data(), path.size() + 1);
  *static_cast<std::string*>(name) = path.substr(path.find_last_of('/') + 1);
  return 1;  // the first scale of the axis names it
}

}  // namespace

std::string shape_text(const std::vector<hsize_t>& shape) {
  std::string text = "(";
  for (std::size_t k = 0; k < shape.size(); ++k) text += (k ? ", " : "") + std::to_string(shape[k]);
  return text + ")";
}

Reader::Reader(std::string path, std::string kind) : path_(std::move(path)), kind_(std::move(kind)) {
  hdf5::report_errors_by_return_codes();
  hydro::require_readable_data_file(path_, kind_);
  if (H5Fis_hdf5(path_.c_str()) <= 0)
    throw hydro::DataError(path_, 0, "a file that is not an HDF5 file (no HDF5 signature)", kind_);
  file_ = Handle(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  // An HDF5 file written in SWMR mode whose writer still has it open, or was killed,
  // carries the 1.10 superblock's "open for writing" mark: it opens as a SWMR reader.
  if (!file_.valid()) file_ = Handle(H5Fopen(path_.c_str(), H5F_ACC_RDONLY | H5F_ACC_SWMR_READ, H5P_DEFAULT));
  if (!file_.valid())
    throw hydro::DataError(path_, 0, "an HDF5 file that cannot be opened (truncated or damaged)", kind_ + ", complete");
}

void Reader::fail(const std::string& object, const std::string& found, const std::string& expected) const {
  throw hydro::DataError(path_ + ":" + object, 0, found, expected);
}

bool Reader::has(const std::string& object) const {
  // H5Lexists fails (rather than saying no) when an intermediate group is missing, so
  // every prefix is checked in turn.
  for (std::size_t end = object.find('/', 1);; end = object.find('/', end + 1)) {
    const std::string prefix = object.substr(0, end);
    if (H5Lexists(file_.get(), prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    if (end == std::string::npos) return true;
  }
}

Handle Reader::open_dataset(const std::string& dataset) const {
  if (!has(dataset)) fail(dataset, "no such dataset", fmt::format("the dataset {} of {}", dataset, kind_));
  Handle id(H5Dopen2(file_.get(), dataset.c_str(), H5P_DEFAULT));
  if (!id.valid()) fail(dataset, "an object that is not a dataset (or cannot be read)", "a dataset");
  return id;
}

std::vector<hsize_t> Reader::shape(const std::string& dataset) const {
  const Handle id = open_dataset(dataset);
  return dataspace_shape(id.get());
}

Array Reader::read(const std::string& dataset) const {
  const Handle id = open_dataset(dataset);
  const Handle type(H5Dget_type(id.get()));
  const H5T_class_t type_class = H5Tget_class(type.get());
  if (type_class != H5T_INTEGER && type_class != H5T_FLOAT)
    fail(dataset, "a dataset that does not hold numbers", "a numeric (integer or floating-point) dataset");
  // A number is at most 16 bytes (long double); a larger size is a damaged type, which
  // libhdf5 would convert through a buffer of that size per element.
  const std::size_t type_size = H5Tget_size(type.get());
  if (type_size == 0 || type_size > 16)
    fail(dataset, fmt::format("a numeric type of {} bytes", type_size), "integers or floating-point numbers of 1 to 16 bytes");
  Array array;
  array.shape = dataspace_shape(id.get());
  array.values.resize(checked_element_count(*this, dataset, array.shape, std::max(type_size, sizeof(double))));
  if (H5Dread(id.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, array.values.data()) < 0)
    fail(dataset, "data that cannot be read (damaged file)", "a readable dataset");
  return array;
}

double Reader::read_scalar(const std::string& dataset) const {
  const Array array = read(dataset);
  if (array.values.size() != 1) fail(dataset, "shape " + shape_text(array.shape), "a single number");
  return array.values[0];
}

std::vector<std::string> Reader::read_strings(const std::string& dataset) const {
  const Handle id = open_dataset(dataset);
  const Handle type(H5Dget_type(id.get()));
  if (H5Tget_class(type.get()) != H5T_STRING) fail(dataset, "a dataset that does not hold text", "strings");
  const std::size_t count =
      checked_element_count(*this, dataset, dataspace_shape(id.get()), string_element_bytes(type.get()));
  return read_string_elements(type.get(), count, [&](hid_t memory, void* buffer) {
    return H5Dread(id.get(), memory, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer);
  });
}

std::optional<std::string> Reader::text_attribute(const std::string& object, const std::string& name) const {
  if (H5Aexists_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT) <= 0) return std::nullopt;
  const Handle attribute(H5Aopen_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT));
  const Handle type(H5Aget_type(attribute.get()));
  if (H5Tget_class(type.get()) != H5T_STRING) fail(object, "a '" + name + "' attribute that is not text", "text");
  const Handle space(H5Aget_space(attribute.get()));
  const auto points = static_cast<hsize_t>(std::max<hssize_t>(H5Sget_simple_extent_npoints(space.get()), 0));
  const std::size_t count = checked_element_count(*this, object + " (attribute " + name + ")", {points},
                                                  string_element_bytes(type.get()));
  const std::vector<std::string> texts = read_string_elements(
      type.get(), count, [&](hid_t memory, void* buffer) { return H5Aread(attribute.get(), memory, buffer); });
  return texts.empty() ? std::string() : texts.front();
}

std::optional<double> Reader::number_attribute(const std::string& object, const std::string& name) const {
  if (H5Aexists_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT) <= 0) return std::nullopt;
  const Handle attribute(H5Aopen_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT));
  const Handle type(H5Aget_type(attribute.get()));
  const H5T_class_t type_class = H5Tget_class(type.get());
  if (type_class != H5T_INTEGER && type_class != H5T_FLOAT)
    fail(object, "a '" + name + "' attribute that is not a number", "a number");
  const Handle space(H5Aget_space(attribute.get()));
  const hssize_t points = H5Sget_simple_extent_npoints(space.get());
  if (points < 1) fail(object, "an empty '" + name + "' attribute", "a number");
  std::vector<double> values(static_cast<std::size_t>(points));
  if (H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, values.data()) < 0)
    fail(object, "a '" + name + "' attribute that cannot be read", "a readable number");
  return values.front();
}

std::vector<std::string> Reader::attribute_names(const std::string& object) const {
  std::vector<std::string> names;
  if (!has(object)) return names;
  auto visit = [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->push_back(name);
    return 0;
  };
  if (H5Aiterate_by_name(file_.get(), object.c_str(), H5_INDEX_NAME, H5_ITER_INC, nullptr, visit, &names, H5P_DEFAULT) < 0)
    fail(object, "attributes that cannot be listed", "a readable object");
  return names;
}

std::optional<double> Reader::scalar_number_attribute(const std::string& object, const std::string& name) const {
  if (H5Aexists_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT) <= 0) return std::nullopt;
  const Handle attribute(H5Aopen_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT));
  const Handle type(H5Aget_type(attribute.get()));
  const H5T_class_t type_class = H5Tget_class(type.get());
  const Handle space(H5Aget_space(attribute.get()));
  if ((type_class != H5T_INTEGER && type_class != H5T_FLOAT) || H5Sget_simple_extent_npoints(space.get()) != 1)
    return std::nullopt;
  return number_attribute(object, name);
}

std::vector<std::string> Reader::datasets() const {
  std::vector<std::string> names;
  auto visit = [](hid_t, const char* name, const H5O_info_t* info, void* data) -> herr_t {
    if (info->type == H5O_TYPE_DATASET) static_cast<std::vector<std::string>*>(data)->push_back(std::string("/") + name);
    return 0;
  };
  if (H5Ovisit2(file_.get(), H5_INDEX_NAME, H5_ITER_INC, visit, &names, H5O_INFO_BASIC) < 0)
    fail("/", "a group tree that cannot be listed (damaged file)", "a readable file");
  return names;
}

std::vector<std::string> Reader::dimension_names(const std::string& dataset) const {
  const Handle id = open_dataset(dataset);
  std::vector<std::string> names(dataspace_shape(id.get()).size());
  for (std::size_t axis = 0; axis < names.size(); ++axis) {
    int index = 0;
    if (H5DSget_num_scales(id.get(), static_cast<unsigned>(axis)) > 0)
      H5DSiterate_scales(id.get(), static_cast<unsigned>(axis), &index, record_scale_name, &names[axis]);
  }
  return names;
}

void Reader::check_units(const std::string& dataset, const std::vector<std::string>& accepted) const {
  const std::optional<std::string> units = text_attribute(dataset, "units");
  if (!units || std::find(accepted.begin(), accepted.end(), *units) != accepted.end()) return;
  fail(dataset, fmt::format("units = '{}'", *units), fmt::format("units '{}'", fmt::join(accepted, "' or '")));
}

}  // namespace heavesim::hdf5
