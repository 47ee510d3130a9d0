#pragma once
// Older checkpoint formats made from a format-08 file (sim/checkpoint.cpp), for the tests that
// resume them: 05 is 08's payload between its 40-byte header and 8-byte checksum less its body
// order (the file must be of a run in the scene's order, as older files are) and the ledger's
// open sums (each touching pair's pending energy after its list's slots, the ended
// contacts' exact sum after both lists): a file written where the ledger closes holds zeros there.
#include <cstdint>
#include <cstring>
#include <set>
#include <stdexcept>
#include <string>

#include "contact/exact_sum.hpp"
#include "polydem/math.hpp"

namespace polydem {

inline std::uint64_t count_at(const std::string& p, std::size_t at) {
  std::uint64_t n = 0;
  std::memcpy(&n, p.data() + at, 8);
  return n;
}

inline std::string as_format05(const std::string& bytes08) {
  if (bytes08.compare(0, 8, "PDCKPT08") != 0) throw std::runtime_error("not a format-08 checkpoint");
  std::string p = bytes08.substr(40, bytes08.size() - 48);
  for (std::uint64_t b = 0; b < count_at(p, 0); ++b)
    if (std::memcmp(p.data() + 8 + 4 * b, &b, 4) != 0) throw std::runtime_error("not in the scene's body order");
  p = p.substr(8 + 4 * count_at(p, 0));
  auto count = [&](std::size_t at) { return count_at(p, at); };
  std::size_t at = 8 + 8 + 72;  // step, dt, ledger
  for (std::size_t size : {sizeof(Vec3), sizeof(Quat), sizeof(Vec3), sizeof(Vec3), sizeof(Vec3), sizeof(Vec3), sizeof(Vec3)})
    at += 8 + count(at) * size;
  at += 8 + count(at) * (1 + 9 * sizeof(Vec3) + sizeof(Quat));  // the drivers
  std::string out = "PDCKPT05" + p.substr(0, at);
  constexpr std::size_t kSlot = 152;  // bytes of a stored contact
  for (int list = 0; list < 2; ++list) {
    const std::uint64_t n = count(at);
    std::set<std::string> pairs;
    for (std::uint64_t s = 0; s < n; ++s) pairs.insert(p.substr(at + 8 + s * kSlot, 8));
    out += p.substr(at, 8 + n * kSlot);
    at += 8 + n * kSlot + pairs.size() * sizeof(EnergyParts);
  }
  return out + p.substr(at + 8 + 4 * ExactSum::kWords * 8);  // the output progress
}

}  // namespace polydem
