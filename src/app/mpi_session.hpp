#pragma once
// The MPI environment of one program run. MPI is initialised only under a launcher (mpirun
// sets the rank count in the environment): a plain `polydem run` never touches it. With
// N > 1 ranks, `run` shares one scene over them (sim/rank_contacts.hpp) through link().
#include <memory>

#include "sim/rank_link.hpp"

namespace polydem {

class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int ranks() const { return ranks_; }
  bool with_mpi() const { return initialised_; }
  // The ranks of MPI_COMM_WORLD; null when MPI is not initialised.
  const RankLink* link() const { return link_.get(); }

 private:
  int rank_ = 0, ranks_ = 1;
  bool initialised_ = false;
  std::unique_ptr<RankLink> link_;
};

}  // namespace polydem
