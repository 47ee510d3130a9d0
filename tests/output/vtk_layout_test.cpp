// Appended-data layout checked by our own minimal reading: each DataArray's offset points at a
// UInt64 byte count equal to the array's size, blocks are back to back, and the file ends there.
#include <cstdint>
#include <cstring>
#include <map>
#include <regex>

#include "output/vtk.hpp"
#include "output_test_util.hpp"
#include "scene_fixture.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

struct ArrayRecord {
  std::string name;
  std::uint64_t offset;
  std::uint64_t bytes;  // from the block header
};

// Walks the appended block of a VTK XML file; fails the test on any inconsistency.
std::vector<ArrayRecord> appended_arrays(const std::string& path) {
  const std::string file = read_all(path);
  const std::size_t marker = file.find("<AppendedData encoding=\"raw\">");
  REQUIRE(marker != std::string::npos);
  CHECK(file.find("header_type=\"UInt64\"") < marker);
  CHECK(file.find("byte_order=\"LittleEndian\"") < marker);  // the test machines are little-endian
  const std::size_t start = file.find('_', marker) + 1;
  const std::regex element("<DataArray type=\"\\w+\" Name=\"(\\w+)\"[^>]* offset=\"(\\d+)\"/>");
  std::vector<ArrayRecord> out;
  std::uint64_t expected_offset = 0;
  const std::string head = file.substr(0, marker);
  for (auto it = std::sregex_iterator(head.begin(), head.end(), element); it != std::sregex_iterator(); ++it) {
    ArrayRecord a{(*it)[1], std::stoull((*it)[2]), 0};
    CHECK(a.offset == expected_offset);
    REQUIRE(start + a.offset + 8 <= file.size());
    std::memcpy(&a.bytes, file.data() + start + a.offset, 8);
    expected_offset = a.offset + 8 + a.bytes;
    out.push_back(a);
  }
  CHECK(file.substr(start + expected_offset) == "\n</AppendedData>\n</VTKFile>\n");
  return out;
}

std::map<std::string, std::uint64_t> bytes_by_name(const std::vector<ArrayRecord>& arrays) {
  std::map<std::string, std::uint64_t> out;
  for (const ArrayRecord& a : arrays) out[a.name] = a.bytes;
  return out;
}

}  // namespace

TEST_CASE("layout: bodies vtu blocks match point, corner and cell counts", "[output][vtk]") {
  const std::vector<Shape> shapes{cube_shape(0.01, 0.001), sphere_shape(0.002)};
  Bodies bodies;
  add_body(bodies, 0, {0, 0, 0}, axis_angle({0, 0, 1}, 0.3), 1.0, Vec3::Zero(), Vec3::Zero(), 0);
  add_body(bodies, 0, {1, 0, 0}, Quat::Identity(), 2.0, Vec3::Zero(), Vec3::Zero(), 0);
  add_body(bodies, 1, {2, 0, 0}, Quat::Identity(), 1.0, Vec3::Zero(), Vec3::Zero(), 0);
  const TempDir tmp("layout_bodies");
  const std::string path = tmp.path + "/bodies.vtu";
  write_bodies_vtu(path, bodies, shapes);
  const auto bytes = bytes_by_name(appended_arrays(path));
  const std::uint64_t points = 8 + 8 + 42, cells = 6 + 6 + 80, corners = 4 * 12 + 3 * 80;
  CHECK(bytes.at("Points") == points * 3 * 8);
  CHECK(bytes.at("connectivity") == corners * 8);
  CHECK(bytes.at("offsets") == cells * 8);
  CHECK(bytes.at("types") == cells);
  CHECK(bytes.at("id") == cells * 8);
  CHECK(bytes.at("group") == cells * 4);
  CHECK(bytes.at("radius") == cells * 8);
  CHECK(bytes.at("velocity") == cells * 24);
  CHECK(bytes.at("angular_velocity") == cells * 24);
}

TEST_CASE("layout: contacts and drivers vtp blocks match their counts", "[output][vtk]") {
  const TempDir tmp("layout_vtp");
  const std::string dir = tmp.path;
  const std::size_t n = GENERATE(0, 1, 5);
  std::vector<ContactOut> contacts(n, ContactOut{});
  write_contacts_vtp(dir + "/contacts.vtp", contacts);
  auto bytes = bytes_by_name(appended_arrays(dir + "/contacts.vtp"));
  CHECK(bytes.at("Points") == 2 * n * 24);
  CHECK(bytes.at("connectivity") == 2 * n * 8);
  CHECK(bytes.at("force") == n * 24);
  CHECK(bytes.at("type") == n * 4);

  const DriverMesh floor{"floor", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 1, 2}}};
  write_drivers_vtp(dir + "/drivers.vtp", {floor, {"no_name", {}, {}}});
  bytes = bytes_by_name(appended_arrays(dir + "/drivers.vtp"));
  CHECK(bytes.at("driver_names") == std::string("floor").size() + 1 + std::string("no_name").size() + 1);
  CHECK(bytes.at("driver") == 1 * 4);
}
