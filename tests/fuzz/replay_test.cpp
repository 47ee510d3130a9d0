// Replays every seed (tests/fuzz/corpus/NAME) and every saved crash reproducer
// (tests/fuzz/crashes/NAME) through its fuzz target in the normal build: each must end in
// success or InputError, never another exception (under ASan/UBSan: never a report).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "fuzz_targets.hpp"

namespace fs = std::filesystem;
using polydem::fuzz::Target;

namespace {

std::vector<fs::path> inputs_of(const std::string& kind, const std::string& name) {
  std::vector<fs::path> files;
  const fs::path dir = fs::path(POLYDEM_SOURCE_DIR) / "tests" / "fuzz" / kind / name;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::size_t replay(const Target& t, const std::string& kind) {
  std::size_t count = 0;
  for (const fs::path& file : inputs_of(kind, t.name)) {
    std::ifstream in(file, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    INFO(file.string());
    CHECK_NOTHROW(t.run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
    ++count;
  }
  return count;
}

}  // namespace

TEST_CASE("fuzz corpus: every seed of every target reads or is refused with InputError", "[fuzz]") {
  for (const Target& t : polydem::fuzz::targets()) {
    INFO("target " << t.name);
    CHECK(replay(t, "corpus") >= 3);  // an empty seed folder would test nothing
  }
}

TEST_CASE("fuzz crashes: every saved reproducer reads or is refused with InputError", "[fuzz]") {
  for (const Target& t : polydem::fuzz::targets()) replay(t, "crashes");
}
