#include "app/output/result_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "signal/fixed_width.hpp"

namespace heavesim {
namespace {

using hdf5::Handle;

constexpr const char* samples_written_name = "samples_written";
// Room held in the object headers of the root and of /summary for the attributes written
// when the run ends (their names depend on the case; a failure's text): released just
// before the first of them is created, so that they fill space the header already has
// instead of a new continuation block (an allocation, which a SIGKILL inside HDF5's
// flush can leave pointing past the end of file; see the header). A v1 attribute
// message of a number takes ~80 bytes; what is left of the room is released at close.
constexpr const char* reserved_room_name = "_reserved_room";
constexpr hsize_t root_room_bytes = 8192, summary_room_bytes = 32768;

// Metadata (object headers, chunk indexes) is taken from blocks of this size instead of
// HDF5's 2 kB: with small blocks, the metadata that growing the series makes lands between
// their chunks, and a block's chunks no longer lie side by side (arrange_chunks_by_block).
// The drilling run's 12 blocks of 100 chunks lie in 16 runs with 64 KiB (block 0 in 5, the
// metadata of the first growth among them), and the run makes 108 pwrites in all (2 kB:
// 296; 16 KiB: 140); the file grows by the unused part of the last block (~30 kB). Larger
// blocks gain nothing more and put a small file over a limit (tests/app/test_write_failures.cpp).
constexpr hsize_t metadata_block_bytes = hsize_t{64} << 10;

// A descriptor of the file HDF5 writes, for the whole blocks' raw chunk data (write_raw),
// or -1 (HDF5 then writes every chunk itself). A duplicate of the POSIX driver's own, so it
// is the same file whatever happens to the path; only with no user block, where an HDF5
// address is a file offset (HDF5 1.10 reports chunk addresses without the user block,
// HDFGroup/hdf5 issue #3003).
int raw_data_descriptor(hid_t file, hid_t access) {
  const Handle creation(H5Fget_create_plist(file));
  hsize_t user_block = 1;
  void* handle = nullptr;
  if (!creation.valid() || H5Pget_userblock(creation.get(), &user_block) < 0 || user_block != 0 ||
      H5Pget_driver(access) != H5FD_SEC2 || H5Fget_vfd_handle(file, access, &handle) < 0 || handle == nullptr)
    return -1;
  return ::fcntl(*static_cast<int*>(handle), F_DUPFD_CLOEXEC, 0);
}

// The writer takes no HDF5 file lock (H5Pset_file_locking, HDF5 1.10.7): a reader may
// open the file while the run writes it without HDF5_USE_FILE_LOCKING=FALSE. What it
// reads then is what a SIGKILL at that moment would leave, whole samples up to
// samples_written (the header), because nothing structural changes during the run.
Handle result_file_access() {
  Handle access(H5Pcreate(H5P_FILE_ACCESS));
  if (H5Pset_file_locking(access.get(), false, true) < 0 ||
      H5Pset_meta_block_size(access.get(), metadata_block_bytes) < 0)
    access.reset();
  return access;
}

// The chunk index's B-tree nodes sized to the series' reserved chunks: HDF5's default
// K = 32 makes every series' node hold 64 chunk addresses (a 2.6 kB node on disk and
// ~17.7 kB in memory each, 1.8 MB for the drilling run's 100 series, which has 12 chunks
// a series); the smallest K whose node holds them all keeps one node a series (a B-tree of
// more levels, as HDF5 grows it, past the reservation). K != 32 makes HDF5 write a
// version 1 superblock, which stores K (HDF5 1.6 and later read it). Without a
// reservation (a file grown as it is written) HDF5's default stays.
// docs/performance.md, "Issue #18, twenty-third round".
Handle result_file_creation(hsize_t reserved_chunks) {
  Handle creation(H5Pcreate(H5P_FILE_CREATE));
  if (reserved_chunks == 0 || !creation.valid()) return creation;
  const auto k = static_cast<unsigned>(std::min<hsize_t>((reserved_chunks + 1) / 2, 32));
  if (H5Pset_istore_k(creation.get(), k) < 0) creation.reset();
  return creation;
}

// Whether an attribute's stored type is `type`, so that it can be overwritten in place.
// The records (compounds of doubles, ~40 fields for a channel's statistics) are compared
// member by member in order: H5Tequal sorts both compounds' members by name first
// (a bubble sort in HDF5 1.10, O(n^2) strcmp), ~1 % of a drilling run's CPU at its end
// for its ~100 statistics attributes. In order is stricter (the same members in another
// order are not equal here), which only means the attribute is written anew.
bool stored_type_is(hid_t stored, hid_t type) {
  if (H5Tget_class(type) != H5T_COMPOUND) return H5Tequal(stored, type) > 0;
  const int members = H5Tget_nmembers(type);
  if (H5Tget_class(stored) != H5T_COMPOUND || H5Tget_nmembers(stored) != members ||
      H5Tget_size(stored) != H5Tget_size(type))
    return false;
  for (int m = 0; m < members; ++m) {
    const auto member = static_cast<unsigned>(m);
    if (H5Tget_member_offset(stored, member) != H5Tget_member_offset(type, member)) return false;
    char* stored_name = H5Tget_member_name(stored, member);
    char* name = H5Tget_member_name(type, member);
    const bool same_name = stored_name != nullptr && name != nullptr && std::strcmp(stored_name, name) == 0;
    H5free_memory(stored_name);
    H5free_memory(name);
    if (!same_name) return false;
    const Handle stored_member(H5Tget_member_type(stored, member)), member_type(H5Tget_member_type(type, member));
    if (H5Tequal(stored_member.get(), member_type.get()) <= 0) return false;
  }
  return true;
}

/// The dataspace of an attribute of `values` values (or records): a scalar for a single
/// value when `scalar_when_single`, else one dimension.
Handle attribute_space(hsize_t values, bool scalar_when_single) {
  return Handle(scalar_when_single && values == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &values, nullptr));
}

/// Records of a compound attribute: one per fields.size() values.
hsize_t record_count(const std::vector<std::string>& fields, const std::vector<double>& values) {
  return fields.empty() ? 0 : values.size() / fields.size();
}

/// `rows` rows of `width` values, `from_stride` values apart, into consecutive rows of
/// `to`. `Width` > 0 fixes the width at compile time, which makes each row a few register
/// moves: a copy of a run-time width is a memmove call per row, and the drilling run's
/// staged rows (101 series of 1 to 6 values, 12001 samples) made 1.2 million of them,
/// 15 % of the samples' thread (docs/performance.md, "Issue #18, eleventh round").
template <int Width>
void copy_strided_rows(const double* from, hsize_t from_stride, double* to, hsize_t rows, hsize_t runtime_width) {
  const hsize_t width = Width > 0 ? static_cast<hsize_t>(Width) : runtime_width;
  for (hsize_t row = 0; row < rows; ++row) {
    const double* source = from + row * from_stride;
    double* target = to + row * width;
    for (hsize_t value = 0; value < width; ++value) target[value] = source[value];
  }
}

// No chunk cache: a write goes to disk in H5Dwrite, where its failure is seen, and a
// dataset never holds data that closing it would have to write.
Handle uncached_dataset_access() {
  Handle access(H5Pcreate(H5P_DATASET_ACCESS));
  if (H5Pset_chunk_cache(access.get(), H5D_CHUNK_CACHE_NSLOTS_DEFAULT, 0, 1.0) < 0) access.reset();
  return access;
}

}  // namespace

