// The cut of a distributed run at a rebuild (issue 20): the loads of the kept cut summed over
// the ranks (a value per rank), and a cut again from a sample of the owned bodies' centres
// when they are unbalanced. The cut decides only who computes what: never the bits.
#include <algorithm>
#include <cmath>
#include <ctime>

#include "sim/rank_contacts.hpp"

namespace polydem {

namespace {

Vec3 get(const double in[3]) { return {in[0], in[1], in[2]}; }
void put(double out[3], const Vec3& v) { out[0] = v.x(); out[1] = v.y(); out[2] = v.z(); }

// A point of the sample a cut is made from: a centre and the weight it stands for.
struct CutPoint {
  double x[3];  // m
  double weight;
};

}  // namespace

// Each owned body's weight from the lists of the interval ending now (this rank counted them),
// in instructions a step (CutWeight): its passes by rotation path, its pairs' candidate feature
// pairs and their sub-contacts at the last step.
std::vector<std::uint64_t> RankContacts::owned_weights(const std::vector<std::uint32_t>& rows) const {
  const std::vector<float> passes = pass_weights(owned_rotors_, store_.size());  // by local index
  const OwnedWork work = owned_work(engine_->body_pairs(), engine_->driver_pairs(), store_);
  std::vector<std::uint64_t> w(rows.size());
  for (std::size_t k = 0; k < w.size(); ++k) w[k] = CutWeight::of(passes[rows[k]], work.candidates[k], work.contacts[k]);
  return w;
}

// Each part's load under cut_ at the owned bodies' centres now (their store rows `rows`), summed over the ranks (exact: integers).
std::vector<double> RankContacts::summed_loads(const std::vector<std::uint32_t>& rows,
                                              const std::vector<std::uint64_t>& w) const {
  std::vector<std::uint64_t> mine(link_.ranks(), 0);
  for (std::size_t k = 0; k < w.size(); ++k) mine[cut_.owner(store_.position[rows[k]])] += w[k];
  const std::vector<std::uint64_t> all = link_.sum(mine);
  return std::vector<double>(all.begin(), all.end());
}

// Keeps the cut until its imbalance over the steps since the last cut has cost more than a new
// cut (recut_: the loads and steps are the same on every rank, so is the decision); then cuts
// again from a sample of the owned bodies (cut_sample).
void RankContacts::recut_if_unbalanced(const std::vector<std::uint32_t>& rows) {
  std::vector<std::uint64_t> w = owned_weights(rows);
  scale_ = measure_time(w);
  for (std::uint64_t& x : w) x = x * scale_ / kScaleOne;
  std::vector<double> loads = summed_loads(rows, w);
  if (recut_.pays(loads, steps_listed_, kCutCost * double(n_bodies_))) {
    cut_from_sample(rows, w);
    loads = summed_loads(rows, w);
  }
  set_load_share(loads);
}

// A cut of every rank's sample (cut_sample) of its owned bodies at store rows `rows`, weighing `w`.
void RankContacts::cut_from_sample(const std::vector<std::uint32_t>& rows, const std::vector<std::uint64_t>& w) {
  std::vector<Vec3> x;
  std::vector<double> weight;
  for (const std::vector<char>& from : link_.all_gather(cut_sample(rows, w))) {
    std::size_t at = 0;
    for (const CutPoint& c : read_section<CutPoint>(from, at)) {
      x.push_back(get(c.x));
      weight.push_back(c.weight);
    }
  }
  cut_ = cut_domain(x, weight, link_.ranks());
  recut_.cut();
  ++cuts_;
}

// The owned bodies as runs of consecutive ones (increasing id), each at its first body's
// centre with the run's weight: at most kCutSample points over all ranks (at least
// kCutSampleRank a rank), every body itself while they are fewer.
std::vector<char> RankContacts::cut_sample(const std::vector<std::uint32_t>& rows,
                                          const std::vector<std::uint64_t>& w) const {
  const std::size_t n = rows.size();
  const std::size_t most = std::max<std::size_t>(kCutSampleRank, kCutSample / std::size_t(link_.ranks()));
  const std::size_t run = (n + most - 1) / std::max<std::size_t>(most, 1);  // bodies a point stands for
  std::vector<CutPoint> points;
  for (std::size_t k = 0; k < n; k += run) {
    CutPoint c{};
    put(c.x, store_.position[rows[k]]);
    for (std::size_t m = k; m < std::min(n, k + run); ++m) c.weight += double(w[m]);
    points.push_back(c);
  }
  std::vector<char> bytes;
  append_section(bytes, points);
  return bytes;
}

void RankContacts::set_load_share(const std::vector<double>& loads) {
  double total = 0.0;
  for (double l : loads) total += l;
  load_share_ = total > 0.0 ? loads[link_.rank()] / total : 0.0;
}

// The interval since the last rebuild: this rank's seconds over the instructions its bodies'
// counted weights `w` (the interval's owned bodies) gave, smoothed; returns this rank's scale
// (kScaleOne: no time on some rank yet). The ranks' mean is summed in fixed point
// (attoseconds an instruction: exact), one reduction, only where a clock is set (time_by:
// the same on every rank).
std::uint64_t RankContacts::measure_time(const std::vector<std::uint64_t>& w) {
  if (!busy_) return kScaleOne;
  std::uint64_t step = 0;  // instructions a step
  for (std::uint64_t x : w) step += x;
  const double counted = double(step) * double(steps_listed_);
  counted_done_ += counted;
  const double now = busy_();  // s
  if (busy_mark_ >= 0.0 && counted > 0.0 && now > busy_mark_) {
    const double unit = (now - busy_mark_) / counted;  // s an instruction
    unit_ = unit_ > 0.0 ? unit_ + kTimeSmoothing * (unit - unit_) : unit;
  }
  busy_mark_ = now;
  const auto mine = std::uint64_t(std::llround(unit_ * 1e18));
  const std::vector<std::uint64_t> all = link_.sum({mine, std::uint64_t(mine > 0)});
  if (mine == 0 || all[1] < std::uint64_t(link_.ranks())) return kScaleOne;
  const double mean = double(all[0]) / double(link_.ranks());
  const auto scale = std::uint64_t(std::llround(double(kScaleOne) * double(mine) / mean));
  return std::clamp(scale, kScaleOne / 4, kScaleOne * 4);
}

// The process's CPU seconds less those inside the link's calls (a waiting rank polls): the wall
// clock less the waits counted the seconds a loaded machine gave other processes too (at load
// 12 on 2 cores, 80 cuts in 283 rebuilds of the box-fill pour at -np 2, against 10 counted).
void RankContacts::time_by_clock() {
  time_by([this] {
    const LinkTimes t = link_.times();
    double waited = 0.0;  // s
    for (double s : t.cpu) waited += s;
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return double(now.tv_sec) + 1e-9 * double(now.tv_nsec) - waited;
  });
}

}  // namespace polydem
