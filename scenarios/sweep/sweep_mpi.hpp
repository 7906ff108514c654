#pragma once
/// The ranks of a sweep: MPI_COMM_WORLD under mpirun, or this process alone.
///
/// MPI is initialised only when the process was started by a launcher (OMPI_COMM_WORLD_SIZE,
/// PMI_SIZE or PMIX_RANK in the environment), so a plain `carom sweep` never touches MPI. A
/// build without MPI (CAROM_HAVE_MPI undefined) that finds itself started as one of several
/// ranks refuses to run, rather than have every rank run every case.
#include <cstdint>
#include <string>

namespace carom {

class SweepRanks {
 public:
  /// Initialises MPI when launched by mpirun. Throws SceneError when launched as several ranks
  /// by a build without MPI.
  SweepRanks();
  /// Finalises MPI if this object initialised it.
  ~SweepRanks();
  SweepRanks(const SweepRanks&) = delete;
  SweepRanks& operator=(const SweepRanks&) = delete;

  /// This process's rank, 0-based.
  int rank() const { return rank_; }
  /// Number of ranks (1 without mpirun).
  int size() const { return size_; }
  /// True on the rank that prints errors and writes the summary.
  bool leader() const { return rank_ == 0; }

  /// Largest `value` over all ranks (every rank gets it; also a barrier).
  int max(int value) const;
  /// Rank 0's `value`, on every rank.
  int broadcast(int value) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  bool initialised_ = false;
};

/// The number of ranks the launcher says it started (1 when there is no launcher).
int launcher_rank_count();
/// True on the process that prints errors found before MPI is up, and that writes what is
/// gathered after it is down: rank 0, or the only process when there is no launcher.
bool first_launched_process();

}  // namespace carom
