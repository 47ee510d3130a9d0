#include "sim/build_bodies.hpp"

#include "integrate/integrate.hpp"
#include "polydem/error.hpp"

namespace polydem {

Bodies build_bodies(const std::vector<BodySpec>& specs, const ShapeLibrary& library) {
  Bodies b;
  b.resize(specs.size());
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const BodySpec& s = specs[i];
    const int shape = library.find(s.shape);
    if (shape < 0)
      throw InputError(input_message(s.loc.file, s.loc.line, "shape", "unknown shape '" + s.shape + "'"));
    const Shape& sh = library.shapes[shape];
    if (sh.radius <= 0.0)
      throw InputError(input_message(s.loc.file, s.loc.line, "shape",
                                     "shape '" + s.shape + "' has radius 0: polydem needs a rounded body (radius > 0)"));
    b.shape[i] = shape;
    b.scale[i] = s.scale;
    b.mass[i] = s.density * sh.volume * s.scale * s.scale * s.scale;
    b.inertia[i] = b.mass[i] * sh.inertia_per_mass * s.scale * s.scale;
    b.position[i] = s.position;
    b.orientation[i] = (s.orientation * sh.input_rotation).normalized();
    b.velocity[i] = s.velocity;
    b.group[i] = s.group;
    set_angular_velocity(b, i, s.angular_velocity);
  }
  update_angular_velocity(b);
  return b;
}

}  // namespace polydem
