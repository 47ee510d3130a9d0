#pragma once
// Ranks as threads joined by an in-process link, so the distributed run's code is tested
// without MPI (and in the sanitized builds, which have none).
#include <algorithm>
#include <atomic>
#include <barrier>
#include <functional>
#include <thread>
#include <vector>

#include "sim/rank_link.hpp"

namespace polydem::test {

// Ranks as threads: each all_gather posts its bytes, waits for all, copies all, waits again.
// An exchange posts each parcel in the box of (sender, receiver) and reads its own the same way.
struct ThreadRanks {
  explicit ThreadRanks(int n) : posted(n), box(n, std::vector<std::vector<char>>(n)), sync(n) {}
  std::vector<std::vector<char>> posted;
  std::vector<std::vector<std::vector<char>>> box;  // [from][to]
  std::atomic<bool> mismatch = false;  // a parcel of another size than the receiver expects
  std::barrier<> sync;
};

class ThreadLink final : public RankLink {
 public:
  ThreadLink(ThreadRanks& all, int rank) : all_(all), rank_(rank) {}
  int rank() const override { return rank_; }
  int ranks() const override { return int(all_.posted.size()); }
  std::vector<std::vector<char>> all_gather(const std::vector<char>& mine) const override {
    all_.posted[rank_] = mine;
    all_.sync.arrive_and_wait();
    std::vector<std::vector<char>> copy = all_.posted;
    all_.sync.arrive_and_wait();
    return copy;
  }
  // The parcels go to their boxes; what this rank receives reads as NaNs until finish(), as an
  // MPI receive in flight holds any bytes: a ghost read before it lands is not the owner's.
  void post(const std::vector<Parcel>& out, std::vector<Parcel>& in) const override {
    for (const Parcel& p : out) all_.box[rank_][p.rank] = p.bytes;
    for (Parcel& p : in) std::fill(p.bytes.begin(), p.bytes.end(), char(0xff));  // 0xff...: a NaN double
  }
  void finish(const std::vector<Parcel>& out, std::vector<Parcel>& in) const override {
    all_.sync.arrive_and_wait();
    for (Parcel& p : in) {
      if (all_.box[p.rank][rank_].size() != p.bytes.size()) all_.mismatch = true;  // the sizes both plans give
      p.bytes = all_.box[p.rank][rank_];
    }
    all_.sync.arrive_and_wait();
    for (const Parcel& p : out) all_.box[rank_][p.rank].clear();
  }

 private:
  ThreadRanks& all_;
  int rank_;
};

// Runs `rank(link)` on `n` threads, one rank each, and waits for them all.
inline void on_thread_ranks(int n, const std::function<void(const RankLink&)>& rank) {
  ThreadRanks all(n);
  std::vector<std::thread> threads;
  for (int r = 0; r < n; ++r)
    threads.emplace_back([&, r] {
      const ThreadLink link(all, r);
      rank(link);
    });
  for (std::thread& t : threads) t.join();
}

}  // namespace polydem::test
