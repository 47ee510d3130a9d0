#include "sim/checkpoint_pieces.hpp"

#include <algorithm>
#include <cstring>
#include <numeric>

#include "polydem/error.hpp"
#include "sim/body_rows.hpp"
#include "sim/checkpoint_io.hpp"
#include "sim/contact_table.hpp"

namespace polydem {

namespace {

// Manifest 03: the body order (sim/body_order.hpp) first in its payload; the pieces hold bodies
// and contacts by index, as the manifest's 02. 02: each piece holds its touching pairs' pending energies after its slots and its ended
// contacts' exact sum (the ledger's open part, as format 07); 01 (a closed ledger) still resumes.
constexpr char kManifestMagic[kMagicBytes] = {'P', 'D', 'C', 'K', 'M', 'A', '0', '3'};
constexpr char kManifestMagic02[kMagicBytes] = {'P', 'D', 'C', 'K', 'M', 'A', '0', '2'};
constexpr char kPieceMagic[kMagicBytes] = {'P', 'D', 'C', 'K', 'P', 'C', '0', '2'};
constexpr char kManifestMagic01[kMagicBytes] = {'P', 'D', 'C', 'K', 'M', 'A', '0', '1'};
constexpr char kPieceMagic01[kMagicBytes] = {'P', 'D', 'C', 'K', 'P', 'C', '0', '1'};

struct PieceHeader {  // after the piece's magic
  std::uint64_t fingerprint, step, piece, pieces, bodies, payload_bytes;
};
constexpr std::size_t kPieceHeaderBytes = kMagicBytes + sizeof(PieceHeader);

// "out/checkpoint_000100.bin" -> "out/checkpoint_000100_p2.bin"
std::string piece_path(const std::string& manifest, std::size_t piece) {
  const std::size_t dot = manifest.rfind(".bin");
  return manifest.substr(0, dot) + "_p" + std::to_string(piece) + (dot == std::string::npos ? "" : ".bin");
}

std::string file_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

std::string folder_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

void write_slots(Writer& w, const std::vector<TableSlot>& slots) {
  w.pod<std::uint64_t>(slots.size());
  for (const TableSlot& t : slots) {
    w.pod(t.i);
    w.pod(t.j);
    slot_fields(w, t.key, t.slot, t.record);
  }
  for (std::size_t s = 0; s < slots.size(); ++s)  // each pair's first slot: its pending energy
    if (s == 0 || slots[s].i != slots[s - 1].i || slots[s].j != slots[s - 1].j) w.pod(slots[s].slot.pending);
}

// This rank's bodies (ids, then the state arrays of format 06 for them) and contacts.
FileSeal write_piece(const std::string& path, const Simulation& sim, std::size_t piece, std::size_t pieces) {
  const RankContacts& ranks = *sim.rank_contacts();
  const std::vector<std::uint32_t> ids = ranks.output_bodies();
  const std::vector<TableSlot> body = ranks.output_slots(sim.engine(), false);
  const std::vector<TableSlot> driver = ranks.output_slots(sim.engine(), true);
  const PieceHeader header{scene_fingerprint(sim), std::uint64_t(sim.step_index()), piece, pieces, ids.size(), 0};
  return write_sealed(path, kPieceMagic, header, [&](Writer& w) {
    w.array(ids);
    ranks.with_output_rows(sim.bodies, [&](const auto& b, const std::vector<std::uint32_t>& rows) {
      w.array(subset(b.position, rows)); w.array(subset(b.orientation, rows)); w.array(subset(b.velocity, rows));
      w.array(subset(b.angular_velocity, rows)); w.array(subset(b.angular_momentum, rows));
      w.array(subset(b.force, rows)); w.array(subset(b.torque, rows));
    });
    write_slots(w, body);
    write_slots(w, driver);
    write_flushed(w, ranks.output_flushed(sim.engine()));
  });
}

void write_manifest(const std::string& path, const Simulation& sim, const std::vector<FileSeal>& seals,
                    const OutputProgress& progress) {
  const Header header{scene_fingerprint(sim), sim.bodies.size(), sim.drivers.size(), 0};
  write_sealed(path, kManifestMagic, header, [&](Writer& w) {
    w.array(sim.bodies.id);
    write_clock(w, sim);
    write_drivers(w, sim.drivers);
    w.pod<std::uint64_t>(seals.size());
    for (std::size_t k = 0; k < seals.size(); ++k) {
      w.string(file_name(piece_path(path, k)));
      w.pod(seals[k].bytes);
      w.pod(seals[k].checksum);
    }
    write_progress(w, progress);
  });
}

// What the pieces add up to while they are read (the slots and ended contacts of one rank's
// pieces, or every piece's).
struct Assembly {
  std::vector<TableSlot> body, driver;
  ExactEnergy flushed;  // J, the pieces' ended contacts summed
  bool open = true;     // pieces 02: the ledger's open part held
  bool whole_rows = false;  // the pieces' bodies as a rank's share (piece_rows)
};

// `partners`: bodies (i < j < partners) or drivers (j < partners); each pair's lower body i
// among `ids` (increasing), the piece's bodies.
void read_slots(Reader& r, std::vector<TableSlot>& out, const std::vector<std::uint32_t>& ids, std::size_t bodies,
                std::size_t partners, bool driver, bool pending) {
  std::uint64_t n = 0;
  r.pod(n);
  r.count(n, kContactBytes03, "contact");
  const std::size_t first = out.size();
  for (std::uint64_t e = 0; e < n; ++e) {
    TableSlot t{};
    r.pod(t.i);
    r.pod(t.j);
    if (t.i >= bodies || t.j >= partners || (!driver && t.i >= t.j))
      r.fail("contact " + std::to_string(e) + " names the pair (" + std::to_string(t.i) + ", " + std::to_string(t.j) +
             "), out of range");
    if (!std::binary_search(ids.begin(), ids.end(), t.i))
      r.fail("contact " + std::to_string(e) + " names body " + std::to_string(t.i) + ", not one of the piece's");
    slot_fields(r, t.key, t.slot, t.record);
    if (std::uint8_t(t.key.type) >= kPairTypeCount) r.fail("contact " + std::to_string(e) + " has an unknown type");
    out.push_back(t);
  }
  if (!pending) return;
  for (std::size_t s = first; s < out.size(); ++s)
    if (s == first || out[s].i != out[s - 1].i || out[s].j != out[s - 1].j) {
      r.pod(out[s].slot.pending);
      check_open_energy(r, out[s].slot.pending);
    }
}

struct PieceEntry {
  std::string file;  // path
  FileSeal seal;     // as the manifest recorded it
};

std::string piece_named(const std::string& manifest, const PieceEntry& entry, std::size_t k, std::size_t pieces) {
  return manifest + ": piece " + std::to_string(k) + " of " + std::to_string(pieces) + " (" + entry.file + ")";
}

// A piece's bodies as store rows: their state as read and, for a rank's share (`whole`), their
// constants from `b` and every array of a store; else (read into Bodies) their user ids alone.
LocalStore piece_rows(Reader& r, std::size_t n, const Bodies& b, const std::string& which, bool whole) {
  LocalStore s;
  if (whole) s.resize(n);
  else s.id.resize(n);
  r.array(s.global_id, n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t g = s.global_id[k];
    if (g >= b.size()) r.fail("body id " + std::to_string(g) + " out of range");
    if (k > 0 && g <= s.global_id[k - 1])  // pieces list their bodies in increasing id
      throw InputError(which + ": body " + std::to_string(b.id[g]) + " is in two pieces or out of order");
    s.id[k] = b.id[g];
    if (!whole) continue;
    s.shape[k] = b.shape[g];
    s.scale[k] = b.scale[g];
    s.mass[k] = b.mass[g];
    s.inertia[k] = b.inertia[g];
    s.group[k] = b.group[g];
  }
  r.array(s.position, n); r.array(s.orientation, n); r.array(s.velocity, n);
  r.array(s.angular_velocity, n); r.array(s.angular_momentum, n);
  r.array(s.force, n); r.array(s.torque, n);
  check_body_state(r, s);
  return s;
}

// Piece k of `pieces`, checked against the manifest's record: its bodies, and its slots and
// ended contacts into `into`.
LocalStore read_piece(const std::string& manifest, const PieceEntry& entry, std::size_t k, std::size_t pieces,
                      const Simulation& sim, Assembly& into) {
  const std::string which = piece_named(manifest, entry, k, pieces);
  std::string bytes;
  try {
    bytes = read_file(entry.file);
  } catch (const InputError&) {
    throw InputError(which + " is missing or unreadable");
  }
  PieceHeader h{};
  if (bytes.size() < kPieceHeaderBytes + kChecksumBytes ||
      std::memcmp(bytes.data(), into.open ? kPieceMagic : kPieceMagic01, kMagicBytes) != 0)
    throw InputError(which + " is not a checkpoint piece (damaged or truncated)");
  std::memcpy(&h, bytes.data() + kMagicBytes, sizeof(h));
  try {
    check_size_and_checksum(bytes, entry.file, kPieceHeaderBytes, h.payload_bytes);
  } catch (const InputError& e) {
    throw InputError(which + " is damaged: " + e.what());
  }
  if (bytes.size() != entry.seal.bytes ||
      std::memcmp(bytes.data() + bytes.size() - kChecksumBytes, &entry.seal.checksum, kChecksumBytes) != 0)
    throw InputError(which + " is not the piece the manifest names (its size or checksum differs: another "
                     "checkpoint's?)");
  if (h.fingerprint != scene_fingerprint(sim) || h.step != std::uint64_t(sim.step_index()) || h.piece != k ||
      h.pieces != pieces)
    throw InputError(which + " belongs to another checkpoint (its scene, step or piece number differs)");
  Reader r{bytes, kPieceHeaderBytes, bytes.size() - kChecksumBytes, entry.file};
  const std::size_t n = sim.bodies.size();
  r.count(h.bodies, sizeof(std::uint32_t), "body");
  LocalStore rows = piece_rows(r, h.bodies, sim.bodies, which, into.whole_rows);
  read_slots(r, into.body, rows.global_id, n, n, false, into.open);
  read_slots(r, into.driver, rows.global_id, n, sim.drivers.size(), true, into.open);
  if (into.open) into.flushed.add(read_flushed(r));
  if (r.left() != 0) r.fail(std::to_string(r.left()) + " bytes after the end of the piece");
  return rows;
}

// Every piece into `sim`'s arrays (one process, or ranks that integrate every body).
Assembly read_every_piece(const std::string& path, const std::vector<PieceEntry>& entries, Simulation& sim,
                          bool open) {
  Bodies& b = sim.bodies;
  b.grow_state();  // a rank dropped them at its first cut
  std::vector<std::uint8_t> seen(b.size(), 0);  // per body: 1 once a piece held it
  Assembly into{{}, {}, {}, open};
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const LocalStore rows = read_piece(path, entries[k], k, entries.size(), sim, into);
    for (std::size_t m = 0; m < rows.size(); ++m) {
      const std::uint32_t g = rows.global_id[m];
      if (seen[g]++)
        throw InputError(piece_named(path, entries[k], k, entries.size()) + ": body " + std::to_string(b.id[g]) +
                         " is in two pieces");
      b.position[g] = rows.position[m], b.orientation[g] = rows.orientation[m], b.velocity[g] = rows.velocity[m];
      b.angular_velocity[g] = rows.angular_velocity[m], b.angular_momentum[g] = rows.angular_momentum[m];
      b.force[g] = rows.force[m], b.torque[g] = rows.torque[m];
    }
  }
  for (std::size_t g = 0; g < b.size(); ++g)
    if (!seen[g])
      throw InputError(path + ": body " + std::to_string(b.id[g]) + " is in none of its " +
                       std::to_string(entries.size()) + " pieces");
  return into;
}

// The table as read_active lays out one process's checkpoint: touching counts are the next
// rebuild's to set.
PairList checkpoint_list(const std::vector<TableSlot>& slots) {
  PairList list = table_of(slots);
  std::fill(list.touching.begin(), list.touching.end(), 0);
  return list;
}

// A body of a piece a rank read, sent to the rank that checks its range of ids.
struct HeldBody {
  std::uint32_t body, piece;
};

// Every body in exactly one of the pieces the ranks read, each checked by the rank whose
// equal range of ids holds it (a collective: O(this rank's bodies) each way).
void check_each_body_once(const RankLink& link, const std::string& path, const std::vector<PieceEntry>& entries,
                          const std::vector<HeldBody>& held, const Bodies& b) {
  const std::uint64_t n = b.size(), ranks = std::uint64_t(link.ranks());
  if (n == 0) return;
  const auto home = [&](std::uint32_t g) { return int(std::uint64_t(g) * ranks / n); };
  const auto first = [&](std::uint64_t h) { return std::uint32_t((h * n + ranks - 1) / ranks); };
  std::vector<std::vector<HeldBody>> to(link.ranks());
  for (const HeldBody& x : held) to[home(x.body)].push_back(x);
  std::vector<Parcel> out;
  for (int q = 0; q < link.ranks(); ++q) {
    if (to[q].empty()) continue;
    out.push_back({q, {}});
    append_section(out.back().bytes, to[q]);
  }
  const std::vector<Parcel> in = link.deliver(std::move(out));
  const std::uint32_t lo = first(std::uint64_t(link.rank())), hi = first(std::uint64_t(link.rank()) + 1);
  on_every_rank<InputError>(link, [&] {
    std::vector<std::uint8_t> seen(hi - lo, 0);
    for (const Parcel& p : in) {
      std::size_t at = 0;
      for (const HeldBody& x : read_section<HeldBody>(p.bytes, at))
        if (seen[x.body - lo]++)
          throw InputError(piece_named(path, entries[x.piece], x.piece, entries.size()) + ": body " +
                           std::to_string(b.id[x.body]) + " is in two pieces");
    }
    for (std::uint32_t g = lo; g < hi; ++g)
      if (!seen[g - lo])
        throw InputError(path + ": body " + std::to_string(b.id[g]) + " is in none of its " +
                         std::to_string(entries.size()) + " pieces");
  });
}

// This rank's share of the pieces (k = rank, rank + ranks, ...) into its store, every body
// checked to be in one piece: no rank reads or holds the others' (a collective).
LandedShare read_share(const std::string& path, const std::vector<PieceEntry>& entries, const Simulation& sim,
                       bool open) {
  const RankLink& link = *sim.link();
  LandedShare share;
  Assembly into{{}, {}, {}, open, true};
  std::vector<HeldBody> held;
  on_every_rank<InputError>(link, [&] {
    for (std::size_t k = std::size_t(link.rank()); k < entries.size(); k += std::size_t(link.ranks())) {
      LocalStore rows = read_piece(path, entries[k], k, entries.size(), sim, into);
      for (std::uint32_t g : rows.global_id) held.push_back({g, std::uint32_t(k)});
      if (share.store.size() == 0) {  // the first piece: no copy
        share.store = std::move(rows);
        continue;
      }
      std::vector<std::uint32_t> all(rows.size());
      std::iota(all.begin(), all.end(), 0u);
      share.store.append(rows, all);
    }
  });
  check_each_body_once(link, path, entries, held, sim.bodies);
  share.store.sort_by_id();
  share.body = std::move(into.body);
  share.driver = std::move(into.driver);
  share.flushed = into.flushed;
  return share;
}

}  // namespace

