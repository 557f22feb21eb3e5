// P1, P2: the complementarity solvers (kernel/complementarity) on textbook problems with
// known pivot sequences and counts, and on random problems whose answer is chosen first
// (docs/physics/complementarity.md; the tests in tests/kernel/test_lemke.cpp and
// test_dantzig.cpp check the same and more).
#include <algorithm>
#include <cmath>
#include <vector>

#include "kernel/complementarity/dantzig.hpp"
#include "kernel/complementarity/lemke.hpp"
#include "samples/complementarity_problems.hpp"
#include "validation/checks/validation_suite.hpp"

namespace heavesim::validation {

std::vector<ValidationRow> check_p1_lcp_textbook() {
  std::vector<ValidationRow> rows;
  {
    // The source document's QP: min 1/2 (2 x1^2 - 2 x1 x2 + 10 x2^2) - x1 - 10 x2,
    // 3 x1 + 2 x2 <= 6; its tableaux pivot (z0, w2), (z2, w1), (z1, z0) to x = (20/19, 21/19).
    MatrixX M(3, 3);
    M << 2, -1, 3, -1, 10, 2, -3, -2, 0;
    const VectorX q = Eigen::Vector3d(-1, -10, 6);
    LemkeWorkspace workspace(3);
    std::vector<LemkePivot> pivots;
    pivots.reserve(8);
    LemkeOptions options;
    options.pivot_log = &pivots;
    VectorX z(3);
    const ComplementarityResult result = lemke({M, q}, workspace, z, options);
    using Kind = LemkeVariable::Kind;
    const std::vector<LemkePivot> source{{{Kind::covering, 0}, {Kind::w, 1}},
                                         {{Kind::z, 1}, {Kind::w, 0}},
                                         {{Kind::z, 0}, {Kind::covering, 0}}};
    int differing = std::abs(static_cast<int>(pivots.size()) - 3);
    for (std::size_t k = 0; k < std::min<std::size_t>(3, pivots.size()); ++k) differing += pivots[k] == source[k] ? 0 : 1;
    const std::string subject = "Lemke, the source document's tableau example (QP, n = 3)";
    rows.push_back({"P1", subject, "pivots differing from the source's sequence", double(differing), 0.0});
    const double error = result.solved() ? (z - Eigen::Vector3d(20.0 / 19, 21.0 / 19, 0)).lpNorm<Eigen::Infinity>()
                                         : INFINITY;
    rows.push_back({"P1", subject, "z vs (20/19, 21/19, 0)", error, 1e-15});
  }
  {
    double count_error = 0.0, answer_error = 0.0;
    for (int n = 2; n <= 10; ++n) {
      const samples::LcpSample murty = samples::murty_problem(n);
      LemkeWorkspace workspace(n);
      VectorX z(n);
      LemkeOptions options;
      options.max_pivots = 1 << 12;
      const ComplementarityResult result = lemke({murty.M, murty.q}, workspace, z, options);
      count_error = std::max(count_error, std::abs(double(result.pivots) - std::ldexp(1.0, n)));
      answer_error = std::max(answer_error, result.solved() ? (z - murty.z).lpNorm<Eigen::Infinity>() : INFINITY);
    }
    const std::string subject = "Lemke, Murty's problem n = 2..10";
    rows.push_back({"P1", subject, "pivots - 2^n", count_error, 0.0});
    rows.push_back({"P1", subject, "z vs (2^n, 0, ..., 0)", answer_error, 0.0});
  }
  return rows;
}

std::vector<ValidationRow> check_p2_lcp_random() {
  std::vector<ValidationRow> rows;
  for (const bool symmetric : {true, false}) {
    double lemke_residual = 0.0, lemke_error = 0.0, dantzig_residual = 0.0;
    for (const int n : {10, 50, 200, 500}) {
      const samples::LcpSample sample =
          symmetric ? samples::random_spd_lcp(n, 100 + n) : samples::random_p_matrix_lcp(n, 200 + n);
      LemkeWorkspace workspace(n);
      VectorX z(n);
      const ComplementarityResult result = lemke({sample.M, sample.q}, workspace, z);
      lemke_residual = std::max(lemke_residual, result.solved() ? result.residual : INFINITY);
      lemke_error = std::max(lemke_error, (z - sample.z).lpNorm<Eigen::Infinity>());
      if (symmetric) {
        DantzigWorkspace dantzig_workspace(n);
        const ComplementarityResult by_dantzig = dantzig({sample.M, sample.q}, dantzig_workspace, z);
        dantzig_residual = std::max(dantzig_residual, by_dantzig.solved() ? by_dantzig.residual : INFINITY);
      }
    }
    const std::string subject = std::string(symmetric ? "random SPD" : "random P-matrix") + " LCPs, n = 10, 50, 200, 500";
    rows.push_back({"P2", subject, "Lemke residual |min(z, w)| / |q|", lemke_residual, 1e-10});
    rows.push_back({"P2", subject, "Lemke z vs the chosen answer", lemke_error, 1e-9});
    if (symmetric) rows.push_back({"P2", subject, "Dantzig residual |min(z, w)| / |q|", dantzig_residual, 1e-10});
  }
  return rows;
}

}  // namespace heavesim::validation
