// Checkpoints you can trust: format 06 carries the payload of format 05 between a header and a
// checksum; damaged, truncated, extended or foreign checkpoints are refused with a message
// (InputError), never a crash or an allocation failure; formats 05 and older still resume.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "polydem/error.hpp"
#include "sim/checkpoint.hpp"
#include "old_formats.hpp"
#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

// 27 cubes thrown on a floor with random orientations, faster from higher: contacts with the
// floor and each other.
struct Drop {
  Scene scene = base_scene(law(1e5, 0.5, 0.4, 1e5), true, Vec3(0, 0, -9.807));
  ShapeLibrary lib = library({cube_shape(0.009, 0.0005)});
  std::vector<BodySpec> specs;
  Drop() {
    std::mt19937_64 rng(3);
    auto u = [&] { return double(rng() >> 11) * 0x1.0p-53 - 0.5; };
    for (int k = 0; k < 27; ++k)
      specs.push_back(body("cube", Vec3(0.017 * (k % 3 - 1), 0.017 * ((k / 3) % 3 - 1), 0.0085 + 0.017 * (k / 9)),
                           Vec3(0, 0, -0.5 - 0.2 * (k / 9)), Quat(Eigen::Vector4d(u(), u(), u(), u())).normalized()));
  }
};

struct TempDir {
  std::filesystem::path path = std::filesystem::temp_directory_path() /
                               ("polydem_test_ckpt_" + std::to_string(::getpid()));
  TempDir() { std::filesystem::create_directories(path); }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::string operator/(const char* name) const { return (path / name).string(); }
};

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// Format 03 from format 07: the ledger without its 3 shares, each contact without its last
// dashpot force, gap and weight (the last 24 of its 152 bytes).
std::string as_format03(const std::string& bytes07, std::size_t bodies) {
  const std::string p = as_format05(bytes07);
  std::size_t at = 8 + 8 + 8;
  std::string out = "PDCKPT03" + p.substr(8, 16) + p.substr(at, 72 - 24);
  at += 72;
  const std::size_t arrays = 7 * 8 + bodies * (6 * sizeof(Vec3) + sizeof(Quat));
  std::uint64_t drivers = 0;
  std::memcpy(&drivers, p.data() + at + arrays, 8);
  const std::size_t state = arrays + 8 + drivers * (1 + 9 * sizeof(Vec3) + sizeof(Quat));
  out += p.substr(at, state);
  at += state;
  for (int list = 0; list < 2; ++list) {
    std::uint64_t n = 0;
    std::memcpy(&n, p.data() + at, 8);
    out += p.substr(at, 8);
    at += 8;
    for (std::uint64_t k = 0; k < n; ++k, at += 152) out += p.substr(at, 128);
  }
  return out + p.substr(at);
}

std::uint64_t state_hash(const Bodies& b) {
  std::uint64_t h = 1469598103934665603ull;
  auto add = [&](const void* data, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) h = (h ^ static_cast<const unsigned char*>(data)[k]) * 1099511628211ull;
  };
  add(b.position.data(), b.size() * sizeof(Vec3));
  add(b.orientation.data(), b.size() * sizeof(Quat));
  add(b.velocity.data(), b.size() * sizeof(Vec3));
  add(b.angular_momentum.data(), b.size() * sizeof(Vec3));
  return h;
}

// Writes a checkpoint of the drop after `steps` steps with two output frames, and returns
// the state hash after `more` further steps from it.
Bodies checkpoint_then_run_bodies(const Drop& d, const std::string& path, int steps, int more) {
  Simulation sim(d.scene, d.lib, d.specs);
  for (int s = 0; s < steps; ++s) sim.step();
  REQUIRE(sim.engine().stats().contacts > 0);
  OutputProgress progress{2, {{0.0, {"bodies_000000.vtu"}}, {sim.time(), {"bodies_000001.vtu", "drivers_000001.vtp"}}}};
  write_checkpoint(path, sim, progress);
  sim.engine().force_rebuild();  // as the runner does at every checkpoint
  for (int s = 0; s < more; ++s) sim.step();
  return sim.bodies;
}
std::uint64_t checkpoint_then_run(const Drop& d, const std::string& path, int steps, int more) {
  return state_hash(checkpoint_then_run_bodies(d, path, steps, more));
}

