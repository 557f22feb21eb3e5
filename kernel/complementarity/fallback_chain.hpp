#pragma once
// A chain of complementarity solvers tried in order until one solves the problem: e.g.
// projected Gauss-Seidel (cheap, warm-started, but stalls on poorly conditioned M), then
// Dantzig (exact on symmetric positive definite M, stops on a singular active block),
// then Lemke (processes any P-matrix and more). The result names the solver that
// produced the answer and how many were tried; if none solves it, the last failure is
// returned with every solver's status in its message. Invalid input stops the chain at
// once: no solver can mend it.
#include <array>

#include "kernel/complementarity/dantzig.hpp"
#include "kernel/complementarity/lemke.hpp"
#include "kernel/complementarity/projected_gauss_seidel.hpp"

namespace heavesim {

struct FallbackChainOptions {
  std::array<ComplementaritySolver, 3> order{ComplementaritySolver::projected_gauss_seidel,
                                             ComplementaritySolver::dantzig, ComplementaritySolver::lemke};
  int count = 3;  ///< how many of `order` to use
  ProjectedGaussSeidelOptions projected_gauss_seidel;
  DantzigOptions dantzig;
  LemkeOptions lemke;
};

/// One workspace per solver, each sized once for problems of up to `size` rows.
struct ComplementarityWorkspace {
  explicit ComplementarityWorkspace(int size = 0) : lemke(size), dantzig(size), projected_gauss_seidel(size) {}
  LemkeWorkspace lemke;
  DantzigWorkspace dantzig;
  ProjectedGaussSeidelWorkspace projected_gauss_seidel;
};

ComplementarityResult solve_complementarity(const ComplementarityProblem& problem,
                                            ComplementarityWorkspace& workspace, VectorView z,
                                            const FallbackChainOptions& options = {});

}  // namespace heavesim
