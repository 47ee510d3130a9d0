// scene.pvd: every frame listed with its exact time, one part per file stem, valid after each add.
#include "output/vtk.hpp"
#include "output_test_util.hpp"
#include "scene_fixture.hpp"

using namespace polydem;
using namespace polydem::test;

TEST_CASE("pvd: VTK-readable after every frame, each frame with its time and parts", "[output][vtk]") {
  const TempDir tmp("pvd");
  const std::string dir = tmp.path;
  const std::vector<Shape> shapes{cube_shape(0.01, 0.001)};
  Bodies bodies;
  add_body(bodies, 0, Vec3::Zero(), Quat::Identity(), 1.0, Vec3::Zero(), Vec3::Zero(), 0);
  const double times[] = {0.0, 0.1, 1e-3 / 3.0};  // s; 0.1 and 1e-3/3 are not exact in binary
  PvdSeries pvd(dir + "/scene.pvd");
  for (std::size_t f = 0; f < 3; ++f) {
    const std::string n = std::to_string(f);
    write_bodies_vtu(dir + "/bodies_00000" + n + ".vtu", bodies, shapes);
    write_contacts_vtp(dir + "/contacts_00000" + n + ".vtp", {});
    pvd.add(times[f], {"bodies_00000" + n + ".vtu", "contacts_00000" + n + ".vtp"});

    const Json series = read_with_vtk(dir + "/scene.pvd");  // also reads every listed file
    CHECK(series["type"].text == "Collection");
    const Json& sets = series["datasets"];
    REQUIRE(sets.size() == 2 * (f + 1));
    for (std::size_t g = 0; g <= f; ++g) {
      const std::string m = std::to_string(g);
      CHECK(sets[2 * g]["timestep"].number == times[g]);  // %.17g: the exact double
      CHECK(sets[2 * g + 1]["timestep"].number == times[g]);
      CHECK(sets[2 * g]["file"].text == "bodies_00000" + m + ".vtu");
      CHECK(sets[2 * g]["part"].number == 0);
      CHECK(sets[2 * g]["n_cells"].number == 6);
      CHECK(sets[2 * g + 1]["file"].text == "contacts_00000" + m + ".vtp");
      CHECK(sets[2 * g + 1]["part"].number == 1);
    }
  }
  CHECK_FALSE(std::filesystem::exists(dir + "/scene.pvd.tmp"));
}

TEST_CASE("pvd: a stem that appears later gets its own part, kept for later frames", "[output][vtk]") {
  const TempDir tmp("pvd_parts");
  const std::string dir = tmp.path;
  for (const char* f : {"bodies_000000.vtu", "bodies_000001.vtu", "bodies_000002.vtu"})
    write_bodies_vtu(dir + "/" + f, {}, {});
  for (const char* f : {"drivers_000001.vtp", "drivers_000002.vtp"}) write_drivers_vtp(dir + "/" + f, {});
  PvdSeries pvd(dir + "/scene.pvd");
  pvd.add(0.0, {"bodies_000000.vtu"});
  pvd.add(1.0, {"drivers_000001.vtp", "bodies_000001.vtu"});
  pvd.add(2.0, {"bodies_000002.vtu", "drivers_000002.vtp"});
  const Json sets = read_with_vtk(dir + "/scene.pvd")["datasets"];
  REQUIRE(sets.size() == 5);
  for (std::size_t k = 0; k < 5; ++k) {
    const bool drivers = sets[k]["file"].text.rfind("drivers", 0) == 0;
    CHECK(sets[k]["part"].number == (drivers ? 1 : 0));
  }
}
