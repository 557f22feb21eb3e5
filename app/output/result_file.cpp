#include "app/output/result_file.hpp"

#include <algorithm>
#include <stdexcept>

namespace heavesim {
namespace {

using hdf5::Handle;

void replace_attribute(hid_t object, const std::string& name) {
  if (H5Aexists(object, name.c_str()) > 0) H5Adelete(object, name.c_str());
}

}  // namespace

ResultFile::ResultFile(const std::string& path) : path_(path) {
  H5Eset_auto(H5E_DEFAULT, nullptr, nullptr);  // errors are reported by return codes below
  file_ = Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  if (!file_.valid()) throw std::runtime_error("cannot create result file '" + path + "'");
}

ResultFile::~ResultFile() {
  flush();
  // The series' datasets close before the file (members are destroyed in reverse
  // order of declaration, and series_ is declared after file_).
}

Handle ResultFile::open_object(const std::string& object_path) {
  if (object_path == "/" || object_path.empty()) return Handle(H5Oopen(file_.get(), "/", H5P_DEFAULT));
  if (H5Lexists(file_.get(), object_path.c_str(), H5P_DEFAULT) <= 0) {
    const Handle links = hdf5::intermediate_group_links();
    return Handle(H5Gcreate2(file_.get(), object_path.c_str(), links.get(), H5P_DEFAULT, H5P_DEFAULT));
  }
  return Handle(H5Oopen(file_.get(), object_path.c_str(), H5P_DEFAULT));
}

void ResultFile::set_attribute(const std::string& object_path, const std::string& name, const std::string& value) {
  const Handle object = open_object(object_path);
  replace_attribute(object.get(), name);
  const Handle type = hdf5::variable_text_type();
  const Handle space(H5Screate(H5S_SCALAR));
  const Handle attribute(H5Acreate2(object.get(), name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT));
  const char* text = value.c_str();
  H5Awrite(attribute.get(), type.get(), &text);
}

void ResultFile::set_attribute(const std::string& object_path, const std::string& name, double value) {
  set_attribute(object_path, name, std::vector<double>{value});
}

void ResultFile::set_attribute(const std::string& object_path, const std::string& name, long value) {
  const Handle object = open_object(object_path);
  replace_attribute(object.get(), name);
  const Handle space(H5Screate(H5S_SCALAR));
  const Handle attribute(
      H5Acreate2(object.get(), name.c_str(), H5T_NATIVE_LONG, space.get(), H5P_DEFAULT, H5P_DEFAULT));
  H5Awrite(attribute.get(), H5T_NATIVE_LONG, &value);
}

void ResultFile::set_attribute(const std::string& object_path, const std::string& name,
                               const std::vector<double>& values) {
  const Handle object = open_object(object_path);
  replace_attribute(object.get(), name);
  const hsize_t size = values.size();
  const Handle space(size == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &size, nullptr));
  const Handle attribute(
      H5Acreate2(object.get(), name.c_str(), H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT, H5P_DEFAULT));
  H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, values.data());
}

void ResultFile::write_text(const std::string& dataset_path, const std::string& text, const std::string& description) {
  const Handle type = hdf5::variable_text_type();
  const Handle space(H5Screate(H5S_SCALAR));
  const Handle links = hdf5::intermediate_group_links();
  const Handle dataset(
      H5Dcreate2(file_.get(), dataset_path.c_str(), type.get(), space.get(), links.get(), H5P_DEFAULT, H5P_DEFAULT));
  if (!dataset.valid()) throw std::runtime_error("cannot create dataset " + dataset_path + " in " + path_);
  const char* data = text.c_str();
  H5Dwrite(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, &data);
  set_attribute(dataset_path, "description", description);
  set_attribute(dataset_path, "units", std::string("-"));
}

int ResultFile::add_series(const std::string& dataset_path, int columns, const std::string& units,
                           const std::string& description) {
  const int rank = columns == 0 ? 1 : 2;
  const hsize_t initial[2] = {0, static_cast<hsize_t>(columns)};
  const hsize_t maximum[2] = {H5S_UNLIMITED, static_cast<hsize_t>(columns)};
  const hsize_t chunk[2] = {chunk_rows, static_cast<hsize_t>(std::max(columns, 1))};
  const Handle space(H5Screate_simple(rank, initial, maximum));
  const Handle create(H5Pcreate(H5P_DATASET_CREATE));
  H5Pset_chunk(create.get(), rank, chunk);
  const Handle links = hdf5::intermediate_group_links();
  Handle dataset(H5Dcreate2(file_.get(), dataset_path.c_str(), H5T_NATIVE_DOUBLE, space.get(), links.get(),
                            create.get(), H5P_DEFAULT));
  if (!dataset.valid()) throw std::runtime_error("cannot create dataset " + dataset_path + " in " + path_);
  Series series;
  series.dataset = std::move(dataset);
  series.columns = columns;
  series_.push_back(std::move(series));
  set_attribute(dataset_path, "units", units);
  set_attribute(dataset_path, "description", description);
  return static_cast<int>(series_.size()) - 1;
}

void ResultFile::append(int series_id, const double* row) {
  Series& series = series_[series_id];
  const int width = std::max(series.columns, 1);
  series.buffer.insert(series.buffer.end(), row, row + width);
}

void ResultFile::end_sample() {
  if (++buffered_samples_ >= chunk_rows) flush();
}

void ResultFile::flush() {
  if (!file_.valid()) return;
  buffered_samples_ = 0;
  for (Series& series : series_) {
    const int width = std::max(series.columns, 1);
    const hsize_t rows = series.buffer.size() / width;
    if (rows == 0) continue;
    const int rank = series.columns == 0 ? 1 : 2;
    const hsize_t new_size[2] = {series.rows_written + rows, static_cast<hsize_t>(series.columns)};
    H5Dset_extent(series.dataset.get(), new_size);
    const Handle file_space(H5Dget_space(series.dataset.get()));
    const hsize_t start[2] = {series.rows_written, 0};
    const hsize_t count[2] = {rows, static_cast<hsize_t>(series.columns)};
    H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr);
    const Handle memory_space(H5Screate_simple(rank, count, nullptr));
    H5Dwrite(series.dataset.get(), H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(), H5P_DEFAULT,
             series.buffer.data());
    series.rows_written += rows;
    series.buffer.clear();
  }
  H5Fflush(file_.get(), H5F_SCOPE_GLOBAL);
}

}  // namespace heavesim