ResultFile::ResultFile(const std::string& path, hsize_t reserved_samples)
    : path_(path), partial_path_(path + ".partial"), reserved_samples_(reserved_samples) {
  hdf5::report_errors_by_return_codes();
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw OutputError(path_, "cannot create result file", "the path is a directory");
  // Today's result replaces any earlier one at once, as opening with truncation did: a
  // stale complete = 1 file must not stand for a run that then fails in its set-up.
  // Removing a file frees its pages, ~3 ms for the drilling case's 21 MB: with the file
  // held open, the name goes now and the pages when the last descriptor closes, which a
  // helper thread does beside the set-up (docs/performance.md, "Issue #18, sixteenth round").
  // (On NFS the open file's name becomes .nfsXXXX in its directory until that close.)
  if (std::filesystem::exists(path, error)) {
    // A regular file only, never followed through a link nor waited on (a FIFO's open
    // would wait for a writer): anything else, or one not readable, is removed in line.
    if (std::filesystem::is_regular_file(std::filesystem::symlink_status(path, error)))
      previous_result_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (!std::filesystem::remove(path, error)) {
      if (previous_result_ >= 0) ::close(std::exchange(previous_result_, -1));
      throw OutputError(path_, "cannot replace result file", error.message());
    }
    if (previous_result_ >= 0) previous_result_release_.start();
  }
  const Handle access = result_file_access();
  const Handle creation = result_file_creation((reserved_samples + block_rows - 1) / block_rows);
  file_ = Handle(H5Fcreate(partial_path_.c_str(), H5F_ACC_TRUNC, creation.valid() ? creation.get() : H5P_DEFAULT,
                           access.get()));
  if (!file_.valid()) throw OutputError(path_, "cannot create result file", hdf5::last_error());
  text_type_ = hdf5::variable_text_type();
  links_ = hdf5::intermediate_group_links();
  dataset_access_ = uncached_dataset_access();
  check(text_type_.valid() && links_.valid() && dataset_access_.valid(), "cannot create result file");
  set_attribute("/", samples_written_name, 0L);
  for (const auto& [object, bytes] : {std::pair{"/", root_room_bytes}, std::pair{"/summary", summary_room_bytes}}) {
    const std::vector<unsigned char> room(bytes, 0);
    const Handle room_space(H5Screate_simple(1, &bytes, nullptr));
    write_attribute(open_object(object).get(), reserved_room_name, H5T_NATIVE_UCHAR, room_space.get(), room.data());
  }
  raw_data_ = raw_data_descriptor(file_.get(), access.get());  // last: nothing after it throws
}

