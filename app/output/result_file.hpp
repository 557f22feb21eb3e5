#pragma once
// The HDF5 result file (contract in docs/result-file.md): time series written in whole
// samples as the run goes, so that a run stopped in any way (a signal, a numerical
// failure, a full disk, even SIGKILL) leaves a readable file with complete = 0 whose
// root attribute `samples_written` counts the samples every series holds.
//
// Why the file survives SIGKILL at any point (the design; tested by killing a writer
// at every one of its writes, tests/app/test_interrupted_runs.cpp):
//  * HDF5 writes its metadata (object headers, chunk indexes) in an order of its own
//    and the superblock, which records the end of the allocated space, last of all
//    (HDF5 User's Guide, "The HDF5 metadata cache": entries are flushed ring by ring,
//    superblock ring last). A process killed inside that flush leaves headers that
//    disagree with each other (one series extended, the next not) or that point past
//    the recorded end of file ("addr overflow" on read). Appending by extending every
//    dataset as it goes (the former design) therefore broke at ~20 % of the write
//    points of a flush.
//  * So nothing structural changes while the run writes samples: before the layout is
//    published every series is grown to its final length (`reserved_samples`, known from
//    t_end and the output interval), a block of every series at a time, each growth
//    allocating the new chunks (H5D_ALLOC_TIME_EARLY) but not filling them
//    (H5D_FILL_TIME_NEVER: no write, the file is sparse); a block's chunks thus lie side
//    by side, in the order of the series, and a whole block is written as raw bytes over
//    them in one pwrite a run of adjacent chunks. A flush then only overwrites raw data in
//    place and afterwards the fixed-size `samples_written` attribute in place: no
//    allocation, no index change, no header moves.
//  * The layout itself (every dataset, attribute and the first flush) is written to
//    "<path>.partial", renamed to <path> once it is on disk: the name never points at a
//    half-built file.
//  * A series longer than its reservation (a caller that did not know the count) is
//    extended, the data flushed, and only then is `samples_written` raised, in a flush
//    of its own: readers trust the count, not the extent.
//  * Readers may open the file while the run writes it: the writer takes no HDF5 file
//    lock (H5Pset_file_locking), and a reader finds what a SIGKILL at that moment
//    would leave (every point tested below), whole samples up to samples_written; it
//    reopens the file to see more. HDF5's SWMR mode (H5Fstart_swmr_write) was tried and
//    measured for this and left out, with HDF5 1.10.8 (docs/result-file.md): its 1.10
//    superblock keeps an "open for writing" mark after SIGKILL that locks out every
//    non-SWMR reader until `h5clear -s`; an object header that grows in SWMR mode (the
//    end-of-run /summary attributes, named by the case) fails the flush ("slist not
//    empty"); and it reset the datasets' chunk caches (HDF5 issue #1730).
//  * Everything a run rewrites (samples_written, complete, the per-series statistics)
//    exists from the layout on and is overwritten in place; the end-of-run attributes
//    are created in room reserved in the root's and /summary's headers.
// An orderly end (close) shrinks every series to `samples_written`; after SIGKILL the
// series keep their reserved length and the rows past `samples_written` are unwritten
// (or zeros: the part of a block written at a flush mid-block that no sample reached).
//
// Every HDF5 call is checked: a failure throws OutputError naming the file and the
// system's cause, and the file is then left as the last complete flush wrote it.
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "app/output/background_worker.hpp"
#include "app/output/output_error.hpp"
#include "io/hdf5/hdf5_error.hpp"
#include "io/hdf5/hdf5_handle.hpp"

namespace heavesim {

class ResultFile {
 public:
  /// Creates "<path>.partial" (replacing any file at `path`); throws OutputError if it
  /// cannot. Series have `reserved_samples` rows from when the layout is published (the
  /// first flush; 0: grown as written).
  explicit ResultFile(const std::string& path, hsize_t reserved_samples = 0);
  /// Never throws: closes a published file (reporting nothing), abandons a failed one,
  /// removes one that was never published. Call close() to hear about failures.
  ~ResultFile();
  ResultFile(const ResultFile&) = delete;
  ResultFile& operator=(const ResultFile&) = delete;

  const std::string& path() const { return path_; }
  /// Whole samples on disk (the root attribute `samples_written`).
  hsize_t samples_written() const { return samples_written_; }
  /// Whether the file exists under its name (its first flush succeeded).
  bool published() const { return published_; }

