#pragma once
// The channels of a response amplitude operator (`heavesim rao`, docs/rao.md): what the
// user names with --channel, and its time series read from a result file.
//  * a platform mode: surge, sway, heave (m: the body reference point's position, world
//    axes) or roll, pitch, yaw (deg: the components of the body's rotation vector, world
//    axes; for small angles the Euler angles), of the floating body the case's
//    wave_excitation acts on (the platform);
//  * a point fixed on a body: /bodies/<body>/point(x, y, z)[c], the world position [m]
//    of the point (x, y, z) [m, body frame], column c = 0, 1, 2 (x, y, z);
//  * any recorded series by its result path, with a column for a multi-column dataset:
//    /joints/<joint>/reaction_force[2], /forces/<compensator>/stroke.
// An RAO is per unit wave amplitude: the channel's unit over m.
#include <string>
#include <vector>

#include "io/hdf5/hdf5_reader.hpp"
#include "kernel/spatial/types.hpp"

namespace heavesim {

struct CaseDefinition;

struct RaoChannel {
  std::string name;     // as given: "heave", "/joints/platform/reaction_force[2]"
  int mode = -1;        // 0 .. 5 for surge .. yaw, else -1
  std::string body;     // a mode's or a point's body
  bool point = false;   // a body point
  Vector3 point_in_body = Vector3::Zero();  // m, body frame
  std::string dataset;  // a recorded series
  int column = -1;      // its column; -1: a one-column dataset
};

/// The six modes' names, WAMIT order.
const std::vector<std::string>& platform_mode_names();

/// Parses one --channel; `platform` is the body of the modes. An InputError at the
/// argument `--channel` (found, expected) for anything else.
RaoChannel parse_rao_channel(const std::string& text, const std::string& platform);

/// Refuses (InputError at `--channel`) a channel whose body, joint, force element,
/// constraint or driver the case does not have: before a sweep runs, not after.
void check_rao_channel(const RaoChannel& channel, const CaseDefinition& definition);

/// The channel's first `samples` values from a result file, and its unit ("m", "deg",
/// the dataset's `units`). An InputError naming the file and the channel when the file
/// lacks what it needs (the dataset, the column, the body's position or orientation).
struct ChannelSeries {
  std::vector<double> values;
  std::string unit;
};
ChannelSeries read_rao_channel(const hdf5::Reader& file, const std::string& file_path, const RaoChannel& channel,
                               std::size_t samples);

}  // namespace heavesim
