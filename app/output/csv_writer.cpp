#include "app/output/csv_writer.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>

namespace heavesim {

CsvWriter::CsvWriter(const std::string& path) : path_(path) {
  errno = 0;
  out_.open(path);
  check("cannot create CSV file");
}

void CsvWriter::check(const char* action) {
  // A stream fails when its buffer's write to the file does; errno is that write's
  // (ENOSPC, EFBIG): the standard streams keep no other record of the cause.
  if (out_) return;
  throw OutputError(path_, action, errno != 0 ? std::string(std::strerror(errno)) : std::string("write failed"));
}

void CsvWriter::write_header(const std::vector<std::string>& column_names) {
  errno = 0;
  for (std::size_t i = 0; i < column_names.size(); ++i) out_ << (i ? "," : "") << column_names[i];
  out_ << '\n';
  check("cannot write CSV file");
}

void CsvWriter::write_row(const std::vector<double>& values) {
  errno = 0;
  for (std::size_t i = 0; i < values.size(); ++i) out_ << (i ? "," : "") << fmt::format("{:.17g}", values[i]);
  out_ << '\n';
  check("cannot write CSV file");
}

void CsvWriter::flush() {
  errno = 0;
  out_.flush();
  check("cannot write CSV file");
}

void CsvWriter::close() {
  if (!out_.is_open()) return;
  errno = 0;
  out_.flush();
  check("cannot write CSV file");
  out_.close();
  check("cannot close CSV file");
}

}  // namespace heavesim
