#pragma once
// Handing out a sweep's tasks (run number i -> its record as bytes) dynamically: the next
// index goes to whichever worker is free, so that runs of unequal cost balance
// (docs/sweeps.md, "Scaling"). Two implementations behind one interface: a pool of
// forked worker processes on one machine (process_pool.cpp; HDF5 is not thread-safe, so
// parallel means processes), and MPI ranks (mpi_distribution.cpp, only under mpirun).
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace heavesim {

struct TaskCallbacks {
  /// Runs task `index` on worker or rank `worker`; returns its record (bytes).
  std::function<std::string(int index, int worker)> run;
  /// The record of a task whose worker died of `signal` while running it.
  std::function<std::string(int index, int worker, int signal)> crashed;
  /// Called on the coordinator after each finished task (for the progress line).
  std::function<void(int index, const std::string& record)> finished;
  /// True once the sweep should stop handing out tasks (SIGINT/SIGTERM).
  std::function<bool()> stop_requested;
};

class TaskDistribution {
 public:
  virtual ~TaskDistribution() = default;
  /// Runs tasks 0 .. count-1 and returns, on the coordinator, every record by index
  /// (nothing for a task never handed out because the sweep was stopped); elsewhere an
  /// empty vector.
  virtual std::vector<std::optional<std::string>> run(int count, const TaskCallbacks& callbacks) = 0;
  /// Whether this process writes the index and prints (the parent; MPI rank 0).
  virtual bool coordinator() const = 0;
  /// The coordinator's `value`, on every process.
  virtual bool broadcast(bool value) = 0;
  /// Workers or ranks.
  virtual int size() const = 0;
};

/// `jobs` forked worker processes, each running tasks one after the other in-process. A
/// worker killed by a signal gets its task recorded by `crashed` and is replaced.
std::unique_ptr<TaskDistribution> make_process_pool(int jobs);

/// Whether this process was started by mpirun (Open MPI's OMPI_COMM_WORLD_SIZE, or
/// PMI_SIZE / PMIX_RANK of other launchers and srun).
bool started_by_mpirun();
/// The ranks of MPI_COMM_WORLD (MPI_Init here, MPI_Finalize when destroyed), from the MPI
/// module libheavesim_mpi.so (mpi_distribution.cpp) beside the running executable, loaded
/// here (mpi_module.cpp). Throws std::runtime_error naming the module's path and the
/// loader's message when it cannot be loaded.
std::unique_ptr<TaskDistribution> make_mpi_distribution();

}  // namespace heavesim
