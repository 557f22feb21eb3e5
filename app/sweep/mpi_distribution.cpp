// The cluster task distribution: the ranks of MPI_COMM_WORLD share one task counter held
// by rank 0 in an MPI window; every rank, rank 0 included, takes the next index with an
// atomic MPI_Fetch_and_op (passive target, MPI-3 one-sided communication) and runs it,
// so a rank that draws short runs simply takes more (dynamic scheduling without a
// dispatcher that would cost a core). At the end rank 0 gathers every rank's records
// (MPI_Gatherv) and writes the index. Each rank writes its runs' result files itself
// (DIR must be shared by the ranks' nodes).
//
// Built as a module of its own (libheavesim_mpi.so), loaded only by a process that mpirun
// started (mpi_module.cpp): Open MPI's libraries (libmpi, its runtime, hwloc, libevent,
// udev) cost every other heavesim process ~3 ms of its start (docs/performance.md, "Issue
// #18, seventeenth round"). It depends on nothing of heavesim's but the interface's header.
#include <mpi.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "app/sweep/task_distribution.hpp"

namespace heavesim {
namespace {

void check(int code, const char* call) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + call + " failed");
}

class MpiDistribution final : public TaskDistribution {
 public:
  MpiDistribution() {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized) check(MPI_Init(nullptr, nullptr), "MPI_Init");
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiDistribution() override {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
  }

  std::vector<std::optional<std::string>> run(int count, const TaskCallbacks& callbacks) override {
    // The counter: one int64 in rank 0's window.
    std::int64_t* counter = nullptr;
    MPI_Win window;
    check(MPI_Win_allocate(rank_ == 0 ? sizeof(std::int64_t) : 0, sizeof(std::int64_t), MPI_INFO_NULL, MPI_COMM_WORLD,
                           &counter, &window),
          "MPI_Win_allocate");
    if (rank_ == 0) *counter = 0;
    MPI_Barrier(MPI_COMM_WORLD);  // the counter is 0 before anyone draws

    // Records of this rank: index, then bytes.
    std::string mine;
    check(MPI_Win_lock_all(0, window), "MPI_Win_lock_all");
    for (;;) {
      if (callbacks.stop_requested()) break;
      const std::int64_t one = 1;
      std::int64_t index = 0;
      check(MPI_Fetch_and_op(&one, &index, MPI_INT64_T, 0, 0, MPI_SUM, window), "MPI_Fetch_and_op");
      check(MPI_Win_flush(0, window), "MPI_Win_flush");
      if (index >= count) break;
      const std::string record = callbacks.run(static_cast<int>(index), rank_);
      const std::int64_t size = static_cast<std::int64_t>(record.size());
      mine.append(reinterpret_cast<const char*>(&index), sizeof index);
      mine.append(reinterpret_cast<const char*>(&size), sizeof size);
      mine += record;
      if (rank_ == 0) callbacks.finished(static_cast<int>(index), record);
    }
    check(MPI_Win_unlock_all(window), "MPI_Win_unlock_all");
    MPI_Win_free(&window);

    // Gather on rank 0.
    const int my_size = static_cast<int>(mine.size());
    std::vector<int> sizes(static_cast<std::size_t>(size_)), offsets(static_cast<std::size_t>(size_));
    check(MPI_Gather(&my_size, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Gather");
    std::string all;
    if (rank_ == 0) {
      long total = 0;
      for (int r = 0; r < size_; ++r) {
        offsets[static_cast<std::size_t>(r)] = static_cast<int>(total);
        total += sizes[static_cast<std::size_t>(r)];
      }
      if (total > 2'000'000'000L) throw std::runtime_error("MPI: the run records exceed 2 GB");
      all.resize(static_cast<std::size_t>(total));
    }
    check(MPI_Gatherv(mine.data(), my_size, MPI_CHAR, all.data(), sizes.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD),
          "MPI_Gatherv");
    if (rank_ != 0) return {};
    std::vector<std::optional<std::string>> records(static_cast<std::size_t>(count));
    for (std::size_t position = 0; position < all.size();) {
      std::int64_t index = 0, size = 0;
      std::memcpy(&index, all.data() + position, sizeof index);
      std::memcpy(&size, all.data() + position + sizeof index, sizeof size);
      position += sizeof index + sizeof size;
      records[static_cast<std::size_t>(index)] = all.substr(position, static_cast<std::size_t>(size));
      position += static_cast<std::size_t>(size);
    }
    return records;
  }

  bool coordinator() const override { return rank_ == 0; }
  bool broadcast(bool value) override {
    int flag = value ? 1 : 0;
    check(MPI_Bcast(&flag, 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Bcast");
    return flag != 0;
  }
  int size() const override { return size_; }

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace
}  // namespace heavesim

// The module's one entry point, looked up by name (mpi_module.cpp): the ranks of
// MPI_COMM_WORLD, MPI_Init here. The caller owns the object; its destructor (MPI_Finalize)
// is this module's code, which stays loaded to the end of the process.
extern "C" __attribute__((visibility("default"))) heavesim::TaskDistribution* heavesim_make_mpi_distribution() {
  return new heavesim::MpiDistribution();
}
