#include "sim/checkpoint.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>

#include "polydem/error.hpp"

namespace polydem {

namespace {

constexpr char kMagic[8] = {'P', 'D', 'C', 'K', 'P', 'T', '0', '5'};  // 05: the ledger's dissipation by mechanism
// Older formats still resume, with what only the energy ledger reads missing (forces and
// motion unchanged): 04 has no ledger shares (all its dissipation counts as dashpot); 03 has
// neither those nor the last dashpot force, gap and weight per contact (its contacts' ledgers
// restart as new contacts).
constexpr char kMagic04[8] = {'P', 'D', 'C', 'K', 'P', 'T', '0', '4'};
constexpr char kMagic03[8] = {'P', 'D', 'C', 'K', 'P', 'T', '0', '3'};
// Bytes of EnergyLedger up to its format-05 shares: what formats 03 and 04 hold.
constexpr std::size_t kLedgerBytes04 = 3 * sizeof(double) + sizeof(Vec3);
static_assert(sizeof(EnergyLedger) == kLedgerBytes04 + 3 * sizeof(double), "EnergyLedger: shares after the format-04 fields");

struct Writer {
  std::ofstream out;
  template <class T> void pod(const T& v) { out.write(reinterpret_cast<const char*>(&v), sizeof(T)); }
  template <class T> void array(const std::vector<T>& v) {
    pod<std::uint64_t>(v.size());
    out.write(reinterpret_cast<const char*>(v.data()), std::streamsize(v.size() * sizeof(T)));
  }
  void string(const std::string& s) { pod<std::uint64_t>(s.size()); out.write(s.data(), std::streamsize(s.size())); }
};

struct Reader {
  std::ifstream in;
  std::string path;
  bool last_step_fields = true;  // false for format 03
  void fail() const { throw InputError(path + ": truncated or damaged checkpoint"); }
  template <class T> void pod(T& v) { if (!in.read(reinterpret_cast<char*>(&v), sizeof(T))) fail(); }
  template <class T> void array(std::vector<T>& v, std::size_t expected) {
    std::uint64_t n = 0;
    pod(n);
    if (n != expected) throw InputError(path + ": checkpoint holds " + std::to_string(n) +
                                        " entries where the scene has " + std::to_string(expected) +
                                        " (was it written for another scene?)");
    v.resize(n);
    if (!in.read(reinterpret_cast<char*>(v.data()), std::streamsize(n * sizeof(T)))) fail();
  }
  void string(std::string& s) {
    std::uint64_t n = 0;
    pod(n);
    if (n > (1u << 20)) fail();
    s.resize(n);
    if (!in.read(s.data(), std::streamsize(n))) fail();
  }
};

// Active slots with their pair, so the next rebuild hands their history over by key. Field by
// field: no padding bytes in the file, so equal states give equal files.
template <class IO, class Key, class Slot>
void slot_fields(IO& io, Key& f, Slot& s, bool last_step_fields = true) {
  bool active = true;  // only active slots are stored: a constant byte, kept from format 03
  io.pod(f.type); io.pod(f.a); io.pod(f.b); io.pod(active);
  io.pod(s.history.ft); io.pod(s.history.mr); io.pod(s.point); io.pod(s.force); io.pod(s.fn);
  io.pod(s.history.gap);  // the last gap, stored twice: format 03 has it here and not below
  if (!last_step_fields) return;
  io.pod(s.history.fd); io.pod(s.history.gap); io.pod(s.history.weight);
}

// The moving state of a driver (placement, motion, reactions), one writer/reader for both ways.
template <class IO, class D>
void driver_fields(IO& io, D& d) {
  io.pod(d.active); io.pod(d.point); io.pod(d.normal); io.pod(d.center); io.pod(d.axis);
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
        slot_fields(w, list.features[s], list.slots[s]);
      }
}

void read_active(Reader& r, PairList& list) {
  std::uint64_t n = 0;
  r.pod(n);
  list = PairList{};
  list.slot_begin.push_back(0);
  for (std::uint64_t e = 0; e < n; ++e) {
    BodyPair pair;
    FeaturePair key;
    ContactSlot slot;
    r.pod(pair.i);
    r.pod(pair.j);
    slot_fields(r, key, slot, r.last_step_fields);
    if (!r.last_step_fields) slot.history.gap = kNoGap;  // format 03: no last step for the energy ledger
    if (list.pairs.empty() || list.pairs.back().i != pair.i || list.pairs.back().j != pair.j) {
      list.pairs.push_back(pair);
      list.slot_begin.push_back(list.slot_begin.back());
    }
    list.features.push_back(key);
    list.slots.push_back(slot);
    list.active.push_back(1);
    ++list.slot_begin.back();
  }
  list.resize_results();
}

}  // namespace

