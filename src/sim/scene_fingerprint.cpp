#include "sim/scene_fingerprint.hpp"

#include <cstring>

#include "driver/mesh.hpp"

namespace polydem {

std::uint64_t fnv1a(const char* data, std::size_t size, std::uint64_t hash) {
  // Unrolled: a checkpoint's bytes (written, then read back on resume) took 6 instructions each.
#pragma GCC unroll 8
  for (std::size_t k = 0; k < size; ++k) hash = (hash ^ std::uint8_t(data[k])) * 1099511628211ull;
  return hash;
}

namespace {

struct Hasher {
  std::uint64_t hash = fnv1a(nullptr, 0);
  void add(double v) { hash = fnv1a(reinterpret_cast<const char*>(&v), sizeof(v), hash); }
  void add(std::int64_t v) { hash = fnv1a(reinterpret_cast<const char*>(&v), sizeof(v), hash); }
  void add(const Vec3& v) { add(v.x()); add(v.y()); add(v.z()); }
  void add(const Quat& q) { add(q.x()); add(q.y()); add(q.z()); add(q.w()); }
  void add(const ContactParams& p) {
    for (double v : {p.kn, p.kt, p.kr, p.mur, p.mu, p.en, p.damp_rate, p.damp_tangential, p.fc, p.dncut}) add(v);
    if (p.damping_contact_mass) add(std::int64_t(1));  // only when set: the default's fingerprint is as before
  }
};

// Where the driver stands and its size, as the scene gives them (a mesh: also its vertices).
void add_geometry(Hasher& h, const KindSettings& settings, const DriverKind& kind) {
  if (const auto* w = std::get_if<WallSettings>(&settings)) {
    h.add(w->point);
    h.add(w->normal);
  } else if (const auto* c = std::get_if<CylinderSettings>(&settings)) {
    h.add(c->center);
    h.add(c->axis);
    h.add(c->radius);
    h.add(c->length.value_or(-1.0));
    h.add(std::int64_t(c->inside));
  } else if (const auto* b = std::get_if<BallSettings>(&settings)) {
    h.add(b->center);
    h.add(b->radius);
  } else if (const auto* m = std::get_if<MeshSettings>(&settings)) {
    h.add(m->scale);
    h.add(m->translation);
    h.add(m->rotation);
    for (const Vec3& v : std::get<MeshDriver>(kind).features().vertices) h.add(v);
  }
}

// Drag and the prescribed fluid: coefficients, field, grid and properties (a .vti file by its
// name only: its values are not read again).
void add_fluid(Hasher& h, const FieldSettings& f) {
  h.add(f.quadratic ? Vec3(1.0, f.quadratic->cx, f.quadratic->mu) : Vec3::Zero());
  h.add(f.fluid_friction ? f.fluid_friction->cx : -1.0);
  h.add(f.pressure_force ? f.pressure_force->added_mass : -1.0);
  h.add(f.viscous_force ? f.viscous_force->added_mass : -1.0);
  h.add(std::int64_t(f.archimedes));
  h.add(f.void_fraction ? Vec3(1.0, f.void_fraction->alpha_min, f.void_fraction->samples) : Vec3::Zero());
  if (!f.fluid) return;
  const FieldSettings::FluidField& fl = *f.fluid;
  h.hash = fnv1a(fl.file.data(), fl.file.size(), h.hash);
  h.add(fl.grid_min);
  h.add(fl.grid_max);
  h.add(fl.cells.cast<double>().eval());
  h.add(fl.velocity);
  for (int r = 0; r < 3; ++r) h.add(fl.velocity_gradient.row(r).transpose().eval());
  h.add(fl.reference);
  h.add(fl.pressure);
  h.add(fl.pressure_gradient);
  h.add(fl.rho.value_or(-1.0));
  h.add(fl.nu.value_or(-1.0));
}

}  // namespace

std::uint64_t scene_fingerprint(const Simulation& sim) {
  Hasher h;
  const Scene& scene = sim.scene();
  h.add(sim.dt());
  h.add(scene.forces.gravity ? *scene.forces.gravity : Vec3::Zero());
  const ContactOperator& c = scene.forces.contact;
  h.add(std::int64_t(c.present) + 2 * std::int64_t(c.sphere) + 4 * std::int64_t(c.cohesion));
  h.add(c.config);
  h.add(c.config_driver);  // the parser made it config when absent
  const Bodies& b = sim.bodies;
  h.add(std::int64_t(b.size()));
  for (std::uint32_t k : b.by_user_id()) {  // the same for any body order
    h.add(std::int64_t(b.shape[k]));
    h.add(b.mass[k]);
    h.add(b.scale[k]);
    h.add(b.inertia[k]);
  }
  h.add(std::int64_t(sim.drivers.size()));
  for (std::size_t j = 0; j < sim.drivers.size(); ++j) {
    const DriverSettings& d = sim.scene().drivers[j];
    h.add(std::int64_t(d.kind.index()));
    add_geometry(h, d.kind, sim.drivers.kind(std::uint32_t(j)));
    h.add(d.motion.velocity);
    h.add(d.motion.omega);
    h.add(d.motion.force.value_or(0.0));
    h.add(d.motion.pressure.value_or(0.0));
  }
  add_fluid(h, scene.forces);
  return h.hash;
}

}  // namespace polydem
