#pragma once
// Large blocks on 2 MiB pages: a million bodies' arrays span ~1 GB, and with 4 KiB pages the
// pair loop's reads of partners miss the TLB (README, "Large pages").
#include <cstddef>

namespace polydem {

// Bytes from which an allocation asks for transparent huge pages: a whole 2 MiB page fits in it
// wherever it starts (216,000 bodies' Vec3 arrays, 5 MB, and up).
inline constexpr std::size_t kLargePagesFrom = std::size_t(4) << 20;

// Asks the kernel (madvise MADV_HUGEPAGE) to back the 2 MiB-aligned part of [p, p + bytes) with
// huge pages. False where no whole 2 MiB page fits or the kernel refuses.
bool advise_large_pages(void* p, std::size_t bytes);

}  // namespace polydem
