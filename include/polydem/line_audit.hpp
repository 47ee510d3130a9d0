#pragma once
// Which cache lines cross the two cores in a step (issue 19). Built with -DPOLYDEM_LINE_AUDIT=ON
// (a folder of its own: tools/bench/regions/line_audit.sh), every load and store of polydem's
// code calls GCC's thread-sanitizer hooks, which tools/bench/regions/line_audit.cpp implements:
// each thread's lines are kept per stage of the step and counted at its end. Otherwise these
// marks are empty and cost nothing.
#include <cstddef>

namespace polydem::audit {

// The stages of a step, in the order they run (kSerial: thread 0 outside the regions).
enum Stage : int { kNone = 0, kPasses, kSerial, kRebuild, kWalk, kDriverPairs, kKick, kClose, kStages };

#ifdef POLYDEM_LINE_AUDIT
void enter(int stage);  // this thread's accesses belong to `stage` from now on (kNone: the serial stage's)
void serial(int stage);  // thread 0, outside any region: the stage of the serial code from now on
void name(const void* data, std::size_t bytes, const char* what);  // an array, for this step's tables
void step_end();  // thread 0, outside any region: the step's lines counted, its sets cleared
#else
inline void enter(int) {}
inline void serial(int) {}
inline void name(const void*, std::size_t, const char*) {}
inline void step_end() {}
#endif

// The calling thread's stage for a scope.
struct Scope {
  explicit Scope(int stage) { enter(stage); }
  ~Scope() { enter(kNone); }
  Scope(const Scope&) = delete;
  Scope& operator=(const Scope&) = delete;
};

// A vector's elements named (audit::name).
template <class V>
void name_vector(const V& v, const char* what) {
  if (!v.empty()) name(v.data(), v.size() * sizeof(v[0]), what);
}

}  // namespace polydem::audit
