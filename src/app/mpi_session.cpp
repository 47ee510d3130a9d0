#include "app/mpi_session.hpp"

#include <cstdlib>
#include <initializer_list>

#ifdef POLYDEM_WITH_MPI
#include <mpi.h>
#endif

namespace polydem {

namespace {

// The first of the launchers' variables that is set (OpenMPI, then PMI: MPICH, Slurm), else `absent`.
int launcher_value(const char* openmpi, const char* pmi, int absent) {
  for (const char* name : {openmpi, pmi})
    if (const char* v = std::getenv(name)) return std::atoi(v);
  return absent;
}

}  // namespace

MpiSession::MpiSession([[maybe_unused]] int& argc, [[maybe_unused]] char**& argv) {
  ranks_ = launcher_value("OMPI_COMM_WORLD_SIZE", "PMI_SIZE", 1);
  rank_ = launcher_value("OMPI_COMM_WORLD_RANK", "PMI_RANK", 0);
#ifdef POLYDEM_WITH_MPI
  if (ranks_ > 1 || std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE")) {
    MPI_Init(&argc, &argv);
    initialised_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
  }
#endif
}

MpiSession::~MpiSession() {
#ifdef POLYDEM_WITH_MPI
  if (initialised_) MPI_Finalize();
#endif
}

}  // namespace polydem
