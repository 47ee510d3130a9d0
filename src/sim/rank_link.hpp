#pragma once
// The link between the ranks of a distributed run (issue 20), as the step needs it: every
// rank's bytes on every rank (a collective), and parcels to and from chosen ranks (the ghost
// exchange, point to point). The MPI implementation lives with the program (app/mpi_link.cpp),
// so the library and its tests build without MPI; one process has no link at all.
#include <cstdint>
#include <cstring>
#include <exception>
#include <string>
#include <type_traits>
#include <vector>

#include "polydem/error.hpp"

namespace polydem {

// Bytes to or from one rank; a receiver knows each parcel's size beforehand.
struct Parcel {
  int rank;
  std::vector<char> bytes;
};

// What a rank has sent since the start: point-to-point parcels and its share of the collectives.
struct LinkCounts {
  std::uint64_t parcels = 0, parcel_bytes = 0;          // sent point to point
  std::uint64_t collectives = 0, collective_bytes = 0;  // all_gather and gather calls, this rank's bytes in them
  std::uint64_t collective_bytes_in = 0;                // the other ranks' bytes they brought to this rank
};

// Seconds a rank spent inside MPI calls since the start, by kind: timed, to split a step's clock
// into work and waiting (POLYDEM_MPI_TIMES prints them: README, MPI section), and the CPU seconds
// for a rank's busy seconds (the cut in time: RankContacts::time_by_clock).
struct LinkTimes {
  enum Kind { kExchange, kReduction, kGather, kKinds };  // ghost waits; sums (the step's decision); gathers, transposes
  double wall[kKinds] = {}, cpu[kKinds] = {};  // s elapsed, s of this thread's CPU (a waiting rank polls)
};

class RankLink {
 public:
  virtual ~RankLink() = default;
  virtual int rank() const = 0;
  virtual int ranks() const = 0;
  // Every rank's `mine`, in rank order, on every rank (a collective: all ranks call it).
  virtual std::vector<std::vector<char>> all_gather(const std::vector<char>& mine) const = 0;
  // all_gather where every rank's `mine` has the same size (fixed records: the step's decision,
  // a failing id): one message each way, no sizes first. By default all_gather.
  virtual std::vector<std::vector<char>> all_gather_same(const std::vector<char>& mine) const {
    return all_gather(mine);
  }
  // Every rank's `mine`, in rank order, on rank `root` only (none elsewhere; a collective):
  // what only rank 0 reads (output). By default an all_gather whose copies are dropped.
  virtual std::vector<std::vector<char>> gather(const std::vector<char>& mine, int root) const {
    std::vector<std::vector<char>> all = all_gather(mine);
    if (rank() != root) all.clear();
    return all;
  }
  // Sends each parcel of `out` to its rank and fills each parcel of `in` (its bytes sized by
  // the caller) from its rank. Every rank calls it; the pattern is symmetric between ranks.
  void exchange(const std::vector<Parcel>& out, std::vector<Parcel>& in) const {
    post(out, in);
    finish(out, in);
  }
  // exchange in two halves, so a rank works while its parcels travel: post() sends `out` and
  // posts the receipt of `in`; finish() waits until every parcel has landed. Between them `in`'s
  // bytes are undefined (a receive in flight), `out` must stay as it is, and the rank calls no
  // other method of the link.
  virtual void post(const std::vector<Parcel>& out, std::vector<Parcel>& in) const = 0;
  virtual void finish(const std::vector<Parcel>& out, std::vector<Parcel>& in) const = 0;
  virtual LinkCounts counts() const { return {}; }
  virtual LinkTimes times() const { return {}; }
  // Element [q] of rank q's `to_each`, for every q, in rank order (a collective, ranks values
  // each way): the sizes of the parcels a rebuild sends, so each receiver posts them. By
  // default from an all_gather.
  virtual std::vector<std::uint64_t> all_to_all(const std::vector<std::uint64_t>& to_each) const {
    std::vector<char> mine;
    append_values(mine, to_each);
    std::vector<std::uint64_t> from(ranks());
    const std::vector<std::vector<char>> all = all_gather(mine);
    for (int q = 0; q < ranks(); ++q)
      std::memcpy(&from[q], all[q].data() + rank() * sizeof(std::uint64_t), sizeof(std::uint64_t));
    return from;
  }
  // The sum over the ranks of each element of `mine`, on every rank (a collective; integers:
  // exact in any order). By default from an all_gather.
  virtual std::vector<std::uint64_t> sum(const std::vector<std::uint64_t>& mine) const {
    std::vector<char> bytes;
    append_values(bytes, mine);
    std::vector<std::uint64_t> total(mine.size(), 0), one(mine.size());
    for (const std::vector<char>& from : all_gather(bytes)) {
      std::memcpy(one.data(), from.data(), from.size());
      for (std::size_t k = 0; k < total.size(); ++k) total[k] += one[k];
    }
    return total;
  }

