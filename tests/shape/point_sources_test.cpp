// Point lists, OBJ and STL (ASCII and binary, including a binary header that starts with "solid").
#include "shape/point_sources.hpp"

#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>

#include "polydem/error.hpp"
#include "temp_file.hpp"

using namespace polydem;

namespace {

// Two triangles sharing an edge: 4 distinct corners.
const float kQuad[2][3][3] = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}};

std::string binary_stl(const std::string& header) {
  std::string bytes(80, ' ');
  bytes.replace(0, header.size(), header);
  const std::uint32_t count = 2;
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& tri : kQuad) {
    const float normal[3] = {0, 0, 1};
    bytes.append(reinterpret_cast<const char*>(normal), 12);
    bytes.append(reinterpret_cast<const char*>(tri), 36);
    bytes.append(2, '\0');  // attribute byte count
  }
  return bytes;
}

std::string ascii_stl() {
  std::string s = "solid quad\n";
  for (const auto& tri : kQuad) {
    s += "  facet normal 0 0 1\n    outer loop\n";
    for (const auto& v : tri)
      s += "      vertex " + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) +
           "\n";
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid quad\n";
}

void check_quad(const TriangleMesh& m) {
  CHECK(m.vertices.size() == 4);  // shared corners welded
  REQUIRE(m.triangles.size() == 2);
  CHECK(m.triangles[0][0] == m.triangles[1][0]);
  CHECK(m.triangles[0][2] == m.triangles[1][1]);
  CHECK(m.vertices[m.triangles[1][2]] == Vec3(0, 1, 0));
}

}  // namespace

TEST_CASE("STL: ASCII, binary, and binary whose header begins with 'solid'", "[points]") {
  check_quad(read_stl(test::write_temp("quad_ascii.stl", ascii_stl())));
  check_quad(read_stl(test::write_temp("quad_bin.stl", binary_stl("binary"))));
  check_quad(read_stl(test::write_temp("quad_solid.stl", binary_stl("solid exported by CAD"))));
}

TEST_CASE("STL errors name the file and line", "[points]") {
  CHECK_THROWS_WITH(
      read_stl(test::write_temp("bad.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n")),
      Catch::Contains("bad.stl:4") && Catch::Contains("three numbers"));
  CHECK_THROWS_WITH(read_stl(test::write_temp("junk.stl", "hello")), Catch::Contains("not an STL file"));
  CHECK_THROWS_WITH(read_stl("/nonexistent.stl"), Catch::Contains("cannot open"));
}

TEST_CASE("a truncated binary STL is refused with its file and the byte count it lacks", "[points]") {
  for (const std::string header : {"binary", "solid exported by CAD"}) {
    const std::string whole = binary_stl(header);  // 84 + 2 x 50 = 184 bytes
    for (std::size_t keep : {std::size_t(183), std::size_t(134), std::size_t(90), std::size_t(84)}) {
      INFO(header << ", " << keep << " bytes");
      const std::string path = test::write_temp("cut.stl", whole.substr(0, keep));
      CHECK_THROWS_WITH(read_stl(path), Catch::Contains(path) && Catch::Contains("announces 2 triangles, 184 bytes") &&
                                            Catch::Contains("has " + std::to_string(keep)));
    }
    CHECK_THROWS_WITH(read_stl(test::write_temp("cut.stl", whole.substr(0, 40))),
                      Catch::Contains("40 bytes, shorter than a binary STL header"));
  }
}

TEST_CASE("point list and OBJ", "[points]") {
  const auto p = read_points(test::write_temp("pts.txt", "# a comment\n0 0 0\n\n1 2 3  # trailing\n"));
  REQUIRE(p.size() == 2);
  CHECK(p[1] == Vec3(1, 2, 3));
  CHECK_THROWS_WITH(read_points(test::write_temp("bad.txt", "0 0 0\n1 2\n")), Catch::Contains("bad.txt:2"));
  const auto o = read_points(test::write_temp("m.obj", "# obj\nv 0 0 0\nv 1 0 0 1.0\nvn 0 0 1\nf 1 2 3\n"));
  REQUIRE(o.size() == 2);
  CHECK(o[1] == Vec3(1, 0, 0));
  CHECK_THROWS_WITH(read_points(test::write_temp("bad.obj", "v 0 0\n")), Catch::Contains("bad.obj:1"));
}
