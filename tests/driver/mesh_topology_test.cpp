// Mesh drivers: welding, edges once, the flat-edge rule, zero-area triangles, the spatial
// index's cost, and the errors for missing or broken STL files.
#include <catch2/catch.hpp>

#include "driver/mesh.hpp"
#include "mesh_fixtures.hpp"
#include "polydem/error.hpp"
#include "shape/point_sources.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

MeshFeatures features_of(const std::vector<Tri>& tris, const std::string& path, std::size_t& skipped) {
  write_ascii_stl(path, tris);
  return MeshFeatures(read_stl(path), 1.0, skipped);
}

std::string error_of(const std::vector<DriverSettings>& specs) {
  try {
    Drivers drivers(specs);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a closed cube mesh: 8 welded vertices, 12 feature edges, face diagonals flat", "[driver][mesh]") {
  TempFolder dir;
  std::size_t skipped = 0;
  const MeshFeatures m = features_of(cube_triangles(0.01), dir.file("cube.stl"), skipped);
  CHECK(m.vertices.size() == 8);   // 36 corners welded
  CHECK(m.faces.size() == 12);
  CHECK(m.edges.size() == 12);     // 18 distinct edges less the 6 coplanar diagonals
  CHECK(skipped == 0);
  for (std::uint8_t f : m.vertex_feature) CHECK(f == 1);
  for (std::size_t e = 0; e < m.edges.size(); ++e) {  // a cube edge joins two faces at 90 degrees
    REQUIRE(m.edge_inward_begin[e + 1] - m.edge_inward_begin[e] == 2);
    CHECK(std::abs(m.edge_inward[m.edge_inward_begin[e]].dot(m.edge_inward[m.edge_inward_begin[e] + 1])) < 1e-12);
  }
}

TEST_CASE("a flat floor mesh: only its rim is made of features", "[driver][mesh]") {
  TempFolder dir;
  std::size_t skipped = 0;
  const int n = 5;
  const MeshFeatures m = features_of(floor_triangles(n, 0.01), dir.file("floor.stl"), skipped);
  CHECK(m.vertices.size() == std::size_t((n + 1) * (n + 1)));
  CHECK(m.edges.size() == std::size_t(4 * n));  // the boundary edges
  int interior_features = 0;
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    const bool rim = std::abs(std::abs(m.vertices[v].x()) - 0.025) < 1e-12 || std::abs(std::abs(m.vertices[v].y()) - 0.025) < 1e-12;
    if (!rim) interior_features += m.vertex_feature[v];
    else CHECK(m.vertex_feature[v] == 1);
  }
  CHECK(interior_features == 0);
  // Every interior edge is flat and named by its two faces, the lower one its owner.
  const std::size_t interior = 3 * n * n - 2 * n;  // Euler: V + F - 1 edges, less the 4n on the rim
  CHECK(m.flat_edges.size() == interior);
  std::vector<int> uses(m.flat_edges.size(), 0);
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (int k = 0; k < 3; ++k)
      if (m.face_flat[f][k] >= 0) {
        ++uses[m.face_flat[f][k]];
        CHECK(m.flat_edges[m.face_flat[f][k]].owner <= int(f));
      }
  for (int u : uses) CHECK(u == 2);
}

TEST_CASE("zero-area triangles are skipped and counted", "[driver][mesh]") {
  TempFolder dir;
  std::vector<Tri> tris = floor_triangles(1, 0.01);
  tris.push_back({Vec3(0, 0, 0), Vec3(0.01, 0, 0), Vec3(0.02, 0, 0)});  // collinear
  std::size_t skipped = 0;
  const MeshFeatures m = features_of(tris, dir.file("sliver.stl"), skipped);
  CHECK(skipped == 1);
  CHECK(m.faces.size() == 2);
}

TEST_CASE("the grid search cost follows the triangles near the body, not the mesh size", "[driver][mesh]") {
  TempFolder dir;
  const double cell = 0.005;  // m, triangles of a fixed size
  std::vector<std::size_t> examined, found, pairs;
  for (int n : {10, 100, 300}) {  // 200 to 180,000 triangles
    write_binary_stl(dir.file("floor.stl"), floor_triangles(n, cell));
    const Drivers drivers({stl_spec(dir.file("floor.stl"))});
    std::size_t skipped = 0;
    const MeshFeatures& m = std::get<MeshDriver>(drivers.kind(0)).features();
    std::vector<std::uint32_t> faces;
    examined.push_back(m.faces_near(Vec3(0.0012, 0.0013, 0.004), 0.006, faces));
    found.push_back(faces.size());
    const Shape sphere = one_vertex_shape(0.004);
    const Placed p(sphere, Vec3(0.0012, 0.0013, 0.0041));
    std::vector<FeaturePair> candidates;
    drivers.candidates(p.body, 0, 0.0005, candidates);
    pairs.push_back(candidates.size());
    (void)skipped;
  }
  INFO("examined " << examined[0] << " " << examined[1] << " " << examined[2]);
  CHECK(found[0] == found[1]);
  CHECK(found[1] == found[2]);
  CHECK(examined[2] <= examined[1] + examined[1] / 2);  // the same neighbourhood, whatever the mesh size
  CHECK(examined[2] < 200);
  CHECK(pairs[0] == pairs[2]);
  CHECK(pairs[2] >= 1);
  // A finer mesh over the same area: the cost grows with the triangles near the body.
  write_binary_stl(dir.file("fine.stl"), floor_triangles(300, cell / 3));
  const Drivers fine({stl_spec(dir.file("fine.stl"))});
  std::vector<std::uint32_t> faces;
  std::get<MeshDriver>(fine.kind(0)).features().faces_near(Vec3(0.0012, 0.0013, 0.004), 0.006, faces);
  CHECK(faces.size() > 6 * found[0]);  // 9 x the triangle density, less the edge effects
}

TEST_CASE("missing and broken STL files stop with the scene's file:line:key", "[driver][mesh][errors]") {
  TempFolder dir;
  const std::string missing = error_of({stl_spec(dir.file("nowhere.stl"))});
  CHECK_THAT(missing, Catch::StartsWith("scene.yaml:7: key 'file': driver 'mesh'") && Catch::Contains("cannot open"));
  std::ofstream(dir.file("broken.stl")) << "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0\n";
  const std::string broken = error_of({stl_spec(dir.file("broken.stl"))});
  CHECK_THAT(broken, Catch::StartsWith("scene.yaml:7: key 'file'") && Catch::Contains("broken.stl:5"));
  std::ofstream(dir.file("junk.stl")) << "this is not a mesh";
  CHECK_THAT(error_of({stl_spec(dir.file("junk.stl"))}), Catch::Contains("not an STL file"));
  write_ascii_stl(dir.file("flat.stl"), {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)}});
  CHECK_THAT(error_of({stl_spec(dir.file("flat.stl"))}), Catch::Contains("no triangle with a non-zero area"));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  write_binary_stl(dir.file("nan.stl"), {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, nan, 0)}});
  CHECK_THAT(error_of({stl_spec(dir.file("nan.stl"))}), Catch::Contains("not finite"));
  for (const std::string& message : {missing, broken}) CHECK(message.find('\n') == std::string::npos);
}
