// CFD-DEM operators on a whole Simulation: Archimedes (neutral body, sinking body), the
// hydrostatic pressure-gradient force against buoyancy, and the viscous force of a
// Poiseuille profile read from a .vti file.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "polydem/error.hpp"
#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

const double kR = 0.005, kRho = 1000.0;  // m, kg/m^3
const Vec3 kG(0, 0, -9.807);

// Water at rest on a grid around the origin, hydrostatic pressure p = rho g . x.
Scene water(bool hydrostatic = false) {
  Scene s = base_scene(law(1.0e4, 0.5), false, kG);
  s.simulation.dt = 1.0e-4;
  ForceSettings::FluidField f;
  f.grid_min = Vec3(-0.1, -0.1, -0.5);
  f.grid_max = Vec3(0.1, 0.1, 0.1);
  f.cells = Eigen::Vector3i(4, 4, 12);
  f.rho = kRho;
  if (hydrostatic) f.pressure_gradient = kRho * kG;
  s.forces.fluid = f;
  return s;
}

BodySpec dense(double density, Vec3 x = Vec3::Zero()) {
  BodySpec b = body("sphere", x);
  b.density = density;
  return b;
}

}  // namespace

TEST_CASE("Archimedes: a body of fluid density neither rises nor sinks", "[sim][fluid]") {
  Scene s = water();
  s.forces.archimedes = true;
  Simulation sim(s, library({sphere_shape(kR)}), {dense(kRho)});
  for (int k = 0; k < 2000; ++k) sim.step();
  CHECK(sim.bodies.velocity[0].norm() < 1e-15);
  CHECK(sim.bodies.position[0].norm() < 1e-15);
}

TEST_CASE("Archimedes: a denser body sinks with (m - rho_f Vs) g", "[sim][fluid]") {
  // Constant force: velocity Verlet is exact, v(t) = (1 - rho_f / rho_s) g t. Vs is the whole
  // volume, with or without the void-fraction model (the body lies inside the grid).
  for (bool void_fraction : {false, true}) {
    Scene s = water();
    s.forces.archimedes = true;
    if (void_fraction) s.forces.void_fraction = ForceSettings::VoidFraction{0.1, 6};
    Simulation sim(s, library({sphere_shape(kR)}), {dense(2700.0)});
    for (int k = 0; k < 2000; ++k) sim.step();
    const double a = (1.0 - kRho / 2700.0) * 9.807;
    CHECK(-sim.bodies.velocity[0].z() == Approx(a * sim.time()).epsilon(1e-9));
    CHECK(-sim.bodies.position[0].z() == Approx(0.5 * a * sim.time() * sim.time()).epsilon(1e-9));
  }
}

TEST_CASE("The hydrostatic pressure-gradient force equals the buoyancy", "[sim][fluid]") {
  // -Vs grad p = -Vs rho g = the Archimedes force; with C_added_mass the first scales by 1 + C.
  Scene archimedes = water(), pressure = water(true);
  archimedes.forces.archimedes = true;
  pressure.forces.pressure_force = ForceSettings::CfdForce{0.0};
  const auto lib = library({sphere_shape(kR)});
  const std::vector<BodySpec> bodies = {dense(2700.0, Vec3(0.01, -0.02, -0.13))};
  const Simulation a(archimedes, lib, bodies), p(pressure, lib, bodies);
  const Vec3 buoyancy = -kRho * lib.shapes[0].volume * kG;
  CHECK((a.bodies.force[0] - a.bodies.mass[0] * kG - buoyancy).norm() < 1e-12 * buoyancy.norm());
  CHECK((p.bodies.force[0] - a.bodies.force[0]).norm() < 1e-9 * buoyancy.norm());
  pressure.forces.pressure_force->added_mass = 0.5;
  const Simulation p15(pressure, lib, bodies);
  CHECK((p15.bodies.force[0] - p15.bodies.mass[0] * kG - 1.5 * buoyancy).norm() < 1e-9 * buoyancy.norm());
}

