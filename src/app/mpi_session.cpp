#include "app/mpi_session.hpp"

#include <chrono>
#include <cstdlib>
#include <ctime>
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

#ifdef POLYDEM_WITH_MPI
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Adds its scope's wall and CPU seconds to one kind of `times`, when `times` is given.
class TimedCall {
 public:
  TimedCall(LinkTimes* times, LinkTimes::Kind kind) : times_(times), kind_(kind) {
    if (!times_) return;
    wall_ = std::chrono::steady_clock::now();
    cpu_ = thread_cpu_seconds();
  }
  ~TimedCall() {
    if (!times_) return;
    times_->wall[kind_] += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count();
    times_->cpu[kind_] += thread_cpu_seconds() - cpu_;
  }
  TimedCall(const TimedCall&) = delete;
  TimedCall& operator=(const TimedCall&) = delete;

 private:
  LinkTimes* times_;
  LinkTimes::Kind kind_;
  std::chrono::steady_clock::time_point wall_;
  double cpu_ = 0.0;  // s
};

class MpiLink final : public RankLink {
 public:
  // Timed where read: POLYDEM_MPI_TIMES prints the times, the cut in time (POLYDEM_CUT_TIMED) reads the CPU seconds.
  MpiLink(int rank, int ranks)
      : rank_(rank), ranks_(ranks), timed_(std::getenv("POLYDEM_MPI_TIMES") || std::getenv("POLYDEM_CUT_TIMED")) {}
  int rank() const override { return rank_; }
  int ranks() const override { return ranks_; }
  std::vector<std::vector<char>> all_gather(const std::vector<char>& mine) const override {
    return collect(mine, kEveryRank);
  }
  std::vector<std::vector<char>> gather(const std::vector<char>& mine, int root) const override {
    return collect(mine, root);
  }
  std::vector<std::vector<char>> all_gather_same(const std::vector<char>& mine) const override {
    const int n = int(mine.size());
    const TimedCall timed = timer(LinkTimes::kGather);
    ++counts_.collectives;
    counts_.collective_bytes += mine.size();
    std::vector<int> offsets(ranks_ + 1);
    for (int r = 0; r <= ranks_; ++r) offsets[r] = r * n;
    std::vector<char> all(std::size_t(offsets[ranks_]) + 1);  // + 1: data() of an empty gather
    MPI_Allgather(mine.data(), n, MPI_CHAR, all.data(), n, MPI_CHAR, MPI_COMM_WORLD);
    counts_.collective_bytes_in += std::uint64_t(offsets[ranks_] - n);
    return split(all, offsets);
  }
  void post(const std::vector<Parcel>& out, std::vector<Parcel>& in) const override {
    pending_.resize(out.size() + in.size());
    for (std::size_t k = 0; k < in.size(); ++k)
      MPI_Irecv(in[k].bytes.data(), int(in[k].bytes.size()), MPI_CHAR, in[k].rank, kGhostTag, MPI_COMM_WORLD,
                &pending_[k]);
    for (std::size_t k = 0; k < out.size(); ++k) {
      MPI_Isend(out[k].bytes.data(), int(out[k].bytes.size()), MPI_CHAR, out[k].rank, kGhostTag, MPI_COMM_WORLD,
                &pending_[in.size() + k]);
      ++counts_.parcels;
      counts_.parcel_bytes += out[k].bytes.size();
    }
  }
  void finish(const std::vector<Parcel>&, std::vector<Parcel>&) const override {
    const TimedCall timed = timer(LinkTimes::kExchange);
    MPI_Waitall(int(pending_.size()), pending_.data(), MPI_STATUSES_IGNORE);
    pending_.clear();
  }
  LinkCounts counts() const override { return counts_; }
  LinkTimes times() const override { return times_; }
  std::vector<std::uint64_t> all_to_all(const std::vector<std::uint64_t>& to_each) const override {
    std::vector<std::uint64_t> from(ranks_);
    const TimedCall timed = timer(LinkTimes::kGather);
    MPI_Alltoall(to_each.data(), 1, MPI_UINT64_T, from.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD);
    count_collective(to_each.size());
    return from;
  }
  std::vector<std::uint64_t> sum(const std::vector<std::uint64_t>& mine) const override {
    std::vector<std::uint64_t> total(mine.size());
    const TimedCall timed = timer(LinkTimes::kReduction);
    MPI_Allreduce(mine.data(), total.data(), int(mine.size()), MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
    count_collective(mine.size());
    return total;
  }

 private:
  static constexpr int kEveryRank = -1;
  TimedCall timer(LinkTimes::Kind kind) const { return TimedCall(timed_ ? &times_ : nullptr, kind); }
  // A collective of `n` values each way (the bytes in: what a reduction or a transpose brings).
  void count_collective(std::size_t n) const {
    ++counts_.collectives;
    counts_.collective_bytes += n * sizeof(std::uint64_t);
    counts_.collective_bytes_in += n * sizeof(std::uint64_t);
  }
  // Every rank's `mine` onto `root`, or onto every rank (kEveryRank): sizes first, then bytes.
  std::vector<std::vector<char>> collect(const std::vector<char>& mine, int root) const {
    const int n = int(mine.size());
    const TimedCall timed = timer(LinkTimes::kGather);
    ++counts_.collectives;
    counts_.collective_bytes += mine.size();
    std::vector<int> sizes(ranks_), offsets(ranks_ + 1, 0);
    if (root == kEveryRank) MPI_Allgather(&n, 1, MPI_INT, sizes.data(), 1, MPI_INT, MPI_COMM_WORLD);
    else MPI_Gather(&n, 1, MPI_INT, sizes.data(), 1, MPI_INT, root, MPI_COMM_WORLD);
    for (int r = 0; r < ranks_; ++r) offsets[r + 1] = offsets[r] + sizes[r];
    std::vector<char> all(std::size_t(offsets[ranks_]) + 1);  // + 1: data() of an empty gather
    if (root == kEveryRank)
      MPI_Allgatherv(mine.data(), n, MPI_CHAR, all.data(), sizes.data(), offsets.data(), MPI_CHAR, MPI_COMM_WORLD);
    else
      MPI_Gatherv(mine.data(), n, MPI_CHAR, all.data(), sizes.data(), offsets.data(), MPI_CHAR, root, MPI_COMM_WORLD);
    if (root != kEveryRank && rank_ != root) return {};
    counts_.collective_bytes_in += std::uint64_t(offsets[ranks_] - n);
    return split(all, offsets);
  }
  // Each rank's bytes of a gathered buffer at `offsets`.
  std::vector<std::vector<char>> split(const std::vector<char>& all, const std::vector<int>& offsets) const {
    std::vector<std::vector<char>> per_rank(ranks_);
    for (int r = 0; r < ranks_; ++r) per_rank[r].assign(all.begin() + offsets[r], all.begin() + offsets[r + 1]);
    return per_rank;
  }
  static constexpr int kGhostTag = 20;  // the number: one kind of point-to-point message
  int rank_, ranks_;
  bool timed_;
  mutable LinkCounts counts_;
  mutable LinkTimes times_;
  mutable std::vector<MPI_Request> pending_;  // an exchange's requests (kept: no allocation a step)
};
#endif

}  // namespace

MpiSession::MpiSession([[maybe_unused]] int& argc, [[maybe_unused]] char**& argv) {
  ranks_ = launcher_value("OMPI_COMM_WORLD_SIZE", "PMI_SIZE", 1);
  rank_ = launcher_value("OMPI_COMM_WORLD_RANK", "PMI_RANK", 0);
#ifdef POLYDEM_WITH_MPI
  if (ranks_ > 1 || std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE")) {
    // A rank waiting for a message yields its core (OpenMPI polls without yielding unless
    // oversubscribed): beside other work, -np 2 ran 2-4x faster (README, "A slow core").
    // `--mca mpi_yield_when_idle 0` (or the variable) keeps the user's choice.
    setenv("OMPI_MCA_mpi_yield_when_idle", "1", 0);
    MPI_Init(&argc, &argv);
    initialised_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
    link_ = std::make_unique<MpiLink>(rank_, ranks_);
  }
#endif
}

MpiSession::~MpiSession() {
#ifdef POLYDEM_WITH_MPI
  if (initialised_) MPI_Finalize();
#endif
}

}  // namespace polydem
