#include "memory/large_pages.hpp"

#include <cstdint>

#include <sys/mman.h>

namespace polydem {

bool advise_large_pages(void* p, std::size_t bytes) {
  constexpr std::uintptr_t page = std::uintptr_t(2) << 20;  // bytes, x86-64's huge page
  const auto start = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t begin = (start + page - 1) & ~(page - 1), end = (start + bytes) & ~(page - 1);
  return end > begin && madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE) == 0;
}

}  // namespace polydem
