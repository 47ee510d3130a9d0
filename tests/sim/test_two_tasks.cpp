// two_tasks (parallel.hpp) runs its two tasks once each: on two threads at once where two are
// allowed and it is worth waking them, else first then second on the calling thread, so a
// rebuild's two lists come out the same at any thread count.
#include <catch2/catch.hpp>

#include <omp.h>

#include <vector>

#include "polydem/parallel.hpp"

using namespace polydem;

namespace {

struct Ran {
  std::vector<int> order;  // 1 first, 2 second, as each task started (under the lock)
  int first_thread = -1, second_thread = -1;
};

Ran run_two(bool worth_waking) {
  Ran r;
  two_tasks(
      worth_waking,
      [&] {
        r.first_thread = omp_get_thread_num();
#pragma omp critical(two_tasks_test)
        r.order.push_back(1);
      },
      [&] {
        r.second_thread = omp_get_thread_num();
#pragma omp critical(two_tasks_test)
        r.order.push_back(2);
      });
  return r;
}

}  // namespace

TEST_CASE("two_tasks runs each task once, on two threads when allowed", "[parallel]") {
  const int before = omp_get_max_threads();
  omp_set_num_threads(2);
  const Ran both = run_two(true);
  REQUIRE(both.order.size() == 2);
  CHECK(both.first_thread != both.second_thread);  // at once, not one after the other
  omp_set_num_threads(before);
}

TEST_CASE("two_tasks runs first then second on one thread", "[parallel]") {
  const int before = omp_get_max_threads();
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    const bool worth = threads == 1;  // one thread allowed, or two not worth waking
    const Ran serial = run_two(worth);
    CHECK(serial.order == std::vector<int>{1, 2});
    CHECK(serial.first_thread == 0);
    CHECK(serial.second_thread == 0);
  }
  int inner_order = 0;
#pragma omp parallel num_threads(2)
  {
    if (omp_get_thread_num() == 0) {  // inside a team: here, in order, on this thread alone
      int step = 0;
      two_tasks(true, [&] { step = step * 10 + 1; }, [&] { step = step * 10 + 2; });
      inner_order = step;
    }
  }
  CHECK(inner_order == 12);
  omp_set_num_threads(before);
}
