// Loading the MPI task distribution (mpi_distribution.cpp) only where it is used: a
// process started by mpirun. Linking Open MPI into the executable loaded its libraries
// into every process (a single run, a test, a sweep's forked workers) at ~3 ms of start
// each (docs/performance.md, "Issue #18, seventeenth round").
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

#include "app/sweep/task_distribution.hpp"

namespace heavesim {
namespace {

constexpr const char* mpi_module_name = "libheavesim_mpi.so";
constexpr const char* mpi_factory_name = "heavesim_make_mpi_distribution";

/// The module's path: beside the running executable (the build puts both in the build
/// directory). An absolute path, so that neither LD_LIBRARY_PATH nor the loader's search
/// can substitute another build's module.
std::filesystem::path mpi_module_path() {
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) throw std::runtime_error("heavesim sweep under mpirun: cannot find the running executable (/proc/self/exe: " +
                                      error.message() + "), beside which its MPI module " + mpi_module_name + " lies");
  return executable.parent_path() / mpi_module_name;
}

}  // namespace

bool started_by_mpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
}

std::unique_ptr<TaskDistribution> make_mpi_distribution() {
  const std::string path = mpi_module_path().string();
  // RTLD_GLOBAL: Open MPI opens its components (mca_*.so) with dlopen, and they use
  // libmpi's and libopen-pal's symbols without naming those libraries: they must be in the
  // global scope. Never closed: the distribution's code must outlive the object.
  void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
  if (module == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error("heavesim sweep under mpirun needs its MPI module " + path + ": " +
                             (why ? why : "not loaded") +
                             ". Build the target heavesim_mpi (it needs Open MPI's development files, "
                             "libopenmpi-dev), or run the sweep without mpirun (-j N).");
  }
  using Factory = TaskDistribution* (*)();
  auto factory = reinterpret_cast<Factory>(dlsym(module, mpi_factory_name));
  if (factory == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error(path + " has no " + mpi_factory_name + " (" + (why ? why : "not found") +
                             "): a module of another heavesim version? Rebuild the target heavesim_mpi.");
  }
  return std::unique_ptr<TaskDistribution>(factory());
}

}  // namespace heavesim