Bodies resume_and_run_bodies(const Drop& d, const std::string& path, int more, bool force = false) {
  Simulation sim(d.scene, d.lib, d.specs);
  OutputProgress progress;
  read_checkpoint(path, sim, progress, force);
  CHECK(progress.frames.size() == 2);
  CHECK(progress.frames[1].files.size() == 2);
  for (int s = 0; s < more; ++s) sim.step();
  return sim.bodies;
}
std::uint64_t resume_and_run(const Drop& d, const std::string& path, int more, bool force = false) {
  return state_hash(resume_and_run_bodies(d, path, more, force));
}

bool refused(const Drop& d, const std::string& path, const std::string& text = "") {
  Simulation sim(d.scene, d.lib, d.specs);
  OutputProgress progress;
  try {
    read_checkpoint(path, sim, progress);
  } catch (const InputError& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).find(path) == 0);  // the message names the checkpoint
    CHECK(std::string(e.what()).find(text) != std::string::npos);
    return true;
  }
  return false;
}

}  // namespace

TEST_CASE("format 07 and format 05 checkpoints resume bit for bit", "[checkpoint]") {
  const Drop d;
  const TempDir dir;
  const std::uint64_t uninterrupted = checkpoint_then_run(d, dir / "a.bin", 2000, 1000);
  CHECK(resume_and_run(d, dir / "a.bin", 1000) == uninterrupted);
  write_bytes(dir / "a05.bin", as_format05(read_bytes(dir / "a.bin")));
  CHECK(resume_and_run(d, dir / "a05.bin", 1000) == uninterrupted);
}

// Written between two closes of the energy ledger, where the uninterrupted run does not rebuild
// its lists (a SIGTERM's stop) and the resumed run must: the open sums (the touching pairs'
// pending energies, the ended contacts' exact sum) come back, so the ledger keeps its bits
// through the closes and the contacts that end after.
TEST_CASE("a checkpoint written between ledger closes resumes with the ledger's bits", "[checkpoint]") {
  const Drop d;
  const TempDir dir;
  Simulation sim(d.scene, d.lib, d.specs);
  for (int s = 0; s < 2050; ++s) sim.step();
  REQUIRE(sim.engine().stats().contacts > 0);
  const EnergyRow open = sim.energy();
  REQUIRE(open.dissipated != sim.ledger.dissipated);  // J, 50 steps open
  write_checkpoint(dir / "mid.bin", sim, OutputProgress{});
  Simulation resumed(d.scene, d.lib, d.specs);
  OutputProgress progress;
  read_checkpoint(dir / "mid.bin", resumed, progress);
  CHECK(std::bit_cast<std::uint64_t>(resumed.energy().dissipated) == std::bit_cast<std::uint64_t>(open.dissipated));
  std::size_t ended = 0;  // contacts that ended after the checkpoint
  for (int s = 0; s < 1000; ++s) {
    const std::size_t before = sim.engine().stats().contacts;
    sim.step();
    resumed.step();
    ended += before > sim.engine().stats().contacts;
  }
  CHECK(ended > 0);
  CHECK(state_hash(resumed.bodies) == state_hash(sim.bodies));
  const EnergyRow a = sim.energy(), b = resumed.energy();
  for (auto field : {&EnergyRow::dissipated, &EnergyRow::dissipated_sliding, &EnergyRow::dissipated_dashpot,
                     &EnergyRow::patch_work, &EnergyRow::elastic, &EnergyRow::kinetic})
    CHECK(std::bit_cast<std::uint64_t>(a.*field) == std::bit_cast<std::uint64_t>(b.*field));
}

// Format 03 lacks each contact's last dashpot force, gap and weight, which the dashpot reads
// (contact/law/second_order.hpp): its contacts take one step as new ones, so the run ends near
// the uninterrupted one, not on its bits.
TEST_CASE("a format-03 checkpoint (shortest contacts) still resumes, near the uninterrupted run", "[checkpoint]") {
  const Drop d;
  const TempDir dir;
  const Bodies uninterrupted = checkpoint_then_run_bodies(d, dir / "a.bin", 2000, 10);
  write_bytes(dir / "a03.bin", as_format03(read_bytes(dir / "a.bin"), d.specs.size()));
  const Bodies resumed = resume_and_run_bodies(d, dir / "a03.bin", 10);
  double apart = 0.0;  // m
  for (std::size_t b = 0; b < resumed.size(); ++b)
    apart = std::max(apart, (resumed.position[b] - uninterrupted.position[b]).norm());
  std::printf("format 03: %.3g m from the uninterrupted run after 10 steps\n", apart);
  CHECK(apart > 0.0);
  CHECK(apart < 1e-6);  // m, measured 2.6e-8 (cubes of 9 mm)
}

