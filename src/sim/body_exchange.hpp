#pragma once
// Body state as bytes between ranks. At a rebuild a mover's parcel carries all its new owner's
// store holds of it (state and constants), and a ghost parcel what the contact stage reads
// and output names (pose, velocities, shape, scale, mass, group, user id) in the order of a
// GhostPlan list both ranks hold; each step a motion parcel carries the ghosts' motion alone;
// an owned-state record carries all that integration changes (224 bytes and the id), for the
// gathers that give every rank the whole state (output, drag and fluid forces).
#include <cstdint>
#include <vector>

#include "polydem/bodies.hpp"
#include "sim/local_store.hpp"

namespace polydem {

// A ghost's constants: shape, scale, mass, group, user id (4 + 8 + 8 + 4 + 4 bytes).
constexpr std::size_t kGhostConstantBytes = 2 * sizeof(double) + 2 * sizeof(int) + sizeof(std::uint32_t);
// A ghost at a rebuild: 5 vectors, 1 quaternion and its constants (180 bytes).
constexpr std::size_t kGhostBytes = 19 * sizeof(double) + kGhostConstantBytes;
constexpr std::size_t kOwnedBytes = sizeof(std::uint32_t) + 28 * sizeof(double);  // id, 8 vectors, 1 quaternion
// A body changing owner: its owned record, its ghost constants and its inertia (280 bytes).
constexpr std::size_t kMoverBytes = kOwnedBytes + kGhostConstantBytes + 3 * sizeof(double);

// The ghost state and constants of a store's rows `rows`, in that order.
std::vector<char> pack_ghosts(const LocalStore& store, const std::vector<std::uint32_t>& rows);
// Appends the bodies of a pack_ghosts parcel to `store` as ghosts of global ids `ids` (the
// parcel's order); their integration state (angular momentum, force, torque) and inertia zero.
void unpack_ghosts(const std::vector<char>& bytes, const std::vector<std::uint32_t>& ids, LocalStore& store);

// The owned bodies at a store's rows `rows` changing owner: everything the store holds of
// each (global id, integration state, constants).
std::vector<char> pack_movers(const LocalStore& store, const std::vector<std::uint32_t>& rows);
// Appends the bodies of a pack_movers parcel to `store` as owned bodies, bit for bit.
void unpack_movers(const std::vector<char>& bytes, LocalStore& store);

// A step's ghost parcel between rebuilds (the ghosts' motion): the velocities, their prediction
// for the step's end and, when bodies turn, the orientation, not the position: the receiver
// drifts its copy as the owner did, x += v dt, the same bits (the only write of a position
// between rebuilds). What it leaves out where the scene never reads it of a ghost:
struct MotionFields {
  bool orientation = true;  // false: a spheres-only scene, every orientation the identity
  bool spin_end = true;     // angular_velocity_end; false: spheres whose law has no tangential dashpot (its only reader)
};
// Bytes a body: spheres 72 without spin_end, 96 with it; else 128.
std::size_t motion_bytes(MotionFields fields);
// The motion of a rank's bodies at local indices `local` of its store (its owned bodies).
void pack_motion(const LocalStore& store, const std::vector<std::uint32_t>& local, MotionFields fields, char* into);
// Writes a pack_motion parcel into the store's ghosts at local indices `local`, each position
// `drifted[k]` (the k-th body's at the last step) moved by v dt first.
struct MotionTarget {
  const std::vector<std::uint32_t>& local;
  Vec3* drifted;  // m
};
void unpack_motion(const char* bytes, const MotionTarget& to, MotionFields fields, double dt, LocalStore& store);

// The integration state of bodies `ids` with their ids.
std::vector<char> pack_owned(const Bodies& bodies, const std::vector<std::uint32_t>& ids);
// The same records of a store's rows `rows`, each with its global id (a gather from the store).
std::vector<char> pack_owned(const LocalStore& store, const std::vector<std::uint32_t>& rows);
// Writes each record of a pack_owned parcel into its body; returns their ids, in parcel order.
std::vector<std::uint32_t> unpack_owned(const std::vector<char>& bytes, Bodies& bodies);

}  // namespace polydem
