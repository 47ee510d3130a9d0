#include "sim/body_exchange.hpp"

#include <cstring>

namespace polydem {

namespace {

// Appends and reads doubles and ids at a moving offset.
struct Writer {
  char* at;
  void field(const Vec3& v) { doubles(v.data(), 3); }
  void field(const Quat& q) { doubles(q.coeffs().data(), 4); }
  template <class T>  // a scalar: an id, a shape or group index, a double
  void field(T v) { std::memcpy(at, &v, sizeof v); at += sizeof v; }
  void doubles(const double* d, std::size_t n) { std::memcpy(at, d, n * sizeof(double)); at += n * sizeof(double); }
};

struct Reader {
  const char* at;
  void field(Vec3& v) { doubles(v.data(), 3); }
  void field(Quat& q) { doubles(q.coeffs().data(), 4); }
  template <class T>
  void field(T& v) { std::memcpy(&v, at, sizeof v); at += sizeof v; }
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

// What a receiver cannot know of a body it did not hold: a ghost's constants (contacts read
// shape, scale and mass; output group and user id), and an owner's inertia too.
template <class Io, class B>
void ghost_constants(Io& io, B& b, std::size_t i) {
  io.field(b.shape[i]);
  io.field(b.scale[i]);
  io.field(b.mass[i]);
  io.field(b.group[i]);
  io.field(b.id[i]);
}

template <class Io, class B>
void mover_fields(Io& io, B& b, std::size_t i) {
  io.field(b.global_id[i]);
  owned_fields(io, b, i);
  ghost_constants(io, b, i);
  io.field(b.inertia[i]);
}

// Appends n rows to `store` to be read into; returns the first.
std::size_t grown(LocalStore& store, std::size_t n) {
  const std::size_t first = store.size();
  store.resize(first + n);
  return first;
}

}  // namespace

std::vector<char> pack_ghosts(const LocalStore& store, const std::vector<std::uint32_t>& rows) {
  std::vector<char> bytes(rows.size() * kGhostBytes);
  Writer w{bytes.data()};
  for (std::uint32_t k : rows) {
    ghost_fields(w, store, k);
    ghost_constants(w, store, k);
  }
  return bytes;
}

void unpack_ghosts(const std::vector<char>& bytes, const std::vector<std::uint32_t>& ids, LocalStore& store) {
  Reader r{bytes.data()};
  const std::size_t first = grown(store, ids.size());
  for (std::size_t k = 0; k < ids.size(); ++k) {
    store.global_id[first + k] = ids[k];
    store.ghost[first + k] = 1;
    ghost_fields(r, store, first + k);
    ghost_constants(r, store, first + k);
  }
}

std::size_t motion_bytes(MotionFields fields) {
  return (fields.orientation ? 16 : fields.spin_end ? 12 : 9) * sizeof(double);  // with_fields' kinds
}

namespace {

// What a motion parcel reads or writes of a store, its arrays' addresses in locals: a copy
// into a store's vector could otherwise move its data pointer, which the loop then reloads (~2
// times the instructions a body).
template <class V, class Q>
struct MotionArrays {
  Q* orientation;
  V* velocity;
  V* angular_velocity;
  V* velocity_end;
  V* angular_velocity_end;
};

template <class V, class Q, class S>
MotionArrays<V, Q> motion_arrays(S& store) {
  return {store.orientation.data(), store.velocity.data(), store.angular_velocity.data(), store.velocity_end.data(),
          store.angular_velocity_end.data()};
}

// A motion parcel's fields of body k, in one order for both directions (Io: Writer or Reader).
template <bool kOrientation, bool kSpinEnd, class Io, class A>
void motion_fields(Io& io, const A& a, std::size_t k) {
  if (kOrientation) io.field(a.orientation[k]);
  io.field(a.velocity[k]);
  io.field(a.angular_velocity[k]);
  io.field(a.velocity_end[k]);
  if (kSpinEnd) io.field(a.angular_velocity_end[k]);
}

template <bool kOrientation, bool kSpinEnd>
void pack_rows(const std::vector<std::uint32_t>& local, const MotionArrays<const Vec3, const Quat> a, char* into) {
  Writer w{into};
  for (std::uint32_t k : local) motion_fields<kOrientation, kSpinEnd>(w, a, k);
}

template <bool kOrientation, bool kSpinEnd>
void unpack_rows(const char* bytes, const MotionTarget& to, double dt, const MotionArrays<Vec3, Quat> a, Vec3* x) {
  Reader r{bytes};
  const std::uint32_t* local = to.local.data();
  Vec3* drifted = to.drifted;  // m
  for (std::size_t k = 0, n = to.local.size(); k < n; ++k) {
    const std::uint32_t l = local[k];
    motion_fields<kOrientation, kSpinEnd>(r, a, l);
    drifted[k] += a.velocity[l] * dt;  // the owner's drift (integrate.hpp drift_body): its bits
    x[l] = drifted[k];
  }
}

// f.template operator()<kOrientation, kSpinEnd>() for `fields`: the loops compiled per kind.
template <class F>
void with_fields(MotionFields fields, F&& f) {
  if (fields.orientation) f.template operator()<true, true>();  // polyhedra read every field
  else if (fields.spin_end) f.template operator()<false, true>();
  else f.template operator()<false, false>();
}

}  // namespace

void pack_motion(const LocalStore& store, const std::vector<std::uint32_t>& local, MotionFields fields, char* into) {
  const auto a = motion_arrays<const Vec3, const Quat>(store);
  with_fields(fields, [&]<bool kO, bool kS>() { pack_rows<kO, kS>(local, a, into); });
}

void unpack_motion(const char* bytes, const MotionTarget& to, MotionFields fields, double dt, LocalStore& store) {
  const auto a = motion_arrays<Vec3, Quat>(store);
  with_fields(fields, [&]<bool kO, bool kS>() { unpack_rows<kO, kS>(bytes, to, dt, a, store.position.data()); });
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

std::vector<char> pack_owned(const LocalStore& store, const std::vector<std::uint32_t>& rows) {
  std::vector<char> bytes(rows.size() * kOwnedBytes);
  Writer w{bytes.data()};
  for (std::uint32_t k : rows) {
    w.field(store.global_id[k]);
    owned_fields(w, store, k);
  }
  return bytes;
}

std::vector<char> pack_movers(const LocalStore& store, const std::vector<std::uint32_t>& rows) {
  std::vector<char> bytes(rows.size() * kMoverBytes);
  Writer w{bytes.data()};
  for (std::uint32_t k : rows) mover_fields(w, store, k);
  return bytes;
}

void unpack_movers(const std::vector<char>& bytes, LocalStore& store) {
  Reader r{bytes.data()};
  const std::size_t n = bytes.size() / kMoverBytes;
  const std::size_t first = grown(store, n);
  for (std::size_t k = first; k < first + n; ++k) {
    store.ghost[k] = 0;
    mover_fields(r, store, k);
  }
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
