// heavesim next to Pinocchio 3 on identical models, in one binary and one run, so that
// ratios (not absolute times) can be quoted. Pinocchio is used header-only from a source
// tree given to CMake (PINOCCHIO_SOURCE_DIR) and compiled with the same flags as ours.
//
// Before timing, the two codes are checked to agree on every model and 100 random
// states: joint torques (RNEA), accelerations (ABA) and the mass matrix (CRBA); the
// largest relative differences are printed in the benchmark's context, and a
// difference above 1e-9 stops the run (a timing of two different computations means
// nothing).
//
// Coordinates: Pinocchio's free-flyer has q = (p, quaternion x, y, z, w) and
// v = (linear, angular), both local; heavesim's free joint has q = (p, quaternion
// w, x, y, z) and v = (angular, linear), both body (= local) coordinates. The states are
// converted once, outside the timed loops. Revolute joints (all about X, Y or Z in these
// models) use Pinocchio's axis-specialised joints RX, RY, RZ: its fastest form.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cstdlib>
#include <memory>
#include <stdexcept>

#include "pinocchio/algorithm/aba.hpp"
#include "pinocchio/algorithm/crba.hpp"
#include "pinocchio/algorithm/kinematics.hpp"
#include "pinocchio/algorithm/rnea.hpp"
#include "pinocchio/multibody/data.hpp"
#include "pinocchio/multibody/model.hpp"

#include "kernel/algorithms/forward_dynamics.hpp"
#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "samples/bench_models.hpp"

namespace heavesim::bench {
namespace {

using samples::BenchLink;
using samples::BenchModel;
using samples::BenchStates;

constexpr int model_count = 4;

BenchModel model_for(int index) {
  switch (index) {
    case 0: return samples::bench_double_pendulum();
    case 1: return samples::chain7();
    case 2: return samples::humanoid32();
    default: return samples::tree32_fixed();
  }
}

pinocchio::JointModel revolute_about(const Vector3& axis) {
  if (axis == Vector3::UnitX()) return pinocchio::JointModelRX();
  if (axis == Vector3::UnitY()) return pinocchio::JointModelRY();
  if (axis == Vector3::UnitZ()) return pinocchio::JointModelRZ();
  return pinocchio::JointModelRevoluteUnaligned(axis);
}

/// The same tree as samples::to_model: joint i + 1 of both codes is link i.
pinocchio::Model to_pinocchio(const BenchModel& bench) {
  pinocchio::Model model;
  model.gravity.linear(Vector3(0.0, 0.0, -9.81));
  for (std::size_t i = 0; i < bench.links.size(); ++i) {
    const BenchLink& link = bench.links[i];
    const auto parent = static_cast<pinocchio::JointIndex>(link.parent + 1);
    const pinocchio::SE3 placement(Matrix3::Identity(), link.offset);
    const std::string name = "joint" + std::to_string(i);
    const pinocchio::JointIndex joint =
        link.free ? model.addJoint(parent, pinocchio::JointModelFreeFlyer(), placement, name)
                  : model.addJoint(parent, revolute_about(link.axis), placement, name);
    model.appendBodyToJoint(joint, pinocchio::Inertia(link.mass, link.com, link.inertia.asDiagonal()),
                            pinocchio::SE3::Identity());
  }
  return model;
}

/// Maps heavesim's coordinates to Pinocchio's and back, joint by joint.
struct CoordinateMap {
  CoordinateMap(const Model& ours, const pinocchio::Model& theirs) : ours(ours), theirs(theirs) {}

  VectorX configuration(const VectorX& q) const {
    VectorX out(theirs.nq);
    for (int i = 1; i < ours.num_links(); ++i) {
      const Joint& joint = ours.joints[i];
      const int at = theirs.idx_qs[i];
      if (joint.nq == 7) {  // p, (w, x, y, z) -> p, (x, y, z, w)
        out.segment<3>(at) = q.segment<3>(joint.q_index);
        out.segment<3>(at + 3) = q.segment<3>(joint.q_index + 4);
        out(at + 6) = q(joint.q_index + 3);
      } else {
        out.segment(at, joint.nq) = q.segment(joint.q_index, joint.nq);
      }
    }
    return out;
  }
  /// Velocities, accelerations and generalized forces: (angular, linear) <-> (linear, angular).
  VectorX tangent_to_theirs(const VectorX& x) const { return swap_free_halves(x, true); }
  VectorX tangent_to_ours(const VectorX& x) const { return swap_free_halves(x, false); }