  void set_attribute(const std::string& object_path, const std::string& name, const std::string& value);
  void set_attribute(const std::string& object_path, const std::string& name, double value);
  void set_attribute(const std::string& object_path, const std::string& name, long value);
  void set_attribute(const std::string& object_path, const std::string& name, const std::vector<double>& values);
  /// A compound attribute: one record per row of `values` (row-major, fields.size() numbers a
  /// row), each a double field per name; h5py reads it as a numpy structured array. The
  /// type lists its fields in name order (each at its place in the row): see record_type.
  void set_record_attribute(const std::string& object_path, const std::string& name,
                            const std::vector<std::string>& fields, const std::vector<double>& values);
  /// The same two on a series (add_series' id), through the dataset it holds open: no
  /// lookup by path (a run writes a dozen attributes on each of its series). A series'
  /// attributes are written this way only: the by-path writes above would not see the
  /// attributes the series keeps open (Series::kept_attributes).
  void set_attribute(int series, const std::string& name, const std::vector<double>& values);
  void set_record_attribute(int series, const std::string& name, const std::vector<std::string>& fields,
                            const std::vector<double>& values);

  /// A fixed string dataset (e.g. /case/yaml).
  void write_text(const std::string& dataset_path, const std::string& text, const std::string& description);

  /// Per-column statistics attributes every series carries (NaN until written).
  static constexpr const char* series_statistics[] = {"minimum", "maximum", "mean", "standard_deviation"};

  /// A series: shape (N) when columns == 0, else (N, columns).
  /// Returns its id for append(); `units` and `description` become attributes.
  int add_series(const std::string& dataset_path, int columns, const std::string& units,
                 const std::string& description);
  /// The sample being built, sized once: every series' row (max(columns, 1) values) side
  /// by side in the order the series were added. A writer fills it in place (the recorder
  /// fills the whole row), then calls end_sample().
  /// Valid until the next end_sample(), flush() or block(). The samples are staged
  /// (staged_rows of them) and go to the series' blocks a run of samples at a time: a
  /// sample's ~100 rows, each in its own block, were as many scattered stores into memory
  /// no cache holds (docs/performance.md).
  double* sample_row() { return staging_.data() + staged_samples_ * staging_width_; }
  /// The series' row of the sample being built (as sample_row()).
  double* sample_row(int series) { return sample_row() + series_[series].staging_offset; }
  /// The whole row's width [values].
  hsize_t staging_width() const { return staging_width_; }
  /// The series' block of samples being built, row after row: the rows of the samples
  /// buffered (buffered_samples()). Moves the staged rows into the blocks first.
  const double* block(int series) {
    move_staged_rows_to_blocks();
    return building_block_.get() + block_offset(series_[series]);
  }
  /// The series' last whole block (block_rows rows), which end_sample() handed to the
  /// block writer (valid once a whole block has been ended). It stays untouched, and may
  /// be read on another thread, until end_sample() ends the next whole block: the two
  /// blocks trade places then (no copy).
  const double* last_block(int series) const { return last_block_.get() + block_offset(series_[series]); }
  /// Whole samples in the block, not yet written.
  hsize_t buffered_samples() const { return buffered_samples_; }
  /// Copies one row (max(columns, 1) values) into sample_row(series).
  void append(int series, const double* row);
  /// Ends one sample (a row filled in every series). The rows go to disk only here, a
  /// block of `block_rows` samples at a time (a chunk of each series, their chunks side by
  /// side in the file: a pwrite for each run of them), on a second thread
  /// (the block writer) while the next block is filled; `samples_written` is
  /// raised (a commit: the count, then a file flush) after a block only when it is the
  /// first, when `commit_interval_s` of wall time has passed since the last commit, or
  /// when a series had to be extended (a structural change, committed at once): the flush, not the data, is
  /// what costs, and a reader needs whole samples, not every block, as they come.
  void end_sample();
  /// Writes the whole samples buffered, then `samples_written`, and flushes the file to
  /// disk; the first flush publishes the file under its name.
  void flush();
  /// The run is whole: flushes everything written so far (the statistics and the summary
  /// among it), then sets the root attribute complete = 1, for close() to write. HDF5 writes
  /// a flush's dirty metadata in no set order, so a SIGKILL during one flush that held
  /// both could leave complete = 1 beside statistics still NaN.
  void mark_complete();
  /// Samples a block holds (one chunk of every series: a block write fills whole chunks).
  static constexpr hsize_t block_rows = 1024;
  /// Samples staged side by side before they go to the blocks (a divisor of block_rows:
  /// a block ends with a run): 64 samples of the drilling case's 206 columns are 105 kB.
  static constexpr hsize_t staged_rows = 64;
  static_assert(block_rows % staged_rows == 0);
  /// Wall time between two commits while the run writes blocks [s].
  static constexpr double commit_interval_s = 0.25;
  /// Flushes, shrinks every series to `samples_written`, closes everything and checks
  /// that it closed (a failure at close is a failed write).
  void close();

