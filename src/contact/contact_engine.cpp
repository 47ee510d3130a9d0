#include "contact/contact_engine.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>
#include <tuple>
#include <type_traits>
#include <utility>

#include "polydem/line_audit.hpp"
#include "polydem/parallel.hpp"
#include "polydem/release.hpp"
#include "contact/body_pose.hpp"
#include "contact/candidate_memory.hpp"
#include "contact/lone_pairs.hpp"
#include "contact/pair_loop.hpp"
#include "contact/pair_partners.hpp"
#include "contact/sphere_kernel.hpp"
#include "contact/sphere_wall_lanes.hpp"

namespace polydem {

namespace {

using engine_detail::BodyPartner;
using engine_detail::DriverPartner;
using engine_detail::pose_body;
using engine_detail::PoseArrays;

// Of the skin: how far beyond the range a body pair's candidate search looks, to be kept over
// the next rebuilds (candidate_memory.hpp).
constexpr double kSearchExtra = 1.0;

// m, the farthest core vertex from the centre of mass, unscaled.
double core_reach(const Shape& s) {
  double r = 0.0;
  for (const Vec3& v : s.vertices) r = std::max(r, v.norm());
  return r;
}

// f(std::true_type{}) where a box's vertices are made where read, else f(std::false_type{}): the
// walk's kernels chosen once a step, the stored path with no test a pair (made_pose.hpp).
template <class F>
void with_made(bool made, F&& f) {
  if (made) f(std::true_type{});
  else f(std::false_type{});
}

}  // namespace

ContactEngine::ContactEngine(const std::vector<Shape>& shapes, const LocalBodies& bodies,
                             ContactSettings settings, ContactEngine* was)
    : shapes_(shapes), settings_(settings), memory_(kSearchExtra * settings.skin) {
  band_particle_ = settings_.particle.cohesion ? settings_.particle.dncut : 0.0;
  band_driver_ = settings_.driver.cohesion ? settings_.driver.dncut : 0.0;
  const std::size_t n = bodies.size();
  const std::vector<int>& shape = *bodies.shape;
  const std::vector<double>& scale = *bodies.scale;
  vertex_offset_.assign(n + 1, 0);
  std::vector<double> reach;  // m, per shape: a rank makes an engine at each rebuild
  for (const Shape& s : shapes_) boxes_.push_back(box_corners(s)), reach.push_back(core_reach(s));
  bounding_.resize(n);
  core_reach_.resize(n);
  for (std::size_t b = 0; b < n; ++b) {
    const Shape& s = shapes_[shape[b]];
    vertex_offset_[b + 1] = vertex_offset_[b] + std::uint32_t(s.vertices.size());
    bounding_[b] = s.bounding_radius * scale[b];
    core_reach_[b] = reach[std::size_t(shape[b])] * scale[b];
  }
  spheres_only_ = settings_.spheres_only >= 0 ? settings_.spheres_only == 1
                  : std::all_of(shape.begin(), shape.end(), [&](int s) { return shapes_[s].is_sphere(); });
  // Of this body set, as vertex_offset_ (a new set builds a new engine).
  any_sphere_ = std::any_of(shape.begin(), shape.end(), [&](int s) { return shapes_[s].is_sphere(); });
  radius_.resize(n);
  for (std::size_t b = 0; b < n; ++b) radius_[b] = shapes_[shape[b]].radius * scale[b];
  made_vertices_ = settings_.made_vertices >= 0 ? settings_.made_vertices == 1 : n >= kMadeVerticesBodies;
  made_vertices_ = made_vertices_ && std::any_of(shape.begin(), shape.end(), [&](int s) { return boxes_[s].has_value(); });
  boxes_only_ = std::all_of(shape.begin(), shape.end(), [&](int s) { return boxes_[s].has_value(); });
  alike_ = alike_bodies(shape, scale, *bodies.mass);
  if (spheres_only_) return;  // spheres are posed when read (sphere_pose), or kept by keep_sphere_poses
  world_vertices_.resize(vertex_offset_[n]);
  if (was && !was->spheres_only_) posed_ = std::move(was->posed_);  // its rows are posed again before read
  posed_.resize(n);
}

// Spheres keep no pose unless a driver pair's kernel reads it each step (a driver other than a
// wall, or the contact point's mass): 152 bytes a body (the pose and its vertex) otherwise freed.
void ContactEngine::keep_sphere_poses(const LocalBodies& bodies, bool needed) {
  if (!needed) {
    release(posed_);
    release(world_vertices_);
    return;
  }
  const std::size_t n = bodies.size();
  const std::vector<Vec3>& position = *bodies.position;
  if (posed_.size() != n) {  // everything but the centre is set once here
    world_vertices_.resize(n);
    posed_.resize(n);
    for (std::size_t b = 0; b < n; ++b) {
      posed_[b] = sphere_pose(bodies, b);
      posed_[b].vertices = &world_vertices_[b];
    }
  }
  parallel_for(n, [&](std::size_t b) { posed_[b].position = world_vertices_[b] = position[b]; });
}

void ContactEngine::pose(const LocalBodies& bodies, const std::vector<std::uint32_t>& some, bool wait,
                         std::size_t min_items, bool box_vertices) {
  const std::size_t n = some.size();
  if (n == 0) return;  // the same on every thread: no barrier skipped by some only
  // The arrays' addresses, copied into each thread's loop: read through the vectors, each body
  // reloaded them (Eigen's stores may alias anything), ~25 instructions a body.
  const PoseArrays arrays{bodies.position->data(), bodies.orientation->data(), bodies.shape->data(),
                          bodies.scale->data(),    shapes_.data(),             boxes_.data(),
                          some.data(),             vertex_offset_.data(),      world_vertices_.data(),
                          posed_.data(),           box_vertices || !made_vertices_};
  wait = wait && omp_get_level() > 0;  // a region of its own ends at its own barrier
  in_team(n >= min_items, [&] {
    const PoseArrays a = arrays;
    for (const auto [first, last] : team_shares(some, pass_cut()))  // the bodies this thread moved
      for (std::size_t e = first; e < last; ++e) pose_body(a, a.listed[e]);
    if (wait) {
#pragma omp barrier
    }
  });
}

ListedPoses ContactEngine::listed_poses(const LocalBodies& bodies) {
  return {{bodies.position->data(), bodies.orientation->data(), bodies.shape->data(), bodies.scale->data(),
           shapes_.data(), boxes_.data(), listed_.data(), vertex_offset_.data(), world_vertices_.data(),
           posed_.data(), !made_vertices_},
          std::uint32_t(unposed_boxes() ? 0 : listed_.size()), boxes_only_};
}

// Bodies far from every other body and driver (falling in a pour) need no world vertices.
void ContactEngine::mark_listed(std::size_t n_bodies, const std::vector<BodyPair>& body_pairs,
                                const std::vector<BodyPair>& driver_pairs) {
  std::vector<std::uint8_t> in_pair(n_bodies, 0);
  for (const BodyPair& p : body_pairs) in_pair[p.i] = in_pair[p.j] = 1;
  for (const BodyPair& p : driver_pairs) in_pair[p.i] = 1;
  listed_.clear();
  for (std::uint32_t b = 0; b < n_bodies; ++b)
    if (in_pair[b]) listed_.push_back(b);
}

// Ghosts' own pairs are their owners' to compute: a pair is listed where one of its bodies is owned.
static void drop_ghost_pairs(const LocalBodies& bodies, std::vector<BodyPair>& pairs) {
  if (!bodies.ghost) return;
  std::erase_if(pairs, [&](BodyPair p) { return !bodies.owned(p.i) && !bodies.owned(p.j); });
}

// The bodies of `now` (increasing) not in `before` (increasing).
static std::vector<std::uint32_t> newcomers(const std::vector<std::uint32_t>& now, const std::vector<std::uint32_t>& before) {
  std::vector<std::uint32_t> fresh;
  std::set_difference(now.begin(), now.end(), before.begin(), before.end(), std::back_inserter(fresh));
  return fresh;
}

void ContactEngine::rebuild(const LocalBodies& bodies, const Drivers& drivers, bool listed_posed) {
  const double range_p = settings_.skin + band_particle_;
  free_results(body_list_);  // read by nothing from here: the new lists' results replace them
  if (spheres_only_) body_list_.set_recording(false);  // a sphere list's records are not carried: freed
  free_results(driver_list_);
  PairList old_body, old_driver;
  // One team for the old lists' active parts and the skins: the two lists' parts on two threads at
  // once (a team of one does both), ~0.12e6 instructions a pour's rebuild the other thread waited through.
  in_team(bodies.size() >= kParallelMinItems, [&] {
    on_two_threads(
        [&] {
          // active_part keeps the pairs with an active slot: any other's energy is counted now (none
          // after a step here: flush_ended took them). Both flushes here: flushed_ is one sum.
          flush_idle(body_list_, bodies.ghost);
          flush_idle(driver_list_, bodies.ghost);  // its idle pairs, not active_part's: no pair read by both
          old_body = active_part(body_list_);
        },
        [&] { old_driver = active_part(driver_list_); });
    choose_skins(bodies);
  });
  body_list_ = PairList{};  // freed before the new lists are built
  driver_list_ = PairList{};
  PairList fresh, fresh_d;
  // A sphere list's records are written by the step's kernel, not carried: sized only once the
  // old lists are freed, so a rebuild at an output step holds no more than another.
  fresh.recording = !spheres_only_ && record_contacts_;  // a sparse list's states are sized with their records
  fresh.sparse = !spheres_only_;  // the sphere kernel's one slot a pair stays dense
  fresh.rolls = fresh.sparse && settings_.particle.rolling;  // its states' rolling moments, apart
  fresh_d.recording = record_contacts_;
  fresh_d.sparse = true;
  fresh_d.rolls = settings_.driver.rolling;
  {  // the broad phase's pairs are freed before the slots' state is sized
    std::vector<BodyPair> near;
    if (skin_.empty()) {
      cells_.build_pairs(*bodies.position, bounding_, range_p, near);
    } else {  // each body's sphere grown by half its skin: |x_i - x_j| < R_i + R_j + (s_i + s_j) / 2 + band
      std::vector<double> grown(bounding_.size());  // m
      for (std::size_t b = 0; b < grown.size(); ++b) grown[b] = bounding_[b] + 0.5 * skin_[b];
      cells_.build_pairs(*bodies.position, grown, band_particle_, near);
    }
    stats_.broad_tests += cells_.candidate_tests();
    stats_.broad_levels = cells_.levels();
    stats_.broad_bytes = std::max(stats_.broad_bytes, cells_.bytes());
    cells_ = CellList{};  // its search arrays freed before the lists are sized (~100 bytes a sphere)
    drop_ghost_pairs(bodies, near);
    fresh_d.pairs = near_drivers(bodies, drivers);
    if (spheres_only_) {  // no listed_ or pose(): posed where read
      body_candidates(near, [&](std::uint32_t b) { return sphere_pose(bodies, b); }, range_p, fresh);
      release(fresh.gap_at_build);  // the sphere kernel's test is the distance itself: 12 bytes a pair freed
      release(fresh.slot_gap);
    } else {
      std::vector<std::uint32_t> posed_before = listed_posed ? std::move(listed_) : std::vector<std::uint32_t>{};
      mark_listed(bodies.size(), near, fresh_d.pairs);
      // ~500 instructions a body: a pour's ~100 newcomers pay for the team, where the step has one
      const std::size_t min_posed = bodies.size() >= kParallelMinItems ? kParallelMinHeavyItems : kParallelMinItems;
      // The searches read stored vertices: a box posed by this step's pass (none stored) is posed again.
      const bool newcomers_only = listed_posed && !made_vertices_;
      pose(bodies, newcomers_only ? newcomers(listed_, posed_before) : listed_, true, min_posed, true);
      const PairRange range = skin_.empty() ? PairRange(range_p) : PairRange(band_particle_, skin_.data());
      memory_.find(near, posed_, {bodies.position->data(), bodies.orientation->data(), core_reach_.data()}, range,
                   fresh);
    }
  }
  // Cut for the team that will walk the list (forces' region), here: the loop then meets for no
  // cut (two barriers a rebuild). Another team recuts in the loop.
  const int team = bodies.size() >= kParallelMinItems ? omp_get_max_threads() : 1;
  // The body list's close and the driver list's making share nothing but the exact energy sum
  // (the driver pairs' flush follows the join): on two threads at once, not one after the other
  // (issue 19: ~0.3e6 instructions a pour rebuild the other thread waited through asleep).
  std::vector<std::uint32_t> uncarried_d;  // old driver pairs whose energy is flushed now
  // Two tasks pay on two threads; a larger team shares the driver candidates among all instead.
  const bool at_once = team == 2;
  two_tasks(
      at_once,
      [&] {
        close_body_list(bodies, old_body, std::move(fresh), team);
        // the lighter task (~0.25e6 against ~0.33e6 on the pour) also marks the trigger: it reads the poses alone
        trigger_.mark_built(*bodies.position, *bodies.orientation, spheres_only_);  // spheres: core_reach_ 0
        trigger_.set_skins(skin_);
      },
      [&] { uncarried_d = make_driver_list(bodies, drivers, std::move(fresh_d), old_driver, !at_once); });
  flush_pairs(old_driver, uncarried_d, bodies.ghost);
  if (spheres_only_ || trailed_) {  // a sphere's weight counts its wall pairs (driver_begin_), a trailed body's too
    weigh_bodies(!own_pass_cut_);
    direct_.cut(body_list_, team);
  }
  spheres_posed_each_step_ = std::any_of(driver_list_.pairs.begin(), driver_list_.pairs.end(),
                                         [&](BodyPair p) { return !drivers.is_wall(p.j); });
  if (spheres_only_)
    keep_sphere_poses(bodies, spheres_posed_each_step_ || (settings_.driver.contact_mass && !driver_list_.pairs.empty()));
  else
    mark_listed(bodies.size(), body_list_.pairs, driver_list_.pairs);
  cut_passes(team);
  must_rebuild_ = false;
  margins_read_ = false;
  ++stats_.rebuilds;
  stats_.body_pairs = body_list_.size();
  stats_.driver_pairs = driver_list_.size();
  stats_.slots = body_list_.slot_count() + driver_list_.slot_count();
}

// A rebuild's new body list: the old one's history carried, its results sized and, for
// polyhedra, the walk's cut for a team of `team` (rebuild). Touches no driver list.
void ContactEngine::close_body_list(const LocalBodies& bodies, PairList& old_body, PairList fresh, int team) {
  size_slots(fresh);  // once the broad phase's pairs are freed
  flush_pairs(old_body, carry_history(old_body, fresh), bodies.ghost);
  old_body = PairList{};
  equal_spheres_ = spheres_only_ && settings_.equal_spheres ? equal_spheres(bodies) : std::nullopt;
  // The walk's static cut falls between blocks: a pour's few pairs in small ones. Driver pairs
  // keep kPairBlock (a dynamic loop; the cubes' 873 in 16s moved only valgrind's split).
  if (!spheres_only_) fresh.block = polyhedron_pair_block(fresh.size());
  size_results(fresh, !equal_spheres_);  // equal spheres: one k', c' for all pairs (sphere_pair_loop)
  for (auto* v : {&fresh.force_i, &fresh.torque_i, &fresh.torque_j}) release(*v);  // summed in the loop: DirectSums
  body_list_ = std::move(fresh);
  if (spheres_only_) body_list_.set_recording(record_contacts_);
  direct_.reset(bodies.size());
  if (spheres_only_ || trailed_) return;  // its weights read the driver pairs: cut after both lists
  weigh_bodies(!own_pass_cut_);  // the last lists' passes had their own cut: likely these too
  direct_.cut(body_list_, team);
}

// A rebuild's new driver list from its pairs `fresh` (posed bodies): candidates, slots, the old
// list's history carried; returns the old pairs whose energy is to be flushed (flushed_ is
// another task's). Touches no body list; the candidates on the threads when `share_candidates`
// (not a task of two_tasks, whose other thread is busy), else on this one.
std::vector<std::uint32_t> ContactEngine::make_driver_list(const LocalBodies& bodies, const Drivers& drivers,
                                                           PairList fresh, const PairList& old_driver,
                                                           bool share_candidates) {
  std::vector<std::vector<FeaturePair>> per_pair(fresh.pairs.size());
  const auto find = [&](std::size_t k) {  // each pair writes its own run, sorted
    const std::uint32_t i = fresh.pairs[k].i;
    drivers.candidates(spheres_only_ ? sphere_pose(bodies, i) : posed_[i], fresh.pairs[k].j, skin_of(i) + band_driver_,
                       per_pair[k]);
    sort_by_key(per_pair[k]);
  };
  if (share_candidates)
    parallel_for(fresh.pairs.size(), find, kParallelMinHeavyItems);
  else
    for (std::size_t k = 0; k < fresh.pairs.size(); ++k) find(k);
  fresh.gap_at_build.assign(fresh.pairs.size(), -std::numeric_limits<double>::infinity());  // drivers move
  fill_driver_slots(per_pair, fresh);
  size_slots(fresh);
  std::vector<std::uint32_t> uncarried = carry_history(old_driver, fresh);
  size_results(fresh);
  driver_list_ = std::move(fresh);
  driver_begin_ = pairs_by_body(driver_list_.pairs, bodies.size());
  return uncarried;
}

std::optional<EqualSpheres> ContactEngine::equal_spheres(const LocalBodies& bodies) const {
  const std::vector<double>& mass = *bodies.mass;
  if (mass.empty()) return std::nullopt;
  for (std::size_t b = 1; b < mass.size(); ++b)
    if (radius_[b] != radius_[0] || mass[b] != mass[0]) return std::nullopt;
  return EqualSpheres{radius_[0], mass[0]};
}

// Called by every thread of a team (or one alone): its loop shared, its sizing on one thread.
void ContactEngine::choose_skins(const LocalBodies& bodies) {
  const bool per_body = per_body_skins(settings_, spheres_only_);
  const std::vector<Vec3>& v = *bodies.velocity;       // m/s
  const std::vector<Vec3>& w = *bodies.angular_velocity;  // rad/s
#pragma omp single
  {
    if (per_body)
      skin_.resize(v.size());
    else
      skin_.clear();
  }
  if (!per_body) return;
  parallel_for(v.size(), [&](std::size_t b) {  // each body its own: 2,000 of them were ~4% of a pour's serial rebuild
    const double speed = v[b].norm() + core_reach_[b] * w[b].norm();  // m/s, of its fastest core point
    // NaN speed: std::max keeps the scene's skin (the trigger then sees the NaN position)
    skin_[b] = std::min(settings_.skin_max, std::max(settings_.skin, 2.0 * speed * skin_time_));
  });
  // No body fast enough for more (a settled pile): the scene's skin each, by the lists' own path.
#pragma omp single
  if (std::all_of(skin_.begin(), skin_.end(), [&](double s) { return s == settings_.skin; })) skin_.clear();
}

// Body-driver pairs within reach of owned bodies, in (body, driver) order; each body is tested in
// parallel. The same pass marks the drivers for driver_shift (their placements, and the lever:
// the farthest body reach from a driver's centre), so a rebuild meets once for both.
std::vector<BodyPair> ContactEngine::near_drivers(const LocalBodies& bodies, const Drivers& drivers) {
  const std::size_t n = bodies.size(), m = drivers.size();
  drivers_at_build_.clear();
  std::vector<Vec3> centers;  // m
  for (std::uint32_t j = 0; j < m; ++j) {
    drivers_at_build_.push_back({drivers[j], drivers[j].active});
    centers.push_back(drivers.center(j));
  }
  std::vector<double> lever(n, 0.0);  // m, per body: the max is exact in any order
  std::vector<std::vector<BodyPair>> found(omp_get_max_threads());  // a thread's run of bodies' pairs
  const std::vector<Vec3>& position = *bodies.position;
  assert(omp_get_level() == 0);  // a region of its own (rebuild's serial stretch): `found` is shared
  in_team(n >= kParallelMinItems, [&] {  // the pairs gathered here too: ~120,000 instructions a pour's rebuild
    const std::size_t t = omp_get_thread_num(), threads = omp_get_num_threads();
    std::vector<BodyPair>& mine = found[t];
    for (std::uint32_t i = std::uint32_t(n * t / threads); i < n * (t + 1) / threads; ++i) {
      for (const Vec3& c : centers) lever[i] = std::max(lever[i], (position[i] - c).norm() + bounding_[i]);
      if (!bodies.owned(i)) continue;  // a ghost's driver contacts are its owner's
      const double range = skin_of(i) + band_driver_;  // m
      for (std::uint32_t j = 0; j < m; ++j)
        if (drivers.near(j, position[i], bounding_[i] + range)) mine.push_back({i, j});
    }
  });
  driver_lever_ = lever.empty() ? 0.0 : *std::max_element(lever.begin(), lever.end());  // 0 with no driver
  std::vector<BodyPair> pairs;  // the threads' runs in order: (body, driver) order
  for (const std::vector<BodyPair>& run : found) pairs.insert(pairs.end(), run.begin(), run.end());
  return pairs;
}

// A moving driver can reach bodies the lists did not pair it with: how far its surface may have
// moved where bodies are (translation, plus turning times the lever), the largest of the drivers.
double ContactEngine::driver_shift(const Drivers& drivers) const {
  double largest = 0.0;  // m
  for (std::size_t j = 0; j < drivers_at_build_.size(); ++j) {
    const DriverState& now = drivers[j];
    const Placement& then = drivers_at_build_[j].placement;
    if (now.active != drivers_at_build_[j].active) continue;  // a removed driver only loses contacts
    const double shift = (now.point - then.point).norm() + (now.center - then.center).norm() +
                         driver_lever_ * ((now.normal - then.normal).norm() + (now.axis - then.axis).norm());
    largest = std::max(largest, shift);
  }
  return largest;
}

bool ContactEngine::lists_stale(const LocalBodies& bodies, const Drivers& drivers, bool watched) {
  measure_in_team(bodies, watched);
  return stale_after_measure(bodies, drivers);
}

void ContactEngine::measure_in_team(const LocalBodies& bodies, bool watched, const OwnedPart* owned) {
  in_team(bodies.size() >= kParallelMinItems, [&] {
    measure_motion(bodies, watched, owned);
#pragma omp barrier
  });  // the barrier: for a caller inside a team already
}

PairMargins ContactEngine::owned_margins(const LocalBodies& bodies, const Drivers& drivers, bool watched,
                                         bool ghosts_later) {
  const double shift = driver_shift(drivers);  // m
  const std::uint8_t* ghost = bodies.ghost ? bodies.ghost->data() : nullptr;
  const OwnedPart owned{ghost, shift, ghosts_later};
  measure_in_team(bodies, watched, spheres_only_ ? nullptr : &owned);
  const bool past_half = trigger_.take_exceeded();
  PairMargins m;
  if (spheres_only_) {
    m = point_part(bodies, shift, past_half);
  } else {
    m = trigger_.take_margins(*bodies.position, settings_.skin, shift, ghost);
  }
  m.alone = m.alone || must_rebuild_;
  return m;
}

// Points test skin/2 in their pass; their margins are measured only once a step since the rebuild
// read the pair rule (margins_read_: kept in the team's pass where watched), as one process's.
PairMargins ContactEngine::point_part(const LocalBodies& bodies, double shift, bool past_half) {
  PairMargins m;
  if (margins_read_) m = trigger_.point_margins(*bodies.position, settings_.skin, shift, bodies.ghost ? bodies.ghost->data() : nullptr);
  else m.exact = false;
  trigger_.forget_point_margins();  // this step's, read or not
  keep_margins_ = false;
  m.past = past_half || shift > 0.5 * settings_.skin;
  return m;
}

PairMargins ContactEngine::owned_point_margins(const LocalBodies& bodies, const Drivers& drivers) const {
  const std::uint8_t* ghost = bodies.ghost ? bodies.ghost->data() : nullptr;
  PairMargins m = trigger_.point_margins(*bodies.position, settings_.skin, driver_shift(drivers), ghost);
  m.alone = m.alone || must_rebuild_;
  return m;
}

void ContactEngine::measure_motion(const LocalBodies& bodies, bool watched, const OwnedPart* owned) {
  // A sphere's pose is its centre: set in this pass, no loop (and barrier) of its own.
  if (spheres_only_ && spheres_posed_each_step_) {
    const std::vector<Vec3>& position = *bodies.position;
    for (const auto [first, last] : team_shares(position.size(), pass_cut()))
      for (std::size_t b = first; b < last; ++b) posed_[b].position = world_vertices_[b] = position[b];
  }
  if (!watched) trigger_.measure(*bodies.position, *bodies.orientation, core_reach_, settings_.skin, pass_cut(), owned);
  else if (keep_margins_) trigger_.keep_point_margins(*bodies.position, pass_cut(), bodies.ghost ? bodies.ghost->data() : nullptr);
}

void ContactEngine::remeasure(const LocalBodies& bodies, const std::vector<std::uint32_t>& some) {
  const std::vector<Vec3>& position = *bodies.position;
  if (spheres_only_ && spheres_posed_each_step_)
    for (std::uint32_t b : some) posed_[b].position = world_vertices_[b] = position[b];
  trigger_.remeasure(position, *bodies.orientation, core_reach_, some);
}

bool ContactEngine::stale_after_measure(const LocalBodies& bodies, const Drivers& drivers) {
  const bool stale = lists_past_skin(bodies, drivers);
  trigger_.forget_point_margins();  // this step's, read or not
  keep_margins_ = false;
  return stale;
}

bool ContactEngine::lists_past_skin(const LocalBodies& bodies, const Drivers& drivers) {
  const bool past_half = trigger_.take_exceeded();  // taken every step: the next step measures afresh
  if (must_rebuild_) return true;
  const double shift = driver_shift(drivers);  // m
  if (!past_half && !(shift > 0.5 * settings_.skin)) return false;  // every body and driver within skin/2
  margins_read_ = settings_.pair_trigger;  // likely again at the next steps, until the rebuild
  return !settings_.pair_trigger || trigger_.pair_exceeded(*bodies.position, settings_.skin, shift);
}

void ContactEngine::compute(const LocalBodies& bodies, Drivers& drivers, double dt, bool stale) {
  if (stale) rebuild(bodies, drivers);  // poses the bodies it pairs
  in_team(bodies.size() >= kParallelMinItems, [&] { forces(bodies, drivers, dt, !stale, AfterPairs::sum_bodies); });
  if (!bodies.ghost) sums_taken();  // every body's, in reduce_bodies
  close_forces(bodies, drivers);
}

#ifdef POLYDEM_LINE_AUDIT
// The arrays the step's stages touch, named for this step's tables (line_audit.hpp).
void ContactEngine::name_arrays(const LocalBodies& bodies) const {
  using audit::name_vector;
  name_vector(*bodies.position, "bodies.position");
  name_vector(*bodies.orientation, "bodies.orientation");
  name_vector(*bodies.velocity, "bodies.velocity");
  name_vector(*bodies.angular_velocity, "bodies.angular_velocity");
  name_vector(*bodies.velocity_end, "bodies.velocity_end");
  name_vector(*bodies.angular_velocity_end, "bodies.angular_velocity_end");
  name_vector(*bodies.shape, "bodies.shape");
  name_vector(*bodies.scale, "bodies.scale");
  name_vector(*bodies.mass, "bodies.mass");
  name_vector(*bodies.force, "bodies.force");
  name_vector(*bodies.torque, "bodies.torque");
  name_vector(posed_, "engine.posed");
  name_vector(world_vertices_, "engine.world_vertices");
  name_vector(listed_, "engine.listed");
  name_vector(bounding_, "engine.bounding");
  name_vector(core_reach_, "engine.core_reach");
  name_vector(radius_, "engine.radius");
  name_vector(trigger_.displacement(), "trigger.displacement");
  name_vector(driver_begin_, "engine.driver_begin");
  name_vector(pass_cut_, "engine.pass_cut");
  for (const auto& [list, prefix] : {std::pair{&body_list_, "body"}, std::pair{&driver_list_, "driver"}}) {
    const auto named = [&](const auto& v, const char* what) {
      static thread_local std::string s;  // audit::name keeps its own copy
      s = std::string(prefix) + "." + what;
      name_vector(v, s.c_str());
    };
    named(list->pairs, "pairs");
    named(list->slot_begin, "slot_begin");
    named(list->features, "features");
    named(list->state_of, "state_of");
    named(list->slots, "slots");
    named(list->active, "active");
    named(list->slot_gap, "slot_gap");
    named(list->gap_at_build, "gap_at_build");
    named(list->force_i, "force_i");
    named(list->torque_i, "torque_i");
    named(list->torque_j, "torque_j");
    named(list->touching, "touching");
    named(list->block_contacts, "block_contacts");
    named(list->pending, "pending");
    named(list->block_ended, "block_ended");
    named(list->linear_steps, "linear_steps");
    for (std::uint32_t g = 0; g < list->states.size(); g += 256) {
      const SlotState& first = list->states[g];
      audit::name(&first, 256 * sizeof(SlotState), (std::string(prefix) + ".states").c_str());
    }
  }
  name_vector(direct_.sums, "direct.sums");
  name_vector(direct_.foreign, "direct.foreign");
  name_vector(direct_.pace, "direct.pace");
  name_vector(direct_.zero, "direct.zero");
  name_vector(direct_.split.foreign, "split.foreign");
  name_vector(direct_.split.foreign_side, "split.foreign_side");
  name_vector(direct_.split.foreign_begin, "split.foreign_begin");
  name_vector(direct_.split.home_begin, "split.home_begin");
  name_vector(direct_.split.homes, "split.homes");
  name_vector(direct_.split.late_begin, "split.late_begin");
  name_vector(direct_.split.late, "split.late");
  name_vector(direct_.split.cut, "split.cut");
  name_vector(direct_.split.body_cut, "split.body_cut");
}
#endif

void ContactEngine::forces(const LocalBodies& bodies, Drivers& drivers, double dt, bool pose_bodies,
                           AfterPairs then, const WalkTrail* trail) {
#ifdef POLYDEM_LINE_AUDIT
  if (omp_get_thread_num() == 0) name_arrays(bodies);
#endif
  if (pose_bodies && !spheres_only_) pose(bodies, listed_);  // spheres: by measure_motion, where a driver pair reads the pose
  const BodyView view{posed_.data(),
                      bodies.position->data(),
                      radius_.data(),
                      bodies.velocity->data(),
                      bodies.angular_velocity->data(),
                      bodies.velocity_end->data(),
                      bodies.angular_velocity_end->data(),
                      bodies.mass->data(),
                      any_sphere_,
                      &turns_,
                      {shapes_.data(), boxes_.data(), bodies.shape->data(), bodies.scale->data(),
                       bodies.position->data(), bodies.orientation->data(), boxes_only_, alike_ ? 0u : ~0u}};
  // Both pair loops end without a barrier: the one after them is kept only where the region
  // reads their results (the sums) before its end. A trailing pass reads a body's driver pairs
  // after its body pairs: each thread makes its driver pairs first.
  if (trail) {
    turns_left_here = 0;  // this thread's, from its driver pairs on (ChunkTrail)
    trail_driver_range(*trail);
    driver_pair_forces(view, drivers, dt, true);
  }
  if (spheres_only_) {
    sphere_pair_loop(settings_.particle, band_particle_, dt, view, body_list_, direct_,
                     equal_spheres_ ? &*equal_spheres_ : nullptr, true, trail);
  } else {
    const audit::Scope walk(audit::kWalk);
    with_made(made_vertices_, [&](auto made) {
      using Partner = BodyPartner<decltype(made)::value>;
      const Partner partner{posed_.data(),          view.position,         view.velocity,
                            view.angular_velocity,  view.velocity_end,     view.angular_velocity_end,
                            view.mass,              trigger_.displacement().data(),
                            world_vertices_.data(),  vertex_offset_.data(),
                            view.boxes};
      with_law(settings_.particle, [&](auto parts) {
        using Parts = decltype(parts);
        if constexpr (lanes_law<Parts>()) {  // lone contacts of two pairs side by side
          all_pair_forces<true>(
              body_list_,
              LonePairKernel<Parts, Partner>{settings_.particle, band_particle_, dt, view, partner, body_list_},
              &direct_, trail);
        } else {
          all_pair_forces<true>(body_list_, [&](std::uint32_t k, PairScratch& scratch) {
            return pair_forces<Parts>(settings_.particle, band_particle_, dt, view, partner, body_list_, k, scratch);
          }, &direct_, trail);
        }
      });
    });
  }
  if (!trail) driver_pair_forces(view, drivers, dt);
  if (then != AfterPairs::region_ends) {
#pragma omp barrier
  }
  if (then == AfterPairs::sum_bodies) reduce_bodies(bodies);
}

// This thread's bodies whose driver pairs it makes (even_pair_forces' blocks): all of each one's.
void ContactEngine::trail_driver_range(const WalkTrail& trail) const {
  const std::size_t t = omp_get_thread_num();
  const std::uint32_t n = std::uint32_t(driver_begin_.size() - 1);
  if (driver_list_.pairs.empty()) {
    trail.done[t] = {0, n};
    return;
  }
  const auto [first, end] = even_blocks(driver_list_, driver_begin_.data(), body_cut(), t, omp_get_num_threads());
  const std::uint32_t p0 = std::uint32_t(first * driver_list_.block);
  const std::uint32_t p1 = std::uint32_t(std::min(end * driver_list_.block, driver_list_.size()));
  const auto at = driver_begin_.begin();
  const std::uint32_t lo = std::uint32_t(std::lower_bound(at, driver_begin_.end(), p0) - at);  // driver_begin[b] >= p0
  const std::uint32_t hi = std::uint32_t(std::upper_bound(at, driver_begin_.end(), p1) - at) - 1;  // [b + 1] <= p1
  trail.done[t] = {lo, std::max(lo, hi)};
}

void ContactEngine::driver_pair_forces(const BodyView& view, Drivers& drivers, double dt, bool by_bodies) {
  if (!driver_list_.pairs.empty()) {
    const audit::Scope driver_pairs(audit::kDriverPairs);
    with_made(made_vertices_, [&](auto made) {
      with_law(settings_.driver, [&](auto parts) {
        using Parts = decltype(parts);
        const LawParams& law = settings_.driver;
        using Partner = DriverPartner<decltype(made)::value>;
        const Partner partner{&drivers, view.mass, view.boxes.body_mask};
        const std::uint64_t at_rest = drivers_at_rest(drivers);
        // Equal spheres: one radius, mass and k', c' for all (index 0 through mask 0).
        const double r = equal_spheres_ ? equal_spheres_->radius : 0.0, m = equal_spheres_ ? equal_spheres_->mass : 0.0;
        LinearStep step;
        if (equal_spheres_ && !law.contact_mass) step = same_linear_step<Parts>(law, m, dt);
        const WallSpheres sizes = equal_spheres_ ? WallSpheres{&r, &m, &step, 0}
                                                 : WallSpheres{view.radius, view.mass, driver_list_.linear_steps.data(), ~0u};
        const auto kernel = [&](std::uint32_t k, PairScratch& scratch) {
          if (spheres_only_ && drivers.is_wall(driver_list_.pairs[k].j))  // one slot, the centre: sphere_wall.hpp
            return sphere_wall_forces<Parts>(law, band_driver_, dt, view, drivers, driver_list_, k, scratch, sizes, at_rest);
          return pair_forces<Parts>(law, band_driver_, dt, view, partner, driver_list_, k, scratch);
        };
        // Spheres' pairs cost alike: a fixed share each. Polyhedra's shared as they come (they
        // also even out the body pairs' walk, which ends without a barrier), but by bodies ahead of a
        // trailing pass (trail_driver_range).
        const auto by_body = [&](const auto& k) { even_pair_forces(driver_list_, k, driver_begin_.data(), body_cut()); };
        if (spheres_only_ && wall_lanes_fit<Parts>(law)) {  // steady sphere-wall pairs two at a time
          by_body(WallLanesKernel<decltype(kernel)>{kernel, law, band_driver_, dt, view, drivers, driver_list_, sizes,
                                                    at_rest});
        } else if (spheres_only_) {
          by_body(kernel);
        } else if (by_bodies) {
          // Pairs of one steady contact (a cube's corner on a wall) two at a time, a flat cube's
          // four corners in four lanes in the AVX build (lone_pairs.hpp).
          if constexpr (lanes_law<Parts>())
            by_body(LonePairKernel<Parts, Partner>{law, band_driver_, dt, view, partner, driver_list_});
          else
            by_body(kernel);
        } else {
          all_pair_forces<true>(driver_list_, kernel);
        }
      });
    });
  }
}

std::vector<BodyTurn> ContactEngine::take_turns(const std::vector<std::uint8_t>* ghost) {
  struct Share {
    std::uint32_t body, kind, other;  // kind 0: j a driver, 1: i's partner body j, 2: j's partner body i
    Vec3 moment;                      // N m s^2
  };
  std::vector<Share> shares;
  const auto owned = [&](std::uint32_t b) { return !ghost || !(*ghost)[b]; };
  for (const PairTurn& t : turns_) {
    if (owned(t.i)) shares.push_back({t.i, t.driver ? 0u : 1u, t.j, t.moment_i});
    if (!t.driver && owned(t.j)) shares.push_back({t.j, 2u, t.i, t.moment_j});
  }
  turns_.clear();
  std::sort(shares.begin(), shares.end(), [](const Share& a, const Share& b) {
    return std::tie(a.body, a.kind, a.other) < std::tie(b.body, b.kind, b.other);
  });
  std::vector<BodyTurn> turns;
  for (const Share& s : shares) {
    if (turns.empty() || turns.back().body != s.body) turns.push_back({s.body, Vec3::Zero()});
    turns.back().moment += s.moment;
  }
  return turns;
}

void ContactEngine::close_forces(const LocalBodies& bodies, Drivers& drivers) {
  add_totals();
  flush_ended(bodies.ghost);
  if (reactions_wanted_) reduce_drivers(drivers);
}

void ContactEngine::add_totals() {
  stats_.contacts = 0;
  for (const PairList* list : {&body_list_, &driver_list_})
    for (std::uint32_t c : list->block_contacts) stats_.contacts += c;  // counted by the blocks: one thread sums few
}

void ContactEngine::reduce_bodies(const LocalBodies& bodies) {
  // One process has no ghost: its loop is compiled without the test.
  const ForceSums sums = force_sums(bodies);
  with_flag(bodies.ghost != nullptr, [&](auto has_ghosts) {
    parallel_for(bodies.size(), [&](std::size_t b) {
      if constexpr (decltype(has_ghosts)::value)
        if ((*bodies.ghost)[b]) return;  // a ghost's force is summed by its owner
      sums(b);
    });
  });
}

void ContactEngine::reduce_drivers(Drivers& drivers) const {
  for (std::size_t j = 0; j < drivers.size(); ++j) drivers[j].force = drivers[j].torque = Vec3::Zero();
  for (std::size_t k = 0; k < driver_list_.size(); ++k) {  // pair order: repeatable
    if (!driver_list_.touching[k]) continue;
    DriverState& d = drivers[driver_list_.pairs[k].j];
    d.force -= driver_list_.force_i[k];
    d.torque += driver_list_.torque_j[k];
  }
}

}  // namespace polydem
