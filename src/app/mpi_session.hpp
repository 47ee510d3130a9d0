#pragma once
// The MPI environment of one program run. A scene over many ranks is not built yet (issue
// 20), so a launch of N > 1 copies stops at once, rank 0 saying why, rather than running the
// scene N times into one folder. MPI is initialised only under a launcher (mpirun sets the
// rank count in the environment): a plain `polydem run` never touches it.
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

 private:
  int rank_ = 0, ranks_ = 1;
  bool initialised_ = false;
};

}  // namespace polydem
