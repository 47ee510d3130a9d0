#include "contact/pair_split.hpp"

#include <algorithm>

namespace polydem {

namespace {

// A trailed cut made again at most this often (split_pairs): the settled cubes' stays after 3.
constexpr int kTrailedCuts = 4;

// A contact's cost in pairs apart (the law and the contact search on top of the distance test):
// a pour's few contacts sit in its pile, so pairs counted alike left one thread twice the work.
constexpr double kContactWeight = 3.0;

double pair_weight(const std::vector<std::uint16_t>& touching, std::uint32_t k) {
  return 1.0 + (touching.empty() ? 0.0 : kContactWeight * touching[k]);
}

// Cuts at block boundaries so that chunk t's blocks weigh about shares[t] of all (empty: the same).
void cut_by_weight(const std::vector<double>& block_weight, const std::vector<double>& shares, int threads,
                   std::size_t n, std::size_t block_size, std::vector<std::uint32_t>& cut) {
  double total = 0.0;
  for (double w : block_weight) total += w;
  cut.assign(threads + 1, std::uint32_t(n));
  cut[0] = 0;
  double reached = 0.0, before = 0.0;  // the shares of the chunks before t
  std::size_t b = 0;
  for (int t = 1; t < threads; ++t) {
    before += shares.size() == std::size_t(threads) ? shares[t - 1] : 1.0 / threads;
    const double target = total * before;
    while (b < block_weight.size() && reached + 0.5 * block_weight[b] < target) reached += block_weight[b++];
    cut[t] = std::uint32_t(std::min(n, b * block_size));
  }
}

// Per body, the chunk of its first pair (-1: no pair): its home, where its sum begins.
std::vector<int> home_chunks(const std::vector<BodyPair>& pairs, std::size_t n_bodies, const std::vector<std::uint32_t>& cut) {
  std::vector<int> home(n_bodies, -1);
  int c = 0;
  for (std::uint32_t k = 0; k < pairs.size(); ++k) {
    while (k >= cut[c + 1]) ++c;
    for (std::uint32_t b : {pairs[k].i, pairs[k].j})
      if (home[b] < 0) home[b] = c;
  }
  return home;
}

// Per body, the block of its first pair as i (or of the next body's): where the body cut puts its passes.
std::vector<std::uint32_t> body_blocks(const std::vector<BodyPair>& pairs, std::size_t n_bodies, std::size_t block_size) {
  std::vector<std::uint32_t> block(pairs.empty() ? 0 : n_bodies);
  std::size_t k = 0;
  for (std::uint32_t b = 0; b < block.size(); ++b) {
    while (k < pairs.size() && pairs[k].i < b) ++k;
    block[b] = std::uint32_t(std::min(k, pairs.size() - 1) / block_size);
  }
  return block;
}

// Per block, the bodies' other work (`body_weight`), each body's in its block (body_blocks).
std::vector<double> body_weights(const std::vector<BodyPair>& pairs, const std::vector<float>& body_weight,
                                 const std::vector<std::uint32_t>& block, std::size_t block_size) {
  std::vector<double> weight((pairs.size() + block_size - 1) / block_size, 0.0);
  for (std::uint32_t b = 0; b < std::min(body_weight.size(), block.size()); ++b) weight[block[b]] += body_weight[b];
  return weight;
}

// A cut's crossing work added where it runs: each foreign pair's (its walk's block) and each late
// term's (its body's passes' block, in `bodies`: not walk work).
void add_crossing(const std::vector<BodyPair>& pairs, const std::vector<int>& home, const std::vector<std::uint32_t>& cut,
                  const std::vector<std::uint32_t>& block, std::size_t block_size, CrossWeights cross,
                  std::vector<double>& walk, std::vector<double>& bodies) {
  int c = 0;
  for (std::uint32_t k = 0; k < pairs.size(); ++k) {
    while (k >= cut[c + 1]) ++c;
    const bool home_i = home[pairs[k].i] == c, home_j = home[pairs[k].j] == c;
    if (home_i && home_j) continue;
    walk[k / block_size] += cross.foreign;
    for (std::uint32_t b : {pairs[k].i, pairs[k].j})
      if (home[b] != c) bodies[block[b]] += cross.late;
  }
}

// Per block + 1, one past the largest body of the pairs before it (j > i): what a cut there leaves read.
std::vector<std::uint32_t> reads_below(const std::vector<BodyPair>& pairs, std::size_t block_size) {
  std::vector<std::uint32_t> below((pairs.size() + block_size - 1) / block_size + 1, 0);
  for (std::size_t k = 0; k < pairs.size(); ++k)
    below[k / block_size + 1] = std::max(below[k / block_size + 1], pairs[k].j + 1);
  for (std::size_t b = 1; b < below.size(); ++b) below[b] = std::max(below[b], below[b - 1]);
  return below;
}

// Each chunk's bodies (body_cut) and its first body no earlier chunk's pair reads (trail_from).
void cut_bodies(const std::vector<BodyPair>& pairs, const std::vector<std::uint32_t>& below, std::size_t n_bodies,
                int threads, std::size_t block_size, PairSplit& split) {
  const std::size_t n = pairs.size();
  split.body_cut.assign(threads + 1, std::uint32_t(n_bodies));
  for (int t = 0; t < threads; ++t)  // no pairs: even shares
    split.body_cut[t] = n == 0 ? std::uint32_t(n_bodies * t / threads) : t == 0 ? 0 : split.cut[t] < n ? pairs[split.cut[t]].i : n_bodies;
  split.trail_from.assign(threads + 1, std::uint32_t(n_bodies));
  split.trail_from[0] = split.body_cut[0];  // no pair before chunk 0 (one thread: `below` empty)
  for (int t = 1; t < threads; ++t)  // a cut falls at a block's start or the list's end
    split.trail_from[t] = std::max(split.body_cut[t], below[(split.cut[t] + block_size - 1) / block_size]);
}

// `body_weight` less the trailing pass (`trailed` each) of the bodies an earlier chunk reads (from
// body_cut[t] to trail_from[t]): it leaves them to the next step's first region, shared evenly there
// (WalkTrail); their driver pairs stay with their chunk.
std::vector<float> trailed_weights(const std::vector<float>& body_weight, double trailed, const PairSplit& split) {
  std::vector<float> moved = body_weight;
  for (int t = 1; t < split.threads; ++t)
    for (std::size_t b = split.body_cut[t]; b < std::min<std::size_t>(split.trail_from[t], moved.size()); ++b)
      moved[b] = float(std::max(0.0, moved[b] - trailed));
  return moved;
}

// Per block, its walk's weight (`walk`: its pairs and crossing work) and its bodies' (`bodies`).
struct BlockWeights {
  std::vector<double> walk, bodies;
  std::vector<double> sum() const {
    std::vector<double> all = walk;
    for (std::size_t b = 0; b < all.size(); ++b) all[b] += bodies[b];
    return all;
  }
};

}  // namespace

void split_pairs(const std::vector<BodyPair>& pairs, const std::vector<std::uint16_t>& touching,
                 const std::vector<float>& body_weight, std::size_t n_bodies, int threads, PairSplit& split,
                 const std::vector<double>& shares, CrossWeights cross, std::size_t block_size, double trailed) {
  const std::size_t n = pairs.size();
  split.threads = threads;
  // A late term is added where its body is moved: a trailed cut's all by the next step's first
  // region (its body is read by an earlier chunk), none behind the walk.
  if (trailed > 0.0) cross.late = 0.0;
  const std::vector<std::uint32_t> block = body_blocks(pairs, n_bodies, block_size);
  BlockWeights w{std::vector<double>((n + block_size - 1) / block_size, 0.0), body_weights(pairs, body_weight, block, block_size)};
  for (std::uint32_t k = 0; k < n; ++k) w.walk[k / block_size] += pair_weight(touching, k);  // each by its chunk's thread
  cut_by_weight(w.sum(), shares, threads, n, block_size, split.cut);
  if (threads > 1 && (cross.foreign > 0.0 || cross.late > 0.0)) {  // once more, with this cut's crossing work
    add_crossing(pairs, home_chunks(pairs, n_bodies, split.cut), split.cut, block, block_size, cross, w.walk, w.bodies);
    cut_by_weight(w.sum(), shares, threads, n, block_size, split.cut);
  }
  const std::vector<std::uint32_t> below = threads > 1 ? reads_below(pairs, block_size) : std::vector<std::uint32_t>{};
  // Trailed: again without the passes the last cut leaves to the next step, until the cut stays
  // (the bodies left move with it).
  for (int again = 0; trailed > 0.0 && threads > 1 && again < kTrailedCuts; ++again) {
    const std::vector<std::uint32_t> last = split.cut;
    cut_bodies(pairs, below, n_bodies, threads, block_size, split);
    w.bodies = body_weights(pairs, trailed_weights(body_weight, trailed, split), block, block_size);
    cut_by_weight(w.sum(), shares, threads, n, block_size, split.cut);
    if (split.cut == last) break;
  }
  const std::vector<int> home = home_chunks(pairs, n_bodies, split.cut);
  split.walk_weight.assign(threads, 0.0);
  for (int t = 0; t < threads; ++t)
    for (std::size_t b = split.cut[t] / block_size; b * block_size < split.cut[t + 1]; ++b)
      split.walk_weight[t] += w.walk[b] + (trailed > 0.0 ? w.bodies[b] : 0.0);  // trailed: timed with the walk
  cut_bodies(pairs, below, n_bodies, threads, block_size, split);
  // The foreign pairs, with the side (if any) homed in their own chunk.
  split.foreign.clear();
  split.foreign_side.clear();
  split.foreign_begin.assign(threads + 1, 0);
  int c = 0;
  for (std::uint32_t k = 0; k < n; ++k) {
    while (k >= split.cut[c + 1]) ++c;
    const bool home_i = home[pairs[k].i] == c, home_j = home[pairs[k].j] == c;
    if (home_i && home_j) continue;
    split.foreign.push_back(k);
    split.foreign_side.push_back(std::uint8_t(home_i | home_j << 1));
    ++split.foreign_begin[c + 1];
  }
  for (int t = 0; t < threads; ++t) split.foreign_begin[t + 1] += split.foreign_begin[t];
  split.foreign.push_back(std::uint32_t(n));
  // The bodies by home chunk, in id order within one.
  split.home_begin.assign(threads + 1, 0);
  for (int h : home)
    if (h >= 0) ++split.home_begin[h + 1];
  for (int t = 0; t < threads; ++t) split.home_begin[t + 1] += split.home_begin[t];
  split.homes.resize(split.home_begin[threads]);
  std::vector<std::uint32_t> fill(split.home_begin.begin(), split.home_begin.end() - 1);
  for (std::uint32_t b = 0; b < n_bodies; ++b)
    if (home[b] >= 0) split.homes[fill[home[b]]++] = b;
  // Each body's pairs after its home chunk (all foreign), in increasing order: its late terms.
  split.late_begin.assign(n_bodies + 1, 0);
  auto for_each_late = [&](auto add) {
    for (std::uint32_t f = 0; f < split.foreign_side.size(); ++f) {
      const BodyPair p = pairs[split.foreign[f]];
      if (!(split.foreign_side[f] & 1u)) add(p.i, f << 1);
      if (!(split.foreign_side[f] & 2u)) add(p.j, f << 1 | 1u);
    }
  };
  for_each_late([&](std::uint32_t b, std::uint32_t) { ++split.late_begin[b + 1]; });
  for (std::size_t b = 0; b < n_bodies; ++b) split.late_begin[b + 1] += split.late_begin[b];
  split.late.resize(split.late_begin.back());
  fill.assign(split.late_begin.begin(), split.late_begin.end() - 1);
  for_each_late([&](std::uint32_t b, std::uint32_t entry) { split.late[fill[b]++] = entry; });
}

std::vector<double> paced_shares(const PairSplit& split, const std::vector<ThreadPace>& pace,
                                 const std::vector<double>& shares) {
  constexpr std::uint32_t kFewest = 32;  // steps timed: fewer say nothing past one step's noise
  const std::size_t threads = pace.size();
  if (threads < 2 || split.walk_weight.size() != threads) return shares;
  std::vector<double> speed(threads);
  double all = 0.0;
  for (std::size_t t = 0; t < threads; ++t) {
    const std::uint32_t steps = std::min(pace[t].steps, ThreadPace::kSteps);
    if (steps < kFewest || split.walk_weight[t] <= 0.0) return shares;
    std::array<float, ThreadPace::kSteps> s = pace[t].seconds;
    std::nth_element(s.begin(), s.begin() + steps / 2, s.begin() + steps);
    if (!(s[steps / 2] > 0.0f)) return shares;
    all += speed[t] = split.walk_weight[t] / s[steps / 2];
  }
  std::vector<double> next(threads);
  double sum = 0.0;
  for (std::size_t t = 0; t < threads; ++t) {
    const double even = 1.0 / threads, last = shares.size() == threads ? shares[t] : even;
    sum += next[t] = std::clamp(0.5 * (last + speed[t] / all), 0.5 * even, 1.5 * even);
  }
  for (double& s : next) s /= sum;
  return next;
}

void DirectSums::cut(const PairList& list, int threads) {
  if (follow_pace) shares = paced_shares(split, pace, shares);
  if (shares.size() != std::size_t(threads)) shares.clear();  // another team: even shares
  split_pairs(list.pairs, list.touching, body_weight, sums.size(), threads, split, shares, cross, list.block, trailed);
  foreign.resize(split.foreign_side.size());
  pace.assign(threads > 1 ? threads : 0, ThreadPace{});
  const bool on = !zero.empty() && zero[0].on;  // the flags agree between loops
  zero.assign(threads, SumsZero{on});
}

}  // namespace polydem
