// The program's operator new: malloc's, and a large block asks for huge pages before its first
// touch (the kernel then faults it in 2 MiB at a time). Delete is free, as new is malloc.
#include <cstdlib>
#include <new>

#include "memory/large_pages.hpp"

namespace {

void* allocate(std::size_t bytes) {
  void* p = std::malloc(bytes ? bytes : 1);
  if (!p) throw std::bad_alloc();
  if (bytes >= polydem::kLargePagesFrom) polydem::advise_large_pages(p, bytes);
  return p;
}

}  // namespace

void* operator new(std::size_t bytes) { return allocate(bytes); }
void* operator new[](std::size_t bytes) { return allocate(bytes); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
