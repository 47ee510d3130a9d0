#pragma once
// Time series polydem computes from the bodies (output.probes, written on csv_every): the mass
// that has passed a plane (silo and hopper discharge) and the dynamic angle of repose of the
// free surface in a rotating drum.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "output/csv.hpp"
#include "sim/simulation.hpp"

namespace polydem {

struct FlowReading {
  double mass = 0.0;      // kg
  std::size_t count = 0;  // bodies
};

// The bodies whose centre lies strictly on the `normal` side of the plane through `point`.
FlowReading flow_beyond(const Bodies& bodies, const Vec3& point, const Vec3& normal);

// The cross-section a drum's free surface is measured in.
struct DrumSection {
  Vec3 center = Vec3::Zero();   // m, middle of the axis
  Vec3 axis = Vec3::UnitY();    // unit
  Vec3 up = Vec3::UnitZ();      // unit, against gravity, normal to the axis
  double radius = 0.0;          // m
  std::optional<double> length; // m; empty: infinite
};

struct SurfaceFit {
  double angle = 0.0;      // deg, slope of the fitted free surface; NaN below 3 surface points
  std::size_t points = 0;  // surface points fitted
};

// Method: the centres of the bodies inside the drum are projected on the cross-section
// (h across, y = up) and binned in columns of width `column` along h; the highest centre of
// each column is a surface point. The points whose h lies in the central `fit` fraction of
// the surface's width (away from the wall, where the surface curls) get a least-squares line
// y = a + b h; angle = atan(|b|).
SurfaceFit repose_angle(const Bodies& bodies, const DrumSection& drum, double column, double fit);

// Mean diameter of the spheres of the same volume as the bodies (m); 0 without bodies.
double mean_equivalent_diameter(const Bodies& bodies, const std::vector<Shape>& shapes);

// A rank's part of a reading, met on rank 0 (one gather a row; no body state sent): each body
// past a flow plane by global id, so rank 0 sums their masses in id order as one process does,
// and each column's highest centre, the highest of the ranks' kept (the lowest id on a tie).
struct FlowTerm {
  std::uint32_t body = 0;  // global id
  double mass = 0.0;       // kg
};
struct ColumnTop {
  long column = 0;
  std::uint32_t body = 0;  // global id
  double h = 0.0, y = 0.0;  // m, across and up the section
};

// The probes of a scene, each with its NAME.csv (written by the process that writes, `io`); a
// resumed run appends and takes the flow rate's previous row from the file.
class Probes {
 public:
  Probes(const Simulation& sim, const std::string& dir, bool resume, bool io = true);
  // One row of every probe at the current time (distributed runs: a collective of every rank).
  void row();

 private:
  struct Flow {
    OutputSettings::FlowProbe spec;
    std::unique_ptr<CsvSeries> csv;
    std::optional<double> last_time, last_mass;  // s, kg: the previous row
  };
  struct Repose {
    OutputSettings::ReposeProbe spec;
    std::unique_ptr<CsvSeries> csv;
    std::uint32_t driver = 0;
    double column = 0.0;  // m
  };
  DrumSection section(const Repose& r) const;
  // Each probe's part from this process's bodies, then from every rank's on the writing one.
  std::vector<char> measure() const;
  std::vector<char> met(const std::vector<char>& mine) const;

  const Simulation& sim_;
  bool io_;
  std::vector<Flow> flows_;
  std::vector<Repose> reposes_;
};

}  // namespace polydem