void write_checkpoint_pieces(const std::string& path, const Simulation& sim, const OutputProgress& progress) {
  const RankLink& link = *sim.link();
  FileSeal mine;
  on_every_rank(link, [&] { mine = write_piece(piece_path(path, link.rank()), sim, link.rank(), link.ranks()); });
  std::vector<char> bytes;
  append_record(bytes, mine);
  const std::vector<std::vector<char>> all = link.gather(bytes, 0);
  on_every_rank(link, [&] {
    if (all.empty()) return;  // not rank 0
    std::vector<FileSeal> seals(all.size());
    for (std::size_t k = 0; k < all.size(); ++k) std::memcpy(&seals[k], all[k].data(), sizeof(FileSeal));
    write_manifest(path, sim, seals, progress);
  });
}

bool is_checkpoint_manifest(const std::string& bytes) {
  const auto is = [&](const char (&m)[kMagicBytes]) { return std::memcmp(bytes.data(), m, kMagicBytes) == 0; };
  return bytes.size() >= kMagicBytes && (is(kManifestMagic) || is(kManifestMagic02) || is(kManifestMagic01));
}

std::vector<std::uint32_t> manifest_body_order(const std::string& path, std::size_t bodies) {
  return stored_body_order(path, kManifestMagic, bodies);
}

