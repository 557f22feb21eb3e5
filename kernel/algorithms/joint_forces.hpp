#pragma once
// Generalized forces of the joints' own elements: springs, dampers and soft limits.
#include "kernel/model/model.hpp"

namespace heavesim {

/// Adds spring-damper and limit forces of every joint to tau (nv).
void add_joint_element_forces(const Model& model, const VectorX& q, const VectorX& v, VectorX& tau);

/// Elastic energy [J] stored in joint springs and penetrated limits.
double joint_elastic_energy(const Model& model, const VectorX& q);

}  // namespace heavesim
