#include "sim/body_exchange.hpp"

#include <cstring>

namespace polydem {

namespace {

// Appends and reads doubles and ids at a moving offset.
struct Writer {
  char* at;
  void field(const Vec3& v) { doubles(v.data(), 3); }
  void field(const Quat& q) { doubles(q.coeffs().data(), 4); }
  void field(std::uint32_t id) { std::memcpy(at, &id, sizeof id); at += sizeof id; }
  void doubles(const double* d, std::size_t n) { std::memcpy(at, d, n * sizeof(double)); at += n * sizeof(double); }
};

struct Reader {
  const char* at;
  void field(Vec3& v) { doubles(v.data(), 3); }
  void field(Quat& q) { doubles(q.coeffs().data(), 4); }
  void field(std::uint32_t& id) { std::memcpy(&id, at, sizeof id); at += sizeof id; }
  void doubles(double* d, std::size_t n) { std::memcpy(d, at, n * sizeof(double)); at += n * sizeof(double); }
};

// What a motion parcel carries of a body after its orientation (when sent).
template <class Io, class B>
void velocity_fields(Io& io, B& b, std::size_t i) {
  io.field(b.velocity[i]);
  io.field(b.angular_velocity[i]);
  io.field(b.velocity_end[i]);
  io.field(b.angular_velocity_end[i]);
}

// The fields in one order for both directions: Io is a Writer (const bodies) or a Reader.
template <class Io, class B>
void ghost_fields(Io& io, B& b, std::size_t i) {
  io.field(b.position[i]);
  io.field(b.orientation[i]);
  velocity_fields(io, b, i);
}

template <class Io, class B>
void owned_fields(Io& io, B& b, std::size_t i) {
  ghost_fields(io, b, i);
  io.field(b.angular_momentum[i]);
  io.field(b.force[i]);
  io.field(b.torque[i]);
}

}  // namespace

std::vector<char> pack_ghosts(const Bodies& bodies, const std::vector<std::uint32_t>& ids) {
  std::vector<char> bytes(ids.size() * kGhostBytes);
  pack_ghosts(bodies, ids, bytes.data());
  return bytes;
}

void pack_ghosts(const Bodies& bodies, const std::vector<std::uint32_t>& ids, char* into) {
  Writer w{into};
  for (std::uint32_t b : ids) ghost_fields(w, bodies, b);
}

void unpack_ghosts(const std::vector<char>& bytes, const std::vector<std::uint32_t>& ids, Bodies& bodies) {
  Reader r{bytes.data()};
  for (std::uint32_t b : ids) ghost_fields(r, bodies, b);
}

void unpack_ghosts(const std::vector<char>& bytes, const std::vector<std::uint32_t>& local, LocalStore& store) {
  Reader r{bytes.data()};
  for (std::uint32_t k : local) ghost_fields(r, store, k);
}

std::size_t motion_bytes(bool turning) { return (turning ? 16 : 12) * sizeof(double); }  // 4 vectors (1 quaternion)

void pack_motion(const LocalStore& store, const std::vector<std::uint32_t>& local, bool turning, char* into) {
  Writer w{into};
  for (std::uint32_t k : local) {
    if (turning) w.field(store.orientation[k]);
    velocity_fields(w, store, k);
  }
}

void unpack_motion(const char* bytes, const MotionTarget& to, bool turning, double dt, LocalStore& store) {
  Reader r{bytes};
  for (std::size_t k = 0; k < to.local.size(); ++k) {
    const std::uint32_t l = to.local[k];
    if (turning) r.field(store.orientation[l]);
    velocity_fields(r, store, l);
    to.drifted[k] += store.velocity[l] * dt;  // the owner's drift (integrate.hpp drift_body): its bits
    store.position[l] = to.drifted[k];
  }
}

std::vector<char> pack_owned(const Bodies& bodies, const std::vector<std::uint32_t>& ids) {
  std::vector<char> bytes(ids.size() * kOwnedBytes);
  Writer w{bytes.data()};
  for (std::uint32_t b : ids) {
    w.field(b);
    owned_fields(w, bodies, b);
  }
  return bytes;
}

std::vector<std::uint32_t> unpack_owned(const std::vector<char>& bytes, Bodies& bodies) {
  Reader r{bytes.data()};
  std::vector<std::uint32_t> ids(bytes.size() / kOwnedBytes);
  for (std::uint32_t& b : ids) {
    r.field(b);
    owned_fields(r, bodies, b);
  }
  return ids;
}

}  // namespace polydem
