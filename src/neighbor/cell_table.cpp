#include "neighbor/cell_table.hpp"

#include <bit>

namespace polydem {

void CellTable::reset(std::size_t max_cells) {
  const std::size_t capacity = std::bit_ceil(2 * max_cells + 2);
  keys.resize(capacity);
  ids.assign(capacity, kNoCell);
  mask = capacity - 1;
  count = 0;
}

// splitmix64 finaliser over the three coordinates: neighbouring cells land in unrelated slots.
std::size_t CellTable::slot_of(const CellCoord& c) const {
  std::uint64_t h = static_cast<std::uint64_t>(c.x) * 0x9E3779B97F4A7C15ull;
  h ^= static_cast<std::uint64_t>(c.y) * 0xC2B2AE3D27D4EB4Full;
  h ^= static_cast<std::uint64_t>(c.z) * 0x165667B19E3779F9ull;
  h ^= h >> 31;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 29;
  return static_cast<std::size_t>(h) & mask;
}

std::uint32_t CellTable::insert(const CellCoord& c) {
  std::size_t s = slot_of(c);
  while (ids[s] != kNoCell) {
    if (keys[s] == c) return ids[s];
    s = (s + 1) & mask;
  }
  keys[s] = c;
  ids[s] = count;
  return count++;
}

std::uint32_t CellTable::find(const CellCoord& c) const {
  std::size_t s = slot_of(c);
  while (ids[s] != kNoCell) {
    if (keys[s] == c) return ids[s];
    s = (s + 1) & mask;
  }
  return kNoCell;
}

}  // namespace polydem