void ResultFile::close_previous_result() { ::close(std::exchange(previous_result_, -1)); }

ResultFile::~ResultFile() {
  try {
    settle();
  } catch (...) {
    // The block writer's failure is recorded in failure_: the file is abandoned below.
  }
  if (published_ && !closed_ && failure_.empty()) {
    try {
      close();
    } catch (...) {
      // close() has recorded the failure and abandoned the file; a destructor reports nothing.
    }
  }
  if (!closed_) abandon();
  if (!published_) {
    std::error_code ignored;
    std::filesystem::remove(partial_path_, ignored);
  }
}

void ResultFile::fail(const std::string& action) { fail(action, hdf5::last_error()); }

void ResultFile::fail_with_errno(const std::string& action) {
  // The message of errno's value, read once (std::strerror may use a buffer every thread shares).
  fail(action, std::generic_category().message(errno));
}

void ResultFile::fail(const std::string& action, const std::string& cause) {
  failure_cause_ = cause;
  failure_ = OutputError(path_, action, cause).what();
  throw OutputError(path_, action, cause);
}

void ResultFile::check_usable() const {
  if (!failure_.empty()) throw OutputError(path_, "result file not written after an earlier failure", failure_cause_);
  if (closed_) throw std::logic_error("ResultFile: write after close: " + path_);
}

void ResultFile::abandon() {
  // Nothing more reaches the disk: the file stays as the last complete flush left it.
  for (Series& series : series_) {
    for (Series::KeptAttribute& kept : series.kept_attributes) kept.attribute.abandon();
    series.dataset.abandon();
  }
  for (auto& [fields, type] : record_types_) type.abandon();
  file_.abandon();
  if (raw_data_ >= 0) ::close(std::exchange(raw_data_, -1));
}

Handle ResultFile::open_object(const std::string& object_path) {
  if (object_path == "/" || object_path.empty()) {
    Handle root(H5Oopen(file_.get(), "/", H5P_DEFAULT));
    check(root.valid(), "cannot write result file");
    return root;
  }
  const htri_t exists = H5Lexists(file_.get(), object_path.c_str(), H5P_DEFAULT);
  Handle object;
  if (exists <= 0) {
    object = Handle(H5Gcreate2(file_.get(), object_path.c_str(), links_.get(), H5P_DEFAULT, H5P_DEFAULT));
  } else {
    object = Handle(H5Oopen(file_.get(), object_path.c_str(), H5P_DEFAULT));
  }
  check(object.valid(), "cannot write result file");
  return object;
}

