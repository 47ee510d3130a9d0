#include "sim/probes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>

#include "polydem/error.hpp"
#include "sim/local_store.hpp"
#include "sim/rank_contacts.hpp"
#include "sim/rank_link.hpp"

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

std::uint32_t global_of(const Bodies&, std::uint32_t row) { return row; }
std::uint32_t global_of(const LocalStore& s, std::uint32_t row) { return s.global_id[row]; }

// A body scanned in increasing id keeps a column's top on a tie, as one process's scan does.
bool higher(const ColumnTop& a, const ColumnTop& b) { return a.y > b.y || (a.y == b.y && a.body < b.body); }

// Keeps each column's highest of `tops` in `top` (ordered by column: fixed sums after).
void keep_highest(std::map<long, ColumnTop>& top, const std::vector<ColumnTop>& tops) {
  for (const ColumnTop& c : tops) {
    const auto [it, fresh] = top.emplace(c.column, c);
    if (!fresh && higher(c, it->second)) it->second = c;
  }
}

// The kept tops in column order.
std::vector<ColumnTop> by_column(const std::map<long, ColumnTop>& top) {
  std::vector<ColumnTop> out;
  for (const auto& [k, c] : top) out.push_back(c);
  return out;
}

// The highest body centre of each column across the drum among `rows` of `a`, by column.
template <class Arrays>
std::vector<ColumnTop> column_tops(const Arrays& a, const std::vector<std::uint32_t>& rows, const DrumSection& drum,
                                   double column) {
  const Vec3 across = drum.up.cross(drum.axis);
  std::vector<ColumnTop> all;
  for (std::uint32_t i : rows) {
    const Vec3 r = a.position[i] - drum.center;
    const double s = r.dot(drum.axis), h = r.dot(across), y = r.dot(drum.up);
    if (drum.length && std::abs(s) > 0.5 * *drum.length) continue;
    if (h * h + y * y > drum.radius * drum.radius) continue;
    all.push_back({std::lround(std::floor(h / column)), global_of(a, i), h, y});
  }
  std::map<long, ColumnTop> top;
  keep_highest(top, all);
  return by_column(top);
}

// The bodies among `rows` of `a` whose centre lies strictly on the `normal` side of the plane.
template <class Arrays>
std::vector<FlowTerm> flow_terms(const Arrays& a, const std::vector<std::uint32_t>& rows, const Vec3& point,
                                 const Vec3& normal) {
  std::vector<FlowTerm> terms;
  for (std::uint32_t i : rows)
    if ((a.position[i] - point).dot(normal) > 0.0) terms.push_back({global_of(a, i), a.mass[i]});
  return terms;
}

// The masses summed in increasing id, the order of one process's scan.
FlowReading flow_total(std::vector<FlowTerm> terms) {
  std::sort(terms.begin(), terms.end(), [](const FlowTerm& a, const FlowTerm& b) { return a.body < b.body; });
  FlowReading r;
  for (const FlowTerm& t : terms) r.mass += t.mass;
  r.count = terms.size();
  return r;
}

std::vector<std::uint32_t> every_row(const Bodies& b) {
  std::vector<std::uint32_t> rows(b.size());
  std::iota(rows.begin(), rows.end(), 0u);
  return rows;
}

// The surface's points as (h, y), by column, and the fit of their central `fit` fraction.
SurfaceFit fit_surface(const std::vector<ColumnTop>& tops, double fit) {
  std::vector<std::pair<double, double>> all;
  for (const ColumnTop& c : tops) all.emplace_back(c.h, c.y);
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

// The drum's index among the drivers (the scene parser checks it; scenes built in code may not).
std::uint32_t drum_index(const Drivers& drivers, const OutputSettings::ReposeProbe& spec) {
  for (std::uint32_t j = 0; j < drivers.size(); ++j)
    if (drivers.name(j) == spec.driver && drivers.cylinder(j)) return j;
  throw InputError(input_message(spec.loc.file, spec.loc.line, "driver", "no cylinder driver named '" + spec.driver + "'"));
}

}  // namespace

FlowReading flow_beyond(const Bodies& b, const Vec3& point, const Vec3& normal) {
  return flow_total(flow_terms(b, every_row(b), point, normal));
}

SurfaceFit repose_angle(const Bodies& b, const DrumSection& drum, double column, double fit) {
  return fit_surface(column_tops(b, every_row(b), drum, column), fit);
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

Probes::Probes(const Simulation& sim, const std::string& dir, bool resume, bool io) : sim_(sim), io_(io) {
  const OutputSettings& out = sim.scene().output;
  for (const OutputSettings::FlowProbe& spec : out.flow_probes) {
    const std::string path = dir + "/" + spec.name + ".csv";
    Flow f{spec, nullptr, std::nullopt, std::nullopt};
    if (io_ && resume)
      if (const auto last = previous_flow_row(path, sim.time() + 0.5 * sim.dt())) {
        f.last_time = last->first;
        f.last_mass = last->second;
      }
    if (io_)
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
    if (io_)
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

std::vector<char> Probes::measure() const {
  std::vector<char> mine;
  auto add = [&](const auto& a, const std::vector<std::uint32_t>& rows) {
    for (const Flow& f : flows_) append_section(mine, flow_terms(a, rows, f.spec.point, f.spec.normal));
    for (const Repose& r : reposes_) append_section(mine, column_tops(a, rows, section(r), r.column));
  };
  if (const RankContacts* ranks = sim_.rank_contacts()) ranks->with_output_rows(sim_.bodies, add);
  else add(sim_.bodies, every_row(sim_.bodies));
  return mine;
}

// Rank 0's: each probe's sections of every rank, met in one section a probe.
std::vector<char> Probes::met(const std::vector<char>& mine) const {
  if (!sim_.distributed()) return mine;
  const std::vector<std::vector<char>> all = sim_.link()->gather(mine, 0);
  std::vector<char> out;
  if (all.empty()) return out;  // not rank 0
  std::vector<std::size_t> at(all.size(), 0);
  for (std::size_t j = 0; j < flows_.size(); ++j) {
    std::vector<FlowTerm> terms;
    for (std::size_t r = 0; r < all.size(); ++r) {
      const std::vector<FlowTerm> theirs = read_section<FlowTerm>(all[r], at[r]);
      terms.insert(terms.end(), theirs.begin(), theirs.end());
    }
    append_section(out, terms);
  }
  for (std::size_t j = 0; j < reposes_.size(); ++j) {
    std::map<long, ColumnTop> top;
    for (std::size_t r = 0; r < all.size(); ++r) keep_highest(top, read_section<ColumnTop>(all[r], at[r]));
    append_section(out, by_column(top));
  }
  return out;
}

void Probes::row() {
  if (flows_.empty() && reposes_.empty()) return;
  const std::vector<char> all = met(measure());
  if (!io_) return;
  std::size_t at = 0;
  const double t = sim_.time();
  for (Flow& f : flows_) {
    const FlowReading now = flow_total(read_section<FlowTerm>(all, at));
    const double rate = f.last_time && t > *f.last_time ? (now.mass - *f.last_mass) / (t - *f.last_time) : 0.0;
    f.csv->row({t, now.mass, double(now.count), rate});
    f.last_time = t;
    f.last_mass = now.mass;
  }
  for (Repose& r : reposes_) {
    const SurfaceFit fit = fit_surface(read_section<ColumnTop>(all, at), r.spec.fit);
    r.csv->row({t, fit.angle, double(fit.points)});
  }
}

}  // namespace polydem
