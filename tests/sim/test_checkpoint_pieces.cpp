// Checkpoint pieces without MPI (ranks as threads, thread_link.hpp): the pile stepped over 2
// ranks writes a manifest and a piece per rank; resumed in one process and over 3 ranks it ends
// on the bits of one process stepped straight through, each rank having read only its share of
// the pieces; a missing or damaged piece is refused with its number and file named, on every rank.
#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "../unique_temp_dir.hpp"
#include "pile.hpp"
#include "polydem/error.hpp"
#include "sim/checkpoint_pieces.hpp"
#include "thread_link.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr int kThen = 300;  // steps after the checkpoint

void require_same_bodies(const Bodies& a, const Bodies& b) {
  CHECK(same_bits(a.position, b.position));
  CHECK(same_bits(a.orientation, b.orientation));
  CHECK(same_bits(a.velocity, b.velocity));
  CHECK(same_bits(a.angular_momentum, b.angular_momentum));
  CHECK(same_bits(a.force, b.force));
  CHECK(same_bits(a.torque, b.torque));
}

std::size_t active_slots(const PairList& list) {
  std::size_t n = 0;
  for (std::uint8_t a : list.active) n += a;
  return n;
}

// The pile over 2 thread ranks for `steps`, its checkpoint written in pieces at `manifest`.
void write_pieces(const Pile& p, int steps, const std::string& manifest) {
  on_thread_ranks(2, [&](const RankLink& link) {
    Simulation sim(p.scene, p.lib, p.specs, &link);
    for (int s = 0; s < steps; ++s) sim.step();
    write_checkpoint_pieces(manifest, sim, OutputProgress{});
  });
}

}  // namespace

TEST_CASE("Checkpoint pieces of 2 thread ranks resume in one process and over 3 ranks on one process's bits",
          "[checkpoint]") {
  const Pile p;
  Simulation straight(p.scene, p.lib, p.specs);
  // Steps until the pile holds 150 contacts (the checkpoint then carries many), to a step where
  // the energy ledger closes, as the runner writes checkpoints (Simulation::kLedgerSteps).
  int first = 0;
  for (; first < 100000 && (straight.contacts() < 150 || !Simulation::ledger_closes(first)); ++first) straight.step();
  for (int s = 0; s < kThen; ++s) straight.step();
  UniqueTempDir dir("pieces");
  const std::string manifest = (dir.path / "checkpoint_000100.bin").string();
  write_pieces(p, first, manifest);
  for (const char* piece : {"checkpoint_000100_p0.bin", "checkpoint_000100_p1.bin"})
    REQUIRE(std::filesystem::file_size(dir.path / piece) > 0);

  Simulation one(p.scene, p.lib, p.specs);
  OutputProgress progress;
  read_checkpoint(manifest, one, progress);
  REQUIRE(one.step_index() == first);
  INFO(active_slots(one.engine().body_pairs()) << " active slots");
  REQUIRE(active_slots(one.engine().body_pairs()) > 50);  // the pieces carried the contact histories
  REQUIRE(active_slots(one.engine().driver_pairs()) > 0);
  for (int s = 0; s < kThen; ++s) one.step();
  require_same_bodies(straight.bodies, one.bodies);
  CHECK(std::memcmp(&straight.ledger, &one.ledger, sizeof(EnergyLedger)) == 0);

  std::vector<Bodies> ranks(3);
  on_thread_ranks(3, [&](const RankLink& link) {
    Simulation sim(p.scene, p.lib, p.specs, &link);
    OutputProgress mine;
    read_checkpoint(manifest, sim, mine);
    for (int s = 0; s < kThen; ++s) sim.step();
    sim.gather_state(true);
    ranks[link.rank()] = sim.bodies;
  });
  for (int r = 0; r < 3; ++r) {
    INFO("rank " << r << " of 3");
    require_same_bodies(straight.bodies, ranks[r]);
  }
}