Handle ResultFile::write_attribute(hid_t object, const std::string& name, hid_t type, hid_t space, const void* data,
                                   std::vector<Series::KeptAttribute>* open_attributes) {
  Handle attribute;
  if (H5Aexists(object, name.c_str()) > 0) {
    attribute = Handle(H5Aopen(object, name.c_str(), H5P_DEFAULT));
    check(attribute.valid(), "cannot write result file");
    const Handle stored_type(H5Aget_type(attribute.get()));
    const Handle stored_space(H5Aget_space(attribute.get()));
    if (!stored_type_is(stored_type.get(), type) || H5Sextent_equal(stored_space.get(), space) <= 0) {
      attribute.reset();
      // HDF5 deletes an attribute safely with none of its object's attributes open; the
      // series' kept ones are opened again as they are written.
      if (open_attributes) open_attributes->clear();
      check(H5Adelete(object, name.c_str()) >= 0, "cannot write result file");
    }
  }
  if (!attribute.valid()) {
    // Once published only: while the layout is built, headers grow as they need.
    if (published_ && name != reserved_room_name && H5Aexists(object, reserved_room_name) > 0)
      check(H5Adelete(object, reserved_room_name) >= 0, "cannot write result file");
    attribute = Handle(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT));
  }
  check(attribute.valid(), "cannot write result file");
  check(H5Awrite(attribute.get(), type, data) >= 0, "cannot write result file");
  return attribute;
}

void ResultFile::write_doubles(hid_t object, const std::string& name, const std::vector<double>& values) {
  const Handle space = attribute_space(values.size(), true);
  write_attribute(object, name, H5T_NATIVE_DOUBLE, space.get(), values.data());
}

hid_t ResultFile::record_type(const std::vector<std::string>& fields) {
  auto known = std::find_if(record_types_.begin(), record_types_.end(),
                            [&fields](const auto& entry) { return entry.first == fields; });
  if (known == record_types_.end()) {
    // Members in name order, each at its field's place in the values (f * 8 bytes): HDF5
    // 1.10 compares two compound types (H5Awrite's conversion path, H5Acreate2's copy) after
    // bubble-sorting both member lists by name, O(n^2) strcmp for the ~40 statistics in
    // the order of their meaning and one pass when already sorted. The drilling run's
    // 101 statistics attributes, made with their placeholders and overwritten at the end,
    // spent ~7 % of the main thread there (docs/performance.md, "Issue #18, eleventh round").
    std::vector<std::size_t> by_name(fields.size());
    std::iota(by_name.begin(), by_name.end(), std::size_t{0});
    std::sort(by_name.begin(), by_name.end(),
              [&fields](std::size_t a, std::size_t b) { return fields[a] < fields[b]; });
    Handle type(H5Tcreate(H5T_COMPOUND, fields.size() * sizeof(double)));
    check(type.valid(), "cannot write result file");
    for (const std::size_t f : by_name)
      check(H5Tinsert(type.get(), fields[f].c_str(), f * sizeof(double), H5T_NATIVE_DOUBLE) >= 0,
            "cannot write result file");
    // Stored once in the file (a datatype object no group links to): every attribute of
    // these fields refers to it instead of holding the members' names and types in its
    // series' header (~2.5 kB for the ~40 statistics), which every flush of a header
    // rewrites. Readers see the same compound (docs/performance.md, "Issue #18,
    // twenty-third round"). Before the layout is published only: a datatype object made
    // later would change the file's structure under a reader. (An attribute of these fields
    // deleted and made again after that changes the type's reference count: a header write,
    // as the attribute's own is.)
    if (!published_)
      check(H5Tcommit_anon(file_.get(), type.get(), H5P_DEFAULT, H5P_DEFAULT) >= 0, "cannot write result file");
    record_types_.emplace_back(fields, std::move(type));
    known = record_types_.end() - 1;
  }
  return known->second.get();
}

void ResultFile::write_records(hid_t object, const std::string& name, const std::vector<std::string>& fields,
                               const std::vector<double>& values) {
  const Handle space = attribute_space(record_count(fields, values), false);
  write_attribute(object, name, record_type(fields), space.get(), values.data());
}

void ResultFile::write_series_attribute(Series& series, const std::string& name, hid_t type, hsize_t values,
                                        bool scalar_when_single, const void* data) {
  auto kept = std::find_if(series.kept_attributes.begin(), series.kept_attributes.end(),
                           [&name](const Series::KeptAttribute& attribute) { return attribute.name == name; });
  if (kept != series.kept_attributes.end() && kept->type == type && kept->values == values) {
    check(H5Awrite(kept->attribute.get(), type, data) >= 0, "cannot write result file");
    return;
  }
  if (kept != series.kept_attributes.end()) series.kept_attributes.erase(kept);  // another type or shape
  const Handle space = attribute_space(values, scalar_when_single);
  Handle attribute = write_attribute(series.dataset.get(), name, type, space.get(), data, &series.kept_attributes);
  series.kept_attributes.push_back({name, std::move(attribute), type, values});
}

