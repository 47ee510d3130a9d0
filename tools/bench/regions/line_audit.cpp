// Which cache lines cross the two cores in a step (issue 19): GCC's thread-sanitizer hooks
// (-fsanitize=thread, no libtsan linked) implemented here, compiled without them. Each thread
// keeps the 64-byte lines it reads and writes per stage of the step (line_audit.hpp); at the
// step's end the stages are replayed in order against each line's holders and last writer:
//   fetch    a thread touches a line the other thread wrote last, with no copy of its own since
//            (the line comes from the other core's cache: ~266 ns here, stops.txt #19);
//   upgrade  a thread writes a line the other one holds clean (an invalidation round trip);
//   true / false sharing  both threads touch a line in the same stretch between barriers, one
//            writing bytes the other reads or writes (true) or only other bytes (false).
// Per array (audit::name), per step; steps with a rebuild apart. Written to stderr at exit, or
// to $POLYDEM_LINE_AUDIT_OUT. A model: no evictions (2 MB of L2 a core holds the pour).
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "polydem/line_audit.hpp"

namespace polydem::audit {
namespace {

constexpr int kThreads = 2;  // the two cores; a third thread's accesses count as thread 1's
struct Masks {
  std::uint64_t read = 0, write = 0;  // bytes of the line
};
using Lines = std::unordered_map<std::uint64_t, Masks>;

std::atomic<bool> g_on{false};      // recording (from the first mark until exit)
std::atomic<int> g_serial{kSerial};  // the serial code's stage (thread 0 sets it)
Lines g_lines[kThreads][kStages];    // each thread writes its own row only
const void* g_stack[kThreads] = {};  // an address on each thread's stack
thread_local int t_index = -1, t_stage = kNone;
thread_local std::uint64_t t_last_line = ~0ull, t_last_read = 0, t_last_write = 0;
thread_local int t_last_stage = -1;

int index() {
  if (t_index < 0) t_index = std::min(omp_get_thread_num(), kThreads - 1);
  return t_index;
}

void record(const void* p, std::size_t bytes, bool write) {
  if (!g_on.load(std::memory_order_relaxed)) return;
  const int stage = t_stage != kNone ? t_stage : g_serial.load(std::memory_order_relaxed);
  std::uint64_t a = std::uint64_t(p);
  const std::uint64_t end = a + bytes;
  while (a < end) {
    const std::uint64_t line = a >> 6, stop = std::min(end, (line + 1) << 6);
    const unsigned lo = unsigned(a & 63), n = unsigned(stop - a);
    const std::uint64_t mask = (n == 64 ? ~0ull : ((1ull << n) - 1)) << lo;
    if (line == t_last_line && stage == t_last_stage && !(mask & ~(write ? t_last_write : t_last_read))) {
      a = stop;
      continue;
    }
    Masks& m = g_lines[index()][stage][line];
    (write ? m.write : m.read) |= mask;
    t_last_line = line, t_last_stage = stage, t_last_read = m.read, t_last_write = m.write;
    a = stop;
  }
}

// The step's named arrays.
struct Range {
  std::uint64_t lo, hi;  // bytes [lo, hi)
  int name;
};
std::vector<Range> g_ranges;
std::map<std::string, int> g_name_index;
std::vector<std::string> g_names;

int name_of(const std::string& s) {
  auto [it, fresh] = g_name_index.emplace(s, int(g_names.size()));
  if (fresh) g_names.push_back(s);
  return it->second;
}

int line_name(std::uint64_t line) {
  const std::uint64_t lo = line << 6, hi = lo + 64;
  auto it = std::upper_bound(g_ranges.begin(), g_ranges.end(), hi, [](std::uint64_t a, const Range& r) { return a <= r.lo; });
  while (it != g_ranges.begin()) {  // the last range starting inside or before the line
    --it;
    if (it->hi > lo) return it->name;
    if (it->hi <= lo) break;
  }
  for (int t = 0; t < kThreads; ++t) {
    const std::int64_t d = std::int64_t(lo) - std::int64_t(std::uint64_t(g_stack[t]));
    if (g_stack[t] && d > -(1ll << 23) && d < (1ll << 23)) return name_of(t == 0 ? "(stack of thread 0)" : "(stack of thread 1)");
  }
  return name_of("(other)");
}

// Each line's holders and last writer across stages and steps.
struct Holder {
  std::uint8_t holders = 0;  // bit t: thread t has a valid copy
  std::int8_t writer = -1;   // the last writer: 0, 1, 2 (both in one stretch), -1 none yet
  std::uint8_t stage = 0;    // the last writer's stage
};
std::unordered_map<std::uint64_t, Holder> g_holder;

struct Count {
  double touched[kThreads] = {}, fetch[kThreads] = {}, upgrade[kThreads] = {};
  double from[kStages] = {};  // fetches by the writer's stage
};
struct Sharing {
  double true_lines = 0, false_lines = 0;
};
struct Tally {
  int steps = 0;
  std::map<std::pair<int, int>, Count> counts;       // (stage, name)
  std::map<std::pair<int, int>, Sharing> sharing;    // (first stage of the stretch, name)
};
Tally g_tally[2];  // steps without a rebuild, with one

const char* stage_name(int s) {
  static const char* names[kStages] = {"none", "passes", "serial", "rebuild", "walk", "driver_pairs", "kick", "close"};
  return names[s];
}

// The stretches between barriers, in step order.
const std::vector<std::vector<int>> kStretches = {{kPasses}, {kSerial}, {kRebuild}, {kWalk, kDriverPairs}, {kKick}, {kClose}};

void count_stretch(const std::vector<int>& stages, Tally& tally) {
  // Fetches and upgrades against the holders before the stretch.
  for (int s : stages)
    for (int t = 0; t < kThreads; ++t)
      for (const auto& [line, m] : g_lines[t][s]) {
        Count& c = tally.counts[{s, line_name(line)}];
        c.touched[t] += 1;
        auto it = g_holder.find(line);
        if (it == g_holder.end()) continue;
        const Holder& h = it->second;
        const bool mine = h.holders >> t & 1u;
        if (h.writer >= 0 && h.writer != t && !mine) {
          c.fetch[t] += 1;
          c.from[h.stage] += 1;
        } else if (m.write && (h.holders & ~(1u << t))) {
          c.upgrade[t] += 1;
        }
      }
  // Both threads in the stretch: true or false sharing.
  std::unordered_map<std::uint64_t, Masks> both[kThreads];
  for (int t = 0; t < kThreads; ++t)
    for (int s : stages)
      for (const auto& [line, m] : g_lines[t][s]) {
        Masks& b = both[t][line];
        b.read |= m.read, b.write |= m.write;
      }
  for (const auto& [line, m0] : both[0]) {
    auto it = both[1].find(line);
    if (it == both[1].end()) continue;
    const Masks& m1 = it->second;
    if (!(m0.write | m1.write)) continue;
    Sharing& sh = tally.sharing[{stages[0], line_name(line)}];
    if ((m0.write & (m1.read | m1.write)) | (m1.write & (m0.read | m0.write)))
      sh.true_lines += 1;
    else
      sh.false_lines += 1;
  }
  // The holders after the stretch.
  for (int t = 0; t < kThreads; ++t)
    for (const auto& [line, m] : both[t]) {
      Holder& h = g_holder[line];
      const bool other_wrote = [&] {
        auto o = both[1 - t].find(line);
        return o != both[1 - t].end() && o->second.write;
      }();
      if (m.write) {
        h.writer = other_wrote ? 2 : std::int8_t(t);
        h.holders = other_wrote ? 0 : std::uint8_t(1u << t);
        for (int s : stages)
          if (g_lines[t][s].count(line) && g_lines[t][s].at(line).write) h.stage = std::uint8_t(s);
      } else if (!other_wrote) {
        h.holders |= std::uint8_t(1u << t);
      }
    }
}

void report() {
  const char* path = std::getenv("POLYDEM_LINE_AUDIT_OUT");
  FILE* out = path ? std::fopen(path, "w") : stderr;
  if (!out) out = stderr;
  for (int r = 0; r < 2; ++r) {
    const Tally& tally = g_tally[r];
    if (!tally.steps) continue;
    const double n = tally.steps;
    std::fprintf(out, "== %s: %d steps; lines a step (64 B)\n", r ? "steps with a rebuild" : "steps without a rebuild", tally.steps);
    std::fprintf(out, "%-13s %-34s %9s %9s %8s %8s %8s %8s  %s\n", "stage", "array", "touch_t0", "touch_t1", "fetch_t0",
                 "fetch_t1", "upgr_t0", "upgr_t1", "fetched from (stage: lines)");
    for (const auto& [key, c] : tally.counts) {
      if (c.fetch[0] + c.fetch[1] + c.upgrade[0] + c.upgrade[1] < 0.05 * n) continue;
      std::string from;
      for (int s = 0; s < kStages; ++s)
        if (c.from[s] > 0) from += std::string(stage_name(s)) + ": " + std::to_string(c.from[s] / n).substr(0, 6) + " ";
      std::fprintf(out, "%-13s %-34s %9.1f %9.1f %8.2f %8.2f %8.2f %8.2f  %s\n", stage_name(key.first),
                   g_names[key.second].c_str(), c.touched[0] / n, c.touched[1] / n, c.fetch[0] / n, c.fetch[1] / n,
                   c.upgrade[0] / n, c.upgrade[1] / n, from.c_str());
    }
    double fetch_sum[kStages] = {};
    for (const auto& [key, c] : tally.counts) fetch_sum[key.first] += (c.fetch[0] + c.fetch[1] + c.upgrade[0] + c.upgrade[1]) / n;
    std::fprintf(out, "-- fetches + upgrades a step, by stage:");
    for (int s = 1; s < kStages; ++s) std::fprintf(out, " %s %.1f", stage_name(s), fetch_sum[s]);
    std::fprintf(out, "\n-- lines both threads touch in one stretch, one writing (a step): stretch array true false\n");
    for (const auto& [key, sh] : tally.sharing)
      std::fprintf(out, "%-13s %-34s %8.2f %8.2f\n", stage_name(key.first), g_names[key.second].c_str(), sh.true_lines / n,
                   sh.false_lines / n);
  }
  if (out != stderr) std::fclose(out);
}

void start() {
  static bool started = false;
  if (started) return;
  started = true;
  std::atexit([] {
    g_on = false;
    report();
  });
  g_on = true;
}

}  // namespace

void enter(int stage) {
  if (omp_get_thread_num() == 0) start();
  t_stage = stage;
  int local = 0;
  g_stack[index()] = &local;
}

void serial(int stage) {
  start();
  g_serial.store(stage, std::memory_order_relaxed);
}

void name(const void* data, std::size_t bytes, const char* what) {
  const std::uint64_t lo = std::uint64_t(data);
#pragma omp critical(polydem_line_audit)
  g_ranges.push_back({lo, lo + bytes, name_of(what)});
}

void step_end() {
  if (!g_on) return;
  g_on = false;
  std::sort(g_ranges.begin(), g_ranges.end(), [](const Range& a, const Range& b) { return a.lo < b.lo; });
  bool rebuilt = false;
  for (int t = 0; t < kThreads; ++t) rebuilt |= !g_lines[t][kRebuild].empty();
  Tally& tally = g_tally[rebuilt];
  ++tally.steps;
  for (const std::vector<int>& stretch : kStretches) count_stretch(stretch, tally);
  for (auto& row : g_lines)
    for (Lines& lines : row) lines.clear();
  g_ranges.clear();
  t_last_line = ~0ull;
  g_serial = kSerial;
  g_on = true;
}

}  // namespace polydem::audit

