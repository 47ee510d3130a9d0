// The thread governor against a model machine: a fake clock advanced by a given cost per step
// at each thread count, so its choices are checked without timing anything.
#include <catch2/catch.hpp>

#include <functional>
#include <random>

#include "sim/thread_governor.hpp"

using namespace polydem;

namespace {

// s per step at `threads` threads, at step `step`
using CostModel = std::function<double(int threads, long step)>;

struct Outcome {
  double seconds = 0.0;                // the run's modelled wall time
  std::vector<long> steps_at;          // steps at each thread count
  std::vector<int> threads;            // count used at each step
};

Outcome run(int max_threads, long steps, const CostModel& cost) {
  ThreadGovernor g(max_threads, true);
  Outcome o;
  o.steps_at.assign(std::size_t(max_threads) + 1, 0);
  int threads = g.threads();
  for (long s = 0; s < steps; ++s) {
    o.threads.push_back(threads);
    ++o.steps_at[std::size_t(threads)];
    o.seconds += cost(threads, s);
    threads = g.after_step(o.seconds);
  }
  return o;
}

// The best a clairvoyant choice could do, step by step.
double best_seconds(int max_threads, long steps, const CostModel& cost) {
  double total = 0.0;
  for (long s = 0; s < steps; ++s) {
    double best = cost(1, s);
    for (int t = 2; t <= max_threads; ++t) best = std::min(best, cost(t, s));
    total += best;
  }
  return total;
}

}  // namespace

TEST_CASE("thread governor: on an idle machine 2 threads stay, the probes cost under 2%", "[governor]") {
  const CostModel idle = [](int t, long) { return t == 2 ? 0.6e-3 : 1.0e-3; };  // s per step
  const long steps = 40000;                                                      // 24 s of stepping
  const Outcome o = run(2, steps, idle);
  CHECK(o.steps_at[2] > 0.97 * steps);
  CHECK(o.seconds < 1.02 * best_seconds(2, steps, idle));
  CHECK(o.seconds < 0.65 * best_seconds(1, steps, idle));  // far better than one thread
}

TEST_CASE("thread governor: on a busy machine where 2 threads wait on each other, 1 thread runs", "[governor]") {
  const CostModel busy = [](int t, long) { return t == 2 ? 5.0e-3 : 1.0e-3; };  // 2 threads 5x slower
  const long steps = 20000;
  const Outcome o = run(2, steps, busy);
  CHECK(o.steps_at[1] > 0.97 * steps);
  CHECK(o.seconds < 1.1 * best_seconds(2, steps, busy));
}

TEST_CASE("thread governor: a probe 30 times slower ends after one step", "[governor]") {
  // What 2 threads did here with three builds running: 28-58 ms a step against 1.4 at 1 thread.
  const CostModel crowded = [](int t, long) { return t == 2 ? 40.0e-3 : 1.4e-3; };
  const long steps = 20000;  // 28 s at 1 thread
  const Outcome o = run(2, steps, crowded);
  CHECK(o.steps_at[2] < 10);  // one step per probe
  CHECK(o.seconds < 1.05 * best_seconds(2, steps, crowded));
}

TEST_CASE("thread governor: follows the machine when another job starts and stops", "[governor]") {
  // 2 threads win until step 20,000, lose 4-fold until 40,000, win again after.
  const CostModel shifting = [](int t, long s) {
    const bool busy = s >= 20000 && s < 40000;
    return t == 1 ? 1.0e-3 : (busy ? 4.0e-3 : 0.6e-3);
  };
  const long steps = 60000;
  const Outcome o = run(2, steps, shifting);
  long late_two = 0;  // steps still at 2 threads after the job started: within a few windows
  for (long s = 20000; s < 40000; ++s) late_two += o.threads[std::size_t(s)] == 2;
  CHECK(late_two < 200);
  long back_to_two = 40000;  // the first step at 2 threads after the job ended
  while (back_to_two < steps && o.threads[std::size_t(back_to_two)] != 2) ++back_to_two;
  CHECK(back_to_two < 40000 + 8000);  // within one longest hold (128 windows of 50 ms at 1 ms)
  CHECK(o.seconds < 1.1 * best_seconds(2, steps, shifting));
}

TEST_CASE("thread governor: equal costs with noise neither flap nor lose time", "[governor]") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> noise(0.9, 1.1);
  std::vector<double> factor(30000);
  for (double& f : factor) f = noise(rng);
  const CostModel flat = [&](int, long s) { return 1.0e-3 * factor[std::size_t(s)]; };
  const Outcome o = run(2, long(factor.size()), flat);
  int switches = 0;
  for (std::size_t s = 1; s < o.threads.size(); ++s) switches += o.threads[s] != o.threads[s - 1];
  CHECK(switches < 40);  // probes only: two switches each, at most every 8 windows
  CHECK(o.seconds < 1.01 * best_seconds(2, long(factor.size()), flat));
}

TEST_CASE("thread governor: with 4 threads allowed it finds the fastest count by halving and doubling",
          "[governor]") {
  const CostModel knee = [](int t, long) { return t == 1 ? 1.0e-3 : t == 2 ? 0.55e-3 : t == 3 ? 0.5e-3 : 0.9e-3; };
  const long steps = 40000;
  const Outcome o = run(4, steps, knee);
  CHECK(o.steps_at[2] > 0.9 * steps);  // 4 loses to 2; 3 is never a candidate from 2 or 4
  CHECK(o.steps_at[4] < 0.02 * steps);
}

TEST_CASE("thread governor: one thread allowed, nothing to choose", "[governor]") {
  const Outcome o = run(1, 1000, [](int, long) { return 1e-3; });
  CHECK(o.steps_at[1] == 1000);
}
