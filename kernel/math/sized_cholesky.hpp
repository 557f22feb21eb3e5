#pragma once
// Eigen's LLT with its storage sized when it is made, so that the later factorizations
// of an n x n matrix do not allocate (the hot path's rule), and with every member
// defined. Eigen 3.4's LLT(size) constructor sizes the storage but leaves the status
// (m_info) and the norm unset, and a copy of the object reads them (UBSan: a load of an
// invalid enum value). Factoring an identity instead would define them at O(n^3): 45 %
// of the set-up of a 512-link chain's Data (docs/performance.md, "Set-up"). Here the
// status says "not factorized yet": a solve before the first compute() is Eigen's
// "LLT is not initialized" assertion (an exception in the checked build), never a
// silent solve with a made-up factor.
#include <Eigen/Cholesky>

#include "kernel/spatial/types.hpp"

namespace heavesim {

class SizedCholesky : public Eigen::LLT<MatrixX> {
 public:
  explicit SizedCholesky(Eigen::Index size = 0) : Eigen::LLT<MatrixX>(size) {
    m_matrix.setZero();  // O(n^2): the same pages the first factorization writes
    m_l1_norm = 0.0;
    m_isInitialized = false;
    m_info = Eigen::InvalidInput;
  }
};

}  // namespace heavesim