void ResultFile::write_text_attribute(hid_t object, const std::string& name, const std::string& value) {
  const Handle space(H5Screate(H5S_SCALAR));
  const char* text = value.c_str();
  write_attribute(object, name, text_type_.get(), space.get(), &text);
}

void ResultFile::set_attribute(const std::string& object_path, const std::string& name, const std::string& value) {
  ready_to_write();
  write_text_attribute(open_object(object_path).get(), name, value);
}

void ResultFile::set_attribute(const std::string& object_path, const std::string& name, double value) {
  set_attribute(object_path, name, std::vector<double>{value});
}

void ResultFile::set_attribute(const std::string& object_path, const std::string& name, long value) {
  ready_to_write();
  const Handle space(H5Screate(H5S_SCALAR));
  write_attribute(open_object(object_path).get(), name, H5T_NATIVE_LONG, space.get(), &value);
}

void ResultFile::set_attribute(const std::string& object_path, const std::string& name,
                               const std::vector<double>& values) {
  ready_to_write();
  write_doubles(open_object(object_path).get(), name, values);
}

void ResultFile::set_record_attribute(const std::string& object_path, const std::string& name,
                                     const std::vector<std::string>& fields, const std::vector<double>& values) {
  ready_to_write();
  write_records(open_object(object_path).get(), name, fields, values);
}

void ResultFile::set_attribute(int series, const std::string& name, const std::vector<double>& values) {
  ready_to_write();
  write_series_attribute(series_.at(series), name, H5T_NATIVE_DOUBLE, values.size(), true, values.data());
}

void ResultFile::set_record_attribute(int series, const std::string& name, const std::vector<std::string>& fields,
                                     const std::vector<double>& values) {
  ready_to_write();
  write_series_attribute(series_.at(series), name, record_type(fields), record_count(fields, values), false,
                         values.data());
}

void ResultFile::write_text(const std::string& dataset_path, const std::string& text, const std::string& description) {
  ready_to_write();
  const Handle space(H5Screate(H5S_SCALAR));
  const Handle dataset(H5Dcreate2(file_.get(), dataset_path.c_str(), text_type_.get(), space.get(), links_.get(),
                                  H5P_DEFAULT, H5P_DEFAULT));
  check(dataset.valid(), "cannot create dataset " + dataset_path + " in");
  // One element to convert (a variable-length string: its pointer into the global heap):
  // a conversion buffer of one page, not HDF5's default of 1 MB, which it allocates with
  // calloc, ~1.5 ms of page faults in every run's set-up (docs/performance.md, "Issue #18,
  // eleventh round").
  const Handle transfer(H5Pcreate(H5P_DATASET_XFER));
  check(transfer.valid() && H5Pset_buffer(transfer.get(), 4096, nullptr, nullptr) >= 0, "cannot write result file");
  const char* data = text.c_str();
  check(H5Dwrite(dataset.get(), text_type_.get(), H5S_ALL, H5S_ALL, transfer.get(), &data) >= 0,
        "cannot write result file");
  write_text_attribute(dataset.get(), "description", description);
  write_text_attribute(dataset.get(), "units", "-");
}

