#include "contact/slot_store.hpp"

#include <algorithm>

#include "polydem/release.hpp"

namespace polydem {

// Copies of `from`'s made chunks into `to` (sized alike).
template <class T>
static void copy_chunks(const std::vector<std::unique_ptr<T[]>>& from, std::vector<std::unique_ptr<T[]>>& to,
                        std::size_t n) {
  for (std::size_t c = 0; c < from.size(); ++c)
    if (from[c]) {
      to[c] = std::make_unique<T[]>(n);
      std::copy_n(from[c].get(), n, to[c].get());
    }
}

// N m, a chunk of zero moments (Eigen's vectors are not zeroed by value-initialisation).
static std::unique_ptr<Vec3[]> zero_moments(std::size_t n) {
  auto chunk = std::make_unique<Vec3[]>(n);
  std::fill_n(chunk.get(), n, Vec3::Zero());
  return chunk;
}

SlotStore& SlotStore::operator=(const SlotStore& other) {
  if (this == &other) return *this;
  reset(other.chunks_.size() << kShift, other.rolls_, other.records_);
  made_ = other.made_;
  copy_chunks(other.chunks_, chunks_, kChunk);
  copy_chunks(other.moments_, moments_, kChunk);
  copy_chunks(other.forces_, forces_, kChunk);
  return *this;
}

void SlotStore::reset(std::size_t capacity, bool rolls, bool records) {
  release(chunks_);
  release(moments_);
  release(forces_);
  rolls_ = rolls;
  records_ = records;
  chunks_.resize((capacity + kMask) >> kShift);
  if (rolls_) moments_.resize(chunks_.size());
  if (records_) forces_.resize(chunks_.size());
  made_ = 0;
}

void SlotStore::set_records(bool on) {
  if (on == records_) return;
  records_ = on;
  if (!on) {
    release(forces_);  // 32 bytes a state between the steps whose contacts are read
    return;
  }
  forces_.resize(chunks_.size());
  for (std::size_t c = 0; c < chunks_.size(); ++c)
    if (chunks_[c]) forces_[c] = std::make_unique<SlotForce[]>(kChunk);  // zeroed
}

std::uint32_t SlotStore::make() {
  std::uint32_t g;
  // Rare (a slot's first touch since the rebuild): a lock is cheaper than a state for every slot.
#pragma omp critical(polydem_slot_store)
  {
    g = made_++;
    const std::size_t c = g >> kShift;
    if (!chunks_[c]) {
      chunks_[c] = std::make_unique<SlotState[]>(kChunk);  // zeroed
      if (rolls_) moments_[c] = zero_moments(kChunk);
      if (records_) forces_[c] = std::make_unique<SlotForce[]>(kChunk);
    }
  }
  return g;
}

}  // namespace polydem
