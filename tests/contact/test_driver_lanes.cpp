// The driver pairs' blocks through the lanes (LonePairKernel: two pairs' lone steady contacts side
// by side, a pair's four in four lanes in the AVX build, even_block_avx) against the blocks of
// pair_forces one pair at a time: cubes on walls, flat, on an edge or on a corner, end with the
// same bits, pair by pair (forces, torques, pending energies, touching counts), block by block
// (contacts, ended flags) and slot by slot (histories, records).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/lone_pairs.hpp"
#include "contact/pair_loop.hpp"
#include "contact/pair_partners.hpp"
#include "../geometry/test_shapes.hpp"
#include "sphere_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

using Parts = LawParts<NormalLinear, false, false, false>;
using Partner = engine_detail::DriverPartner<false>;
constexpr double kHalf = 0.005, kRounding = 0.0005;  // m, the cube's half side and Minkowski radius

// A floor, a side wall and a floor that moves.
Drivers three_walls() {
  std::vector<DriverSettings> settings(3);
  settings[0].kind = WallSettings{Vec3(0.0, 0.0, 0.0), Vec3(0.0, 0.0, 1.0), std::nullopt};
  settings[1].kind = WallSettings{Vec3(-0.1, 0.0, 0.0), Vec3(1.0, 0.0, 0.0), std::nullopt};
  settings[2].kind = WallSettings{Vec3(0.0, 0.0, -0.2), Vec3(0.0, 0.0, 1.0), std::nullopt};
  Drivers drivers(settings);
  drivers[2].velocity = Vec3(0.001, 0.0, 0.01);  // m/s
  return drivers;
}

// Cubes on walls, moving and spinning a little, and their poses.
struct Cubes {
  Shape shape = make_cube(kHalf, kRounding);
  std::vector<Vec3> position, velocity, spin, velocity_end, spin_end, world;
  std::vector<Quat> orientation;
  std::vector<double> radius, mass;
  std::vector<PosedBody> posed;

  // Flat (a face's four corners touch), on an edge (two) or on a corner (one), the lowest point
  // `gap` from the wall (mostly an overlap).
  void add(Draw& d, const DriverState& wall) {
    const double lie = d.uniform(0.0, 1.0);
    const Vec3 axis = lie < 0.4    ? d.vec(1.0).normalized()
                      : lie < 0.65 ? wall.normal.unitOrthogonal()
                                   : Vec3(1.0, 1.0, 0.0).normalized();
    const double tilt = lie < 0.4 ? d.uniform(0.0, 2e-3) : d.uniform(0.2, 0.4);  // rad
    orientation.push_back(Quat(Eigen::AngleAxisd(tilt, axis)));
    const Mat3 rotation = orientation.back().toRotationMatrix();
    double low = 1.0;  // m, the lowest corner's height above the centre along the normal
    for (const Vec3& v : shape.vertices) low = std::min(low, (rotation * v).dot(wall.normal));
    const double gap = d.chance(0.05) ? d.uniform(0.0, 2e-5) : d.uniform(-1e-4, 0.0);  // m
    const Vec3 along = d.vec(0.05);
    position.push_back(wall.point + along - along.dot(wall.normal) * wall.normal + (kRounding + gap - low) * wall.normal);
    radius.push_back(kRounding);
    mass.push_back(2700.0 * std::pow(2.0 * (kHalf + kRounding), 3));
    velocity.push_back(d.vec(0.01));
    spin.push_back(d.vec(1.0));
    velocity_end.push_back(velocity.back() + d.vec(0.001));
    spin_end.push_back(spin.back() + d.vec(0.1));
  }
  void pose() {
    world.resize(8 * position.size());
    for (std::size_t b = 0; b < position.size(); ++b) {
      const Mat3 rotation = orientation[b].toRotationMatrix();
      pose_vertices(shape, 1.0, position[b], rotation, &world[8 * b]);
      posed.push_back(PosedBody{&shape, &world[8 * b], rotation, position[b], kRounding, 1.0});
    }
  }
  BodyView view() const {
    return {posed.data(), position.data(), radius.data(), velocity.data(), spin.data(), velocity_end.data(),
            spin_end.data(), mass.data(), false};
  }
};

// A slot's last step with its patch share `weight`: mostly a lasting overlap that sticks.
ContactHistory random_history(Draw& d, double weight) {
  ContactHistory h = test::random_history(d);
  h.weight = d.chance(0.5) ? weight : d.uniform(0.0, 1.0);
  return h;
}

