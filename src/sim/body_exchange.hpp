#pragma once
// Body state as bytes between ranks. A ghost parcel carries what the contact stage reads and
// changes (pose and velocities, 152 bytes a body; at a rebuild) in the order of a GhostPlan
// list both ranks hold, a motion parcel the same less what the receiver knows (each step); an
// owned-state record carries all that integration changes (224 bytes and the id), for the gathers that give every rank the whole state (rebuilds, output).
#include <cstdint>
#include <vector>

#include "polydem/bodies.hpp"
#include "sim/local_store.hpp"

namespace polydem {

constexpr std::size_t kGhostBytes = 19 * sizeof(double);  // 5 vectors, 1 quaternion
constexpr std::size_t kOwnedBytes = sizeof(std::uint32_t) + 28 * sizeof(double);  // id, 8 vectors, 1 quaternion

// The ghost state of bodies `ids`, in that order.
std::vector<char> pack_ghosts(const Bodies& bodies, const std::vector<std::uint32_t>& ids);
void pack_ghosts(const Bodies& bodies, const std::vector<std::uint32_t>& ids, char* into);  // ids.size() x kGhostBytes
// Writes a parcel of pack_ghosts(…, ids) into the bodies `ids`, or into a rank's local store
// at the same bodies' local indices `local`.
void unpack_ghosts(const std::vector<char>& bytes, const std::vector<std::uint32_t>& ids, Bodies& bodies);
void unpack_ghosts(const std::vector<char>& bytes, const std::vector<std::uint32_t>& local, LocalStore& store);

// A step's ghost parcel between rebuilds (the ghosts' motion): the velocities, and the
// orientation when bodies turn (`turning` false: a spheres-only scene, every orientation the
// identity), not the position: the receiver drifts its copy as the owner did, x += v dt, the
// same bits (the only write of a position between rebuilds). Spheres 96 bytes a body, else 128.
std::size_t motion_bytes(bool turning);
// The motion of a rank's bodies at local indices `local` of its store (its owned bodies).
void pack_motion(const LocalStore& store, const std::vector<std::uint32_t>& local, bool turning, char* into);
// Writes a pack_motion parcel into the store's ghosts at local indices `local`, each position
// `drifted[k]` (the k-th body's at the last step) moved by v dt first.
struct MotionTarget {
  const std::vector<std::uint32_t>& local;
  Vec3* drifted;  // m
};
void unpack_motion(const char* bytes, const MotionTarget& to, bool turning, double dt, LocalStore& store);

// The integration state of bodies `ids` with their ids.
std::vector<char> pack_owned(const Bodies& bodies, const std::vector<std::uint32_t>& ids);
// Writes each record of a pack_owned parcel into its body; returns their ids, in parcel order.
std::vector<std::uint32_t> unpack_owned(const std::vector<char>& bytes, Bodies& bodies);

}  // namespace polydem
