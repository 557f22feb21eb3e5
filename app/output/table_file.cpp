#include "app/output/table_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "app/output/output_error.hpp"

namespace heavesim {

TableFile::TableFile(const std::string& path, std::string what) : path_(path), what_(std::move(what)) {
  file_ = hdf5::Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  check(file_.valid(), "cannot create");
}

void TableFile::attribute(const std::string& object, const std::string& name, const std::string& value) {
  const hdf5::Handle type = hdf5::variable_text_type();
  const hdf5::Handle space(H5Screate(H5S_SCALAR));
  const char* text = value.c_str();
  write_attribute(object, name, type.get(), space.get(), &text);
}

void TableFile::attribute(const std::string& object, const std::string& name, double value) {
  const hdf5::Handle space(H5Screate(H5S_SCALAR));
  write_attribute(object, name, H5T_NATIVE_DOUBLE, space.get(), &value);
}

void TableFile::attribute(const std::string& object, const std::string& name, long value) {
  const hdf5::Handle space(H5Screate(H5S_SCALAR));
  write_attribute(object, name, H5T_NATIVE_LONG, space.get(), &value);
}

void TableFile::numbers(const std::string& path, const std::vector<double>& values, std::size_t columns,
                        const std::string& units, const std::string& description) {
  const hsize_t dims[2] = {values.size() / std::max<std::size_t>(columns, 1), columns};
  write(path, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, columns > 1 ? 2 : 1, dims, values.data(), units, description);
}

void TableFile::integers(const std::string& path, const std::vector<long>& values, const std::string& description) {
  const hsize_t dims[1] = {values.size()};
  write(path, H5T_STD_I64LE, H5T_NATIVE_LONG, 1, dims, values.data(), "-", description);
}

void TableFile::texts(const std::string& path, const std::vector<std::string>& values, const std::string& description) {
  std::vector<const char*> pointers;
  for (const std::string& value : values) pointers.push_back(value.c_str());
  const hsize_t dims[1] = {values.size()};
  const hdf5::Handle type = hdf5::variable_text_type();
  write(path, type.get(), type.get(), 1, dims, pointers.data(), "-", description);
}

void TableFile::close() { check(file_.close(), "cannot close"); }

void TableFile::write(const std::string& path, hid_t file_type, hid_t memory_type, int rank, const hsize_t* dims,
                      const void* data, const std::string& units, const std::string& description) {
  const hdf5::Handle space(H5Screate_simple(rank, dims, nullptr));
  const hdf5::Handle links = hdf5::intermediate_group_links();
  const hdf5::Handle dataset(
      H5Dcreate2(file_.get(), path.c_str(), file_type, space.get(), links.get(), H5P_DEFAULT, H5P_DEFAULT));
  check(dataset.valid(), "cannot create dataset " + path + " in");
  if (dims[0] > 0)
    check(H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0, "cannot write " + path + " in");
  attribute(path, "units", units);
  attribute(path, "description", description);
}

void TableFile::write_attribute(const std::string& object, const std::string& name, hid_t type, hid_t space,
                                const void* data) {
  const hdf5::Handle attribute(
      H5Acreate_by_name(file_.get(), object.c_str(), name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  check(attribute.valid() && H5Awrite(attribute.get(), type, data) >= 0, "cannot write attribute " + name + " in");
}

void TableFile::check(bool succeeded, const std::string& action) {
  if (!succeeded) throw OutputError(path_, action + " " + what_, errno ? std::strerror(errno) : "HDF5 error");
}

}  // namespace heavesim
