// Finite differences and sampling on the fluid grid, against closed forms. FD stencils are
// second order (central inside, one-sided on the boundary), so they are exact on quadratic
// fields: every check below holds to rounding.
#include <catch2/catch.hpp>

#include "field/fluid_grid.hpp"

using namespace polydem;

namespace {

FluidGrid grid(Index3 cells, Vec3 spacing, Vec3 origin = Vec3::Zero()) {
  FluidGrid g;
  g.cells = cells;
  g.spacing = spacing;
  g.origin = origin;
  g.U.resize(g.size());
  g.p.resize(g.size());
  g.rho.assign(g.size(), 1000.0);
  g.nu.assign(g.size(), 1.0e-6);
  return g;
}

template <class Fn>
void fill(FluidGrid& g, const Fn& fn) {
  for (int k = 0; k < g.cells.z(); ++k)
    for (int j = 0; j < g.cells.y(); ++j)
      for (int i = 0; i < g.cells.x(); ++i) fn(g.index({i, j, k}), g.center({i, j, k}));
}

}  // namespace

TEST_CASE("Uniform flow has no viscous stress divergence", "[field]") {
  FluidGrid g = grid({4, 5, 6}, {0.01, 0.02, 0.015});
  fill(g, [&](std::size_t k, const Vec3&) { g.U[k] = Vec3(0.3, -0.2, 1.1); });
  derive_fields(g, false, true);
  // zero up to rounding: mu U / h^2 is ~10 N/m^3 here
  for (const Vec3& d : g.div_tau) CHECK(d.norm() < 1e-12);
}

TEST_CASE("Poiseuille profile: div(tau) = -mu u'' e_x everywhere", "[field]") {
  // u(z) = Umax (1 - (z - zc)^2 / h^2): grad U has only d_z u; div U = 0 so the dev term
  // vanishes and div(tau) = -div(mu grad U) = -mu u'' e_x = 2 mu Umax / h^2 e_x.
  FluidGrid g = grid({3, 4, 10}, {0.01, 0.01, 0.002});
  const double umax = 0.5, h = 0.01, zc = 0.01;
  fill(g, [&](std::size_t k, const Vec3& x) { g.U[k] = Vec3(umax * (1.0 - std::pow((x.z() - zc) / h, 2)), 0, 0); });
  derive_fields(g, false, true);
  const double mu = 1000.0 * 1.0e-6, expected = 2.0 * mu * umax / (h * h);
  for (const Vec3& d : g.div_tau) {
    CHECK(d.x() == Approx(expected).epsilon(1e-10));
    CHECK(std::abs(d.y()) + std::abs(d.z()) < 1e-12 * expected);
  }
}

TEST_CASE("Compressible flow: the deviatoric transpose term of div(tau)", "[field]") {
  // U = (x^2, 0, 0): div(mu grad U)_x = 2 mu; (grad U)^T - tr/3 I has xx entry 2x - 2x/3 = 4x/3,
  // whose divergence is 4/3: div(tau)_x = -mu (2 + 4/3) = -10/3 mu.
  FluidGrid g = grid({8, 3, 3}, {0.01, 0.01, 0.01}, {-0.03, 0, 0});
  fill(g, [&](std::size_t k, const Vec3& x) { g.U[k] = Vec3(x.x() * x.x(), 0, 0); });
  derive_fields(g, false, true);
  for (const Vec3& d : g.div_tau) CHECK(d.x() == Approx(-10.0 / 3.0 * 1.0e-3).epsilon(1e-9));
}

TEST_CASE("Hydrostatic pressure gradient is rho g", "[field]") {
  FluidGrid g = grid({3, 3, 7}, {0.01, 0.01, 0.01});
  const Vec3 rho_g(0.0, 0.0, -1000.0 * 9.807);
  fill(g, [&](std::size_t k, const Vec3& x) { g.p[k] = 2.0e5 + rho_g.dot(x - Vec3(0, 0, 0.07)); });
  derive_fields(g, true, false);
  for (const Vec3& d : g.grad_p) CHECK((d - rho_g).norm() < 1e-9 * rho_g.norm());
}

TEST_CASE("Sampling: cell value or trilinear between cell centres", "[field]") {
  FluidGrid g = grid({4, 3, 5}, {0.01, 0.02, 0.01}, {-0.02, 0.0, 0.1});
  const Vec3 a(3.0, -1.0, 2.0);
  fill(g, [&](std::size_t k, const Vec3& x) { g.p[k] = 5.0 + a.dot(x); });
  const Vec3 x(-0.013, 0.027, 0.1234);  // between centres on every axis
  CHECK(g.sample(g.p, x) == Approx(5.0 + a.dot(g.center(*g.locate(x)))).epsilon(1e-14));
  g.trilinear = true;  // exact on a linear field between the outer centres
  CHECK(g.sample(g.p, x) == Approx(5.0 + a.dot(x)).epsilon(1e-13));
  const Vec3 corner = g.origin + Vec3(1e-4, 1e-4, 1e-4);  // outer half cell: the corner centre's value
  CHECK(g.sample(g.p, corner) == Approx(g.p[0]).epsilon(1e-14));
}

TEST_CASE("Locate: lower faces belong to the cell, outside is nothing", "[field]") {
  FluidGrid g = grid({2, 2, 2}, {1.0, 1.0, 1.0});
  CHECK(g.locate({0.0, 0.0, 0.0}) == Index3(0, 0, 0));
  CHECK(g.locate({1.0, 0.5, 1.999}) == Index3(1, 0, 1));
  CHECK_FALSE(g.locate({2.0, 0.5, 0.5}));
  CHECK_FALSE(g.locate({0.5, -1e-12, 0.5}));
  CHECK_FALSE(g.locate({0.5, std::nan(""), 0.5}));
}