// The driver list of cube b on wall pairs[b].j: a slot per corner (a wall's candidates, gaps -inf),
// the near corners active at the last step with ~95% chance each.
PairList corner_list(Draw& d, const std::vector<BodyPair>& pairs, const Cubes& cubes, const Drivers& drivers) {
  PairList list;
  list.pairs = pairs;
  list.sparse = true;
  list.resize_results();
  list.slot_begin.push_back(0);
  for (const BodyPair& p : pairs) {
    for (std::uint16_t v = 0; v < 8; ++v) list.features.push_back({PairType::vertex_face, v, 0});
    list.slot_begin.push_back(std::uint32_t(list.features.size()));
  }
  list.slot_gap.assign(list.features.size(), -std::numeric_limits<float>::infinity());
  list.active.assign(list.features.size(), 0);
  list.state_of.assign(list.features.size(), kNoState);
  list.states.reset(list.features.size(), false, list.recording);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const DriverState& wall = drivers[pairs[k].j];
    for (std::uint32_t s = list.slot_begin[k]; s < list.slot_begin[k + 1]; ++s) {
      const Vec3& corner = cubes.world[8 * pairs[k].i + list.features[s].a];
      if ((corner - wall.point).dot(wall.normal) > kRounding + 2e-4 || d.chance(0.05)) continue;  // m: far, or new
      list.active[s] = 1;
      ++list.touching[k];
      list.set_history(s, random_history(d, 0.25));
      list.set_record(s, {corner - kRounding * wall.normal, Vec3::Zero(), 0.0});
    }
    if (list.touching[k]) list.pending[k] = {d.uniform(0.0, 1e-6), 0.0, 0.0, 0.0};  // J
  }
  return list;
}

// Block b as even_pair_forces runs it: its AVX copy where the CPU has AVX.
template <class Kernel>
void run_block(PairList& list, const Kernel& kernel, std::size_t b, PairScratch& scratch) {
  if (kHasAvx) pair_loop_detail::even_block_avx(list, kernel, b, scratch);
  else pair_loop_detail::even_block(list, kernel, b, scratch);
}

}  // namespace

TEST_CASE("driver lanes: cubes on walls through the lanes have the bits of pair_forces pair by pair", "[contact]") {
  const LawParams law = bed_law();  // its exact step is the spheres': not a cube's
  REQUIRE(lanes_law<Parts>());
  const Drivers drivers = three_walls();
  Draw d;
  Cubes cubes;
  std::vector<BodyPair> pairs;
  for (std::uint32_t b = 0; b < 3000; ++b) {
    const std::uint32_t j = std::uint32_t(d.uniform(0.0, 3.0));
    cubes.add(d, drivers[j]);
    pairs.push_back({b, j});
  }
  cubes.pose();
  const PairList start = corner_list(d, pairs, cubes, drivers);
  PairList one = start, lanes = start;
  const BodyView view = cubes.view();
  const Partner partner{&drivers, cubes.mass.data()};
  const auto pair_by_pair = [&](std::uint32_t k, PairScratch& scratch) {
    return pair_forces<Parts>(law, 0.0, kDt, view, partner, one, k, scratch);
  };
  const LonePairKernel<Parts, Partner> in_lanes{law, 0.0, kDt, view, partner, lanes};
  PairScratch scratch_one, scratch_lanes;
  for (std::size_t b = 0; b < start.blocks(); ++b) {
    pair_loop_detail::block_forces(one, pair_by_pair, b, scratch_one);
    run_block(lanes, in_lanes, b, scratch_lanes);
  }
  int corners[9] = {};
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    INFO("pair " << k << ", " << one.touching[k] << " corners");
    REQUIRE(same_bits(one.force_i[k], lanes.force_i[k]));
    REQUIRE(same_bits(one.torque_i[k], lanes.torque_i[k]));
    REQUIRE(same_bits(one.torque_j[k], lanes.torque_j[k]));
    REQUIRE(same_bits(one.pending[k], lanes.pending[k]));
    REQUIRE(one.touching[k] == lanes.touching[k]);
    ++corners[std::min<int>(one.touching[k], 8)];
  }
  CHECK(corners[1] > 500);  // on a corner: lone contacts, two pairs' side by side
  CHECK(corners[2] > 300);  // on an edge
  CHECK(corners[4] > 500);  // flat: four lanes in the AVX build
  CHECK(one.block_contacts == lanes.block_contacts);
  CHECK(one.block_ended == lanes.block_ended);
  REQUIRE(one.states.size() == lanes.states.size());
  for (std::uint32_t s = 0; s < one.slot_count(); ++s) {
    REQUIRE(one.state_of[s] == lanes.state_of[s]);
    if (one.state_of[s] == kNoState) continue;
    INFO("slot " << s);
    CHECK(same_bits(one.history(s), lanes.history(s)));
    CHECK(same_bits(one.record(s).point, lanes.record(s).point));
    CHECK(same_bits(one.record(s).force, lanes.record(s).force));
    CHECK(same_bits(one.record(s).fn, lanes.record(s).fn));
  }
}
