// drivers and contacts .vtp read back by VTK's own reader.
#include "output/vtk.hpp"
#include "output_test_util.hpp"
#include "polydem/error.hpp"
#include "scene_fixture.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

Vec3 vec_of(const Json& values, std::size_t k) {
  return {values[3 * k].number, values[3 * k + 1].number, values[3 * k + 2].number};
}

std::vector<ContactOut> three_contacts() {
  ContactOut a{{0, 0, 0}, {0.02, 0, 0}, {0.01, 0, 0}, {-3.5, 0.25, 1e-9}, 3.5, 0.25000000000000006, 1e-5, 0, 1, 2};
  ContactOut b{{0.02, 0, 0}, {0.02, 0.02, 0}, {0.02, 0.01, 0}, {0.1, -7, 0}, 7, 0.1, 2e-6, 1, 4, 1};
  ContactOut c{{0.02, 0.02, 0}, {0.02, 0.02, -0.01}, {0.02, 0.02, -0.01}, {0, 0, 9.81}, 9.81, 0, 3e-7, 4, -1, 3};
  return {a, b, c};
}

}  // namespace

TEST_CASE("contacts vtp: VTK reads one line per contact with its fields", "[output][vtk]") {
  const std::vector<ContactOut> contacts = three_contacts();
  const TempDir tmp("contacts");
  const std::string path = tmp.path + "/contacts_000003.vtp";
  write_contacts_vtp(path, contacts);
  const Json data = read_with_vtk(path);
  REQUIRE(data["n_cells"].number == 3);
  CHECK(data["n_points"].number == 6);
  const Json& cd = data["cell_data"];
  for (std::size_t k = 0; k < 3; ++k) {
    const ContactOut& c = contacts[k];
    CHECK(data["cell_types"][k].number == 3);  // VTK_LINE
    const Json& cell = data["cells"][k];
    REQUIRE(cell.size() == 2);
    const Json& from = data["points"][std::size_t(cell[0].number)];
    const Json& to = data["points"][std::size_t(cell[1].number)];
    CHECK(Vec3(from[0].number, from[1].number, from[2].number) == c.from);
    CHECK(Vec3(to[0].number, to[1].number, to[2].number) == c.to);
    CHECK(vec_of(cd["force"]["values"], k) == c.force);
    CHECK(vec_of(cd["point"]["values"], k) == c.point);
    CHECK(cd["fn"]["values"][k].number == c.fn);
    CHECK(cd["ft"]["values"][k].number == c.ft);
    CHECK(cd["overlap"]["values"][k].number == c.overlap);
    CHECK(cd["i"]["values"][k].number == double(c.i));
    CHECK(cd["j"]["values"][k].number == double(c.j));
    CHECK(cd["type"]["values"][k].number == c.type);
  }
}

TEST_CASE("contacts vtp: no contact is a valid empty file", "[output][vtk]") {
  const TempDir tmp("no_contacts");
  const std::string path = tmp.path + "/contacts.vtp";
  write_contacts_vtp(path, {});
  const Json data = read_with_vtk(path);
  CHECK(data["n_cells"].number == 0);
  CHECK(data["n_points"].number == 0);
}

TEST_CASE("drivers vtp: VTK reads the polygons, driver index per cell and the names", "[output][vtk]") {
  const DriverMesh floor{"floor", {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2, 3}}};
  const DriverMesh roof{"roof & <lid>", {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}}, {{0, 1, 2}, {1, 3, 2}}};
  const TempDir tmp("drivers");
  const std::string path = tmp.path + "/drivers_000000.vtp";
  write_drivers_vtp(path, {floor, roof});
  const Json data = read_with_vtk(path);
  REQUIRE(data["n_cells"].number == 3);
  CHECK(data["n_points"].number == 8);
  const std::vector<std::vector<int>> cells{{0, 1, 2, 3}, {4, 5, 6}, {5, 7, 6}};  // roof offset by floor's 4 points
  for (std::size_t c = 0; c < 3; ++c) {
    REQUIRE(data["cells"][c].size() == cells[c].size());
    for (std::size_t k = 0; k < cells[c].size(); ++k) CHECK(data["cells"][c][k].number == cells[c][k]);
    CHECK(data["cell_data"]["driver"]["values"][c].number == (c == 0 ? 0 : 1));
  }
  for (std::size_t k = 0; k < 4; ++k) {
    const Json& p = data["points"][4 + k];
    CHECK(Vec3(p[0].number, p[1].number, p[2].number) == roof.points[k]);
  }
  const Json& names = data["field_data"]["driver_names"]["values"];
  REQUIRE(names.size() == 2);
  CHECK(names[0].text == "floor");
  CHECK(names[1].text == "roof & <lid>");
}

TEST_CASE("drivers vtp: a polygon index out of range is reported with the driver name", "[output][vtk]") {
  const DriverMesh bad{"hopper", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 3}}};
  const TempDir tmp("bad_driver");
  const std::string path = tmp.path + "/drivers.vtp";
  CHECK_THROWS_WITH(write_drivers_vtp(path, {bad}), Catch::Contains("hopper") && Catch::Contains("index 3"));
}

TEST_CASE("writers: an unwritable path throws RunError naming the path and the reason", "[output][vtk]") {
  const TempDir tmp("unwritable");
  const std::string path = tmp.path + "/missing_folder/contacts.vtp";
  CHECK_THROWS_AS(write_contacts_vtp(path, three_contacts()), RunError);
  CHECK_THROWS_WITH(write_contacts_vtp(path, three_contacts()),
                    Catch::Contains(path) && Catch::Contains("No such file or directory"));
  CHECK_THROWS_WITH(write_bodies_vtu(path, Bodies{}, {}), Catch::Contains(path));
  // A full disk shows when the buffered data is flushed at close.
  CHECK_THROWS_WITH(write_contacts_vtp("/dev/full", three_contacts()),
                    Catch::Contains("/dev/full") && Catch::Contains("No space left on device"));
}
