#pragma once
// A std::vector<int> of row or column indices as an Eigen index expression that does
// not copy it. Eigen 3.4's indexed views (A(rows, Eigen::all)) store their index object
// by value: given the std::vector itself, every such view copies it onto the heap, an
// allocation per use that Eigen's own allocation check (EIGEN_RUNTIME_NO_MALLOC) does
// not see. A Map is a pointer and a size.
#include <Eigen/Core>
#include <vector>

namespace heavesim {

inline Eigen::Map<const Eigen::VectorXi> index_list(const std::vector<int>& indices) {
  return Eigen::Map<const Eigen::VectorXi>(indices.data(), static_cast<Eigen::Index>(indices.size()));
}

}  // namespace heavesim