TEST_CASE("A missing or damaged checkpoint piece is refused with its number and file", "[checkpoint]") {
  const Pile p;
  UniqueTempDir dir("pieces_bad");
  const std::string manifest = (dir.path / "checkpoint_000100.bin").string();
  write_pieces(p, 100, manifest);
  const std::filesystem::path second = dir.path / "checkpoint_000100_p1.bin";
  const std::filesystem::path kept = dir.path / "kept.bin";
  std::filesystem::copy_file(second, kept);
  auto resume = [&] {
    Simulation sim(p.scene, p.lib, p.specs);
    OutputProgress progress;
    read_checkpoint(manifest, sim, progress);
  };
  std::filesystem::remove(second);
  CHECK_THROWS_WITH(resume(), Catch::Contains("piece 1 of 2") && Catch::Contains("checkpoint_000100_p1.bin") &&
                                  Catch::Contains("missing"));
  std::filesystem::copy_file(kept, second);
  {
    std::fstream f(second, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(200);
    const char byte = char(f.get());
    f.seekp(200);
    f.put(char(~byte));  // a byte of the state changed
  }
  CHECK_THROWS_WITH(resume(), Catch::Contains("piece 1 of 2") && Catch::Contains("checksum mismatch"));
  std::filesystem::copy_file(dir.path / "checkpoint_000100_p0.bin", second, std::filesystem::copy_options::overwrite_existing);
  CHECK_THROWS_AS(resume(), InputError);  // another rank's piece in its place
}

// The body count a piece's header records (after its magic: fingerprint, step, piece, pieces).
static std::uint64_t piece_bodies(const std::filesystem::path& piece) {
  std::ifstream f(piece, std::ios::binary);
  f.seekg(8 + 4 * sizeof(std::uint64_t));
  std::uint64_t n = 0;
  f.read(reinterpret_cast<char*>(&n), sizeof n);
  return n;
}

TEST_CASE("Ranks resuming checkpoint pieces each hold the pieces they read, none the whole state", "[checkpoint]") {
  const Pile p;
  UniqueTempDir dir("pieces_share");
  const std::string manifest = (dir.path / "checkpoint_000100.bin").string();
  write_pieces(p, 100, manifest);
  std::vector<std::size_t> owned(3), ghosts(3);
  std::vector<int> whole(3);
  on_thread_ranks(3, [&](const RankLink& link) {
    Simulation sim(p.scene, p.lib, p.specs, &link);
    OutputProgress mine;
    read_checkpoint(manifest, sim, mine);
    owned[link.rank()] = sim.owned_bodies();
    ghosts[link.rank()] = sim.ghost_bodies();
    whole[link.rank()] = sim.bodies.has_state();
  });
  // Rank k of 3 reads piece k of 2: rank 2 none, until the first step sends each body to its owner.
  CHECK(owned[0] == piece_bodies(dir.path / "checkpoint_000100_p0.bin"));
  CHECK(owned[1] == piece_bodies(dir.path / "checkpoint_000100_p1.bin"));
  CHECK(owned[0] > 0);
  CHECK(owned[1] > 0);
  CHECK(owned[2] == 0);
  CHECK(owned[0] + owned[1] == p.specs.size());
  for (int r = 0; r < 3; ++r) {
    INFO("rank " << r);
    CHECK(ghosts[r] == 0);
    CHECK(whole[r] == 0);  // no rank laid out every body's state
  }
}

TEST_CASE("A piece one rank cannot read stops every rank resuming, with its name", "[checkpoint]") {
  const Pile p;
  UniqueTempDir dir("pieces_share_bad");
  const std::string manifest = (dir.path / "checkpoint_000100.bin").string();
  write_pieces(p, 100, manifest);
  std::filesystem::remove(dir.path / "checkpoint_000100_p1.bin");  // rank 1's to read
  std::vector<std::string> errors(2);
  on_thread_ranks(2, [&](const RankLink& link) {
    Simulation sim(p.scene, p.lib, p.specs, &link);
    OutputProgress mine;
    try {
      read_checkpoint(manifest, sim, mine);
    } catch (const InputError& e) {
      errors[link.rank()] = e.what();
    }
  });
  for (int r = 0; r < 2; ++r) {
    INFO("rank " << r << ": " << errors[r]);
    CHECK(errors[r].find("piece 1 of 2") != std::string::npos);
    CHECK(errors[r].find("checkpoint_000100_p1.bin) is missing") != std::string::npos);
  }
}
