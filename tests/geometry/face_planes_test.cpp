// The edge planes of the vertex-face kernel against the world-frame polygon test they replace.
#include <catch2/catch.hpp>

#include "geometry/segment.hpp"
#include "test_shapes.hpp"

using namespace polydem;
using namespace polydem::test;

TEST_CASE("edge planes in the body frame decide as projects_inside_polygon in the world") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Shape cube = make_cube(0.5, 0.05), oct = make_octahedron(0.6, 0.05), prism = make_hex_prism(0.5, 0.3, 0.05),
              tet = make_tetrahedron(0.4, 0.05), needle = make_needle(0.05);
  int inside = 0, compared = 0;
  for (const Shape* s : {&cube, &oct, &prism, &tet, &needle}) {
    REQUIRE(s->edge_plane_begin.size() == s->faces.size() + 1);
    for (int trial = 0; trial < 2000; ++trial) {
      const double scale = 0.5 + 0.5 * (u(rng) + 1.0);
      const Posed b(*s, scale, Vec3(u(rng), u(rng), u(rng)), random_rotation(rng));
      const PosedBody body = b.body();
      const Vec3 p = b.position + 1.5 * scale * Vec3(u(rng), u(rng), u(rng));  // m
      const Vec3 q = body.rotation.transpose() * (p - body.position);           // m, p in the body frame
      for (std::size_t f = 0; f < s->faces.size(); ++f) {
        bool planes = true, near_margin = false;
        for (int e = s->edge_plane_begin[f]; e < s->edge_plane_begin[f + 1]; ++e) {
          const double h = s->edge_planes[e].normal.dot(q) - scale * s->edge_planes[e].offset;  // m
          planes = planes && h > 0.0;
          near_margin = near_margin || std::abs(h) < 1e-12;
        }
        if (near_margin) continue;  // within round-off of the margin: either answer is right
        const bool world = projects_inside_polygon(p, body.vertices, s->faces[f], body.rotation * s->face_normals[f]);
        CHECK(planes == world);
        inside += world;
        ++compared;
      }
    }
  }
  CHECK(inside > compared / 20);  // both answers well represented
}
