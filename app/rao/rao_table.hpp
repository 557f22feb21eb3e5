#pragma once
// The result of `heavesim rao` (docs/rao.md): per frequency and channel the complex RAO
// per unit wave amplitude, phase relative to the incident wave elevation at the platform's
// reference point, x = Re[RAO a e^{i w t}] with eta = Re[a e^{i w t}] there (positive
// phase: the response leads the wave crest); for the H1 estimate its coherence; where the
// case has BEM data, the frequency-domain RAO at the same frequencies and on the BEM
// frequencies. Written as DIR/rao.h5 and DIR/rao.csv (units in the header).
#include <complex>
#include <string>
#include <vector>

namespace heavesim {

struct RaoColumn {
  std::string name;   // as given: "heave", "/forces/compensator/stroke"
  std::string unit;   // per unit wave amplitude: "m/m", "deg/m", "N/m"
  std::vector<std::complex<double>> values;     // per row
  std::vector<double> coherence;                // per row (H1 only; empty for the regular sweep)
  std::vector<std::complex<double>> reference;  // frequency-domain RAO per row (modes with BEM data; else empty)
  std::vector<std::complex<double>> reference_on_bem;  // the same on RaoTable::bem_frequencies (the figure's line)
};

struct RaoTable {
  std::string method;   // "regular_sweep" or "h1"
  std::string source;   // the case file or the result file
  std::string wave_elevation_channel;  // the input: /forces/<excitation>/wave_elevation
  std::string platform;                // body of the modes and of the reference point
  double heading = 0.0;                // rad
  double amplitude = 0.0;              // m, regular sweep
  std::string reference_note;          // why there is no frequency-domain RAO ("" when there is)
  std::vector<double> angular_frequencies;  // rad/s, per row
  std::vector<RaoColumn> columns;
  std::vector<double> bem_frequencies;      // rad/s: the BEM frequencies and 7 between each pair
  std::vector<std::string> notes;           // per row, e.g. the run file or why a row is empty
};

/// The channel's key in rao.h5: its name with '/' as '.' ("forces.compensator.stroke").
std::string rao_channel_key(const std::string& name);

/// Writes `directory`/rao.h5 and `directory`/rao.csv; an OutputError when it cannot.
void write_rao_table(const std::string& directory, const RaoTable& table);

}  // namespace heavesim