TEST_CASE("Viscous force: zero in uniform flow, -Vs (1 + C) div(tau) in a Poiseuille profile", "[sim][fluid]") {
  // u(z) = Umax (1 - z^2 / h^2) e_x: div(tau) = -mu u'' e_x = 2 mu Umax / h^2 e_x (div U = 0),
  // so the force is -Vs (1 + C) 2 mu Umax / h^2 e_x. The grid comes from an ASCII .vti.
  const double umax = 0.2, h = 0.01, nu = 1.0e-3, C = 0.5;
  const auto path = std::filesystem::temp_directory_path() / ("polydem_poiseuille_" + std::to_string(getpid()) + ".vti");
  for (bool uniform : {true, false}) {
    std::ostringstream U;
    for (int k = 0; k < 10; ++k)  // 3 x 3 x 10 cells of 2 mm from z = -h
      for (int c = 0; c < 9; ++c) {
        const double z = -h + (k + 0.5) * 0.002;
        U << (uniform ? umax : umax * (1 - z * z / (h * h))) << " 0 0\n";
      }
    std::ofstream(path) << "<VTKFile type=\"ImageData\" version=\"1.0\">\n"
                           "<ImageData WholeExtent=\"0 3 0 3 0 10\" Origin=\"-0.003 -0.003 -0.01\" Spacing=\"0.002 0.002 0.002\">\n"
                           "<Piece Extent=\"0 3 0 3 0 10\"><CellData>\n<DataArray type=\"Float64\" Name=\"U\" "
                           "NumberOfComponents=\"3\" format=\"ascii\">\n" << U.str() << "</DataArray>\n"
                           "</CellData></Piece></ImageData></VTKFile>\n";
    Scene s = base_scene(law(1.0e4, 0.5), false);
    s.simulation.dt = 1.0e-4;
    ForceSettings::FluidField f;
    f.file = path.string();
    f.rho = kRho;
    f.nu = nu;
    s.forces.fluid = f;
    s.forces.viscous_force = ForceSettings::CfdForce{C};
    const auto lib = library({sphere_shape(0.001)});
    const Simulation sim(s, lib, {body("sphere", Vec3(0, 0, 0.0031))});
    const double expected = uniform ? 0.0 : -lib.shapes[0].volume * (1 + C) * 2 * kRho * nu * umax / (h * h);
    CHECK(sim.bodies.force[0].x() == Approx(expected).margin(1e-12 * std::abs(lib.shapes[0].volume * kRho * nu * umax / (h * h))));
    CHECK(sim.bodies.force[0].tail<2>().norm() < 1e-20);
  }
  std::filesystem::remove(path);
}

TEST_CASE("A grid file without a needed array is an error naming the scene key", "[sim][fluid]") {
  const auto path = std::filesystem::temp_directory_path() / ("polydem_norho_" + std::to_string(getpid()) + ".vti");
  std::ofstream(path) << "<VTKFile type=\"ImageData\"><ImageData WholeExtent=\"0 1 0 1 0 1\" Origin=\"0 0 0\" "
                         "Spacing=\"1 1 1\"><Piece Extent=\"0 1 0 1 0 1\"><CellData><DataArray type=\"Float64\" "
                         "Name=\"p\" format=\"ascii\">0</DataArray></CellData></Piece></ImageData></VTKFile>\n";
  Scene s = water();
  s.forces.fluid->file = path.string();
  s.forces.fluid->rho.reset();
  s.forces.fluid->file_loc = {"test.yaml", 21};
  s.forces.archimedes = true;
  std::string message;
  try {
    Simulation sim(s, library({sphere_shape(kR)}), {dense(kRho)});
  } catch (const InputError& e) {
    message = e.what();
  }
  CHECK(message == "test.yaml:21: key 'file': " + path.string() +
                       ": no array 'rho' in its CellData (arrays: p); or give the density in fluid_field (rho: 1000)");
  std::filesystem::remove(path);
}
