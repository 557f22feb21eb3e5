#pragma once
// What the fuzz targets share: a scratch directory per process for the files a reader
// must open by name, and the one way an unexpected exception ends a run (a finding).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace heavesim::fuzz {

/// The fuzzer's bytes as text (YAML, WAMIT and expressions are read as text).
std::string_view as_text(const std::uint8_t* data, std::size_t size);

/// A directory private to this process, created on first use and removed at exit.
/// It mirrors the source tree's layout around `cases/fuzz/`: cases/<folder>, data and
/// tests are links to the source tree's, so that a seed case's relative paths
/// (include: ../rig/platform.yaml, file: ../../data/...) resolve in it.
const std::filesystem::path& scratch_directory();

/// Writes `content` to `path` (replacing it), so the reader sees exactly the fuzzer's bytes.
void write_file(const std::filesystem::path& path, std::string_view content);

/// `text` cut at each line that is exactly `marker`: the parts before, between and after.
std::vector<std::string_view> split_at_marker_lines(std::string_view text, std::string_view marker);

/// Lines of `text` without their line ends.
std::vector<std::string_view> lines(std::string_view text);

/// Call from a catch (...) block: prints the exception's type and message and aborts,
/// which libFuzzer reports as a crash with the input saved. An exception the contract
/// does not allow (anything but the reader's own error type) is a finding.
void report_unexpected_exception(const char* target);

}  // namespace heavesim::fuzz
