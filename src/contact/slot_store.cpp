#include "contact/slot_store.hpp"

#include <algorithm>

#include "polydem/release.hpp"

namespace polydem {

SlotStore& SlotStore::operator=(const SlotStore& other) {
  if (this == &other) return *this;
  reset(other.chunks_.size() << kShift);
  made_ = other.made_;
  for (std::size_t c = 0; c < chunks_.size(); ++c)
    if (other.chunks_[c]) {
      chunks_[c] = std::make_unique<SlotState[]>(std::size_t(kMask) + 1);
      std::copy_n(other.chunks_[c].get(), std::size_t(kMask) + 1, chunks_[c].get());
    }
  return *this;
}

void SlotStore::reset(std::size_t capacity) {
  release(chunks_);
  chunks_.resize((capacity + kMask) >> kShift);
  made_ = 0;
}

std::uint32_t SlotStore::make() {
  std::uint32_t g;
  // Rare (a slot's first touch since the rebuild): a lock is cheaper than a state for every slot.
#pragma omp critical(polydem_slot_store)
  {
    g = made_++;
    std::unique_ptr<SlotState[]>& chunk = chunks_[g >> kShift];
    if (!chunk) chunk = std::make_unique<SlotState[]>(std::size_t(kMask) + 1);  // zeroed
  }
  return g;
}

}  // namespace polydem
