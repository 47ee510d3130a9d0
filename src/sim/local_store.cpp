#include "sim/local_store.hpp"

#include <algorithm>
#include <type_traits>

#include "sim/body_rows.hpp"

namespace polydem {

namespace {

// What contacts read of a body (a ghost's state), copied between two sets of arrays (Bodies or
// LocalStore).
template <class To, class From>
void copy_pose(To& to, std::size_t t, const From& from, std::size_t f) {
  to.position[t] = from.position[f];
  to.orientation[t] = from.orientation[f];
  to.velocity[t] = from.velocity[f];
  to.angular_velocity[t] = from.angular_velocity[f];
  to.velocity_end[t] = from.velocity_end[f];
  to.angular_velocity_end[t] = from.angular_velocity_end[f];
}

// What integration changes of a body.
template <class To, class From>
void copy_motion(To& to, std::size_t t, const From& from, std::size_t f) {
  copy_pose(to, t, from, f);
  to.angular_momentum[t] = from.angular_momentum[f];
  to.force[t] = from.force[f];
  to.torque[t] = from.torque[f];
}

// A new row's value (Eigen's vectors are not zeroed by their constructor): a ghost landed from
// a parcel keeps zero inertia, angular momentum, force and torque.
template <class T>
T blank() {
  if constexpr (std::is_same_v<T, Vec3>) return Vec3::Zero();
  else if constexpr (std::is_same_v<T, Quat>) return Quat::Identity();
  else return T{};
}

// Where each row of two increasing id sequences goes in their merge: a[k] for the first's k-th
// (its id id_a(k)), b[k] for the second's.
struct MergedRows {
  std::vector<std::uint32_t> a, b;
};

template <class IdA>
MergedRows merged_rows(std::size_t n_a, IdA id_a, const std::vector<std::uint32_t>& ids_b) {
  MergedRows to{std::vector<std::uint32_t>(n_a), std::vector<std::uint32_t>(ids_b.size())};
  std::size_t i = 0, j = 0;
  while (i < n_a || j < ids_b.size()) {
    if (j == ids_b.size() || (i < n_a && id_a(i) < ids_b[j])) {
      to.a[i] = std::uint32_t(i + j);
      ++i;
    } else {
      to.b[j] = std::uint32_t(i + j);
      ++j;
    }
  }
  return to;
}

}  // namespace

void LocalStore::select(const Bodies& all, std::vector<std::uint32_t> ids, std::vector<std::uint8_t> is_ghost) {
  resize(ids.size());
  global_id = std::move(ids);
  ghost = std::move(is_ghost);
  const std::size_t n = global_id.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t g = global_id[k];
    shape[k] = all.shape[g];
    scale[k] = all.scale[g];
    mass[k] = all.mass[g];
    inertia[k] = all.inertia[g];
    group[k] = all.group[g];
    id[k] = all.id[g];
    copy_motion(*this, k, all, g);
  }
}

// Grown once per field (a rebuild appends its kept bodies: pushed one by one, each field
// reallocated ~10 times, 14e6 instructions over the pour's -np 2 rebuilds).
void LocalStore::append(const LocalStore& from, const std::vector<std::uint32_t>& rows) {
  with_arrays(from, [&](auto& to, const auto& at) {
    const std::size_t first = to.size();
    to.resize(first + rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) to[first + k] = at[rows[k]];
  });
}

void LocalStore::merge_of(const LocalStore& from, const std::vector<std::uint32_t>& rows, const LocalStore& add,
                          std::size_t spare) {
  const MergedRows to = merged_rows(rows.size(), [&](std::size_t k) { return from.global_id[rows[k]]; }, add.global_id);
  const std::size_t n = rows.size() + add.size();
  with_arrays(from, [&](auto& v, const auto& at) {
    v.clear();
    v.reserve(n + spare);
    v.resize(n);
    for (std::size_t k = 0; k < rows.size(); ++k) v[to.a[k]] = at[rows[k]];
  });
  with_arrays(add, [&](auto& v, const auto& at) {
    for (std::size_t k = 0; k < at.size(); ++k) v[to.b[k]] = at[k];
  });
}

void LocalStore::merge_in(const LocalStore& add) {
  const std::size_t held = size();
  const MergedRows to = merged_rows(held, [&](std::size_t k) { return global_id[k]; }, add.global_id);
  with_arrays(add, [&](auto& v, const auto& at) {
    v.resize(held + at.size());
    std::size_t i = held, k = v.size();  // the next row held to move; one past the next row to write
    for (std::size_t g = at.size(); g-- > 0;) {
      while (k > to.b[g] + 1) v[--k] = v[--i];
      v[--k] = at[g];
    }
  });
}

void LocalStore::sort_by_id() {
  const std::vector<std::uint32_t> order = id_order(global_id);
  if (std::adjacent_find(order.begin(), order.end(), [](std::uint32_t a, std::uint32_t b) { return b != a + 1; }) ==
      order.end())
    return;  // in order already: nothing moves
  with_arrays(*this, [&](auto& v, auto&) { v = subset(v, order); });
}

std::vector<std::uint32_t> id_order(const std::vector<std::uint32_t>& ids) {
  constexpr std::size_t kMaxRuns = 64;  // more: not a rebuild's runs, sorted
  std::vector<std::uint64_t> keys(ids.size());  // id above, row below: one compare a step
  for (std::size_t k = 0; k < ids.size(); ++k) keys[k] = std::uint64_t(ids[k]) << 32 | k;
  std::vector<std::size_t> ends;
  for (std::size_t k = 1; k < keys.size() && ends.size() <= kMaxRuns; ++k)
    if (keys[k] < keys[k - 1]) ends.push_back(k);
  if (ends.size() > kMaxRuns) {
    std::sort(keys.begin(), keys.end());
  } else {
    ends.push_back(keys.size());
    for (std::size_t r = 0; r + 1 < ends.size(); ++r)  // the sorted prefix and the next run
      std::inplace_merge(keys.begin(), keys.begin() + std::ptrdiff_t(ends[r]), keys.begin() + std::ptrdiff_t(ends[r + 1]));
  }
  std::vector<std::uint32_t> order(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) order[k] = std::uint32_t(keys[k]);
  return order;
}

void LocalStore::resize(std::size_t n) {
  with_arrays(*this, [n](auto& v, auto&) { v.resize(n, blank<typename std::decay_t<decltype(v)>::value_type>()); });
}

void LocalStore::publish(Bodies& all) const {
  for (std::size_t k = 0; k < global_id.size(); ++k)
    if (!ghost[k]) copy_motion(all, global_id[k], *this, k);
}

void LocalStore::pull(const Bodies& all) {
  for (std::size_t k = 0; k < global_id.size(); ++k)
    if (!ghost[k]) copy_motion(*this, k, all, global_id[k]);
}

std::uint32_t LocalStore::local_of(std::uint32_t g) const {
  return std::uint32_t(std::lower_bound(global_id.begin(), global_id.end(), g) - global_id.begin());
}

std::vector<std::uint32_t> LocalStore::owned_rows() const {
  std::vector<std::uint32_t> rows;
  for (std::size_t k = 0; k < ghost.size(); ++k)
    if (!ghost[k]) rows.push_back(std::uint32_t(k));
  return rows;
}

}  // namespace polydem
