// What writing the default drilling run's output costs with nothing else to do: the floor
// under the recording of `heavesim run cases/drilling.yaml` (issue #18's recording share,
// docs/performance.md "Issue #18, eighteenth round"). The drilling run records 12,001
// samples (600 s every 0.05 s) of 206 columns in 100 series: 62 of one column, 25 of
// three, 5 of four, 7 of six, 1 of seven (/time among the first). Two floors, whole files
// written to the output directory (default /tmp, HEAVESIM_BENCH_DIR to change it):
//  * hdf5_one_dataset: the same 12,001 x 206 doubles as ONE chunked dataset (chunks of
//    1,024 rows, as the result file's), one H5Dwrite from memory, the file closed: the
//    bytes through HDF5 and the page cache, with no layout to speak of.
//  * result_file_drilling_layout/samples:1: the result file itself
//    (app/output/result_file.hpp) with the drilling run's 100 series, their units and
//    descriptions, 12,001 samples written row by row through sample_row()/end_sample()
//    (its block writer thread included), closed: the writer's whole cost, with no
//    evaluation of the samples and no statistics. samples:0: the same layout, no sample.
//  * pwrite_pieces/pieces:N: the same 19.8 MB written to a new file with N pwrite calls
//    of equal size and nothing else (no HDF5): what a system call costs beyond the
//    copy into the page cache. The result file wrote a block as one pwrite a series (1,200
//    a run) until its blocks' chunks were laid side by side ("Issue #18, twentieth round").
// Wall time (UseRealTime: the result file writes on a second thread); each iteration
// writes a new file (the last one removed untimed). Run:
//   build/bench/heavesim_recording_floor --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "app/output/result_file.hpp"
#include "io/hdf5/hdf5_handle.hpp"

namespace heavesim::bench {
namespace {

constexpr hsize_t drilling_samples = 12001;

/// The drilling result's series widths (columns; 1 for a one-column series), in the
/// counts its result file holds (h5py over a run's output, docs/performance.md).
std::vector<int> drilling_series_widths() {
  const std::pair<int, int> counts[] = {{1, 62}, {3, 25}, {4, 5}, {6, 7}, {7, 1}};
  std::vector<int> widths;
  for (const auto& [columns, series] : counts) widths.insert(widths.end(), series, columns);
  return widths;
}

int total_columns(const std::vector<int>& widths) { return std::accumulate(widths.begin(), widths.end(), 0); }

std::string output_path(const char* name) {
  const char* directory = std::getenv("HEAVESIM_BENCH_DIR");
  return (std::filesystem::path(directory != nullptr ? directory : "/tmp") / name).string();
}

// Sample k, column c: a value that changes (no page of zeros for the file system to skip).
double sample_value(hsize_t k, hsize_t c) { return 1.0 + 1e-3 * static_cast<double>(k) + static_cast<double>(c); }

// Each iteration writes a new file: the one before is removed untimed (truncating a 20 MB
// file in place would be timed in one benchmark and not the other, whose result file
// replaces its predecessor on a helper thread).
void remove_untimed(benchmark::State& state, const std::string& path) {
  state.PauseTiming();
  std::filesystem::remove(path);
  state.ResumeTiming();
}

void hdf5_one_dataset(benchmark::State& state) {
  const hsize_t columns = static_cast<hsize_t>(total_columns(drilling_series_widths()));
  std::vector<double> values(drilling_samples * columns);
  for (hsize_t k = 0; k < drilling_samples; ++k)
    for (hsize_t c = 0; c < columns; ++c) values[k * columns + c] = sample_value(k, c);
  const std::string path = output_path("heavesim_recording_floor_one_dataset.h5");
  for (auto _ : state) {
    remove_untimed(state, path);
    hdf5::Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
    const hsize_t dimensions[2] = {drilling_samples, columns};
    const hsize_t chunk[2] = {ResultFile::block_rows, columns};
    hdf5::Handle space(H5Screate_simple(2, dimensions, nullptr));
    hdf5::Handle create(H5Pcreate(H5P_DATASET_CREATE));
    const bool chunked = create.valid() && H5Pset_chunk(create.get(), 2, chunk) >= 0;
    hdf5::Handle dataset(chunked ? H5Dcreate2(file.get(), "/values", H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT,
                                              create.get(), H5P_DEFAULT)
                                 : -1);
    if (!dataset.valid() ||
        H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0 ||
        !dataset.close() || !file.close()) {
      state.SkipWithError(("cannot write " + path).c_str());
      break;
    }
  }
  std::filesystem::remove(path);
  state.counters["MB"] = static_cast<double>(values.size() * sizeof(double)) / 1e6;
}

// The result file with the drilling run's 100 series, reserved for its 12,001 samples;
// state.range(0) = 1 writes them all, 0 none (the layout alone: create, attributes, the
// first flush, close).
void result_file_drilling_layout(benchmark::State& state) {
  const bool write_samples = state.range(0) == 1;
  const std::vector<int> widths = drilling_series_widths();
  const std::string path = output_path("heavesim_recording_floor_result_file.h5");
  for (auto _ : state) {
    remove_untimed(state, path);
    try {
      ResultFile file(path, drilling_samples);
      for (std::size_t s = 0; s < widths.size(); ++s)
        file.add_series(fmt::format("/series_{}/values", s), widths[s] == 1 ? 0 : widths[s], "m",
                        "a series of the drilling output's shape");
      const hsize_t width = file.staging_width();
      for (hsize_t k = 0; write_samples && k < drilling_samples; ++k) {
        double* row = file.sample_row();
        for (hsize_t c = 0; c < width; ++c) row[c] = sample_value(k, c);
        file.end_sample();
      }
      file.close();
    } catch (const OutputError& error) {  // the file is removed by ~ResultFile or below
      state.SkipWithError(error.what());
      break;
    }
  }
  std::filesystem::remove(path);
  state.counters["series"] = static_cast<double>(widths.size());
}

void pwrite_pieces(benchmark::State& state) {
  const hsize_t pieces = static_cast<hsize_t>(state.range(0));
  const hsize_t columns = static_cast<hsize_t>(total_columns(drilling_series_widths()));
  const hsize_t bytes = drilling_samples * columns * sizeof(double) / pieces * pieces;
  const std::vector<char> values(bytes, 1);
  const std::string path = output_path("heavesim_recording_floor_pwrite.bin");
  for (auto _ : state) {
    remove_untimed(state, path);
    const int descriptor = ::open(path.c_str(), O_CREAT | O_WRONLY | O_TRUNC | O_CLOEXEC, 0644);
    bool written = descriptor >= 0;
    const hsize_t piece = bytes / pieces;
    for (hsize_t p = 0; written && p < pieces; ++p)
      written = ::pwrite(descriptor, values.data() + p * piece, piece, static_cast<off_t>(p * piece)) ==
                static_cast<ssize_t>(piece);
    if (descriptor >= 0 && ::close(descriptor) != 0) written = false;
    if (!written) {
      state.SkipWithError(("cannot write " + path).c_str());
      break;
    }
  }
  std::filesystem::remove(path);
}

BENCHMARK(hdf5_one_dataset)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(result_file_drilling_layout)->ArgName("samples")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(pwrite_pieces)->ArgName("pieces")->Arg(1)->Arg(12)->Arg(100)->Arg(1200)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace heavesim::bench

BENCHMARK_MAIN();
