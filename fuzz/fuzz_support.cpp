#include "fuzz/fuzz_support.hpp"

#include <cxxabi.h>
#include <muParser.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <memory>
#include <typeinfo>

namespace heavesim::fuzz {
namespace {

namespace fs = std::filesystem;

/// Removes the scratch directory when the process ends normally (libFuzzer's -runs=,
/// -max_total_time=); a crash leaves it for inspection.
struct ScratchDirectory {
  fs::path root;
  fs::path cases;
  ScratchDirectory() {
    root = fs::temp_directory_path() / ("heavesim-fuzz-" + std::to_string(::getpid()));
    fs::remove_all(root);
    const fs::path source = HEAVESIM_SOURCE_DIR;
    fs::create_directories(root / "cases");
    for (const fs::directory_entry& entry : fs::directory_iterator(source / "cases"))
      if (entry.is_directory()) fs::create_directory_symlink(entry.path(), root / "cases" / entry.path().filename());
    fs::create_directory_symlink(source / "data", root / "data");
    fs::create_directory_symlink(source / "tests", root / "tests");
    cases = root / "cases" / "fuzz";
    fs::create_directories(cases);
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    fs::remove_all(root, ignored);
  }
};

}  // namespace

std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

const fs::path& scratch_directory() {
  static const ScratchDirectory directory;
  return directory.cases;
}

void write_file(const fs::path& path, std::string_view content) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
}

std::vector<std::string_view> split_at_marker_lines(std::string_view text, std::string_view marker) {
  std::vector<std::string_view> parts;
  std::size_t part_begin = 0, line_begin = 0;
  while (line_begin <= text.size()) {
    std::size_t line_end = text.find('\n', line_begin);
    if (line_end == std::string_view::npos) line_end = text.size();
    if (text.substr(line_begin, line_end - line_begin) == marker) {
      parts.push_back(text.substr(part_begin, line_begin - part_begin));
      part_begin = std::min(line_end + 1, text.size());
    }
    line_begin = line_end + 1;
  }
  parts.push_back(text.substr(part_begin));
  return parts;
}

std::vector<std::string_view> lines(std::string_view text) {
  std::vector<std::string_view> result;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    result.push_back(text.substr(begin, end - begin));
    begin = end + 1;
  }
  return result;
}

void report_unexpected_exception(const char* target) {
  const std::type_info* type = abi::__cxa_current_exception_type();
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> name(
      type ? abi::__cxa_demangle(type->name(), nullptr, nullptr, &status) : nullptr, std::free);
  std::string message = "(not a std::exception)";
  try {
    throw;
  } catch (const std::exception& error) {
    message = error.what();
  } catch (const mu::Parser::exception_type& error) {  // muParser's own type is no std::exception
    message = error.GetMsg() + " (expression '" + error.GetExpr() + "', token '" + error.GetToken() + "')";
  } catch (...) {
  }
  std::fprintf(stderr, "\n%s: unexpected exception %s: %s\n", target,
               name ? name.get() : (type ? type->name() : "(unknown type)"), message.c_str());
  std::abort();
}

}  // namespace heavesim::fuzz
