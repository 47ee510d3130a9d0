// Large blocks ask for huge pages: the kernel marks the 2 MiB-aligned part of the block "hg"
// (VM_HUGEPAGE) in /proc/self/smaps, whatever the machine's transparent_hugepage setting.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "memory/large_pages.hpp"

namespace {

constexpr std::uintptr_t kPage = std::uintptr_t(2) << 20;  // bytes

// The VmFlags of the mapping holding address a, or "" where none does.
std::string vm_flags_at(std::uintptr_t a) {
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> begin >> dash >> end && dash == '-') inside = begin <= a && a < end;
    else if (inside && line.rfind("VmFlags:", 0) == 0) return line + " ";
  }
  return "";
}

bool huge_at(std::uintptr_t a) { return vm_flags_at(a).find(" hg ") != std::string::npos; }

// A kernel built without transparent huge pages refuses the advice (EINVAL): then every answer is no.
bool kernel_has_thp() { return std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled").good(); }

std::uintptr_t first_whole_page(const void* p) { return (reinterpret_cast<std::uintptr_t>(p) + kPage - 1) & ~(kPage - 1); }

}  // namespace

TEST_CASE("advise_large_pages marks the block's whole 2 MiB pages and nothing before them") {
  const std::size_t bytes = std::size_t(9) << 20;
  void* block = std::malloc(bytes);
  REQUIRE(block);
  const std::uintptr_t page = first_whole_page(block);
  REQUIRE_FALSE(huge_at(page));
  const bool thp = kernel_has_thp();
  CHECK(polydem::advise_large_pages(block, bytes) == thp);
  CHECK(huge_at(page) == thp);
  CHECK(huge_at(page + 3 * kPage - 1) == thp);
  if (page > reinterpret_cast<std::uintptr_t>(block)) CHECK_FALSE(huge_at(page - 1));
  std::free(block);
}

TEST_CASE("advise_large_pages declines a block that holds no whole 2 MiB page") {
  const std::uintptr_t base = first_whole_page(reinterpret_cast<void*>(kPage + 4096));
  CHECK_FALSE(polydem::advise_large_pages(reinterpret_cast<void*>(base + 4096), kPage - 8192));
  CHECK_FALSE(polydem::advise_large_pages(reinterpret_cast<void*>(base + 4096), kPage));
}

#if POLYDEM_LARGE_PAGES_NEW
TEST_CASE("the program's operator new puts large vectors on huge pages, small ones not") {
  std::vector<double> large(polydem::kLargePagesFrom / sizeof(double));
  CHECK(huge_at(first_whole_page(large.data())) == kernel_has_thp());
  std::vector<double> small((std::size_t(3) << 20) / sizeof(double));  // 3 MiB: below the threshold
  const std::uintptr_t page = first_whole_page(small.data());
  if (page + 4096 <= reinterpret_cast<std::uintptr_t>(small.data() + small.size())) CHECK_FALSE(huge_at(page));
}

// A type aligned to a cache line (ContactSlot) takes the aligned operator new: its large vectors too.
struct alignas(64) Line {
  double word[8];
};
TEST_CASE("the program's operator new puts large vectors of an over-aligned type on huge pages, at its alignment") {
  // 64 MiB: above glibc's largest mmap threshold (32 MiB), so a mapping of its own, not a block
  // the cases above advised and freed.
  std::vector<Line> large((std::size_t(64) << 20) / sizeof(Line));
  CHECK(reinterpret_cast<std::uintptr_t>(large.data()) % alignof(Line) == 0);
  CHECK(huge_at(first_whole_page(large.data())) == kernel_has_thp());
}
#endif
