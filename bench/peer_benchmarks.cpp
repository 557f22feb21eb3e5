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

#include "bench/benchmark_models.hpp"
#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/forward_dynamics.hpp"
#include "kernel/algorithms/joint_reactions.hpp"

namespace heavesim::bench {
namespace {

BenchModel model_for(int index) {
  switch (index) {
    case 0: return double_pendulum();
    case 1: return chain7();
    default: return humanoid32();
  }
}

// ------------------------------------------------------------------ MuJoCo
struct MujocoModel {
  explicit MujocoModel(const BenchModel& bench) {
    mjVFS vfs;
    mj_defaultVFS(&vfs);
    const std::string xml = to_mjcf(bench);
    mj_makeEmptyFileVFS(&vfs, "model.xml", static_cast<int>(xml.size()));
    const int file = mj_findFileVFS(&vfs, "model.xml");
    std::memcpy(vfs.filedata[file], xml.data(), xml.size());
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
  mjModel* model = nullptr;
  mjData* data = nullptr;
};

// ------------------------------------------------------------------ DART
dart::dynamics::SkeletonPtr to_dart(const BenchModel& bench) {
  namespace dd = dart::dynamics;
  dd::SkeletonPtr skeleton = dd::Skeleton::create(bench.name);
  std::vector<dd::BodyNode*> nodes;
  for (std::size_t i = 0; i < bench.links.size(); ++i) {
    const BenchLink& link = bench.links[i];
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

// ------------------------------------------------------------------ shared states
struct States {
  States(int nq, int nv, const Model& model) {
    std::mt19937_64 random(2);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const VectorX q0 = model.neutral_configuration();
    for (int k = 0; k < 1024; ++k) {
      VectorX d(nv), q(nq), v(nv), tau(nv);
      for (int i = 0; i < nv; ++i) {
        d[i] = uniform(random);
        v[i] = uniform(random);
        tau[i] = uniform(random);
      }
      integrate_configuration(model, q0, d, 1.0, q);
      qs.push_back(q);
      vs.push_back(v);
      taus.push_back(tau);
    }
  }
  std::vector<VectorX> qs, vs, taus;
};

/// Max relative qdd difference of MuJoCo and DART against heavesim (revolute models only).
void agreement_context() {
  for (int index : {0, 1}) {
    const BenchModel bench = model_for(index);
    const Model model = to_heavesim(bench);
    Data data(model);
    MujocoModel mujoco(bench);
    auto dart = to_dart(bench);
    const States states(model.nq, model.nv, model);
    double mujoco_error = 0.0, dart_error = 0.0;
    for (int k = 0; k < 100; ++k) {
      const VectorX qdd = aba(model, data, states.qs[k], states.vs[k], states.taus[k]);
      for (int i = 0; i < model.nv; ++i) {
        mujoco.data->qpos[i] = states.qs[k][i];
        mujoco.data->qvel[i] = states.vs[k][i];
        mujoco.data->qfrc_applied[i] = states.taus[k][i];
      }
      mj_forward(mujoco.model, mujoco.data);
      dart->setPositions(states.qs[k]);
      dart->setVelocities(states.vs[k]);
      dart->setForces(states.taus[k]);
      dart->computeForwardDynamics();
      mujoco_error = std::max(mujoco_error, (Eigen::Map<VectorX>(mujoco.data->qacc, model.nv) - qdd).norm() / qdd.norm());
      dart_error = std::max(dart_error, (dart->getAccelerations() - qdd).norm() / qdd.norm());
    }
    benchmark::AddCustomContext(bench.name + " qdd vs heavesim",
                                fmt::format("MuJoCo {:.1e}, DART {:.1e} (max relative, 100 states)", mujoco_error,
                                            dart_error));
  }
}

// ------------------------------------------------------------------ benchmarks
void BM_heavesim_ABA(benchmark::State& state) {
  const BenchModel bench = model_for(static_cast<int>(state.range(0)));
  const Model model = to_heavesim(bench);
  Data data(model);
  const States states(model.nq, model.nv, model);
  state.SetLabel(bench.name);
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t i = k++ & 1023;
    benchmark::DoNotOptimize(aba(model, data, states.qs[i], states.vs[i], states.taus[i]));
  }
}

void BM_heavesim_ABA_and_reactions(benchmark::State& state) {
  const BenchModel bench = model_for(static_cast<int>(state.range(0)));
  const Model model = to_heavesim(bench);
  Data data(model);
  const States states(model.nq, model.nv, model);
  state.SetLabel(bench.name);
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t i = k++ & 1023;
    aba(model, data, states.qs[i], states.vs[i], states.taus[i]);
    compute_joint_wrenches(model, data);
    benchmark::DoNotOptimize(data.joint_wrench_world.data());
  }
}

void BM_heavesim_RNEA(benchmark::State& state) {
  const BenchModel bench = model_for(static_cast<int>(state.range(0)));
  const Model model = to_heavesim(bench);
  Data data(model);
  const States states(model.nq, model.nv, model);
  state.SetLabel(bench.name);
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t i = k++ & 1023;
    benchmark::DoNotOptimize(rnea(model, data, states.qs[i], states.vs[i], states.taus[i]));
  }
}

void mujoco_set(const MujocoModel& mujoco, const States& states, std::size_t i) {
  for (int j = 0; j < mujoco.model->nq; ++j) mujoco.data->qpos[j] = states.qs[i][j];
  for (int j = 0; j < mujoco.model->nv; ++j) {
    mujoco.data->qvel[j] = states.vs[i][j];
    mujoco.data->qfrc_applied[j] = states.taus[i][j];
    mujoco.data->qacc[j] = states.taus[i][j];
  }
}

void BM_mujoco_forward(benchmark::State& state) {
  const BenchModel bench = model_for(static_cast<int>(state.range(0)));
  MujocoModel mujoco(bench);
  const Model model = to_heavesim(bench);
  const States states(model.nq, model.nv, model);
  state.SetLabel(bench.name + " (mj_forward, full pipeline)");
  std::size_t k = 0;
  for (auto _ : state) {
    mujoco_set(mujoco, states, k++ & 1023);
    mj_forward(mujoco.model, mujoco.data);
    benchmark::DoNotOptimize(mujoco.data->qacc);
  }
}

void BM_mujoco_forward_and_reactions(benchmark::State& state) {
  const BenchModel bench = model_for(static_cast<int>(state.range(0)));
  MujocoModel mujoco(bench);
  const Model model = to_heavesim(bench);
  const States states(model.nq, model.nv, model);
  state.SetLabel(bench.name + " (mj_forward + mj_rnePostConstraint)");
  std::size_t k = 0;
  for (auto _ : state) {
    mujoco_set(mujoco, states, k++ & 1023);
    mj_forward(mujoco.model, mujoco.data);
    mj_rnePostConstraint(mujoco.model, mujoco.data);
    benchmark::DoNotOptimize(mujoco.data->cfrc_int);
  }
}

void BM_mujoco_inverse(benchmark::State& state) {
  const BenchModel bench = model_for(static_cast<int>(state.range(0)));
  MujocoModel mujoco(bench);
  const Model model = to_heavesim(bench);
  const States states(model.nq, model.nv, model);
  state.SetLabel(bench.name + " (mj_inverse)");
  std::size_t k = 0;
  for (auto _ : state) {
    mujoco_set(mujoco, states, k++ & 1023);
    mj_inverse(mujoco.model, mujoco.data);
    benchmark::DoNotOptimize(mujoco.data->qfrc_inverse);
  }
}

void BM_dart_forward(benchmark::State& state) {
  const BenchModel bench = model_for(static_cast<int>(state.range(0)));
  auto dart = to_dart(bench);
  const States states(static_cast<int>(dart->getNumDofs()), static_cast<int>(dart->getNumDofs()), to_heavesim(double_pendulum()));
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<VectorX> qs, vs, taus;
  for (int k = 0; k < 1024; ++k) {
    const int n = static_cast<int>(dart->getNumDofs());
    qs.push_back(VectorX::NullaryExpr(n, [&](Eigen::Index) { return uniform(random); }));
    vs.push_back(VectorX::NullaryExpr(n, [&](Eigen::Index) { return uniform(random); }));
    taus.push_back(VectorX::NullaryExpr(n, [&](Eigen::Index) { return uniform(random); }));
  }
  state.SetLabel(bench.name + " (set q, v, tau + computeForwardDynamics)");
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t i = k++ & 1023;
    dart->setPositions(qs[i]);
    dart->setVelocities(vs[i]);
    dart->setForces(taus[i]);
    dart->computeForwardDynamics();
    benchmark::DoNotOptimize(dart->getAccelerations().data());
  }
}

void BM_dart_inverse(benchmark::State& state) {
  const BenchModel bench = model_for(static_cast<int>(state.range(0)));
  auto dart = to_dart(bench);
  std::mt19937_64 random(4);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const int n = static_cast<int>(dart->getNumDofs());
  std::vector<VectorX> qs, vs, as;
  for (int k = 0; k < 1024; ++k) {
    qs.push_back(VectorX::NullaryExpr(n, [&](Eigen::Index) { return uniform(random); }));
    vs.push_back(VectorX::NullaryExpr(n, [&](Eigen::Index) { return uniform(random); }));
    as.push_back(VectorX::NullaryExpr(n, [&](Eigen::Index) { return uniform(random); }));
  }
  state.SetLabel(bench.name + " (set q, v, qdd + computeInverseDynamics)");
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t i = k++ & 1023;
    dart->setPositions(qs[i]);
    dart->setVelocities(vs[i]);
    dart->setAccelerations(as[i]);
    dart->computeInverseDynamics();
    benchmark::DoNotOptimize(dart->getForces().data());
  }
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
