#pragma once
// Occupied cells only, in an open-addressing hash table: memory O(bodies) however large and
// sparse the domain is (one body far away does not allocate a giant grid).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace polydem {

struct CellCoord {
  std::int64_t x, y, z;  // integer cell coordinates, >= 0
  friend bool operator==(const CellCoord&, const CellCoord&) = default;
};

class CellTable {
 public:
  static constexpr std::uint32_t kNoCell = 0xFFFFFFFFu;

  // Empties the table, sized for up to `max_cells` distinct cells at load factor <= 1/2.
  void reset(std::size_t max_cells);
  // Dense id of `c`, numbered in first-insertion order (so it is deterministic).
  std::uint32_t insert(const CellCoord& c);
  // Dense id of `c`, or kNoCell when no body lies in it.
  std::uint32_t find(const CellCoord& c) const;
  std::size_t size() const { return count; }
  // Bytes held by the table (its capacity).
  std::size_t bytes() const {
    return keys.capacity() * sizeof(CellCoord) + ids.capacity() * sizeof(std::uint32_t);
  }

 private:
  std::size_t slot_of(const CellCoord& c) const;

  std::vector<CellCoord> keys;
  std::vector<std::uint32_t> ids;  // kNoCell marks an empty slot
  std::size_t mask = 0;
  std::uint32_t count = 0;
};

}  // namespace polydem
