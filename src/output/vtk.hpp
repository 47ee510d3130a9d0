#pragma once
// Result files ParaView opens directly: VTK XML with binary appended raw data, and a .pvd series.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "polydem/bodies.hpp"
#include "polydem/math.hpp"
#include "polydem/shape.hpp"

namespace polydem {

// bodies_NNNNNN.vtu: one VTK_POLYGON per face of each body's core polyhedron in world coordinates.
// Shapes without faces (sphere, segment), and every shape when `rounded`, are drawn as a
// subdivided icosahedron swept over their vertices (the rounded surface: a sphere, a capsule, a
// polyhedron with rounded edges and corners). The bodies in user id order; cell data, repeated
// on each cell of a body: id (Int64, the user id: Bodies::id), group (Int32), radius (Float64, m, rounded radius x scale), velocity (m/s),
// angular_velocity (rad/s). FieldData `gravity` (m/s^2, 3 x Float64) when given: which way is
// down for `polydem render`.
void write_bodies_vtu(const std::string& path, const Bodies& bodies, const std::vector<Shape>& shapes,
                      bool rounded = false, const std::optional<Vec3>& gravity = std::nullopt);
// The same file for the bodies at indices `ids` only, in that order (a distributed run's rank:
// its owned bodies, by user id), one piece of a bodies_NNNNNN.pvtu.
void write_bodies_piece(const std::string& path, const Bodies& bodies, const std::vector<std::uint32_t>& ids,
                        const std::vector<Shape>& shapes, bool rounded = false,
                        const std::optional<Vec3>& gravity = std::nullopt);
// bodies_NNNNNN.pvtu: the pieces (paths relative to its folder, in rank order) as one data set
// for ParaView, declaring the arrays write_bodies_vtu writes.
void write_bodies_pvtu(const std::string& path, const std::vector<std::string>& pieces);

// A driver surface as polygons, in world coordinates.
struct DriverMesh {
  std::string name;
  std::vector<Vec3> points;                // m
  std::vector<std::vector<int>> polygons;  // indices into points
};

// drivers_NNNNNN.vtp: driver polygons with cell data `driver` (Int32 index into the list) and
// the driver names as the String array `driver_names` in FieldData.
void write_drivers_vtp(const std::string& path, const std::vector<DriverMesh>& drivers);

// One contact line of the force network.
// Zero by default: Eigen leaves vectors uninitialized, and callers accumulate into ContactOut{}.
struct ContactOut {
  Vec3 from = Vec3::Zero();   // m, body i's centre
  Vec3 to = Vec3::Zero();     // m, body j's centre (or the contact point for a driver)
  Vec3 point = Vec3::Zero();  // m, contact point
  Vec3 force = Vec3::Zero();  // N, on body i
  double fn = 0.0;            // N, normal force
  double ft = 0.0;            // N, tangential force magnitude
  double overlap = 0.0;       // m
  std::int64_t i = 0, j = 0;
  int type = 0;
};

// contacts_NNNNNN.vtp: one line per contact with cell data force, point (3 x Float64), fn, ft,
// overlap (Float64), i, j (Int64), type (Int32).
void write_contacts_vtp(const std::string& path, const std::vector<ContactOut>& contacts);
// contacts_NNNNNN.pvtp: the ranks' contacts_NNNNNN_pK.vtp pieces as one data set, as above.
void write_contacts_pvtp(const std::string& path, const std::vector<std::string>& pieces);

// scene.pvd: the time series, rewritten (atomically) each time a frame is added so a crashed
// run still has a valid .pvd. Files sharing a stem ("bodies" in bodies_000012.vtu) share a part.
class PvdSeries {
 public:
  explicit PvdSeries(std::string path);
  // files: relative to the .pvd's folder.
  void add(double time, const std::vector<std::string>& files);

 private:
  int part_of(const std::string& file);
  std::string path_;
  std::string entries_;             // <DataSet .../> lines so far
  std::vector<std::string> stems_;  // part index -> file stem
};

// scene.pvd with every part, and one STEM.pvd per part beside it (bodies.pvd, drivers.pvd,
// contacts.pvd, ...), each its own series over the same times, so ParaView styles each alone.
class PvdFiles {
 public:
  explicit PvdFiles(std::string dir);
  void add(double time, const std::vector<std::string>& files);  // files: relative to dir

 private:
  std::string dir_;
  PvdSeries scene_;
  std::vector<std::pair<std::string, PvdSeries>> parts_;  // stem -> its own series
};

}  // namespace polydem
