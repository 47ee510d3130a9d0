#pragma once
// The pieces checkpoint files share (sim/checkpoint.cpp: one process's file; sim/checkpoint_pieces.cpp:
// a distributed run's manifest and pieces): the streaming writer with its running checksum, the
// bounds-checked reader, the field lists of a contact and a driver, and the checks on read.
#include <cstdint>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <type_traits>
#include <vector>

#include "polydem/error.hpp"
#include "sim/checkpoint.hpp"
#include "sim/scene_fingerprint.hpp"
#include "sim/simulation.hpp"

namespace polydem {

struct Header {  // format 06 and the manifest, after the 8-byte magic
  std::uint64_t fingerprint, bodies, drivers, payload_bytes;
};
constexpr std::size_t kMagicBytes = 8;
constexpr std::size_t kHeaderBytes = kMagicBytes + sizeof(Header);
constexpr std::size_t kChecksumBytes = sizeof(std::uint64_t);
// Bytes of one stored contact in format 03 (the fewest): the pair, then slot_fields (key, flag,
// ft, mr, point, force, fn, gap; 05 adds fd, gap, weight).
constexpr std::size_t kContactBytes03 = 2 * 4 + 1 + 2 + 4 + 1 + 4 * sizeof(Vec3) + 2 * sizeof(double);
static_assert(kContactBytes03 == 128);
constexpr double kUnitTolerance = 1e-6;  // |q| - 1 of a stored orientation (round-off is ~1e-15)

// Streams the checkpoint to its file with the running checksum; with no file it only counts
// bytes (the payload's size goes in the header before it). The state is never copied whole in
// memory: a buffer of the file tripled the peak memory of a run at each checkpoint.
// Fields go to the file through a small buffer: a stream write per field cost ~150 instructions
// (a checkpoint of 3,375 packed cubes writes ~200,000 fields).
struct Writer {
  static constexpr std::size_t kBufferBytes = 1 << 16;
  std::ofstream* out = nullptr;
  std::uint64_t size = 0, checksum = fnv1a(nullptr, 0);
  std::string buffer{};  // bytes not yet written to out, fewer than kBufferBytes after each raw
  void raw(const char* data, std::size_t n) {
    size += n;
    if (!out) return;
    checksum = fnv1a(data, n, checksum);
    if (n >= kBufferBytes) {  // a whole array: straight to the file, not copied
      flush();
      out->write(data, std::streamsize(n));
      return;
    }
    buffer.append(data, n);
    if (buffer.size() >= kBufferBytes) flush();
  }
  void flush() {
    out->write(buffer.data(), std::streamsize(buffer.size()));
    buffer.clear();
  }
  template <class T> void pod(const T& v) { raw(reinterpret_cast<const char*>(&v), sizeof(T)); }
  void flag(const bool& b) { pod(b); }
  void byte(const std::uint8_t& v, std::uint8_t) { pod(v); }
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
  void byte(std::uint8_t& v, std::uint8_t largest) {
    pod(v);
    if (v > largest) fail("a state byte holds " + std::to_string(v) + " at byte " + std::to_string(at - 1));
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
  // The byte formats 03-06 kept constant at 1 (only active slots are stored) holds whether the
  // tangential spring stuck at the last step (1) and, + 2, whether the rolling spring slipped:
  // files of older builds resume as stuck.
  std::uint8_t state = std::uint8_t((s.history.slipping ? 0 : 1) + (s.history.rolling_slipping ? 2 : 0));
  io.pod(f.type); io.pod(f.a); io.pod(f.b); io.byte(state, 3);
  if constexpr (!std::is_const_v<Slot>) s.history.slipping = !(state & 1), s.history.rolling_slipping = state & 2;
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

// The energy ledger's open part (format 07, pieces 02): the ended contacts' exact sum, as words
// (canonical: equal sums give equal bytes). The pairs' pending energies go with their slots.
void write_flushed(Writer& w, const ExactEnergy& flushed);
ExactEnergy read_flushed(Reader& r);
// A pair's pending energy read must be finite.
void check_open_energy(const Reader& r, const EnergyParts& e);

// Step, time step and energy ledger: the payload's first fields.
void write_clock(Writer& w, const Simulation& sim);
// The body order first in a format-08 payload (or manifest 03): it must be the one `sim` was
// built in (checkpoint_body_order); older files (`stored` false) hold the scene's order.
void read_body_order(Reader& r, const Simulation& sim, bool stored);
// The order stored in `path` if its magic is `magic` and it holds `bodies` bodies, else the
// scene's order (the full read reports a file that does not fit).
std::vector<std::uint32_t> stored_body_order(const std::string& path, const char (&magic)[kMagicBytes],
                                             std::size_t bodies);
// Step and time step (the ledger's bytes vary with the format), checked against the scene.
void read_step(Reader& r, Simulation& sim);
// The driver count, then each driver's moving state.
void write_drivers(Writer& w, const Drivers& drivers);
void read_drivers(Reader& r, Simulation& sim);

// The output progress (frame counter, frames in the .pvd), the payload's last part.
void write_progress(Writer& w, const OutputProgress& progress);
void read_progress(Reader& r, OutputProgress& progress);

// The closing checksum of a file and its size in bytes.
struct FileSeal {
  std::uint64_t checksum = 0, bytes = 0;
};

// Writes `magic`, `header` (its payload_bytes set here), the payload and the checksum of all
// bytes before it to `path`.tmp, then renames it to `path`: a crash never leaves half a file.
// `payload(Writer&)` runs twice: a first pass counts its bytes for the header.
template <class HeaderT, class Payload>
FileSeal write_sealed(const std::string& path, const char (&magic)[kMagicBytes], HeaderT header, Payload payload) {
  Writer counter;
  payload(counter);
  header.payload_bytes = counter.size;
  const std::string tmp = path + ".tmp";
  std::ofstream out(tmp, std::ios::binary);
  if (!out) throw RunError("cannot write checkpoint " + tmp + ": " + std::strerror(errno));
  Writer w{&out};
  w.raw(magic, kMagicBytes);
  w.pod(header);
  payload(w);
  const std::uint64_t checksum = w.checksum;  // of all bytes before it
  w.pod(checksum);
  w.flush();
  out.close();
  if (!out) throw RunError("cannot write checkpoint " + tmp);
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    throw RunError("cannot rename " + tmp + " to " + path + ": " + std::strerror(errno));
  return {checksum, w.size};
}

// The whole file in one string of its size (a stream copy would hold it twice).
std::string read_file(const std::string& path);

// What the checkpoint holds must be a state the run can continue from: its bodies (Bodies, or
// a LocalStore of the bodies a rank read), then the ledger and the drivers.
void check_state(const Reader& r, const Simulation& sim);
template <class T>
bool all_finite(const std::vector<T>& v) {
  for (const T& x : v)
    if (!x.allFinite()) return false;
  return true;
}
template <class Arrays>
void check_body_state(const Reader& r, const Arrays& b) {
  if (!all_finite(b.position) || !all_finite(b.velocity) || !all_finite(b.angular_velocity) ||
      !all_finite(b.angular_momentum) || !all_finite(b.force) || !all_finite(b.torque))
    r.fail("a body's position, velocity or force is not finite");
  for (std::size_t k = 0; k < b.position.size(); ++k)
    if (!(std::abs(b.orientation[k].norm() - 1.0) < kUnitTolerance))
      r.fail("body " + std::to_string(b.id[k]) + "'s orientation quaternion has length " +
             std::to_string(b.orientation[k].norm()) + ", not 1");
}
void check_run_state(const Reader& r, const Simulation& sim);

// The file's size against `payload_bytes` of its header (`header_bytes` with the magic), then
// its closing checksum.
void check_size_and_checksum(const std::string& bytes, const std::string& path, std::size_t header_bytes,
                             std::uint64_t payload_bytes);

// Format 06 and the manifest: sizes, checksum, then the scene's fingerprint and counts.
void check_header(const std::string& bytes, const std::string& path, const Simulation& sim, bool force);

}  // namespace polydem
