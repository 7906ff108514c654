#include "scenarios/sweep/sweep_mpi.hpp"

#include <cstdlib>

#include "scenarios/scene/scene_reader.hpp"

#ifdef CAROM_HAVE_MPI
// The C API only: without these, OpenMPI's and MPICH's mpi.h pull in the deprecated C++
// bindings, which need a library carom does not link.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace carom {

int launcher_rank_count() {
  // OpenMPI's mpirun, MPICH's hydra (and Slurm's PMI), PMIx launchers.
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    const char* value = std::getenv(name);
    if (value != nullptr && std::atoi(value) > 0) return std::atoi(value);
  }
  return 1;
}

bool first_launched_process() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
    if (const char* value = std::getenv(name)) return std::atoi(value) == 0;
  return true;
}

#ifdef CAROM_HAVE_MPI

SweepRanks::SweepRanks() {
  if (launcher_rank_count() <= 1) return;
  MPI_Init(nullptr, nullptr);
  initialised_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

SweepRanks::~SweepRanks() {
  if (initialised_) MPI_Finalize();
}

int SweepRanks::max(int value) const {
  if (!initialised_) return value;
  int result = value;
  MPI_Allreduce(&value, &result, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return result;
}

int SweepRanks::broadcast(int value) const {
  if (initialised_) MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value;
}

#else

SweepRanks::SweepRanks() {
  const int ranks = launcher_rank_count();
  if (ranks > 1)
    throw SceneError(
        "this carom was built without MPI, but it was started as one of " + std::to_string(ranks) +
        " ranks (by mpirun or srun): every rank would run every case. Run `carom sweep` without "
        "mpirun (use --jobs N for several cases at once), or rebuild carom with MPI "
        "(Debian: apt-get install libopenmpi-dev openmpi-bin, then re-run cmake).");
}

SweepRanks::~SweepRanks() = default;
int SweepRanks::max(int value) const {
  return value;
}
int SweepRanks::broadcast(int value) const {
  return value;
}

#endif

}  // namespace carom
