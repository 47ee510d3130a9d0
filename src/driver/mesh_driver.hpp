#pragma once
// An STL triangle mesh as a driver: its features (mesh.hpp) placed in the world by the
// placement's centre (where the mesh origin is) and orientation. Candidates come from the
// mesh's grid around the body's bounding sphere, taken into the mesh frame, so a moving mesh
// needs no new index; faces are two-sided, and edges and vertices use the body-body kernels
// (as a segment or a point of radius 0) plus the normal-cone test of mesh.hpp.
#include <memory>
#include <string>
#include <vector>

#include "driver/motion.hpp"
#include "geometry/features.hpp"
#include "output/frame.hpp"

namespace polydem {

struct DriverMesh;
class MeshFeatures;
class MeshDriver;

struct MeshSettings {             // `stl: {file, scale, translation, rotation}`
  using Kind = MeshDriver;
  std::string file;               // path (resolved against the scene folder)
  double scale = 1.0;             // multiplies the file coordinates
  Vec3 translation = Vec3::Zero();  // m, where the mesh origin is placed
  Quat rotation = Quat::Identity(); // mesh frame -> world
  std::string where;              // prefixed to the errors and warnings about the file ("scene.yaml:12: key 'file': ")
};

class MeshDriver {
 public:
  // Reads and indexes the STL file; throws InputError (`where` + what) for a missing or broken one.
  MeshDriver(const MeshSettings& s, Placement& at);

  double rounding() const { return 0.0; }  // m
  void bounds(const Placement& at, Box3& box) const;
  double r_star(double r_body) const { return r_body; }  // m, Hertz radius: flat triangles
  Vec3 reference(const Placement& at) const { return at.center; }  // m, where the mesh origin is
  Vec3 servo_direction(const Placement&, const MotionSettings& m) const { return given_servo_direction(m); }

  bool near(const Placement& at, const Vec3& center, double reach) const;
  bool overlaps(const Placement& at, const Vec3& center, double radius) const;
  void candidates(const Placement& at, const PosedBody& a, double range, std::vector<FeaturePair>& out) const;
  bool contact(const Placement& at, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out) const;
  // Its triangles at the current placement.
  DriverMesh drawing(const Placement& at, const std::string& name, const ViewFrame& frame) const;

  const MeshFeatures& features() const { return *mesh_; }

 private:
  std::shared_ptr<const MeshFeatures> mesh_;  // shared: a driver list may be copied
};

}  // namespace polydem
