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

// Over-aligned types (a contact slot starts a cache line): aligned_alloc, whose size must be a
// multiple of the alignment, with the same advice for a large block.
void* allocate(std::size_t bytes, std::align_val_t align) {
  const std::size_t a = static_cast<std::size_t>(align);
  const std::size_t rounded = bytes ? (bytes + a - 1) / a * a : a;
  void* p = std::aligned_alloc(a, rounded);
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
void* operator new(std::size_t bytes, std::align_val_t align) { return allocate(bytes, align); }
void* operator new[](std::size_t bytes, std::align_val_t align) { return allocate(bytes, align); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
