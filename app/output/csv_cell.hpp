#pragma once
// A text cell of the CSV tables the commands write beside their HDF5 files (the sweep's
// index.csv, `heavesim rao`'s rao.csv): RFC 4180's quoting.
#include <string>

namespace heavesim {

/// `text` as a CSV cell: quoted, its quotes doubled, when it holds a comma, a quote or a
/// line break; as it is otherwise.
inline std::string csv_text(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace heavesim
