#include "field/fluid_source.hpp"

#include <cmath>

#include "field/vti_reader.hpp"
#include "polydem/error.hpp"

namespace polydem {

namespace {

// The array `name` of the image as cell values of one component each (U: three).
template <class T>
bool take_array(const VtiImage& img, const char* name, std::vector<T>& out, const std::string& where) {
  const auto it = img.arrays.find(name);
  if (it == img.arrays.end()) return false;
  const int components = std::is_same_v<T, Vec3> ? 3 : 1;
  if (it->second.components != components)
    throw InputError(where + "array '" + name + "' has " + std::to_string(it->second.components) +
                     " components, expected " + std::to_string(components));
  const std::vector<double>& v = it->second.values;
  for (std::size_t k = 0; k < v.size(); ++k)
    if (!std::isfinite(v[k]))
      throw InputError(where + "array '" + name + "' holds a non-finite value (" + std::to_string(v[k]) + ") in tuple " +
                       std::to_string(k / std::size_t(components)));
  out.resize(v.size() / std::size_t(components));
  for (std::size_t k = 0; k < out.size(); ++k) {
    if constexpr (std::is_same_v<T, Vec3>) out[k] = Vec3(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
    else out[k] = v[k];
  }
  return true;
}

std::string array_names(const VtiImage& img) {
  std::string s;
  for (const auto& [name, a] : img.arrays) s += (s.empty() ? "" : ", ") + name;
  return s.empty() ? "none" : s;
}

FluidGrid grid_from_file(const FieldSettings::FluidField& f, const FluidNeeds& needs) {
  const VtiImage img = read_vti(f.file);
  FluidGrid g;
  g.cells = img.cell_data ? (img.points - Index3::Ones()).cwiseMax(1) : img.points;
  g.spacing = img.spacing;
  g.origin = img.cell_data ? img.origin : Vec3(img.origin - 0.5 * img.spacing);
  const std::string where = f.file + ": ";
  const std::string data = img.cell_data ? "CellData" : "PointData";
  auto missing = [&](const char* name, const char* hint) {
    throw InputError(where + "no array '" + name + "' in its " + data + " (arrays: " + array_names(img) + ")" + hint);
  };
  if (!take_array(img, "U", g.U, where) && needs.U) missing("U", "");
  if (!take_array(img, "p", g.p, where) && needs.p) missing("p", "");
  if (!take_array(img, "rho", g.rho, where)) {
    if (f.rho) g.rho.assign(g.size(), *f.rho);
    else if (needs.rho) missing("rho", "; or give the density in fluid_field (rho: 1000)");
  }
  if (!take_array(img, "nu", g.nu, where)) {
    if (f.nu) g.nu.assign(g.size(), *f.nu);
    else if (needs.nu) missing("nu", "; or give the kinematic viscosity in fluid_field (nu: 1.0e-6)");
  }
  return g;
}

FluidGrid grid_from_fields(const FieldSettings::FluidField& f) {
  FluidGrid g;
  g.origin = f.grid_min;
  g.cells = f.cells;
  g.spacing = (f.grid_max - f.grid_min).cwiseQuotient(f.cells.cast<double>());
  g.U.resize(g.size());
  g.p.resize(g.size());
  for (int k = 0; k < g.cells.z(); ++k)
    for (int j = 0; j < g.cells.y(); ++j)
      for (int i = 0; i < g.cells.x(); ++i) {
        const Index3 c(i, j, k);
        const Vec3 dx = g.center(c) - f.reference;
        g.U[g.index(c)] = f.velocity + f.velocity_gradient * dx;
        g.p[g.index(c)] = f.pressure + f.pressure_gradient.dot(dx);
      }
  if (f.rho) g.rho.assign(g.size(), *f.rho);
  if (f.nu) g.nu.assign(g.size(), *f.nu);
  return g;
}

}  // namespace

FluidNeeds fluid_needs(const FieldSettings& forces) {
  FluidNeeds n;
  n.U = forces.fluid_friction.has_value() || forces.viscous_force.has_value();
  n.p = n.grad_p = forces.pressure_force.has_value();
  n.rho = forces.archimedes || forces.viscous_force.has_value();
  n.nu = n.div_tau = forces.viscous_force.has_value();
  return n;
}

FluidGrid make_fluid_grid(const FieldSettings::FluidField& f, const FluidNeeds& needs) {
  FluidGrid g;
  try {
    g = f.file.empty() ? grid_from_fields(f) : grid_from_file(f, needs);
  } catch (const InputError& e) {
    throw InputError(input_message(f.file_loc.file, f.file_loc.line, f.file_key, e.what()));
  }
  g.trilinear = f.trilinear;
  derive_fields(g, needs.grad_p, needs.div_tau);
  return g;
}

}  // namespace polydem
