#pragma once
// A wave scatter diagram in the common text form of the published tables (Global Wave
// Statistics, DNV-RP-C205 App. C): one header row of peak-period class centres Tp [s],
// then one row per significant-wave-height class, its centre Hs [m] first and then the
// occurrences (counts or probabilities) in each Tp class. Cells are separated by spaces,
// tabs or commas; '#' starts a comment; an optional label ("Hs/Tp") may stand before the
// header's periods.
#include <string>
#include <vector>

namespace heavesim {

struct ScatterTable {
  std::vector<double> hs;  // m, class centres (rows)
  std::vector<double> tp;  // s, class centres (columns)
  std::vector<std::vector<double>> occurrence;  // [row][column], >= 0, as written
  double total = 0.0;      // sum of every cell (> 0)
};

/// Reads a scatter diagram; every problem (a cell that is not a number, negative or not
/// finite, a row of the wrong length, a height or period that is not positive or repeats,
/// a table of zeros) is an InputError at the file's line and column.
ScatterTable read_scatter_table(const std::string& path);

}  // namespace heavesim
