// The run loop's last good state (sim/last_good.hpp): written as it was kept, bit for bit, and
// without a copy of the orientations while every one is exactly the identity (spheres).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include "sim/last_good.hpp"

using namespace polydem;

namespace {

Bodies moving_bodies(std::size_t n) {
  Bodies b;
  b.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    b.position[i] = Vec3(0.1 * double(i), -0.2, 0.3 / double(i + 1));  // m
    b.velocity[i] = Vec3(1.0 / 3.0, double(i), -0.5);                   // m/s
    b.angular_velocity[i] = Vec3(0.0, 2.0 / 7.0, double(i));            // rad/s
    b.shape[i] = int(i % 2);
  }
  return b;
}

bool same_bits(const std::vector<Quat>& a, const std::vector<Quat>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Quat)) == 0;
}

}  // namespace

TEST_CASE("the last good state keeps no orientation while all are the identity, and gives back the kept state") {
  const Bodies then = moving_bodies(5);
  LastGood good;
  good.keep(then);
  CHECK(good.orientation.capacity() == 0);  // 32 bytes a body not held
  Bodies now = moving_bodies(5);
  for (std::size_t i = 0; i < 5; ++i) now.position[i] = Vec3(NAN, NAN, NAN);  // blown up since
  const Bodies back = good.with_constants_of(now);
  CHECK(back.position == then.position);
  CHECK(back.velocity == then.velocity);
  CHECK(back.angular_velocity == then.angular_velocity);
  CHECK(same_bits(back.orientation, then.orientation));
  CHECK(back.shape == now.shape);
}

TEST_CASE("the last good state keeps every orientation, -0 included, once one body has turned") {
  Bodies then = moving_bodies(4);
  then.orientation[2] = Quat(std::cos(0.3), 0.0, std::sin(0.3), 0.0);
  then.orientation[3] = Quat(1.0, -0.0, 0.0, 0.0);  // equal to the identity, not the same bits
  LastGood good;
  good.keep(then);
  Bodies now = moving_bodies(4);  // since turned back: the kept ones must be written
  const Bodies back = good.with_constants_of(now);
  CHECK(same_bits(back.orientation, then.orientation));
  CHECK(std::signbit(back.orientation[3].x()));
  // Turned back to the identity at the next check: the copy is freed.
  good.keep(now);
  CHECK(good.orientation.capacity() == 0);
  CHECK(same_bits(good.with_constants_of(then).orientation, now.orientation));
}