  const Model& ours;
  const pinocchio::Model& theirs;

 private:
  VectorX swap_free_halves(const VectorX& x, bool to_theirs) const {
    VectorX out(x.size());
    for (int i = 1; i < ours.num_links(); ++i) {
      const Joint& joint = ours.joints[i];
      const int our_index = joint.v_index, their_index = theirs.idx_vs[i];
      const int from = to_theirs ? our_index : their_index, to = to_theirs ? their_index : our_index;
      if (joint.nv == 6) {
        out.segment<3>(to) = x.segment<3>(from + 3);
        out.segment<3>(to + 3) = x.segment<3>(from);
      } else {
        out.segment(to, joint.nv) = x.segment(from, joint.nv);
      }
    }
    return out;
  }
};

/// One model in both codes with 1024 random states in each one's coordinates.
struct Workload {
  explicit Workload(int index)
      : bench(model_for(index)),
        model(samples::to_model(bench)),
        data(model),
        pinocchio_model(to_pinocchio(bench)),
        pinocchio_data(pinocchio_model),
        map(model, pinocchio_model),
        states(samples::bench_states(model, 1024, 1)) {
    for (std::size_t k = 0; k < states.q.size(); ++k) {
      pinocchio_states.q.push_back(map.configuration(states.q[k]));
      pinocchio_states.v.push_back(map.tangent_to_theirs(states.v[k]));
      pinocchio_states.tau.push_back(map.tangent_to_theirs(states.tau[k]));
    }
  }
  BenchModel bench;
  Model model;
  Data data;
  pinocchio::Model pinocchio_model;
  pinocchio::Data pinocchio_data;
  CoordinateMap map;
  BenchStates states, pinocchio_states;
};

Workload& workload(int index) {
  static std::unique_ptr<Workload> workloads[model_count];
  if (!workloads[index]) workloads[index] = std::make_unique<Workload>(index);
  return *workloads[index];
}

double relative_difference(const MatrixX& ours, const MatrixX& theirs) {
  return (ours - theirs).norm() / ours.norm();
}

/// Largest relative differences over 100 states, per algorithm; throws above 1e-9.
void agreement_context() {
  for (int index = 0; index < model_count; ++index) {
    Workload& w = workload(index);
    double rnea_difference = 0.0, aba_difference = 0.0, crba_difference = 0.0;
    for (std::size_t k = 0; k < 100; ++k) {
      const VectorX& q = w.states.q[k];
      const VectorX& v = w.states.v[k];
      const VectorX& tau = w.states.tau[k];
      const VectorX& pin_q = w.pinocchio_states.q[k];
      const VectorX& pin_v = w.pinocchio_states.v[k];
      const VectorX& pin_tau = w.pinocchio_states.tau[k];
      // RNEA with tau read as an acceleration, as both benchmarks time it.
      const VectorX ours_rnea = rnea(w.model, w.data, q, v, tau);
      const VectorX theirs_rnea = w.map.tangent_to_ours(pinocchio::rnea(w.pinocchio_model, w.pinocchio_data, pin_q, pin_v, pin_tau));
      rnea_difference = std::max(rnea_difference, relative_difference(ours_rnea, theirs_rnea));
      const VectorX ours_aba = aba(w.model, w.data, q, v, tau);
      const VectorX theirs_aba = w.map.tangent_to_ours(pinocchio::aba(w.pinocchio_model, w.pinocchio_data, pin_q, pin_v, pin_tau));
      aba_difference = std::max(aba_difference, relative_difference(ours_aba, theirs_aba));
      // Pinocchio fills the upper triangle; the comparison is on M x for a random x.
      const MatrixX ours_mass = crba(w.model, w.data, q);
      pinocchio::crba(w.pinocchio_model, w.pinocchio_data, pin_q);
      const MatrixX theirs_mass = w.pinocchio_data.M.selfadjointView<Eigen::Upper>();
      const VectorX x = w.states.v[k + 1];
      crba_difference = std::max(crba_difference, relative_difference(ours_mass * x, w.map.tangent_to_ours(theirs_mass * w.map.tangent_to_theirs(x))));
    }
    benchmark::AddCustomContext(w.bench.name + " vs Pinocchio",
                                fmt::format("RNEA {:.1e}, ABA {:.1e}, CRBA {:.1e} (max relative, 100 states)",
                                            rnea_difference, aba_difference, crba_difference));
    if (std::max({rnea_difference, aba_difference, crba_difference}) > 1e-9)
      throw std::runtime_error(w.bench.name + ": heavesim and Pinocchio disagree; no timing");
  }
}

template <class Operation>
void run(benchmark::State& state, const char* what, Operation operation) {
  Workload& w = workload(static_cast<int>(state.range(0)));
  state.SetLabel(w.bench.name + " (" + what + ")");
  std::size_t k = 0;
  for (auto _ : state) {
    operation(w, k & 1023);
    benchmark::ClobberMemory();
    ++k;
  }
}

void BM_heavesim_positions(benchmark::State& state) {
  run(state, "position stage", [](Workload& w, std::size_t k) {
    update_positions(w.model, w.data, w.states.q[k]);
    benchmark::DoNotOptimize(w.data.X_world_link.data());
  });
}
void BM_pinocchio_positions(benchmark::State& state) {
  run(state, "forwardKinematics(q)", [](Workload& w, std::size_t k) {
    pinocchio::forwardKinematics(w.pinocchio_model, w.pinocchio_data, w.pinocchio_states.q[k]);
    benchmark::DoNotOptimize(w.pinocchio_data.oMi.data());
  });
}
void BM_heavesim_RNEA(benchmark::State& state) {
  run(state, "rnea", [](Workload& w, std::size_t k) {
    benchmark::DoNotOptimize(rnea(w.model, w.data, w.states.q[k], w.states.v[k], w.states.tau[k]).data());
  });
}
void BM_pinocchio_RNEA(benchmark::State& state) {
  run(state, "rnea", [](Workload& w, std::size_t k) {
    const auto& s = w.pinocchio_states;
    benchmark::DoNotOptimize(pinocchio::rnea(w.pinocchio_model, w.pinocchio_data, s.q[k], s.v[k], s.tau[k]).data());
  });
}
void BM_heavesim_CRBA(benchmark::State& state) {
  run(state, "crba, both triangles", [](Workload& w, std::size_t k) {
    benchmark::DoNotOptimize(crba(w.model, w.data, w.states.q[k]).data());
  });
}
void BM_pinocchio_CRBA(benchmark::State& state) {
  run(state, "crba, upper triangle", [](Workload& w, std::size_t k) {
    benchmark::DoNotOptimize(pinocchio::crba(w.pinocchio_model, w.pinocchio_data, w.pinocchio_states.q[k]).data());
  });
}
void BM_heavesim_ABA(benchmark::State& state) {
  run(state, "aba", [](Workload& w, std::size_t k) {
    benchmark::DoNotOptimize(aba(w.model, w.data, w.states.q[k], w.states.v[k], w.states.tau[k]).data());
  });
}
void BM_pinocchio_ABA(benchmark::State& state) {
  run(state, "aba, local convention", [](Workload& w, std::size_t k) {
    const auto& s = w.pinocchio_states;
    benchmark::DoNotOptimize(pinocchio::aba(w.pinocchio_model, w.pinocchio_data, s.q[k], s.v[k], s.tau[k]).data());
  });
}

#define PINOCCHIO_MODELS ->Arg(0)->Arg(1)->Arg(2)->Arg(3)
BENCHMARK(BM_heavesim_positions) PINOCCHIO_MODELS;
BENCHMARK(BM_pinocchio_positions) PINOCCHIO_MODELS;
BENCHMARK(BM_heavesim_RNEA) PINOCCHIO_MODELS;
BENCHMARK(BM_pinocchio_RNEA) PINOCCHIO_MODELS;
BENCHMARK(BM_heavesim_CRBA) PINOCCHIO_MODELS;
BENCHMARK(BM_pinocchio_CRBA) PINOCCHIO_MODELS;
BENCHMARK(BM_heavesim_ABA) PINOCCHIO_MODELS;
BENCHMARK(BM_pinocchio_ABA) PINOCCHIO_MODELS;

}  // namespace
}  // namespace heavesim::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  try {
    heavesim::bench::agreement_context();
  } catch (const std::exception& error) {
    fmt::print(stderr, "{}\n", error.what());
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