  // Sends each non-empty parcel of `out` to its rank and returns the parcels sent to this
  // rank, in rank order: their sizes first (all_to_all), then point to point (a collective).
  std::vector<Parcel> deliver(std::vector<Parcel> out) const {
    std::erase_if(out, [](const Parcel& p) { return p.bytes.empty(); });
    std::vector<std::uint64_t> size(ranks(), 0);
    for (const Parcel& p : out) size[p.rank] = p.bytes.size();
    const std::vector<std::uint64_t> incoming = all_to_all(size);
    std::vector<Parcel> in;
    for (int q = 0; q < ranks(); ++q)
      if (incoming[q]) in.push_back({q, std::vector<char>(incoming[q])});
    exchange(out, in);
    return in;
  }

  // True on every rank when it is true on some rank (one reduction).
  bool any(bool mine) const { return sum({std::uint64_t(mine)}).at(0) > 0; }

 private:
  static void append_values(std::vector<char>& bytes, const std::vector<std::uint64_t>& values) {
    bytes.resize(values.size() * sizeof(std::uint64_t));
    if (!values.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  }
};

// Runs `task` on this rank, then, if it threw on some rank, throws Error (RunError, or
// InputError for a file read) on every rank with the lowest failing rank's message: no rank
// waits in a later collective for one that stopped (a collective: a file a rank could not
// write stops the run as one process's would).
template <class Error = RunError, class Task>
void on_every_rank(const RankLink& link, Task&& task) {
  std::string error;
  try {
    task();
  } catch (const std::exception& e) {
    error = e.what();
    if (error.empty()) error = "rank " + std::to_string(link.rank()) + " failed";
  }
  for (const std::vector<char>& from : link.all_gather(std::vector<char>(error.begin(), error.end())))
    if (!from.empty()) throw Error(std::string(from.begin(), from.end()));
}

// A record as bytes, for all_gather: plain data with no pointer (Eigen's fixed-size
// vectors and quaternions copy bit for bit, though C++ does not call them trivially copyable).
template <class T>
void append_record(std::vector<char>& bytes, const T& record) {
  static_assert(std::is_standard_layout_v<T> && !std::is_polymorphic_v<T>);
  const std::size_t at = bytes.size();
  bytes.resize(at + sizeof(T));
  std::memcpy(bytes.data() + at, static_cast<const void*>(&record), sizeof(T));
}

// Sections of records, so one gather carries several kinds: a count, then the records.
template <class T>
void append_section(std::vector<char>& bytes, const std::vector<T>& records) {
  append_record(bytes, std::uint64_t(records.size()));
  for (const T& r : records) append_record(bytes, r);
}

// Reads the section at `at` of one rank's bytes and moves `at` past it.
template <class T>
std::vector<T> read_section(const std::vector<char>& bytes, std::size_t& at) {
  std::uint64_t n = 0;
  std::memcpy(&n, bytes.data() + at, sizeof(n));
  at += sizeof(n);
  std::vector<T> records(n);
  if (n) std::memcpy(static_cast<void*>(records.data()), bytes.data() + at, n * sizeof(T));
  at += n * sizeof(T);
  return records;
}

}  // namespace polydem
