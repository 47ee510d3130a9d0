#include "sim/checkpoint_io.hpp"

#include <cmath>
#include <cstdio>

#include "sim/body_order.hpp"
#include "sim/run_limits.hpp"

namespace polydem {

void write_flushed(Writer& w, const ExactEnergy& flushed) { w.array(flushed.words()); }

ExactEnergy read_flushed(Reader& r) {
  std::vector<std::uint64_t> words;
  r.array(words, 4 * ExactSum::kWords);
  return ExactEnergy::from_words(words, 1);  // one sum's words: its digits carried
}

void check_open_energy(const Reader& r, const EnergyParts& e) {
  if (!std::isfinite(e.net) || !std::isfinite(e.sliding) || !std::isfinite(e.rolling) || !std::isfinite(e.patch))
    r.fail("a contact's open energy is not finite");
}

void write_clock(Writer& w, const Simulation& sim) {
  w.pod(sim.step_index());
  w.pod(sim.dt());
  w.pod(sim.ledger);
}

void read_body_order(Reader& r, const Simulation& sim, bool stored) {
  std::vector<std::uint32_t> order = identity_order(sim.bodies.size());
  if (stored) r.array(order, sim.bodies.size());
  if (order != sim.bodies.id)
    r.fail(stored ? "its body order is not the one the run was built in"
                  : "written in the scene's body order, resumed into another");
}

std::vector<std::uint32_t> stored_body_order(const std::string& path, const char (&magic)[kMagicBytes],
                                             std::size_t bodies) {
  std::ifstream in(path, std::ios::binary);
  std::string head(kHeaderBytes + sizeof(std::uint64_t), '\0');
  std::uint64_t n = 0;
  if (!in.read(head.data(), std::streamsize(head.size())) || std::memcmp(head.data(), magic, kMagicBytes) != 0 ||
      (std::memcpy(&n, head.data() + kHeaderBytes, sizeof(n)), n != bodies))
    return identity_order(bodies);
  std::vector<std::uint32_t> order(bodies);
  if (!in.read(reinterpret_cast<char*>(order.data()), std::streamsize(bodies * sizeof(std::uint32_t))) ||
      !is_order_of(order, bodies))
    throw InputError(path + ": damaged checkpoint: its body order is not one of " + std::to_string(bodies) + " bodies");
  return order;
}

void read_step(Reader& r, Simulation& sim) {
  std::int64_t step = 0;
  double dt = 0.0;
  r.pod(step);
  r.pod(dt);
  if (dt != sim.dt())
    throw InputError(r.path + ": checkpoint time step " + std::to_string(dt) + " s differs from the scene's " +
                     std::to_string(sim.dt()) + " s (was it written for another scene?)");
  if (!(step >= 0 && double(step) <= kMaxSteps)) r.fail("step counter " + std::to_string(step) + " out of range");
  sim.set_step_index(step);
}

void write_drivers(Writer& w, const Drivers& drivers) {
  w.pod<std::uint64_t>(drivers.size());
  for (std::size_t j = 0; j < drivers.size(); ++j) driver_fields(w, drivers[j]);
}

void read_drivers(Reader& r, Simulation& sim) {
  std::uint64_t nd = 0;
  r.pod(nd);
  if (nd != sim.drivers.size()) throw InputError(r.path + ": checkpoint driver count differs from the scene's");
  for (std::size_t j = 0; j < nd; ++j) driver_fields(r, sim.drivers[j]);
}

void write_progress(Writer& w, const OutputProgress& progress) {
  w.pod(progress.frame);
  w.pod<std::uint64_t>(progress.frames.size());
  for (const OutputFrame& f : progress.frames) {
    w.pod(f.time);
    w.pod<std::uint64_t>(f.files.size());
    for (const std::string& s : f.files) w.string(s);
  }
}

void read_progress(Reader& r, OutputProgress& progress) {
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
}

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

void check_state(const Reader& r, const Simulation& sim) {
  check_body_state(r, sim.bodies);
  check_run_state(r, sim);
}

void check_run_state(const Reader& r, const Simulation& sim) {
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

void check_size_and_checksum(const std::string& bytes, const std::string& path, std::size_t header_bytes,
                             std::uint64_t payload_bytes) {
  if (payload_bytes != bytes.size() - header_bytes - kChecksumBytes)
    throw InputError(path + ": damaged checkpoint: " + std::to_string(bytes.size()) + " bytes where its header says " +
                     std::to_string(payload_bytes + header_bytes + kChecksumBytes) + " (truncated or appended to)");
  std::uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + bytes.size() - kChecksumBytes, kChecksumBytes);
  if (fnv1a(bytes.data(), bytes.size() - kChecksumBytes) != stored)
    throw InputError(path + ": damaged checkpoint: checksum mismatch (the file was changed after it was written)");
}

void check_header(const std::string& bytes, const std::string& path, const Simulation& sim, bool force) {
  if (bytes.size() < kHeaderBytes + kChecksumBytes) throw InputError(path + ": damaged checkpoint: truncated header");
  Header h;
  std::memcpy(&h, bytes.data() + kMagicBytes, sizeof(h));
  check_size_and_checksum(bytes, path, kHeaderBytes, h.payload_bytes);
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

}  // namespace polydem
