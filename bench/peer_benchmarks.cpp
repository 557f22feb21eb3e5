// heavesim next to MuJoCo and DART on identical models, in one binary and one run,
// so that ratios (not absolute times) can be quoted. Before timing, the three codes
// are checked to agree on qdd for the revolute models (printed in the context).
#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>

#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/RevoluteJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>

#include <fmt/format.h>

#include <cstring>
#include <random>

#include "bench/mjcf_writer.hpp"
#include "kernel/algorithms/forward_dynamics.hpp"
#include "kernel/algorithms/joint_reactions.hpp"

namespace heavesim::bench {
namespace {

using samples::BenchLink;
using samples::BenchModel;
using samples::BenchStates;

BenchModel model_for(int index) {
  switch (index) {
    case 0: return samples::bench_double_pendulum();
    case 1: return samples::chain7();
    default: return samples::humanoid32();
  }
}

struct MujocoModel {
  explicit MujocoModel(const BenchModel& bench) {
    mjVFS vfs;
    mj_defaultVFS(&vfs);
    const std::string xml = to_mjcf(bench);
    mj_makeEmptyFileVFS(&vfs, "model.xml", static_cast<int>(xml.size()));
    std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, "model.xml")], xml.data(), xml.size());
    char error[1000] = "";
    model = mj_loadXML("model.xml", &vfs, error, sizeof error);
    mj_deleteVFS(&vfs);
    if (!model) throw std::runtime_error(std::string("MuJoCo: ") + error);
    data = mj_makeData(model);
  }
  ~MujocoModel() {
    mj_deleteData(data);
    mj_deleteModel(model);
  }
  /// Writes state k into qpos, qvel, qfrc_applied (= tau) and qacc (= tau, for mj_inverse).
  void set(const BenchStates& states, std::size_t k) const {
    for (int j = 0; j < model->nq; ++j) data->qpos[j] = states.q[k][j];
    for (int j = 0; j < model->nv; ++j) {
      data->qvel[j] = states.v[k][j];
      data->qfrc_applied[j] = data->qacc[j] = states.tau[k][j];
    }
  }
  mjModel* model = nullptr;
  mjData* data = nullptr;
};

dart::dynamics::SkeletonPtr to_dart(const BenchModel& bench) {
  namespace dd = dart::dynamics;
  dd::SkeletonPtr skeleton = dd::Skeleton::create(bench.name);
  std::vector<dd::BodyNode*> nodes;
  for (const BenchLink& link : bench.links) {
    dd::BodyNode* parent = link.parent < 0 ? nullptr : nodes[link.parent];
    Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
    offset.translation() = link.offset;
    dd::BodyNode* node = nullptr;
    if (link.free) {
      dd::FreeJoint::Properties properties;
      properties.mT_ParentBodyToJoint = offset;
      node = skeleton->createJointAndBodyNodePair<dd::FreeJoint>(parent, properties).second;
    } else {
      dd::RevoluteJoint::Properties properties;
      properties.mT_ParentBodyToJoint = offset;
      properties.mAxis = link.axis;
      node = skeleton->createJointAndBodyNodePair<dd::RevoluteJoint>(parent, properties).second;
    }
    node->setInertia(dd::Inertia(link.mass, link.com, link.inertia.asDiagonal()));
    nodes.push_back(node);
  }
  skeleton->setGravity(Eigen::Vector3d(0, 0, -9.81));
  return skeleton;
}

/// Max relative qdd difference of MuJoCo and DART against heavesim (revolute models:
/// all three use the same coordinates).
void agreement_context() {
  for (int index : {0, 1}) {
    const BenchModel bench = model_for(index);
    const Model model = samples::to_model(bench);
    Data data(model);
    MujocoModel mujoco(bench);
    auto dart = to_dart(bench);
    const BenchStates states = samples::bench_states(model, 100, 2);
    double mujoco_error = 0.0, dart_error = 0.0;
    for (std::size_t k = 0; k < states.q.size(); ++k) {
      const VectorX qdd = aba(model, data, states.q[k], states.v[k], states.tau[k]);
      mujoco.set(states, k);
      mj_forward(mujoco.model, mujoco.data);
      dart->setPositions(states.q[k]);
      dart->setVelocities(states.v[k]);
      dart->setForces(states.tau[k]);
      dart->computeForwardDynamics();
      mujoco_error = std::max(mujoco_error, (Eigen::Map<VectorX>(mujoco.data->qacc, model.nv) - qdd).norm() / qdd.norm());
      dart_error = std::max(dart_error, (dart->getAccelerations() - qdd).norm() / qdd.norm());
    }
    benchmark::AddCustomContext(bench.name + " qdd vs heavesim",
                                fmt::format("MuJoCo {:.1e}, DART {:.1e} (max relative, 100 states)", mujoco_error,
                                            dart_error));
  }
}

/// Times `operation(k)` over 1024 random states of the selected model. For a free
/// base the states are in heavesim's coordinates; peers only time them.
template <class Setup>
void timed(benchmark::State& state, const std::string& what, Setup setup) {
  const BenchModel bench = model_for(static_cast<int>(state.range(0)));
  const Model model = samples::to_model(bench);
  const BenchStates states = samples::bench_states(model, 1024, 1);
  auto operation = setup(bench, model, states);
  state.SetLabel(bench.name + " (" + what + ")");
  std::size_t k = 0;
  for (auto _ : state) operation(k++ & 1023);
}

