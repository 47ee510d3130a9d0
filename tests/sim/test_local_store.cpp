// A rank's writers, energies and checks read its bodies in its LocalStore (issue 20): the rows of
// its owned bodies there are the rows of the global arrays at their ids, user ids and groups too.
#include <catch2/catch.hpp>

#include "sim/body_rows.hpp"
#include "sim/local_store.hpp"
#include "sim/state_energy.hpp"

using namespace polydem;

namespace {

// Six bodies, each field different per body, user ids reversed (a spatial order).
Bodies six_bodies() {
  Bodies b;
  b.resize(6);
  for (std::size_t k = 0; k < 6; ++k) {
    const double x = double(k) + 1.0;
    b.position[k] = {x, -x, 0.5 * x};
    b.velocity[k] = {0.1 * x, 0.0, -x};
    b.angular_momentum[k] = {x * x, 1.0, 0.0};
    b.orientation[k] = Quat(x, 1.0, 0.0, 0.0).normalized();
    b.mass[k] = 2.0 * x;
    b.inertia[k] = {x, x + 1.0, x + 2.0};
    b.shape[k] = int(k % 2);
    b.group[k] = int(10 + k);
    b.id[k] = std::uint32_t(5 - k);
  }
  return b;
}

}  // namespace

TEST_CASE("a store's owned rows are the global arrays' rows at their ids, user ids and groups kept") {
  const Bodies all = six_bodies();
  LocalStore store;
  store.select(all, {1, 2, 4, 5}, {0, 1, 0, 1});  // owns 1 and 4, ghosts of 2 and 5
  const std::vector<std::uint32_t> rows = store.owned_rows();
  REQUIRE(rows == std::vector<std::uint32_t>{0, 2});
  CHECK(store.local_of(4) == 2);
  CHECK(store.local_of(5) == 3);
  const Bodies from_store = rows_of(store, rows), from_all = rows_of(all, {1, 4});
  CHECK(from_store.id == std::vector<std::uint32_t>{4, 1});
  CHECK(from_store.group == from_all.group);
  CHECK(from_store.position == from_all.position);
  CHECK(from_store.velocity == from_all.velocity);
  CHECK(from_store.angular_momentum == from_all.angular_momentum);
  CHECK(from_store.mass == from_all.mass);
  CHECK(from_store.shape == from_all.shape);
  StateEnergy a, b;  // the energy words (exact sums) alike from either
  for (std::uint32_t k : rows) a.add_body(store, k);
  for (std::uint32_t g : {1u, 4u}) b.add_body(all, g);
  CHECK(a.words() == b.words());
  CHECK(a.kinetic.value() == Approx(0.5 * 4.0 * (0.04 + 4.0) + 0.5 * 10.0 * (0.25 + 25.0)));
}
