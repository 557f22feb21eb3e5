#include "app/output/csv_writer.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace heavesim {

CsvWriter::CsvWriter(const std::string& path) : out_(path) {
  if (!out_) throw std::runtime_error("cannot create CSV file '" + path + "'");
}

void CsvWriter::write_header(const std::vector<std::string>& column_names) {
  for (std::size_t i = 0; i < column_names.size(); ++i) out_ << (i ? "," : "") << column_names[i];
  out_ << '\n';
}

void CsvWriter::write_row(const std::vector<double>& values) {
  for (std::size_t i = 0; i < values.size(); ++i) out_ << (i ? "," : "") << fmt::format("{:.17g}", values[i]);
  out_ << '\n';
}

}  // namespace heavesim