void BM_heavesim_ABA(benchmark::State& state) {
  timed(state, "aba", [](const BenchModel&, const Model& model, const BenchStates& states) {
    return [&model, &states, data = std::make_shared<Data>(model)](std::size_t k) {
      benchmark::DoNotOptimize(aba(model, *data, states.q[k], states.v[k], states.tau[k]));
    };
  });
}

void BM_heavesim_ABA_and_reactions(benchmark::State& state) {
  timed(state, "aba + compute_joint_wrenches", [](const BenchModel&, const Model& model, const BenchStates& states) {
    return [&model, &states, data = std::make_shared<Data>(model)](std::size_t k) {
      aba(model, *data, states.q[k], states.v[k], states.tau[k]);
      compute_joint_wrenches(model, *data);
      benchmark::DoNotOptimize(data->joint_wrench_world.data());
    };
  });
}

void BM_heavesim_RNEA(benchmark::State& state) {
  timed(state, "rnea", [](const BenchModel&, const Model& model, const BenchStates& states) {
    return [&model, &states, data = std::make_shared<Data>(model)](std::size_t k) {
      benchmark::DoNotOptimize(rnea(model, *data, states.q[k], states.v[k], states.tau[k]));
    };
  });
}

void BM_mujoco_forward(benchmark::State& state) {
  timed(state, "mj_forward, full pipeline", [](const BenchModel& bench, const Model&, const BenchStates& states) {
    return [&states, mujoco = std::make_shared<MujocoModel>(bench)](std::size_t k) {
      mujoco->set(states, k);
      mj_forward(mujoco->model, mujoco->data);
      benchmark::DoNotOptimize(mujoco->data->qacc);
    };
  });
}

void BM_mujoco_forward_and_reactions(benchmark::State& state) {
  timed(state, "mj_forward + mj_rnePostConstraint", [](const BenchModel& bench, const Model&, const BenchStates& states) {
    return [&states, mujoco = std::make_shared<MujocoModel>(bench)](std::size_t k) {
      mujoco->set(states, k);
      mj_forward(mujoco->model, mujoco->data);
      mj_rnePostConstraint(mujoco->model, mujoco->data);
      benchmark::DoNotOptimize(mujoco->data->cfrc_int);
    };
  });
}

void BM_mujoco_inverse(benchmark::State& state) {
  timed(state, "mj_inverse", [](const BenchModel& bench, const Model&, const BenchStates& states) {
    return [&states, mujoco = std::make_shared<MujocoModel>(bench)](std::size_t k) {
      mujoco->set(states, k);
      mj_inverse(mujoco->model, mujoco->data);
      benchmark::DoNotOptimize(mujoco->data->qfrc_inverse);
    };
  });
}

/// DART's free joint uses its own coordinates (exponential map), so it gets states of
/// its own size drawn the same way.
BenchStates dart_states(const dart::dynamics::SkeletonPtr& skeleton) {
  const int n = static_cast<int>(skeleton->getNumDofs());
  BenchStates states;
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int k = 0; k < 1024; ++k) {
    states.q.push_back(VectorX::NullaryExpr(n, [&](Eigen::Index) { return uniform(random); }));
    states.v.push_back(VectorX::NullaryExpr(n, [&](Eigen::Index) { return uniform(random); }));
    states.tau.push_back(VectorX::NullaryExpr(n, [&](Eigen::Index) { return uniform(random); }));
  }
  return states;
}

void BM_dart_forward(benchmark::State& state) {
  timed(state, "set q, v, tau + computeForwardDynamics", [](const BenchModel& bench, const Model&, const BenchStates&) {
    auto dart = to_dart(bench);
    return [dart, states = dart_states(dart)](std::size_t k) {
      dart->setPositions(states.q[k]);
      dart->setVelocities(states.v[k]);
      dart->setForces(states.tau[k]);
      dart->computeForwardDynamics();
      benchmark::DoNotOptimize(dart->getAccelerations().data());
    };
  });
}

void BM_dart_inverse(benchmark::State& state) {
  timed(state, "set q, v, qdd + computeInverseDynamics", [](const BenchModel& bench, const Model&, const BenchStates&) {
    auto dart = to_dart(bench);
    return [dart, states = dart_states(dart)](std::size_t k) {
      dart->setPositions(states.q[k]);
      dart->setVelocities(states.v[k]);
      dart->setAccelerations(states.tau[k]);
      dart->computeInverseDynamics();
      benchmark::DoNotOptimize(dart->getForces().data());
    };
  });
}

#define PEER_MODELS ->Arg(0)->Arg(1)->Arg(2)
BENCHMARK(BM_heavesim_ABA) PEER_MODELS;
BENCHMARK(BM_heavesim_ABA_and_reactions) PEER_MODELS;
BENCHMARK(BM_mujoco_forward) PEER_MODELS;
BENCHMARK(BM_mujoco_forward_and_reactions) PEER_MODELS;
BENCHMARK(BM_dart_forward) PEER_MODELS;
BENCHMARK(BM_heavesim_RNEA) PEER_MODELS;
BENCHMARK(BM_mujoco_inverse) PEER_MODELS;
BENCHMARK(BM_dart_inverse) PEER_MODELS;

}  // namespace
}  // namespace heavesim::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  heavesim::bench::agreement_context();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
