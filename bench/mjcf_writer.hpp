#pragma once
// MJCF text of a benchmark model (samples/bench_models.hpp) for MuJoCo: the same tree,
// frames, axes and inertias heavesim builds with samples::to_model.
#include <string>

#include "samples/bench_models.hpp"

namespace heavesim::bench {

/// One <body> per link (pos = offset, hinge about the link's axis or a freejoint,
/// <inertial> with the CoM, mass and principal moments), gravity 9.81 m/s^2 along -Z.
std::string to_mjcf(const samples::BenchModel& model);

}  // namespace heavesim::bench
