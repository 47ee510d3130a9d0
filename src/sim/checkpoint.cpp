#include "sim/checkpoint.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "polydem/error.hpp"
#include "sim/run_limits.hpp"
#include "sim/scene_fingerprint.hpp"

namespace polydem {

namespace {

// 06: a header (scene fingerprint, body and driver counts, payload size) before the payload
// of format 05 and an FNV-1a checksum of all bytes before it after; 05: the ledger's
// dissipation by mechanism.
constexpr char kMagic[8] = {'P', 'D', 'C', 'K', 'P', 'T', '0', '6'};
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

struct Header {  // format 06, after the magic
  std::uint64_t fingerprint, bodies, drivers, payload_bytes;
};
constexpr std::size_t kHeaderBytes = sizeof(kMagic) + sizeof(Header);
constexpr std::size_t kChecksumBytes = sizeof(std::uint64_t);
// Bytes of one stored contact in format 03 (the fewest): the pair, then slot_fields (key, flag,
// ft, mr, point, force, fn, gap; 05 adds fd, gap, weight).
constexpr std::size_t kContactBytes03 = 2 * 4 + 1 + 2 + 4 + 1 + 4 * sizeof(Vec3) + 2 * sizeof(double);
static_assert(kContactBytes03 == 128);
constexpr double kUnitTolerance = 1e-6;  // |q| - 1 of a stored orientation (round-off is ~1e-15)

// Streams the checkpoint to its file with the running checksum; with no file it only counts
// bytes (the payload's size goes in the header before it). The state is never copied whole in
// memory: a buffer of the file tripled the peak memory of a run at each checkpoint.
struct Writer {
  std::ofstream* out = nullptr;
  std::uint64_t size = 0, checksum = fnv1a(nullptr, 0);
  void raw(const char* data, std::size_t n) {
    size += n;
    if (!out) return;
    checksum = fnv1a(data, n, checksum);
    out->write(data, std::streamsize(n));
  }
  template <class T> void pod(const T& v) { raw(reinterpret_cast<const char*>(&v), sizeof(T)); }
  void flag(const bool& b) { pod(b); }
  template <class T> void array(const std::vector<T>& v) {
    pod<std::uint64_t>(v.size());
    raw(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  void string(const std::string& s) { pod<std::uint64_t>(s.size()); raw(s.data(), s.size()); }
};

// Reads the payload from memory; every count is checked against the bytes left before
// anything is allocated.
struct Reader {
  const std::string& bytes;
  std::size_t at, end;
  std::string path;
  bool last_step_fields = true;  // false for format 03
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path + ": damaged checkpoint: " + what); }
  std::size_t left() const { return end - at; }
  template <class T> void pod(T& v) {
    if (left() < sizeof(T)) fail("truncated at byte " + std::to_string(at));
    std::memcpy(static_cast<void*>(&v), bytes.data() + at, sizeof(T));  // Eigen types: trivially copyable in fact
    at += sizeof(T);
  }
  void flag(bool& b) {
    std::uint8_t v = 0;
    pod(v);
    if (v > 1) fail("a flag byte holds " + std::to_string(v) + " at byte " + std::to_string(at - 1));
    b = v;
  }
  void count(std::uint64_t n, std::size_t entry_bytes, const std::string& what) const {
    if (n > left() / entry_bytes)
      fail(what + " count " + std::to_string(n) + " exceeds what the " + std::to_string(left()) + " bytes left hold");
  }
  template <class T> void array(std::vector<T>& v, std::size_t expected) {
    std::uint64_t n = 0;
    pod(n);
    if (n != expected) throw InputError(path + ": checkpoint holds " + std::to_string(n) +
                                        " entries where the scene has " + std::to_string(expected) +
                                        " (was it written for another scene?)");
    count(n, sizeof(T), "entry");
    v.resize(n);
    std::memcpy(static_cast<void*>(v.data()), bytes.data() + at, n * sizeof(T));
    at += n * sizeof(T);
  }
  void string(std::string& s) {
    std::uint64_t n = 0;
    pod(n);
    count(n, 1, "character");
    s.assign(bytes.data() + at, n);
    at += n;
  }
};

// Active slots with their pair, so the next rebuild hands their history over by key. Field by
// field: no padding bytes in the file, so equal states give equal files.
template <class IO, class Key, class Slot, class Record>
void slot_fields(IO& io, Key& f, Slot& s, Record& r, bool last_step_fields = true) {
  bool active = true;  // only active slots are stored: a constant byte, kept from format 03
  io.pod(f.type); io.pod(f.a); io.pod(f.b); io.flag(active);
  io.pod(s.history.ft); io.pod(s.history.mr); io.pod(r.point); io.pod(r.force); io.pod(r.fn);
  io.pod(s.history.gap);  // the last gap, stored twice: format 03 has it here and not below
  if (!last_step_fields) return;
  io.pod(s.history.fd); io.pod(s.history.gap); io.pod(s.history.weight);
}

// The moving state of a driver (placement, motion, reactions), one writer/reader for both ways.
template <class IO, class D>
void driver_fields(IO& io, D& d) {
  io.flag(d.active); io.pod(d.point); io.pod(d.normal); io.pod(d.center); io.pod(d.axis);
  io.pod(d.velocity); io.pod(d.omega); io.pod(d.pivot); io.pod(d.force); io.pod(d.torque);
  io.pod(d.orientation);  // a mesh's placement; a servo's state is its velocity and force
}

void write_active(Writer& w, const PairList& list) {
  std::uint64_t n = 0;
  for (std::uint8_t a : list.active) n += a;
  w.pod(n);
  for (std::size_t k = 0; k < list.size(); ++k)
    for (std::uint32_t s = list.slot_begin[k]; s < list.slot_begin[k + 1]; ++s)
      if (list.active[s]) {
        w.pod(list.pairs[k].i);
        w.pod(list.pairs[k].j);
        slot_fields(w, list.features[s], list.slots[s], list.records.at(s));  // at: a list must record
      }
}

// `partners`: bodies (i < j < partners) or drivers (j < partners).
void read_active(Reader& r, PairList& list, std::size_t bodies, std::size_t partners, bool driver) {
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
}

// Format 05's bytes after the magic: the state, the contacts, the output progress.
void write_payload(Writer& w, const Simulation& sim, const OutputProgress& progress) {
  w.pod(sim.step_index());
  w.pod(sim.dt());
  w.pod(sim.ledger);
  const Bodies& b = sim.bodies;
  w.array(b.position); w.array(b.orientation); w.array(b.velocity); w.array(b.angular_velocity);
  w.array(b.angular_momentum); w.array(b.force); w.array(b.torque);
  w.pod<std::uint64_t>(sim.drivers.size());
  for (std::size_t j = 0; j < sim.drivers.size(); ++j) driver_fields(w, sim.drivers[j]);
  write_active(w, sim.engine().body_pairs());
  write_active(w, sim.engine().driver_pairs());
  w.pod(progress.frame);
  w.pod<std::uint64_t>(progress.frames.size());
  for (const OutputFrame& f : progress.frames) {
    w.pod(f.time);
    w.pod<std::uint64_t>(f.files.size());
    for (const std::string& s : f.files) w.string(s);
  }
}

// The whole file in one string of its size (a stream copy would hold it twice).
std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw InputError(path + ": cannot open checkpoint");
  const std::streamoff size = in.tellg();
  std::string bytes(size > 0 ? std::size_t(size) : 0, '\0');
  in.seekg(0);
  if (size < 0 || !in.read(bytes.data(), std::streamsize(bytes.size())))
    throw InputError(path + ": cannot read checkpoint");
  return bytes;
}

template <class T> bool all_finite(const std::vector<T>& v) {
  for (const T& x : v) if (!x.allFinite()) return false;
  return true;
}

// What the checkpoint holds must be a state the run can continue from.
void check_state(const Reader& r, const Simulation& sim) {
  const Bodies& b = sim.bodies;
  if (!all_finite(b.position) || !all_finite(b.velocity) || !all_finite(b.angular_velocity) ||
      !all_finite(b.angular_momentum) || !all_finite(b.force) || !all_finite(b.torque))
    r.fail("a body's position, velocity or force is not finite");
  for (std::size_t k = 0; k < b.size(); ++k)
    if (!(std::abs(b.orientation[k].norm() - 1.0) < kUnitTolerance))
      r.fail("body " + std::to_string(k) + "'s orientation quaternion has length " +
             std::to_string(b.orientation[k].norm()) + ", not 1");
  const EnergyLedger& l = sim.ledger;
  for (double v : {l.dissipated, l.driver_work, l.external_work, l.sliding, l.rolling, l.patch_work})
    if (!std::isfinite(v)) r.fail("the energy ledger is not finite");
  for (std::size_t j = 0; j < sim.drivers.size(); ++j) {
    const DriverState& d = sim.drivers[j];
    if (!d.point.allFinite() || !d.center.allFinite() || !d.velocity.allFinite() || !d.omega.allFinite() ||
        !d.force.allFinite() || !d.torque.allFinite() || !(std::abs(d.orientation.norm() - 1.0) < kUnitTolerance))
      r.fail("driver '" + sim.drivers.name(std::uint32_t(j)) + "' has a non-finite placement or motion");
  }
}

// Format 06: sizes, checksum, then the scene's fingerprint and counts.
void check_header(const std::string& bytes, const std::string& path, const Simulation& sim, bool force) {
  if (bytes.size() < kHeaderBytes + kChecksumBytes) throw InputError(path + ": damaged checkpoint: truncated header");
  Header h;
  std::memcpy(&h, bytes.data() + sizeof(kMagic), sizeof(h));
  if (h.payload_bytes != bytes.size() - kHeaderBytes - kChecksumBytes)
    throw InputError(path + ": damaged checkpoint: " + std::to_string(bytes.size()) + " bytes where its header says " +
                     std::to_string(h.payload_bytes + kHeaderBytes + kChecksumBytes) + " (truncated or appended to)");
  std::uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + bytes.size() - kChecksumBytes, kChecksumBytes);
  if (fnv1a(bytes.data(), bytes.size() - kChecksumBytes) != stored)
    throw InputError(path + ": damaged checkpoint: checksum mismatch (the file was changed after it was written)");
  if (h.bodies != sim.bodies.size() || h.drivers != sim.drivers.size())
    throw InputError(path + ": checkpoint of " + std::to_string(h.bodies) + " bodies and " + std::to_string(h.drivers) +
                     " drivers; the scene has " + std::to_string(sim.bodies.size()) + " and " +
                     std::to_string(sim.drivers.size()) + " (was it written for another scene?)");
  if (h.fingerprint == scene_fingerprint(sim)) return;
  const std::string what = path + ": checkpoint written for another scene (its time step, gravity, contact law, "
                                  "bodies or drivers differ from " + sim.scene().path + ")";
  if (!force) throw InputError(what + "; give --force to resume it anyway");
  std::fprintf(stderr, "warning: %s; resuming anyway (--force)\n", what.c_str());
}

}  // namespace

