#include "sim/checkpoint.hpp"

#include <cstring>

#include "polydem/error.hpp"
#include "sim/checkpoint_io.hpp"
#include "sim/checkpoint_pieces.hpp"
#include "sim/scene_fingerprint.hpp"

namespace polydem {

namespace {

// 08: the body order (the user id of each stored body, sim/body_order.hpp) first in the payload;
// older files hold the bodies in the scene's order. 07: the ledger's open sums (each touching pair's pending energy after the active slots of
// its list, the ended contacts' exact sum after both lists): written at any step, not only
// where the ledger closes; 06: a header (scene fingerprint, body and driver counts, payload
// size) before the payload of format 05 and an FNV-1a checksum of all bytes before it after;
// 05: the ledger's dissipation by mechanism. 06 and older hold a closed ledger (none open).
constexpr char kMagic[kMagicBytes] = {'P', 'D', 'C', 'K', 'P', 'T', '0', '8'};
constexpr char kMagic07[kMagicBytes] = {'P', 'D', 'C', 'K', 'P', 'T', '0', '7'};
constexpr char kMagic06[kMagicBytes] = {'P', 'D', 'C', 'K', 'P', 'T', '0', '6'};
constexpr char kMagic05[8] = {'P', 'D', 'C', 'K', 'P', 'T', '0', '5'};
// Older formats still resume: 04 has no ledger shares (all its dissipation counts as dashpot;
// forces and motion unchanged); 03 has neither those nor the last dashpot force, gap and
// weight per contact, which the dashpot reads (contact/law/second_order.hpp): its contacts
// restart as new ones, and the run goes on near the uninterrupted one, not on its bits.
// 03-05 have no header and no checksum.
constexpr char kMagic04[8] = {'P', 'D', 'C', 'K', 'P', 'T', '0', '4'};
constexpr char kMagic03[8] = {'P', 'D', 'C', 'K', 'P', 'T', '0', '3'};
// Bytes of EnergyLedger up to its format-05 shares: what formats 03 and 04 hold.
constexpr std::size_t kLedgerBytes04 = 3 * sizeof(double) + sizeof(Vec3);
static_assert(sizeof(EnergyLedger) == kLedgerBytes04 + 3 * sizeof(double), "EnergyLedger: shares after the format-04 fields");

void write_active(Writer& w, const PairList& list) {
  std::uint64_t n = 0;
  for (std::uint8_t a : list.active) n += a;
  w.pod(n);
  for (std::size_t k = 0; k < list.size(); ++k)
    for (std::uint32_t s = list.slot_begin[k]; s < list.slot_begin[k + 1]; ++s)
      if (list.active[s]) {
        w.pod(list.pairs[k].i);
        w.pod(list.pairs[k].j);
        const ContactSlot slot{list.history(s), {}};
        const SlotRecord record = list.record(s);  // a dense list must record
        slot_fields(w, list.features[s], slot, record);
      }
  for (std::size_t k = 0; k < list.size(); ++k)  // the pairs above, in order: their pending energies
    for (std::uint32_t s = list.slot_begin[k]; s < list.slot_begin[k + 1]; ++s)
      if (list.active[s]) {
        w.pod(list.open_energy(k));
        break;
      }
}

// `partners`: bodies (i < j < partners) or drivers (j < partners). `pending`: format 07.
void read_active(Reader& r, PairList& list, std::size_t bodies, std::size_t partners, bool driver, bool pending) {
  std::uint64_t n = 0;
  r.pod(n);
  r.count(n, kContactBytes03, "contact");
  list = PairList{};
  list.slot_begin.push_back(0);
  for (std::uint64_t e = 0; e < n; ++e) {
    BodyPair pair;
    FeaturePair key;
    ContactSlot slot;
    SlotRecord record;
    r.pod(pair.i);
    r.pod(pair.j);
    if (pair.i >= bodies || pair.j >= partners || (!driver && pair.i >= pair.j))
      r.fail("contact " + std::to_string(e) + " names the pair (" + std::to_string(pair.i) + ", " +
             std::to_string(pair.j) + "), out of range");
    slot_fields(r, key, slot, record, r.last_step_fields);
    if (std::uint8_t(key.type) >= kPairTypeCount) r.fail("contact " + std::to_string(e) + " has an unknown type");
    if (!r.last_step_fields) slot.history.gap = kNoGap;  // format 03: no last step for the energy ledger
    if (list.pairs.empty() || list.pairs.back().i != pair.i || list.pairs.back().j != pair.j) {
      list.pairs.push_back(pair);
      list.slot_begin.push_back(list.slot_begin.back());
    }
    list.features.push_back(key);
    list.slots.push_back(slot);
    list.records.push_back(record);
    list.active.push_back(1);
    ++list.slot_begin.back();
  }
  list.resize_results();
  if (!pending) return;
  for (std::size_t k = 0; k < list.size(); ++k) {  // each pair has a slot: its first holds the energy
    EnergyParts& e = list.open_energy(k);
    r.pod(e);
    check_open_energy(r, e);
  }
}

// Format 08's payload: the body order, then format 05's bytes after the magic (the state, the
// contacts, the output progress) with 07's open sums.
void write_payload(Writer& w, const Simulation& sim, const OutputProgress& progress) {
  w.array(sim.bodies.id);
  write_clock(w, sim);
  const Bodies& b = sim.bodies;
  w.array(b.position); w.array(b.orientation); w.array(b.velocity); w.array(b.angular_velocity);
  w.array(b.angular_momentum); w.array(b.force); w.array(b.torque);
  write_drivers(w, sim.drivers);
  write_active(w, sim.engine().body_pairs());
  write_active(w, sim.engine().driver_pairs());
  write_flushed(w, sim.engine().flushed());
  write_progress(w, progress);
}

}  // namespace

std::vector<std::uint32_t> checkpoint_body_order(const std::string& path, std::size_t bodies) {
  std::ifstream in(path, std::ios::binary);
  char magic[kMagicBytes] = {};
  in.read(magic, kMagicBytes);
  if (is_checkpoint_manifest(std::string(magic, kMagicBytes))) return manifest_body_order(path, bodies);
  return stored_body_order(path, kMagic, bodies);
}

void write_checkpoint(const std::string& path, const Simulation& sim, const OutputProgress& progress) {
  write_sealed(path, kMagic, Header{scene_fingerprint(sim), sim.bodies.size(), sim.drivers.size(), 0},
               [&](Writer& w) { write_payload(w, sim, progress); });
}

void read_checkpoint(const std::string& path, Simulation& sim, OutputProgress& progress, bool force) {
  const std::string bytes = read_file(path);
  if (is_checkpoint_manifest(bytes)) return read_checkpoint_pieces(path, bytes, sim, progress, force);
  sim.bodies.grow_state();  // a rank dropped them at its first cut; the read fills every body's
  const auto is = [&](const char (&m)[8]) {
    return bytes.size() >= sizeof(m) && std::memcmp(bytes.data(), m, sizeof(m)) == 0;
  };
  if (!is(kMagic) && !is(kMagic07) && !is(kMagic06) && !is(kMagic05) && !is(kMagic04) && !is(kMagic03))
    throw InputError(path + ": not a polydem checkpoint (formats 03 to " + std::string(kMagic + 6, 2) + " resume)");
  const bool sealed = is(kMagic) || is(kMagic07) || is(kMagic06), open = is(kMagic) || is(kMagic07);
  if (sealed) check_header(bytes, path, sim, force);
  Reader r{bytes, sealed ? kHeaderBytes : sizeof(kMagic), sealed ? bytes.size() - kChecksumBytes : bytes.size(), path};
  r.last_step_fields = !is(kMagic03);
  read_body_order(r, sim, is(kMagic));
  read_step(r, sim);
  sim.ledger = EnergyLedger{};
  const std::size_t ledger_bytes = sealed || is(kMagic05) ? sizeof(EnergyLedger) : kLedgerBytes04;
  if (r.left() < ledger_bytes) r.fail("truncated in the energy ledger");
  std::memcpy(reinterpret_cast<char*>(&sim.ledger), bytes.data() + r.at, ledger_bytes);
  r.at += ledger_bytes;
  Bodies& b = sim.bodies;
  const std::size_t n = b.size();
  r.array(b.position, n); r.array(b.orientation, n); r.array(b.velocity, n); r.array(b.angular_velocity, n);
  r.array(b.angular_momentum, n); r.array(b.force, n); r.array(b.torque, n);
  read_drivers(r, sim);
  check_state(r, sim);
  read_active(r, sim.engine().body_pairs(), n, n, false, open);
  read_active(r, sim.engine().driver_pairs(), n, sim.drivers.size(), true, open);
  sim.engine().flushed() = open ? read_flushed(r) : ExactEnergy{};
  sim.drop_sphere_orientations();  // files of older builds turned them
  sim.force_rebuild();
  read_progress(r, progress);
  if (r.left() != 0) r.fail(std::to_string(r.left()) + " bytes after the end of the checkpoint");
}

}  // namespace polydem