 private:
  struct Series {
    hdf5::Handle dataset;
    int columns = 0;
    hsize_t width = 1;   // values a row: max(columns, 1)
    hsize_t extent = 0;  // rows the dataset has (reserved or grown)
    hsize_t staging_offset = 0;  // of its row in a staged sample
    /// The attributes written through the series' id, kept open with the type and number
    /// of values they were made with: the end of a run overwrites the statistics of every
    /// series, and looking each up again (exists, open, compare the stored type and shape)
    /// cost more than the write (docs/performance.md, "Issue #18, tenth round"). Closed all
    /// together before one of the dataset's attributes is deleted (a type or shape
    /// changed), then opened again as they are written.
    struct KeptAttribute {
      std::string name;
      hdf5::Handle attribute;
      hid_t type = -1;
      hsize_t values = 0;
    };
    std::vector<KeptAttribute> kept_attributes;
  };
  /// Writes attribute `name` of a series: straight into the attribute it keeps open when
  /// made with `type` and `values` values, else as write_attribute() (then kept). A
  /// single value is a scalar attribute when `scalar_when_single`.
  void write_series_attribute(Series& series, const std::string& name, hid_t type, hsize_t values,
                              bool scalar_when_single, const void* data);
  /// The staged samples' rows into the series' blocks, each series' rows one sequential
  /// run; the row being built (a flush between its appends) moves to the first place.
  void move_staged_rows_to_blocks();
  /// Where a series' rows start in a block: the series' blocks lie side by side in the
  /// order of the series, block_rows rows of each, as their chunks do in the file.
  static hsize_t block_offset(const Series& series) { return block_rows * series.staging_offset; }
  /// The two blocks (the one being built and the last whole one), made when first needed
  /// and not filled (every row is written before it is read); add_series, which comes
  /// before any sample, drops them.
  void make_blocks();
  std::unique_ptr<double[]> building_block_, last_block_;  // block_rows * staging_width_ values each
  std::vector<double> staging_;   // staged_rows samples, staging_width_ values each
  hsize_t staging_width_ = 0;     // sum of the series' widths
  hsize_t staged_samples_ = 0;    // whole samples staged, not yet in the blocks
  /// The group or dataset at `object_path`, created as a group (with its parents) if missing.
  hdf5::Handle open_object(const std::string& object_path);
  /// Writes attribute `name` of `object` (an open group or dataset), overwriting it in
  /// place when it exists with the same type and shape (no allocation), else creating it.
  /// It and the three below call HDF5 at once: their callers call ready_to_write() first.
  /// Returns the attribute, open. `open_attributes`: the object's kept attributes, closed
  /// before an attribute of it is deleted.
  hdf5::Handle write_attribute(hid_t object, const std::string& name, hid_t type, hid_t space, const void* data,
                               std::vector<Series::KeptAttribute>* open_attributes = nullptr);
  /// The typed writes behind set_attribute and set_record_attribute, on an open object.
  void write_text_attribute(hid_t object, const std::string& name, const std::string& value);
  void write_doubles(hid_t object, const std::string& name, const std::vector<double>& values);
  void write_records(hid_t object, const std::string& name, const std::vector<std::string>& fields,
                     const std::vector<double>& values);
  /// The compound type of set_record_attribute for these field names (made on first use).
  hid_t record_type(const std::vector<std::string>& fields);
  /// Every series at least `rows` long (extended_since_commit_ when one grows), after
  /// arrange_chunks_by_block().
  void extend_series(hsize_t rows);
  /// The series' dataset `rows` long (its extent recorded); a failure is `action`'s.
  void set_extent(Series& series, hsize_t rows, const char* action);
  /// The bytes of a series' chunk: block_rows rows of its width.
  static hsize_t chunk_bytes(const Series& series) { return block_rows * series.width * sizeof(double); }
  /// Rows [first, first + rows) of a series from `rows_data` (the dataset is long enough).
  void write_rows(Series& series, const double* rows_data, hsize_t first, hsize_t rows);
  /// The block writer's job: every series' last whole block at handed_first_row_.
  void write_last_blocks();
  /// Waits until the block writer is idle (throwing its failure): every public method
  /// that calls HDF5 does so first, so that the file's HDF5 objects are never used from
  /// two threads at once (and the serial build of HDF5 could serve as well).
  void settle() { block_writer_.wait(); }
  /// What every public write does first: settle(), then check_usable().
  /// HDF5's error reporting is set for the calling thread each time (an HDF5 call, so after
  /// settle()): the recorder lays the file out and ends its samples on a thread of its own
  /// (Recorder::evaluate_on_second_thread), and a thread-safe HDF5 keeps the setting per thread.
  void ready_to_write() {
    settle();
    hdf5::report_errors_by_return_codes();
    check_usable();
  }
  /// The first `rows` buffered samples of every series to disk; a sample still being
  /// built moves to the start of the block.
  void write_block(hsize_t rows);
  /// `samples_written` = the rows on disk, then a file flush (after one first if a series
  /// grew: the extents reach the disk before the count that trusts them); publishes.
  void commit();
  void flush_file();
  void publish();
  /// Grows every series from no row to `reserved_samples`, a block of every
  /// series at a time, so that each block's chunks lie side by side in the file in the
  /// order of the series (see write_whole_block); once, before the layout is published.
  void arrange_chunks_by_block();
  /// A block as whole chunks over the places the layout allocated (the block's rows past
  /// `rows`, if any, already zeros): one pwrite for each run of series whose chunks are
  /// adjacent in the file. Where the block is not a chunk (`first_row` not a multiple of
  /// block_rows, after a flush mid-block) or a chunk is not as the layout made it
  /// (unallocated, another size), its `rows` rows go through write_rows.
  void write_whole_block(const double* block, hsize_t first_row, hsize_t rows);
  /// `bytes` of raw chunk data at file offset `address`, through raw_data_.
  void write_raw(const double* data, hsize_t bytes, haddr_t address);
  /// Records the failure (the file is not written again) and throws it: the cause is
  /// HDF5's last error, or `cause`.
  [[noreturn]] void fail(const std::string& action);
  [[noreturn]] void fail(const std::string& action, const std::string& cause);
  /// fail() with the system's message for errno.
  [[noreturn]] void fail_with_errno(const std::string& action);
  void check(bool succeeded, const std::string& action) {
    if (!succeeded) fail(action);
  }
  void check_usable() const;
  void abandon();
  /// The release worker's job: closes previous_result_ (then -1).
  void close_previous_result();