void write_checkpoint(const std::string& path, const Simulation& sim, const OutputProgress& progress) {
  const std::string tmp = path + ".tmp";
  Writer w{std::ofstream(tmp, std::ios::binary)};
  if (!w.out) throw RunError("cannot write checkpoint " + tmp + ": " + std::strerror(errno));
  w.out.write(kMagic, sizeof(kMagic));
  w.pod(sim.step_index());
  w.pod(sim.dt());
  w.pod(sim.ledger);
  const Bodies& b = sim.bodies;
  w.array(b.position); w.array(b.orientation); w.array(b.velocity); w.array(b.angular_velocity);
  w.array(b.angular_momentum); w.array(b.force); w.array(b.torque);
  w.pod<std::uint64_t>(sim.drivers.size());
  for (std::size_t j = 0; j < sim.drivers.size(); ++j) {
    const DriverState& d = sim.drivers[j];
    driver_fields(w, d);
  }
  write_active(w, sim.engine().body_pairs());
  write_active(w, sim.engine().driver_pairs());
  w.pod(progress.frame);
  w.pod<std::uint64_t>(progress.frames.size());
  for (const OutputFrame& f : progress.frames) {
    w.pod(f.time);
    w.pod<std::uint64_t>(f.files.size());
    for (const std::string& s : f.files) w.string(s);
  }
  w.out.close();
  if (!w.out) throw RunError("cannot write checkpoint " + tmp);
  if (std::rename(tmp.c_str(), path.c_str()) != 0)  // atomic: a crash never leaves half a checkpoint
    throw RunError("cannot rename " + tmp + " to " + path + ": " + std::strerror(errno));
}

void read_checkpoint(const std::string& path, Simulation& sim, OutputProgress& progress) {
  Reader r{std::ifstream(path, std::ios::binary), path};
  if (!r.in) throw InputError(path + ": cannot open checkpoint");
  char magic[sizeof(kMagic)];
  const bool read = bool(r.in.read(magic, sizeof(magic)));
  const auto is = [&](const char (&m)[8]) { return read && std::memcmp(magic, m, sizeof(m)) == 0; };
  if (!is(kMagic) && !is(kMagic04) && !is(kMagic03))
    throw InputError(path + ": not a polydem checkpoint of this version (format " + std::string(kMagic + 6, 2) + ")");
  r.last_step_fields = !is(kMagic03);
  std::int64_t step = 0;
  double dt = 0.0;
  r.pod(step);
  r.pod(dt);
  if (dt != sim.dt())
    throw InputError(path + ": checkpoint time step " + std::to_string(dt) + " s differs from the scene's " +
                     std::to_string(sim.dt()) + " s (was it written for another scene?)");
  sim.set_step_index(step);
  sim.ledger = EnergyLedger{};
  if (!r.in.read(reinterpret_cast<char*>(&sim.ledger), is(kMagic) ? sizeof(EnergyLedger) : kLedgerBytes04)) r.fail();
  Bodies& b = sim.bodies;
  const std::size_t n = b.size();
  r.array(b.position, n); r.array(b.orientation, n); r.array(b.velocity, n); r.array(b.angular_velocity, n);
  r.array(b.angular_momentum, n); r.array(b.force, n); r.array(b.torque, n);
  std::uint64_t nd = 0;
  r.pod(nd);
  if (nd != sim.drivers.size()) throw InputError(path + ": checkpoint driver count differs from the scene's");
  for (std::size_t j = 0; j < nd; ++j) {
    DriverState& d = sim.drivers[j];
    driver_fields(r, d);
  }
  read_active(r, sim.engine().body_pairs());
  read_active(r, sim.engine().driver_pairs());
  sim.engine().force_rebuild();
  r.pod(progress.frame);
  std::uint64_t nf = 0;
  r.pod(nf);
  progress.frames.resize(nf);
  for (OutputFrame& f : progress.frames) {
    r.pod(f.time);
    std::uint64_t nfiles = 0;
    r.pod(nfiles);
    f.files.resize(nfiles);
    for (std::string& s : f.files) r.string(s);
  }
}

}  // namespace polydem
