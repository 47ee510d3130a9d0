#include "sim/checkpoint_pieces.hpp"

#include <cstring>

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

// What the pieces add up to while they are read.
struct Assembly {
  std::vector<std::uint8_t> seen;  // per body: 1 once a piece held it
  std::vector<TableSlot> body, driver;
  ExactEnergy flushed;             // J, the pieces' ended contacts summed
  bool open = true;                // pieces 02: the ledger's open part held
};

template <class T>
void read_into(Reader& r, std::vector<T>& all, const std::vector<std::uint32_t>& ids) {
  std::vector<T> part;
  r.array(part, ids.size());
  for (std::size_t m = 0; m < ids.size(); ++m) all[ids[m]] = part[m];
}

// `partners`: bodies (i < j < partners) or drivers (j < partners).
void read_slots(Reader& r, std::vector<TableSlot>& out, std::size_t bodies, std::size_t partners, bool driver,
                bool pending) {
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

// Piece k of `pieces`, checked against the manifest's record, into `sim` and `into`.
void read_piece(const std::string& manifest, const PieceEntry& entry, std::size_t k, std::size_t pieces,
                Simulation& sim, Assembly& into) {
  const std::string which = manifest + ": piece " + std::to_string(k) + " of " + std::to_string(pieces) + " (" +
                            entry.file + ")";
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
  Bodies& b = sim.bodies;
  std::vector<std::uint32_t> ids;
  r.array(ids, h.bodies);
  for (std::uint32_t id : ids) {
    if (id >= b.size()) r.fail("body id " + std::to_string(id) + " out of range");
    if (into.seen[id]++) throw InputError(which + ": body " + std::to_string(b.id[id]) + " is in two pieces");
  }
  read_into(r, b.position, ids); read_into(r, b.orientation, ids); read_into(r, b.velocity, ids);
  read_into(r, b.angular_velocity, ids); read_into(r, b.angular_momentum, ids);
  read_into(r, b.force, ids); read_into(r, b.torque, ids);
  read_slots(r, into.body, b.size(), b.size(), false, into.open);
  read_slots(r, into.driver, b.size(), sim.drivers.size(), true, into.open);
  if (into.open) into.flushed.add(read_flushed(r));
  if (r.left() != 0) r.fail(std::to_string(r.left()) + " bytes after the end of the piece");
}

// The table as read_active lays out one process's checkpoint: touching counts are the next
// rebuild's to set.
PairList checkpoint_list(std::vector<TableSlot> slots) {
  PairList list = table_of(std::move(slots));
  std::fill(list.touching.begin(), list.touching.end(), 0);
  return list;
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
  Assembly into{std::vector<std::uint8_t>(sim.bodies.size(), 0), {}, {}, {},
                ordered || std::memcmp(bytes.data(), kManifestMagic02, kMagicBytes) == 0};
  for (std::size_t k = 0; k < pieces; ++k) read_piece(path, entries[k], k, pieces, sim, into);
  for (std::size_t b = 0; b < sim.bodies.size(); ++b)
    if (!into.seen[b])
      throw InputError(path + ": body " + std::to_string(sim.bodies.id[b]) + " is in none of its " + std::to_string(pieces) +
                       " pieces");
  check_state(r, sim);
  sim.engine().body_pairs() = checkpoint_list(std::move(into.body));
  sim.engine().driver_pairs() = checkpoint_list(std::move(into.driver));
  sim.engine().flushed() = into.flushed;
  sim.drop_sphere_orientations();  // files of older builds turned them
  sim.force_rebuild();
}

}  // namespace polydem