int ResultFile::add_series(const std::string& dataset_path, int columns, const std::string& units,
                           const std::string& description) {
  ready_to_write();
  // A dataset made once the layout is published would change the file's structure while
  // readers (and a SIGKILL) may find it half made (the header).
  if (published_) throw std::logic_error("ResultFile: a series added after the layout was published: " + dataset_path);
  // The staging's layout is the series' (a row of each side by side): fixed before a sample.
  if (buffered_samples_ > 0 || rows_on_disk_ > 0)
    throw std::logic_error("ResultFile: a series added after samples: " + dataset_path);
  const int rank = columns == 0 ? 1 : 2;
  // No row: arrange_chunks_by_block(), which runs only once there are samples or as the
  // layout is published (both refused above), grows every series to its reservation.
  const hsize_t initial[2] = {0, static_cast<hsize_t>(columns)};
  const hsize_t maximum[2] = {H5S_UNLIMITED, static_cast<hsize_t>(columns)};
  const hsize_t chunk[2] = {block_rows, static_cast<hsize_t>(std::max(columns, 1))};
  const Handle space(H5Screate_simple(rank, initial, maximum));
  const Handle create(H5Pcreate(H5P_DATASET_CREATE));
  // Chunks allocated as the dataset grows to its reservation (arrange_chunks_by_block),
  // and never filled: see the header (no structural change after the layout).
  const bool configured = H5Pset_chunk(create.get(), rank, chunk) >= 0 &&
                          H5Pset_alloc_time(create.get(), H5D_ALLOC_TIME_EARLY) >= 0 &&
                          H5Pset_fill_time(create.get(), H5D_FILL_TIME_NEVER) >= 0 &&
                          H5Pset_obj_track_times(create.get(), false) >= 0;
  check(configured, "cannot create result file");
  Handle dataset(H5Dcreate2(file_.get(), dataset_path.c_str(), H5T_NATIVE_DOUBLE, space.get(), links_.get(),
                            create.get(), dataset_access_.get()));
  check(dataset.valid(), "cannot create dataset " + dataset_path + " in");
  Series series;
  series.dataset = std::move(dataset);
  series.columns = columns;
  series.width = static_cast<hsize_t>(std::max(columns, 1));
  series.staging_offset = staging_width_;
  staging_width_ += series.width;
  staging_.resize(staged_rows * staging_width_);  // no sample before the layout stands (resize: amortized, not a fill per series)
  building_block_.reset();  // made for the whole layout when first needed
  last_block_.reset();
  series_.push_back(std::move(series));
  const int id = static_cast<int>(series_.size()) - 1;
  const hid_t object = series_[id].dataset.get();
  write_text_attribute(object, "units", units);
  write_text_attribute(object, "description", description);
  // The per-column statistics written at the end exist from the start ("not computed
  // yet", NaN, until then): writing them then overwrites in place, allocating nothing.
  const std::vector<double> not_computed(std::max(columns, 1), std::nan(""));
  for (const char* statistic : series_statistics) set_attribute(id, statistic, not_computed);
  return id;
}

void ResultFile::append(int series_id, const double* row) {
  std::copy_n(row, series_[series_id].width, sample_row(series_id));
}

void ResultFile::make_blocks() {
  if (building_block_) return;
  // Not filled: a fill was 3.3 MB of stores (and page faults) on the integrating thread
  // before the first step; a block's rows are written before anything reads them.
  building_block_ = std::make_unique_for_overwrite<double[]>(block_rows * staging_width_);
  last_block_ = std::make_unique_for_overwrite<double[]>(block_rows * staging_width_);
}

void ResultFile::move_staged_rows_to_blocks() {
  make_blocks();
  if (staged_samples_ == 0) return;
  if (staged_samples_ > buffered_samples_) throw std::logic_error("ResultFile: more samples staged than buffered");
  const hsize_t first = buffered_samples_ - staged_samples_;
  for (Series& series : series_) {
    const double* from = staging_.data() + series.staging_offset;
    double* to = building_block_.get() + block_offset(series) + first * series.width;
    const hsize_t width = series.width;
    stats::call_with_fixed_width<1, 2, 3, 4, 6>(static_cast<std::ptrdiff_t>(width), [&](auto fixed) {
      copy_strided_rows<decltype(fixed)::value>(from, staging_width_, to, staged_samples_, width);
    });
  }
  // The row of a sample still being built (a flush between its appends) leads the next
  // run. A full run is moved by end_sample(), between samples: nothing is being built then.
  if (staged_samples_ < staged_rows)
    std::copy_n(staging_.begin() + static_cast<std::ptrdiff_t>(staged_samples_ * staging_width_), staging_width_,
                staging_.begin());
  staged_samples_ = 0;
}

void ResultFile::end_sample() {
  ++buffered_samples_;
  // A block's end moves what is staged too: block() may have moved a run short of 64.
  if (++staged_samples_ == staged_rows || buffered_samples_ == block_rows) move_staged_rows_to_blocks();
  if (buffered_samples_ < block_rows) return;
  // The block goes to the block writer, which writes it while the next one is filled;
  // the one before must be on disk first (and a failure of it is thrown here).
  ready_to_write();
  extend_series(rows_on_disk_ + block_rows);  // structural changes stay on this thread
  std::swap(building_block_, last_block_);
  handed_first_row_ = rows_on_disk_;
  rows_on_disk_ += block_rows;
  buffered_samples_ = 0;
  block_writer_.start();
  const double since_commit =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - last_commit_).count();
  // The first block at once: a reader (and a run stopped early) has samples from the start.
  // commit() waits for the block writer first.
  if (samples_written_ == 0 || extended_since_commit_ || since_commit >= commit_interval_s) commit();
}