void read_checkpoint_pieces(const std::string& path, const std::string& bytes, Simulation& sim,
                            OutputProgress& progress, bool force) {
  check_header(bytes, path, sim, force);
  Reader r{bytes, kHeaderBytes, bytes.size() - kChecksumBytes, path};
  const bool ordered = std::memcmp(bytes.data(), kManifestMagic, kMagicBytes) == 0;
  read_body_order(r, sim, ordered);
  read_step(r, sim);
  r.pod(sim.ledger);
  read_drivers(r, sim);
  std::uint64_t pieces = 0;
  r.pod(pieces);
  r.count(pieces, 3 * sizeof(std::uint64_t), "piece");
  if (pieces == 0) r.fail("a manifest of no pieces");
  std::vector<PieceEntry> entries(pieces);
  for (PieceEntry& e : entries) {
    r.string(e.file);
    if (e.file.empty() || e.file.find('/') != std::string::npos) r.fail("a piece's file name is not a plain name");
    e.file = folder_of(path) + "/" + e.file;
    r.pod(e.seal.bytes);
    r.pod(e.seal.checksum);
  }
  read_progress(r, progress);
  if (r.left() != 0) r.fail(std::to_string(r.left()) + " bytes after the end of the manifest");
  const bool open = ordered || std::memcmp(bytes.data(), kManifestMagic02, kMagicBytes) == 0;
  check_run_state(r, sim);
  if (sim.distributed() && sim.scene().forces.contact.present) {  // each rank integrates its own bodies
    sim.land_share(read_share(path, entries, sim, open));
    return;
  }
  Assembly into = read_every_piece(path, entries, sim, open);
  sim.engine().body_pairs() = checkpoint_list(into.body);
  sim.engine().driver_pairs() = checkpoint_list(into.driver);
  sim.engine().flushed() = into.flushed;
  sim.drop_sphere_orientations();  // files of older builds turned them
  sim.force_rebuild();
}

}  // namespace polydem
