#include "io/generate.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "io/placement.hpp"
#include "io/random.hpp"
#include "io/yaml_reader.hpp"
#include "polydem/error.hpp"

namespace polydem {
namespace {

// Tries per body before random insertion gives up: near jamming a free spot becomes rare.
constexpr int kMaxAttempts = 2000;

int shape_index(const ShapeLibrary& lib, const std::string& name, const SourceLoc& loc,
                const std::string& key) {
  const int index = lib.find(name);
  if (index >= 0) return index;
  std::vector<std::string> names;
  for (const Shape& s : lib.shapes) names.push_back(s.name);
  const std::string hint = did_you_mean(name, names);
  throw InputError(
      input_message(loc.file, loc.line, key,
                    "unknown shape '" + name + "'" +
                        (hint.empty() ? " (not in the loaded shape libraries)" : hint)));
}

// contact_sphere promises spheres only: the sphere kernels would ignore a polyhedron's corners.
void check_sphere(const Scene& scene, const Shape& shape, const SourceLoc& loc,
                  const std::string& key) {
  if (!scene.forces.contact.sphere || shape.is_sphere()) return;
  const std::string op =
      scene.forces.contact.cohesion ? "contact_sphere_with_cohesion" : "contact_sphere";
  throw InputError(input_message(
      loc.file, loc.line, key,
      "shape '" + shape.name + "' is not a sphere (" + std::to_string(shape.vertices.size()) +
          " vertices) but the scene uses " + op + ": use the contact_polyhedron operator"));
}

// Library index of every body: exact counts from the fractions (largest remainder), shuffled,
// so a 0.7/0.3 mix of 5000 gives 3500 and 1500.
std::vector<int> shape_sequence(const GeneratorSpec& g, const std::vector<int>& indices,
                                std::mt19937_64& rng) {
  std::vector<int> counts(indices.size());
  std::vector<std::pair<double, int>> remainders;
  int assigned = 0;
  for (std::size_t s = 0; s < indices.size(); ++s) {
    const double exact = g.count * g.shapes[s].second;
    counts[s] = static_cast<int>(std::floor(exact));
    assigned += counts[s];
    remainders.emplace_back(-(exact - counts[s]), static_cast<int>(s));
  }
  std::stable_sort(remainders.begin(), remainders.end());
  for (int k = 0; assigned < g.count; ++k, ++assigned)
    ++counts[remainders[k % remainders.size()].second];
  std::vector<int> sequence;
  for (std::size_t s = 0; s < indices.size(); ++s)
    sequence.insert(sequence.end(), counts[s], indices[s]);
  for (std::size_t i = sequence.size(); i > 1; --i) {  // Fisher-Yates
    const auto j = static_cast<std::size_t>(uniform01(rng) * static_cast<double>(i));
    std::swap(sequence[i - 1], sequence[j]);
  }
  return sequence;
}

// Shape, scale and orientation of every body, positions still unset.
std::vector<BodySpec> draw_bodies(const Scene& scene, const GeneratorSpec& g,
                                  const ShapeLibrary& lib, std::mt19937_64& rng) {
  std::vector<int> indices;
  for (const auto& entry : g.shapes) {
    indices.push_back(shape_index(lib, entry.first, g.shapes_loc, "shapes"));
    check_sphere(scene, lib.shapes[indices.back()], g.shapes_loc, "shapes");
  }
  std::vector<BodySpec> bodies;
  for (int s : shape_sequence(g, indices, rng)) {
    BodySpec b;
    b.shape = lib.shapes[s].name;
    b.scale = g.scale_min + (g.scale_max - g.scale_min) * uniform01(rng);
    if (g.random_orientation) b.orientation = uniform_quaternion(rng);
    b.velocity = g.velocity;
    b.density = g.density;
    b.group = g.group;
    b.loc = g.loc;
    bodies.push_back(b);
  }
  return bodies;
}

double bounding_radius(const BodySpec& b, const ShapeLibrary& lib) {
  return lib.shapes[lib.find(b.shape)].bounding_radius * b.scale;
}

void fail_count(const GeneratorSpec& g, const std::string& message) {
  throw InputError(input_message(g.loc.file, g.loc.line, "count", message));
}

void place_random(const GeneratorSpec& g, const Region& region, const DriverClearance& drivers,
                  const ShapeLibrary& lib, std::vector<BodySpec>& bodies, std::mt19937_64& rng) {
  std::vector<double> radii;
  for (const BodySpec& b : bodies) radii.push_back(bounding_radius(b, lib));
  // Largest first: a big body rarely finds a hole among many small ones.
  std::vector<std::size_t> order(bodies.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return radii[a] > radii[b]; });
  SphereGrid grid(region.lower(), region.upper(), radii.empty() ? 0.0 : radii[order[0]],
                  bodies.size());
  for (std::size_t placed = 0; placed < order.size(); ++placed) {
    const double radius = radii[order[placed]];
    if (!region.fits(radius))
      fail_count(g, "a body of bounding radius " + std::to_string(radius) +
                        " m does not fit in the region: use a bigger region or a smaller scale");
    auto free_at = [&](const Vec3& c) {
      return !grid.overlaps(c, radius) && drivers.clear(c, radius);
    };
    int attempt = 0;
    Vec3 center = region.sample(radius, rng);
    while (!free_at(center) && ++attempt < kMaxAttempts) center = region.sample(radius, rng);
    if (attempt == kMaxAttempts)
      fail_count(g, "placed " + std::to_string(placed) + " of " + std::to_string(g.count) +
                        " bodies without overlap" +
                        (drivers.empty() ? "" : " (with each other or a driver)") +
                        ", then found no free spot in " + std::to_string(kMaxAttempts) +
                        " tries: use a bigger region or a smaller count (about " +
                        std::to_string(placed) + " fit)");
    grid.insert(center, radius);
    bodies[order[placed]].position = center;
  }
}

void place_lattice(const GeneratorSpec& g, const Region& region, const DriverClearance& drivers,
                   const ShapeLibrary& lib, std::vector<BodySpec>& bodies) {
  double spacing = 0.0;  // m, the largest bounding diameter the mix can draw
  for (const auto& entry : g.shapes)
    spacing =
        std::max(spacing, 2.0 * lib.shapes[lib.find(entry.first)].bounding_radius * g.scale_max);
  if (!(spacing > 0.0)) fail_count(g, "the shapes have no size (bounding radius 0)");
  const std::vector<Vec3> all = region.lattice(spacing);
  std::vector<Vec3> sites;  // the sites whose sphere of diameter `spacing` overlaps no driver
  for (const Vec3& site : all)
    if (drivers.clear(site, 0.5 * spacing)) sites.push_back(site);
  if (sites.size() < bodies.size())
    fail_count(g, "the region holds " + std::to_string(all.size()) +
                      " lattice sites of spacing " + std::to_string(spacing) + " m" +
                      (drivers.empty()
                           ? ""
                           : " (" + std::to_string(sites.size()) + " clear of the drivers)") +
                      ", fewer than count = " + std::to_string(g.count) +
                      ": use a bigger region or a smaller count (at most " +
                      std::to_string(sites.size()) + ")");
  for (std::size_t i = 0; i < bodies.size(); ++i) bodies[i].position = sites[i];
}

}  // namespace

std::vector<BodySpec> expand_bodies(const Scene& scene, const ShapeLibrary& lib) {
  std::vector<BodySpec> out;
  // Built only when a generator needs it: a scene without generators reads no STL here.
  const DriverClearance drivers(scene.generators.empty() ? std::vector<DriverSettings>{}
                                                         : scene.drivers);
  for (const BodySpec& b : scene.bodies) {
    check_sphere(scene, lib.shapes[shape_index(lib, b.shape, b.loc, "shape")], b.loc, "shape");
    out.push_back(b);
  }
  for (std::size_t k = 0; k < scene.generators.size(); ++k) {
    const GeneratorSpec& g = scene.generators[k];
    std::mt19937_64 rng = generator_rng(scene.simulation.seed, k);
    std::vector<BodySpec> bodies = draw_bodies(scene, g, lib, rng);
    const Region region(g.region);
    if (g.kind == GeneratorSpec::Kind::random)
      place_random(g, region, drivers, lib, bodies, rng);
    else
      place_lattice(g, region, drivers, lib, bodies);
    out.insert(out.end(), bodies.begin(), bodies.end());
  }
  return out;
}

}  // namespace polydem
