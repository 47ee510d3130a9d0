#include "sim/probes.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>

#include "polydem/error.hpp"

namespace polydem {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The (time, mass) of the last row of flow.csv written at or before `now` (s), or nullopt;
// rows are printed with %.17g, so they read back to the same bits.
std::optional<std::pair<double, double>> previous_flow_row(const std::string& path, double now) {
  std::ifstream in(path);
  std::string line;
  std::optional<std::pair<double, double>> found;
  if (!std::getline(in, line)) return found;  // header
  while (std::getline(in, line)) {
    char* end = nullptr;
    const double t = std::strtod(line.c_str(), &end);
    if (*end != ',' || t > now) break;
    found = {{t, std::strtod(end + 1, nullptr)}};
  }
  return found;
}

// Least-squares slope of y over h (centred sums, so large offsets do not cancel digits).
double slope(const std::vector<std::pair<double, double>>& points) {
  double hm = 0.0, ym = 0.0;
  for (const auto& [h, y] : points) { hm += h; ym += y; }
  hm /= double(points.size());
  ym /= double(points.size());
  double shy = 0.0, shh = 0.0;
  for (const auto& [h, y] : points) {
    shy += (h - hm) * (y - ym);
    shh += (h - hm) * (h - hm);
  }
  return shh > 0.0 ? shy / shh : kNaN;
}

// The highest body centre of each column across the drum, as (h, y) in the cross-section.
std::vector<std::pair<double, double>> surface_points(const Bodies& b, const DrumSection& drum, double column) {
  const Vec3 across = drum.up.cross(drum.axis);
  std::map<long, std::pair<double, double>> top;  // column index -> (h, y), ordered: fixed sums
  for (std::size_t i = 0; i < b.size(); ++i) {
    const Vec3 r = b.position[i] - drum.center;
    const double s = r.dot(drum.axis), h = r.dot(across), y = r.dot(drum.up);
    if (drum.length && std::abs(s) > 0.5 * *drum.length) continue;
    if (h * h + y * y > drum.radius * drum.radius) continue;
    const long k = std::lround(std::floor(h / column));
    const auto [it, fresh] = top.emplace(k, std::pair{h, y});
    if (!fresh && y > it->second.second) it->second = {h, y};
  }
  std::vector<std::pair<double, double>> out;
  for (const auto& [k, p] : top) out.push_back(p);
  return out;
}

// The drum's index among the drivers (the scene parser checks it; scenes built in code may not).
std::uint32_t drum_index(const Drivers& drivers, const OutputSettings::ReposeProbe& spec) {
  for (std::uint32_t j = 0; j < drivers.size(); ++j)
    if (drivers.name(j) == spec.driver && drivers.cylinder(j)) return j;
  throw InputError(input_message(spec.loc.file, spec.loc.line, "driver", "no cylinder driver named '" + spec.driver + "'"));
}

}  // namespace

FlowReading flow_beyond(const Bodies& b, const Vec3& point, const Vec3& normal) {
  FlowReading r;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if ((b.position[i] - point).dot(normal) <= 0.0) continue;
    r.mass += b.mass[i];
    ++r.count;
  }
  return r;
}

SurfaceFit repose_angle(const Bodies& b, const DrumSection& drum, double column, double fit) {
  const std::vector<std::pair<double, double>> all = surface_points(b, drum, column);
  SurfaceFit out{kNaN, 0};
  if (all.empty()) return out;
  const double lo = all.front().first, hi = all.back().first;  // columns are ordered along h
  const double mid = 0.5 * (lo + hi), half = 0.5 * fit * (hi - lo);
  std::vector<std::pair<double, double>> kept;
  for (const auto& p : all)
    if (std::abs(p.first - mid) <= half) kept.push_back(p);
  out.points = kept.size();
  if (kept.size() >= 3) out.angle = std::atan(std::abs(slope(kept))) * 180.0 / kPi;
  return out;
}

double mean_equivalent_diameter(const Bodies& b, const std::vector<Shape>& shapes) {
  if (b.size() == 0) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double volume = shapes[b.shape[i]].volume * std::pow(b.scale[i], 3);  // m^3
    sum += std::cbrt(6.0 * volume / kPi);
  }
  return sum / double(b.size());
}

Probes::Probes(const Simulation& sim, const std::string& dir, bool resume) : sim_(sim) {
  const OutputSettings& out = sim.scene().output;
  for (const OutputSettings::FlowProbe& spec : out.flow_probes) {
    const std::string path = dir + "/" + spec.name + ".csv";
    Flow f{spec, nullptr, std::nullopt, std::nullopt};
    if (resume)
      if (const auto last = previous_flow_row(path, sim.time() + 0.5 * sim.dt())) {
        f.last_time = last->first;
        f.last_mass = last->second;
      }
    f.csv = std::make_unique<CsvSeries>(path, std::vector<std::string>{"time", "mass", "count", "rate"}, resume,
                                         sim.time() + 0.5 * sim.dt());
    flows_.push_back(std::move(f));
  }
  for (const OutputSettings::ReposeProbe& spec : out.repose_probes) {
    Repose r{spec, nullptr, 0, spec.column ? *spec.column : mean_equivalent_diameter(sim.bodies, sim.shapes())};
    r.driver = drum_index(sim.drivers, spec);
    if (!(r.column > 0.0))
      throw InputError(input_message(spec.loc.file, spec.loc.line, "column",
                                     "the scene has no bodies to take a column width from: give `column: \"1 cm\"`"));
    r.csv = std::make_unique<CsvSeries>(dir + "/" + spec.name + ".csv",
                                        std::vector<std::string>{"time", "angle", "points"}, resume,
                                        sim.time() + 0.5 * sim.dt());
    reposes_.push_back(std::move(r));
  }
}

DrumSection Probes::section(const Repose& r) const {
  const DriverState& d = sim_.drivers[r.driver];
  const CylinderShape& drum = *sim_.drivers.cylinder(r.driver);
  const Vec3 g = sim_.scene().forces.gravity.value_or(Vec3::Zero());
  const Vec3 up = -(g - g.dot(d.axis) * d.axis);
  return {d.center, d.axis, up.norm() > 0.0 ? Vec3(up.normalized()) : Vec3::Zero(), drum.radius, drum.length};
}

void Probes::row() {
  const double t = sim_.time();
  for (Flow& f : flows_) {
    const FlowReading now = flow_beyond(sim_.bodies, f.spec.point, f.spec.normal);
    const double rate = f.last_time && t > *f.last_time ? (now.mass - *f.last_mass) / (t - *f.last_time) : 0.0;
    f.csv->row({t, now.mass, double(now.count), rate});
    f.last_time = t;
    f.last_mass = now.mass;
  }
  for (Repose& r : reposes_) {
    const SurfaceFit fit = repose_angle(sim_.bodies, section(r), r.column, r.spec.fit);
    r.csv->row({t, fit.angle, double(fit.points)});
  }
}

}  // namespace polydem
