#pragma once
// Reader of MKSim's model language (docs/mksim-format.md): a tokenizer that keeps the
// line and column of every token and a recursive-descent parser over the grammar
//   MODEL name  statement*  ENDMODEL
//   statement := SYSTEM {..} | BODY name {..} | TRIAD name {..}
//              | <type> JOINT name {triad = a, triad = b} | DRIVER name {target.x = expr}
// Keywords are case-insensitive, names case-sensitive; `//` starts a comment to the end
// of the line. Every malformed input -- syntax, unknown names, degenerate frames, a
// driver expression muParser rejects -- is an InputError at file:line:column naming
// what was found and what was expected (exit code 2).
#include <string>

#include "app/mksim/mksim_model.hpp"

namespace heavesim::mksim {

/// Reads and checks the model text; `file` names it in errors.
Model parse_model(const std::string& text, const std::string& file);
/// Reads a model file (a missing, unreadable, non-regular or oversized file is bad input).
Model read_model_file(const std::string& path);

/// The expression with MKSim's time variable (TIME, in any case) renamed `time_name`.
std::string with_time_named(const std::string& expression, const std::string& time_name);

/// The frame of a par triple: columns x, y, z (orthonormal, right-handed) and the origin.
/// The reader has already refused degenerate triples.
Eigen::Matrix3d frame_axes(const PointTriple& par);

}  // namespace heavesim::mksim