// GCC's thread-sanitizer entry points (what -fsanitize=thread calls), recording each access.
using polydem::audit::record;
extern "C" {
void __tsan_init() {}
void __tsan_func_entry(void*) {}
void __tsan_func_exit() {}
void __tsan_vptr_update(void**, void*) {}
void __tsan_vptr_read(void**) {}
#define POLYDEM_TSAN_SIZE(n)                                               \
  void __tsan_read##n(void* p) { record(p, n, false); }                    \
  void __tsan_write##n(void* p) { record(p, n, true); }                    \
  void __tsan_unaligned_read##n(const void* p) { record(p, n, false); }    \
  void __tsan_unaligned_write##n(void* p) { record(p, n, true); }          \
  void __tsan_volatile_read##n(void* p) { record(p, n, false); }           \
  void __tsan_volatile_write##n(void* p) { record(p, n, true); }
POLYDEM_TSAN_SIZE(1)
POLYDEM_TSAN_SIZE(2)
POLYDEM_TSAN_SIZE(4)
POLYDEM_TSAN_SIZE(8)
POLYDEM_TSAN_SIZE(16)
void __tsan_read_range(void* p, unsigned long n) { record(p, n, false); }
void __tsan_write_range(void* p, unsigned long n) { record(p, n, true); }
// The atomics polydem's code uses, done (sequentially consistent) and recorded.
#define POLYDEM_TSAN_ATOMIC(bits, T)                                                   \
  T __tsan_atomic##bits##_load(const volatile T* a, int) {                             \
    record((const void*)a, sizeof(T), false);                                          \
    return __atomic_load_n(a, __ATOMIC_SEQ_CST);                                       \
  }                                                                                    \
  void __tsan_atomic##bits##_store(volatile T* a, T v, int) {                          \
    record((const void*)a, sizeof(T), true);                                           \
    __atomic_store_n(a, v, __ATOMIC_SEQ_CST);                                          \
  }                                                                                    \
  T __tsan_atomic##bits##_exchange(volatile T* a, T v, int) {                          \
    record((const void*)a, sizeof(T), true);                                           \
    return __atomic_exchange_n(a, v, __ATOMIC_SEQ_CST);                                \
  }                                                                                    \
  T __tsan_atomic##bits##_fetch_add(volatile T* a, T v, int) {                         \
    record((const void*)a, sizeof(T), true);                                           \
    return __atomic_fetch_add(a, v, __ATOMIC_SEQ_CST);                                 \
  }
POLYDEM_TSAN_ATOMIC(8, unsigned char)
POLYDEM_TSAN_ATOMIC(32, unsigned int)
POLYDEM_TSAN_ATOMIC(64, unsigned long)
}
