#include "sim/thread_governor.hpp"

#include <algorithm>

namespace polydem {

namespace {

constexpr double kWindowSeconds = 0.05;     // s, long enough to hold several Verlet rebuilds
constexpr std::int64_t kMinWindowSteps = 8;
constexpr int kMinHold = 8;                 // windows after a switch before the next probe
constexpr int kMaxHold = 1200;              // ~60 s: the longest a run misses a freed core
constexpr double kProbeShare = 0.01;        // a losing probe costs at most this share of the hold after it
constexpr double kSwitchMargin = 0.92;      // a probe must be 8% faster: noise does not flip it
constexpr double kSlowdown = 1.5;           // a held count this much slower than when chosen: probe now
constexpr double kHopeless = 4.0;           // a probe this much slower per step ends at once (a busy machine)

}  // namespace

ThreadGovernor::ThreadGovernor(int max_threads, bool adapt)
    // Starts on one thread and tries more after one window: on a busy machine a step at 2
    // threads took 100 times one at 1 here, so the run does not open with a window of them.
    : max_(std::max(max_threads, 1)), adapt_(adapt && max_ > 1), current_(adapt_ ? 1 : max_), held_(current_),
      hold_windows_(kMinHold), windows_left_(1), steps_at_(std::size_t(max_) + 1, 0) {}

int ThreadGovernor::after_step(double now) {
  ++steps_at_[std::size_t(current_)];
  if (!adapt_) return current_;
  if (window_start_ < 0.0) {  // the first call opens the first window
    window_start_ = now;
    return current_;
  }
  ++window_steps_;
  const double elapsed = now - window_start_;
  const bool hopeless = probing_ && elapsed > kHopeless * held_cost_ * double(window_steps_);
  if (!hopeless && (elapsed < kWindowSeconds || window_steps_ < kMinWindowSteps)) return current_;
  end_window(elapsed, window_steps_);
  window_start_ = now;
  window_steps_ = 0;
  return current_;
}

void ThreadGovernor::end_window(double seconds, std::int64_t steps) {
  const double seconds_per_step = seconds / double(steps);
  if (probing_) {
    probing_ = false;
    if (seconds_per_step < kSwitchMargin * held_cost_) {
      held_ = current_;
      hold_windows_ = kMinHold;
    } else {  // the probe's extra time is at most kProbeShare of the hold that follows
      current_ = held_;
      const double lost = seconds - held_cost_ * double(steps);  // s
      const int fair = int(std::min(lost / (kProbeShare * kWindowSeconds), double(kMaxHold)));
      hold_windows_ = std::min(std::max(2 * hold_windows_, fair), kMaxHold);
    }
    windows_left_ = hold_windows_;
    chosen_cost_ = 0.0;
    return;
  }
  held_cost_ = seconds_per_step;
  if (chosen_cost_ <= 0.0) chosen_cost_ = seconds_per_step;
  const bool slowed = seconds_per_step > kSlowdown * chosen_cost_;  // the machine got busier: ask again now
  if (slowed) hold_windows_ = kMinHold;
  if (--windows_left_ > 0 && !slowed) return;
  probing_ = true;
  held_ = current_;
  current_ = candidate();
  probe_down_ = !probe_down_;
}

int ThreadGovernor::candidate() const {
  const int down = std::max(current_ / 2, 1), up = std::min(2 * current_, max_);
  if (current_ == 1) return up;
  if (current_ == max_) return down;
  return probe_down_ ? down : up;
}

}  // namespace polydem