void ResultFile::write_last_blocks() {
  hdf5::report_errors_by_return_codes();  // on this thread too
  write_whole_block(last_block_.get(), handed_first_row_, block_rows);
}

void ResultFile::arrange_chunks_by_block() {
  if (chunks_arranged_) return;
  chunks_arranged_ = true;
  // Early allocation gives a series all its chunks at its creation, so each series' chunks
  // lay together and a block was one pwrite a series: 1,200 for the drilling run, ~5 us
  // each on this virtual machine beyond the bytes' copy (docs/performance.md, "Issue #18,
  // twentieth round"). Growing all series a block at a time allocates block k's chunks
  // one after another, series by series, and a block is then a few pwrites. The growth
  // is structural, but the layout is not published yet: after it, nothing is.
  for (hsize_t rows = block_rows;; rows += block_rows) {
    const hsize_t step = std::min(rows, reserved_samples_);
    for (Series& series : series_) {
      if (series.extent >= step) continue;
      set_extent(series, step, "cannot create result file");
    }
    if (step == reserved_samples_) break;
  }
}

void ResultFile::write_whole_block(const double* block, hsize_t first_row, hsize_t rows) {
  // The run of series (consecutive in the block, so in memory too) whose chunks of this
  // block follow one another in the file.
  haddr_t run_address = HADDR_UNDEF;
  hsize_t run_bytes = 0;
  const double* run_data = nullptr;
  const auto write_run = [&] {
    if (run_bytes > 0) write_raw(run_data, run_bytes, run_address);
    run_bytes = 0;
  };
  const hsize_t offset[2] = {first_row, 0};
  // Raw writes need the descriptor and a block that starts a chunk (not after a flush mid-block).
  const bool raw_chunks = raw_data_ >= 0 && first_row % block_rows == 0;
  for (Series& series : series_) {
    const double* data = block + block_offset(series);
    const hsize_t bytes = chunk_bytes(series);
    // The chunk as the layout allocated it: unfiltered, at its full size.
    unsigned filter_mask = 0;
    haddr_t address = HADDR_UNDEF;
    hsize_t stored_bytes = 0;
    const bool in_place = raw_chunks &&
                          H5Dget_chunk_info_by_coord(series.dataset.get(), offset, &filter_mask, &address,
                                                     &stored_bytes) >= 0 &&
                          address != HADDR_UNDEF && filter_mask == 0 && stored_bytes == bytes;
    if (!in_place) {
      write_run();
      write_rows(series, data, first_row, rows);
      continue;
    }
    if (run_bytes > 0 && address == run_address + run_bytes) {
      run_bytes += bytes;
      continue;
    }
    write_run();
    run_address = address;
    run_bytes = bytes;
    run_data = data;
  }
  write_run();
}

void ResultFile::write_raw(const double* data, hsize_t bytes, haddr_t address) {
  const char* from = reinterpret_cast<const char*>(data);
  while (bytes > 0) {
    const ssize_t written = ::pwrite(raw_data_, from, bytes, static_cast<off_t>(address));
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) fail_with_errno("cannot write result file");
    if (written == 0) fail("cannot write result file", "nothing was written");
    from += written;
    bytes -= static_cast<hsize_t>(written);
    address += static_cast<haddr_t>(written);
  }
}

void ResultFile::set_extent(Series& series, hsize_t rows, const char* action) {
  const hsize_t size[2] = {rows, static_cast<hsize_t>(series.columns)};
  check(H5Dset_extent(series.dataset.get(), size) >= 0, action);
  series.extent = rows;
}

void ResultFile::extend_series(hsize_t rows) {
  arrange_chunks_by_block();
  for (Series& series : series_) {
    if (series.extent >= rows) continue;
    set_extent(series, rows, "cannot write result file");
    extended_since_commit_ = true;
  }
}