void write_checkpoint(const std::string& path, const Simulation& sim, const OutputProgress& progress) {
  Writer counter;  // a first pass counts the payload's bytes for the header
  write_payload(counter, sim, progress);
  const std::string tmp = path + ".tmp";
  std::ofstream out(tmp, std::ios::binary);
  if (!out) throw RunError("cannot write checkpoint " + tmp + ": " + std::strerror(errno));
  Writer w{&out};
  w.raw(kMagic, sizeof(kMagic));
  w.pod(Header{scene_fingerprint(sim), sim.bodies.size(), sim.drivers.size(), counter.size});
  write_payload(w, sim, progress);
  const std::uint64_t checksum = w.checksum;  // of all bytes before it
  w.pod(checksum);
  out.close();
  if (!out) throw RunError("cannot write checkpoint " + tmp);
  if (std::rename(tmp.c_str(), path.c_str()) != 0)  // atomic: a crash never leaves half a checkpoint
    throw RunError("cannot rename " + tmp + " to " + path + ": " + std::strerror(errno));
}

void read_checkpoint(const std::string& path, Simulation& sim, OutputProgress& progress, bool force) {
  const std::string bytes = read_file(path);
  const auto is = [&](const char (&m)[8]) {
    return bytes.size() >= sizeof(m) && std::memcmp(bytes.data(), m, sizeof(m)) == 0;
  };
  if (!is(kMagic) && !is(kMagic05) && !is(kMagic04) && !is(kMagic03))
    throw InputError(path + ": not a polydem checkpoint (formats 03 to " + std::string(kMagic + 6, 2) + " resume)");
  if (is(kMagic)) check_header(bytes, path, sim, force);
  Reader r{bytes, is(kMagic) ? kHeaderBytes : sizeof(kMagic),
           is(kMagic) ? bytes.size() - kChecksumBytes : bytes.size(), path};
  r.last_step_fields = !is(kMagic03);
  std::int64_t step = 0;
  double dt = 0.0;
  r.pod(step);
  r.pod(dt);
  if (dt != sim.dt())
    throw InputError(path + ": checkpoint time step " + std::to_string(dt) + " s differs from the scene's " +
                     std::to_string(sim.dt()) + " s (was it written for another scene?)");
  if (!(step >= 0 && double(step) <= kMaxSteps)) r.fail("step counter " + std::to_string(step) + " out of range");
  sim.set_step_index(step);
  sim.ledger = EnergyLedger{};
  const std::size_t ledger_bytes = is(kMagic) || is(kMagic05) ? sizeof(EnergyLedger) : kLedgerBytes04;
  if (r.left() < ledger_bytes) r.fail("truncated in the energy ledger");
  std::memcpy(reinterpret_cast<char*>(&sim.ledger), bytes.data() + r.at, ledger_bytes);
  r.at += ledger_bytes;
  Bodies& b = sim.bodies;
  const std::size_t n = b.size();
  r.array(b.position, n); r.array(b.orientation, n); r.array(b.velocity, n); r.array(b.angular_velocity, n);
  r.array(b.angular_momentum, n); r.array(b.force, n); r.array(b.torque, n);
  std::uint64_t nd = 0;
  r.pod(nd);
  if (nd != sim.drivers.size()) throw InputError(path + ": checkpoint driver count differs from the scene's");
  for (std::size_t j = 0; j < nd; ++j) driver_fields(r, sim.drivers[j]);
  check_state(r, sim);
  read_active(r, sim.engine().body_pairs(), n, n, false);
  read_active(r, sim.engine().driver_pairs(), n, nd, true);
  sim.force_rebuild();
  r.pod(progress.frame);
  std::uint64_t nf = 0;
  r.pod(nf);
  r.count(nf, 2 * sizeof(std::uint64_t), "output frame");
  if (progress.frame < std::int64_t(nf)) r.fail("frame counter " + std::to_string(progress.frame) + " out of range");
  progress.frames.resize(nf);
  for (OutputFrame& f : progress.frames) {
    r.pod(f.time);
    if (!std::isfinite(f.time)) r.fail("an output frame's time is not finite");
    std::uint64_t nfiles = 0;
    r.pod(nfiles);
    r.count(nfiles, sizeof(std::uint64_t), "file name");
    f.files.resize(nfiles);
    for (std::string& s : f.files) r.string(s);
  }
  if (r.left() != 0) r.fail(std::to_string(r.left()) + " bytes after the end of the checkpoint");
}

}  // namespace polydem