TEST_CASE("a damaged, truncated or extended checkpoint is refused", "[checkpoint]") {
  const Drop d;
  const TempDir dir;
  checkpoint_then_run(d, dir / "a.bin", 2000, 0);
  const std::string good = read_bytes(dir / "a.bin");
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 40; ++trial) {  // one byte changed anywhere
    std::string bad = good;
    const std::size_t at = rng() % bad.size();
    bad[at] = char(bad[at] ^ (1 + rng() % 255));
    write_bytes(dir / "bad.bin", bad);
    INFO("byte " << at);
    CHECK(refused(d, dir / "bad.bin"));
  }
  write_bytes(dir / "bad.bin", good + "garbage");
  CHECK(refused(d, dir / "bad.bin", "appended"));
  write_bytes(dir / "bad.bin", good.substr(0, good.size() / 2));
  CHECK(refused(d, dir / "bad.bin", "truncated"));
  write_bytes(dir / "bad.bin", good.substr(0, 20));
  CHECK(refused(d, dir / "bad.bin", "truncated"));
}

TEST_CASE("a format-05 checkpoint (no checksum) with absurd counts or values is refused", "[checkpoint]") {
  const Drop d;
  const TempDir dir;
  checkpoint_then_run(d, dir / "a.bin", 2000, 0);
  const std::string good = as_format05(read_bytes(dir / "a.bin"));
  const std::size_t n = d.specs.size();
  // Offsets in format 05: magic, step, dt, ledger (72 bytes), then 7 arrays of n entries with a count each.
  const std::size_t positions = 8 + 8 + 8 + 72, orientations = positions + 8 + n * sizeof(Vec3);
  auto with = [&](std::size_t at, const void* value, std::size_t size) {
    std::string bad = good;
    std::memcpy(bad.data() + at, value, size);
    write_bytes(dir / "bad.bin", bad);
    return dir / "bad.bin";
  };
  const std::uint64_t huge = std::uint64_t(1) << 60;
  CHECK(refused(d, with(positions, &huge, 8), "another scene"));
  const std::int64_t far_step = std::int64_t(1) << 62;  // t ~ 1e14 s: the schedules could not advance
  CHECK(refused(d, with(8, &far_step, 8), "step counter"));
  const Quat zero(0, 0, 0, 0);
  CHECK(refused(d, with(orientations + 8 + 5 * sizeof(Quat), &zero, sizeof(zero)), "orientation"));
  const double nan = std::nan("");
  CHECK(refused(d, with(positions + 8 + 3 * sizeof(Vec3), &nan, 8), "not finite"));
  // The tail: frames of the output progress; their count sits before 2 frames of 1 and 2 names.
  const std::size_t frames_tail = 8 + (8 + 8 + 8 + 17) + (8 + 8 + 8 + 17 + 8 + 18);
  CHECK(refused(d, with(good.size() - frames_tail, &huge, 8), "output frame count"));
  const std::size_t first_name = good.size() - (8 + 8 + 17 + 8 + 8 + 8 + 17 + 8 + 18);
  CHECK(refused(d, with(first_name, &huge, 8), "file name count"));
  // The first driver's `active` flag, after the 7 body arrays and the driver count.
  const std::size_t driver = positions + 7 * 8 + n * (6 * sizeof(Vec3) + sizeof(Quat)) + 8;
  const std::uint8_t flag = 255;
  CHECK(refused(d, with(driver, &flag, 1), "flag"));
}

TEST_CASE("another scene's checkpoint is refused unless forced", "[checkpoint]") {
  const Drop d;
  const TempDir dir;
  checkpoint_then_run(d, dir / "a.bin", 2000, 0);
  Drop flipped;  // same counts and time step, gravity upwards
  flipped.scene.forces.gravity = Vec3(0, 0, 9.807);
  CHECK(refused(flipped, dir / "a.bin", "another scene"));
  Simulation sim(flipped.scene, flipped.lib, flipped.specs);
  OutputProgress progress;
  CHECK_NOTHROW(read_checkpoint(dir / "a.bin", sim, progress, true));
  CHECK(sim.step_index() == 2000);
}
