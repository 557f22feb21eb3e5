#include "app/output/result_file.hpp"

#include <stdexcept>

namespace heavesim {
namespace {

hid_t link_create_plist() {
  const hid_t plist = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(plist, 1);
  return plist;
}

void replace_attribute(hid_t object, const std::string& name) {
  if (H5Aexists(object, name.c_str()) > 0) H5Adelete(object, name.c_str());
}

}  // namespace

ResultFile::ResultFile(const std::string& path) : path_(path) {
  H5Eset_auto(H5E_DEFAULT, nullptr, nullptr);  // errors are reported by return codes below
  file_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) throw std::runtime_error("cannot create result file '" + path + "'");
}

ResultFile::~ResultFile() {
  flush();
  for (Series& series : series_)
    if (series.dataset >= 0) H5Dclose(series.dataset);
  if (file_ >= 0) H5Fclose(file_);
}

hid_t ResultFile::open_object(const std::string& object_path) {
  if (object_path == "/" || object_path.empty()) return H5Oopen(file_, "/", H5P_DEFAULT);
  if (H5Lexists(file_, object_path.c_str(), H5P_DEFAULT) <= 0) {
    const hid_t plist = link_create_plist();
    const hid_t group = H5Gcreate2(file_, object_path.c_str(), plist, H5P_DEFAULT, H5P_DEFAULT);
    H5Pclose(plist);
    return group;
  }
  return H5Oopen(file_, object_path.c_str(), H5P_DEFAULT);
}

void ResultFile::set_attribute(const std::string& object_path, const std::string& name, const std::string& value) {
  const hid_t object = open_object(object_path);
  replace_attribute(object, name);
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attribute = H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  const char* text = value.c_str();
  H5Awrite(attribute, type, &text);
  H5Aclose(attribute);
  H5Sclose(space);
  H5Tclose(type);
  H5Oclose(object);
}

void ResultFile::set_attribute(const std::string& object_path, const std::string& name, double value) {
  set_attribute(object_path, name, std::vector<double>{value});
}

void ResultFile::set_attribute(const std::string& object_path, const std::string& name, long value) {
  const hid_t object = open_object(object_path);
  replace_attribute(object, name);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attribute = H5Acreate2(object, name.c_str(), H5T_NATIVE_LONG, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(attribute, H5T_NATIVE_LONG, &value);
  H5Aclose(attribute);
  H5Sclose(space);
  H5Oclose(object);
}

void ResultFile::set_attribute(const std::string& object_path, const std::string& name,
                               const std::vector<double>& values) {
  const hid_t object = open_object(object_path);
  replace_attribute(object, name);
  const hsize_t size = values.size();
  const hid_t space = size == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &size, nullptr);
  const hid_t attribute = H5Acreate2(object, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(attribute, H5T_NATIVE_DOUBLE, values.data());
  H5Aclose(attribute);
  H5Sclose(space);
  H5Oclose(object);
}

void ResultFile::write_text(const std::string& dataset_path, const std::string& text, const std::string& description) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t plist = link_create_plist();
  const hid_t dataset = H5Dcreate2(file_, dataset_path.c_str(), type, space, plist, H5P_DEFAULT, H5P_DEFAULT);
  if (dataset < 0) throw std::runtime_error("cannot create dataset " + dataset_path + " in " + path_);
  const char* data = text.c_str();
  H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, &data);
  H5Dclose(dataset);
  H5Pclose(plist);
  H5Sclose(space);
  H5Tclose(type);
  set_attribute(dataset_path, "description", description);
  set_attribute(dataset_path, "units", std::string("-"));
}

int ResultFile::add_series(const std::string& dataset_path, int columns, const std::string& units,
                           const std::string& description) {
  const int rank = columns == 0 ? 1 : 2;
  const hsize_t initial[2] = {0, static_cast<hsize_t>(columns)};
  const hsize_t maximum[2] = {H5S_UNLIMITED, static_cast<hsize_t>(columns)};
  const hsize_t chunk[2] = {chunk_rows, static_cast<hsize_t>(std::max(columns, 1))};
  const hid_t space = H5Screate_simple(rank, initial, maximum);
  const hid_t create = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(create, rank, chunk);
  const hid_t plist = link_create_plist();
  const hid_t dataset =
      H5Dcreate2(file_, dataset_path.c_str(), H5T_NATIVE_DOUBLE, space, plist, create, H5P_DEFAULT);
  H5Pclose(plist);
  H5Pclose(create);
  H5Sclose(space);
  if (dataset < 0) throw std::runtime_error("cannot create dataset " + dataset_path + " in " + path_);
  Series series;
  series.dataset = dataset;
  series.columns = columns;
  series_.push_back(series);
  set_attribute(dataset_path, "units", units);
  set_attribute(dataset_path, "description", description);
  return static_cast<int>(series_.size()) - 1;
}

void ResultFile::append(int series_id, const double* row) {
  Series& series = series_[series_id];
  const int width = std::max(series.columns, 1);
  series.buffer.insert(series.buffer.end(), row, row + width);
  if (series.buffer.size() >= chunk_rows * width) flush();
}

void ResultFile::flush() {
  if (file_ < 0) return;
  for (Series& series : series_) {
    const int width = std::max(series.columns, 1);
    const hsize_t rows = series.buffer.size() / width;
    if (rows == 0) continue;
    const int rank = series.columns == 0 ? 1 : 2;
    const hsize_t new_size[2] = {series.rows_written + rows, static_cast<hsize_t>(series.columns)};
    H5Dset_extent(series.dataset, new_size);
    const hid_t file_space = H5Dget_space(series.dataset);
    const hsize_t start[2] = {series.rows_written, 0};
    const hsize_t count[2] = {rows, static_cast<hsize_t>(series.columns)};
    H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, count, nullptr);
    const hid_t memory_space = H5Screate_simple(rank, count, nullptr);
    H5Dwrite(series.dataset, H5T_NATIVE_DOUBLE, memory_space, file_space, H5P_DEFAULT, series.buffer.data());
    H5Sclose(memory_space);
    H5Sclose(file_space);
    series.rows_written += rows;
    series.buffer.clear();
  }
  H5Fflush(file_, H5F_SCOPE_GLOBAL);
}

}  // namespace heavesim
