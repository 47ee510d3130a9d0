#include "field/external_forces.hpp"

#include <cmath>

#include "field/fluid_source.hpp"
#include "polydem/parallel.hpp"

namespace polydem {

bool ExternalForces::wanted(const FieldSettings& f) {
  return f.quadratic || f.fluid_friction || f.pressure_force || f.viscous_force || f.archimedes || f.fluid;
}

ExternalForces::ExternalForces(const FieldSettings& f, const std::vector<Shape>& shapes, const Bodies& bodies)
    : shapes_(shapes) {
  quadratic_on_ = f.quadratic.has_value();
  if (f.quadratic) quadratic_ = *f.quadratic;
  if (f.fluid_friction) friction_cx_ = f.fluid_friction->cx;
  if (f.pressure_force) pressure_ = 1.0 + f.pressure_force->added_mass;
  if (f.viscous_force) viscous_ = 1.0 + f.viscous_force->added_mass;
  archimedes_ = f.archimedes;
  gravity_ = f.gravity.value_or(Vec3::Zero());
  if (f.fluid) grid_ = make_fluid_grid(*f.fluid, fluid_needs(f));
  if (f.fluid && f.void_fraction)
    void_fraction_ = std::make_unique<VoidFraction>(shapes, f.void_fraction->samples, f.void_fraction->alpha_min);
  set_rows(field_rows(bodies));
}

void ExternalForces::set_rows(const FieldBodies& rows) {
  const std::size_t n = rows.size;
  volume_.resize(n);
  area_.resize(n);
  for (std::size_t b = 0; b < n; ++b) {
    const double s = rows.scale[b];
    volume_[b] = shapes_[rows.shape[b]].volume * s * s * s;
    const double r = std::cbrt(3.0 * volume_[b] / (4.0 * kPi));  // equivalent-sphere radius
    area_[b] = kPi * r * r;
  }
  vs_ = volume_;
  power_.assign(n, 0.0);
  outside_flag_.assign(n, 0);
}

Vec3 ExternalForces::grid_force(const FieldBodies& rows, std::size_t b) const {
  const FluidGrid& g = *grid_;
  const FluidGrid::Stencil st = g.stencil(rows.position[b]);
  Vec3 f = Vec3::Zero();
  if (friction_cx_) {  // f = cx |dv| dv pi r^2, dv = fluid - particle velocity
    const Vec3 dv = g.at(g.U, st) - rows.velocity[b];
    f += *friction_cx_ * dv.norm() * area_[b] * dv;
  }
  if (pressure_) f -= vs_[b] * *pressure_ * g.at(g.grad_p, st);
  if (viscous_) f -= vs_[b] * *viscous_ * g.at(g.div_tau, st);
  if (archimedes_) f -= g.at(g.rho, st) * vs_[b] * gravity_;
  return f;
}

void ExternalForces::apply(const FieldBodies& rows) {
  const bool grid_forces = grid_ && (friction_cx_ || pressure_ || viscous_ || archimedes_);
  if (grid_forces && void_fraction_) void_fraction_->particle_volumes(*grid_, rows, vs_);
  parallel_for(rows.size, [&](std::size_t b) {
    if (!rows.owned(b)) {  // its owner applies its forces
      power_[b] = 0.0, outside_flag_[b] = 0;
      return;
    }
    const Vec3& v = rows.velocity[b];
    Vec3 f = Vec3::Zero();
    if (quadratic_on_) f -= quadratic_.mu * quadratic_.cx * v.norm() * v;
    outside_flag_[b] = grid_ && !grid_->locate(rows.position[b]);
    if (grid_forces && !outside_flag_[b]) f += grid_force(rows, b);
    rows.force[b] += f;
    power_[b] = f.dot(v);
  });
  outside_ = 0;
  for (std::size_t b = 0; b < rows.size && grid_; ++b) outside_ += outside_flag_[b];
}

ExactSum ExternalForces::add(const FieldBodies& rows) {
  apply(rows);
  ExactSum power;  // W
  power.add_all(power_.data(), rows.size);
  return power;
}

double ExternalForces::add(Bodies& bodies) {
  apply(field_rows(bodies));
  return ExactSum::rounded_sum(power_.data(), bodies.size());
}

std::optional<VoidFractionField> ExternalForces::void_fraction(const Bodies& bodies) const {
  if (!grid_ || !void_fraction_) return std::nullopt;
  return void_fraction_->field(*grid_, bodies);
}

}  // namespace polydem
