#include "sim/scene_fingerprint.hpp"

#include <cstring>

namespace polydem {

std::uint64_t fnv1a(const char* data, std::size_t size, std::uint64_t hash) {
  for (std::size_t k = 0; k < size; ++k) hash = (hash ^ std::uint8_t(data[k])) * 1099511628211ull;
  return hash;
}

namespace {

struct Hasher {
  std::uint64_t hash = fnv1a(nullptr, 0);
  void add(double v) { hash = fnv1a(reinterpret_cast<const char*>(&v), sizeof(v), hash); }
  void add(std::int64_t v) { hash = fnv1a(reinterpret_cast<const char*>(&v), sizeof(v), hash); }
  void add(const Vec3& v) { add(v.x()); add(v.y()); add(v.z()); }
  void add(const ContactParams& p) {
    for (double v : {p.kn, p.kt, p.kr, p.mur, p.mu, p.en, p.damp_rate, p.damp_tangential, p.fc, p.dncut}) add(v);
  }
};

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
  for (std::size_t k = 0; k < b.size(); ++k) {
    h.add(std::int64_t(b.shape[k]));
    h.add(b.mass[k]);
    h.add(b.scale[k]);
    h.add(b.inertia[k]);
  }
  h.add(std::int64_t(sim.drivers.size()));
  for (std::size_t j = 0; j < sim.drivers.size(); ++j) {
    const DriverSettings& d = sim.scene().drivers[j];
    h.add(std::int64_t(d.kind.index()));
    const auto* cylinder = std::get_if<CylinderSettings>(&d.kind);
    const auto* ball = std::get_if<BallSettings>(&d.kind);
    const auto* mesh = std::get_if<MeshSettings>(&d.kind);
    h.add(cylinder ? cylinder->radius : ball ? ball->radius : 0.0);
    h.add(mesh ? mesh->scale : 1.0);
    h.add(d.motion.velocity);
    h.add(d.motion.omega);
    h.add(d.motion.force.value_or(0.0));
    h.add(d.motion.pressure.value_or(0.0));
  }
  return h.hash;
}

}  // namespace polydem
