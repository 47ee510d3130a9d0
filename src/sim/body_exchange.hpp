#pragma once
// Body state as bytes between ranks. A ghost parcel carries what the contact stage reads and
// changes every step (pose and velocities, 152 bytes a body) in the order of a GhostPlan list
// both ranks hold; an owned-state record carries all that integration changes (224 bytes
// and the id), for the gathers that give every rank the whole state (rebuilds, output).
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

// The integration state of bodies `ids` with their ids.
std::vector<char> pack_owned(const Bodies& bodies, const std::vector<std::uint32_t>& ids);
// Writes each record of a pack_owned parcel into its body; returns their ids, in parcel order.
std::vector<std::uint32_t> unpack_owned(const std::vector<char>& bytes, Bodies& bodies);

}  // namespace polydem
