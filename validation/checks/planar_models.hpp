#pragma once
// Kernel models of the planar validation chains, built from the oracle's link data:
// revolute joints about world +Y at each pin, links hanging along -Z at q = 0,
// link frame = joint frame at the upper pin.
#include "kernel/model/model.hpp"
#include "validation/oracles/planar_chain_oracle.hpp"

namespace heavesim::validation {

Model planar_chain_model(const std::vector<oracle::PlanarLink>& links, double gravity = 9.81);

/// Relative joint angles q_i = theta_i - theta_{i-1} from absolute ones, and back.
VectorX relative_from_absolute(const VectorX& theta);
VectorX absolute_from_relative(const VectorX& q);

/// Relative error ||a - b|| / max(||b||, floor).
double relative_error(const VectorX& a, const VectorX& b, double floor = 1e-12);

}  // namespace heavesim::validation
