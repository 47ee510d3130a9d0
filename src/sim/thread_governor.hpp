#pragma once
// Chooses how many of the allowed threads the step uses, by measuring. Threads meet at every
// parallel loop of a step; on a shared machine a thread that loses its core holds the other
// at each meeting, and 2 threads ran 5-40 times slower than 1 here. Results do not depend on
// the thread count, so the governor changes no bit, only the speed.
#include <cstdint>
#include <vector>

namespace polydem {

class ThreadGovernor {
 public:
  // adapt false (or max_threads 1): nothing to choose, every call returns max_threads.
  ThreadGovernor(int max_threads, bool adapt);

  // Called after each step with the wall time spent stepping so far (s; output apart);
  // returns the thread count for the next step.
  int after_step(double now);

  int threads() const { return current_; }
  // Steps run at each count, index = threads (for the run's summary line).
  const std::vector<std::int64_t>& steps_at() const { return steps_at_; }

 private:
  void end_window(double seconds, std::int64_t steps);
  int candidate() const;

  int max_;
  bool adapt_;
  int current_, held_;              // held_: count to return to after a probe
  bool probing_ = false;
  bool probe_down_ = true;          // alternate halving and doubling when both are possible
  int hold_windows_;                // windows at the chosen count before the next probe
  int windows_left_;
  double held_cost_ = 0.0;          // s per step at held_, in its last window
  double chosen_cost_ = 0.0;        // s per step in the first window after the last probe
  double window_start_ = -1.0;      // s; < 0: no window open
  std::int64_t window_steps_ = 0;
  std::vector<std::int64_t> steps_at_;
};

}  // namespace polydem