void ResultFile::write_rows(Series& series, const double* rows_data, hsize_t first, hsize_t rows) {
  const int rank = series.columns == 0 ? 1 : 2;
  if (rows == block_rows && first % block_rows == 0) {
    // A whole chunk (block_rows rows of the full width, row-major as the chunk is stored),
    // allocated at the layout, that write_whole_block did not find where it expected (or a
    // result file without its raw descriptor): written straight over its place (H5Dwrite_chunk,
    // HDF5 1.10.3). The chunk keeps its address (no filter, same size), so the index does
    // not change; no dataspace, selection or type conversion is built for it, which cost
    // more than the write on the block writer's thread (docs/performance.md, "Issue #18,
    // nineteenth round"). The bytes are the file type's: H5T_NATIVE_DOUBLE both.
    const hsize_t offset[2] = {first, 0};
    check(H5Dwrite_chunk(series.dataset.get(), H5P_DEFAULT, 0, offset, chunk_bytes(series),
                         rows_data) >= 0,
          "cannot write result file");
    return;
  }
  const Handle file_space(H5Dget_space(series.dataset.get()));
  const hsize_t start[2] = {first, 0};
  const hsize_t count[2] = {rows, static_cast<hsize_t>(series.columns)};
  const Handle memory_space(H5Screate_simple(rank, count, nullptr));
  check(file_space.valid() && memory_space.valid() &&
            H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr) >= 0,
        "cannot write result file");
  check(H5Dwrite(series.dataset.get(), H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(), H5P_DEFAULT,
                 rows_data) >= 0,
        "cannot write result file");
}

void ResultFile::write_block(hsize_t rows) {
  settle();
  move_staged_rows_to_blocks();  // the row of a sample still being built stays staged, first
  extend_series(rows_on_disk_ + rows);
  double* const block = building_block_.get();
  // At a chunk's start (the run's last block) whole chunks too, the rows past `rows`
  // zeros: they are past samples_written, a later write of the block replaces them, and
  // close() cuts the series at the last sample (a block's rows were ~100 pwrites).
  if (rows_on_disk_ % block_rows == 0)
    for (const Series& series : series_)
      std::fill(block + block_offset(series) + rows * series.width,
                block + block_offset(series) + block_rows * series.width, 0.0);
  write_whole_block(block, rows_on_disk_, rows);
  rows_on_disk_ += rows;
  buffered_samples_ = 0;
}

void ResultFile::commit() {
  settle();  // the rows counted below are on disk
  if (rows_on_disk_ != samples_written_) {
    if (extended_since_commit_) flush_file();
    set_attribute("/", samples_written_name, static_cast<long>(rows_on_disk_));
    samples_written_ = rows_on_disk_;
    extended_since_commit_ = false;
  }
  if (!published_) arrange_chunks_by_block();
  flush_file();
  last_commit_ = std::chrono::steady_clock::now();
  if (!published_) publish();
}

void ResultFile::flush_file() { check(H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) >= 0, "cannot write result file"); }

void ResultFile::flush() {
  ready_to_write();
  if (buffered_samples_ > 0) write_block(buffered_samples_);
  commit();
}

void ResultFile::publish() {
  if (std::rename(partial_path_.c_str(), path_.c_str()) != 0) fail_with_errno("cannot create result file");
  published_ = true;
}

void ResultFile::mark_complete() {
  flush();
  set_attribute("/", "complete", 1L);
}

void ResultFile::close() {
  if (closed_) return;
  try {
    flush();  // waits for the block writer first
    // Room the end of the run did not take (no failure text, a short summary).
    for (const char* object : {"/", "/summary"}) {
      const Handle room_holder = open_object(object);
      if (H5Aexists(room_holder.get(), reserved_room_name) > 0)
        check(H5Adelete(room_holder.get(), reserved_room_name) >= 0, "cannot write result file");
    }
    // An early stop: series end where the samples do (an orderly stop leaves no unwritten rows).
    for (Series& series : series_) {
      if (series.extent != samples_written_) set_extent(series, samples_written_, "cannot write result file");
    }
    flush_file();
    for (Series& series : series_) {
      for (Series::KeptAttribute& kept : series.kept_attributes)
        check(kept.attribute.close(), "cannot close result file");
      check(series.dataset.close(), "cannot close result file");
    }
    // The record types stored in the file are objects of it too: with one open, HDF5 would
    // end the file (its last writes) only when that handle goes, after close() returned.
    for (auto& [fields, type] : record_types_) check(type.close(), "cannot close result file");
    check(file_.close(), "cannot close result file");
    if (raw_data_ >= 0 && ::close(std::exchange(raw_data_, -1)) != 0) fail_with_errno("cannot close result file");
  } catch (...) {
    abandon();
    closed_ = true;
    throw;
  }
  closed_ = true;
}

}  // namespace heavesim
