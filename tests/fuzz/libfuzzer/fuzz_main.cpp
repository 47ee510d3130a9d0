// libFuzzer entry of one target, chosen at build time (CMake: POLYDEM_FUZZ, fuzz_NAME).
#include "../fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const auto run = polydem::fuzz::target(POLYDEM_FUZZ_TARGET).run;
  run(data, size);
  return 0;
}