  std::string path_, partial_path_;
  hsize_t reserved_samples_ = 0;
  hdf5::Handle file_;
  std::vector<Series> series_;
  /// The compound types of set_record_attribute, one per list of field names, built once
  /// (a run writes the same two lists on every series, at its creation and at the end).
  /// Those made before the layout is published are stored in the file (record_type()):
  /// objects of it, closed before the file in close().
  std::vector<std::pair<std::vector<std::string>, hdf5::Handle>> record_types_;
  /// The text type, link creation and dataset access properties every series and text
  /// attribute uses, made once (a run creates ~100 series with two texts each).
  hdf5::Handle text_type_, links_, dataset_access_;
  hsize_t buffered_samples_ = 0;  // whole samples in the block (not yet on disk)
  hsize_t rows_on_disk_ = 0;      // rows written, or handed to the block writer, in every series (>= samples_written_)
  hsize_t handed_first_row_ = 0;  // the first row of the block in the block writer's hands
  hsize_t samples_written_ = 0;   // rows committed (the root attribute)
  bool extended_since_commit_ = false;
  bool chunks_arranged_ = false;  // arrange_chunks_by_block() has run
  /// A duplicate of HDF5's descriptor of the file, for the whole blocks' raw chunk data
  /// (-1: none, every chunk through HDF5). HDF5 holds no raw data of the file (no chunk
  /// cache, no filter), so bytes written here beside it are what H5Dwrite_chunk would
  /// have written; they are on disk before the commit that counts them (settle()). Its
  /// writes are pwrite calls, as HDF5's are (tests/app/test_interrupted_runs.cpp kills
  /// a writer at each of them).
  int raw_data_ = -1;
  std::chrono::steady_clock::time_point last_commit_ = std::chrono::steady_clock::now();
  bool published_ = false, closed_ = false;
  std::string failure_;  // the OutputError's message once a write has failed
  std::string failure_cause_;
  /// The replaced result's descriptor (-1: none), closed by the release worker
  /// (close_previous_result): the close frees the file's pages (see the constructor).
  int previous_result_ = -1;
  BackgroundWorker previous_result_release_{[this] { close_previous_result(); }};
  // Writes the last whole blocks (docs/performance.md, "Recording on two cores"), data only:
  // the datasets are extended before a block is handed over. While it runs it is the only
  // HDF5 caller and owns the failure fields; this thread waits (settle) before any HDF5
  // call. Declared last: it ends first.
  BackgroundWorker block_writer_{[this] { write_last_blocks(); }};
};

}  // namespace heavesim
