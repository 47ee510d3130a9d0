#include "field/fluid_grid.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "polydem/parallel.hpp"

namespace polydem {

namespace {

template <class T>
T zero() {
  if constexpr (std::is_arithmetic_v<T>) return 0.0;
  else return T::Zero();
}

// d f / d x_axis in cell c.
template <class T>
T derivative(const FluidGrid& g, const std::vector<T>& f, const Index3& c, int axis) {
  const int n = g.cells[axis], i = c[axis];
  const double h = g.spacing[axis];
  auto at = [&](int m) {
    Index3 d = c;
    d[axis] = m;
    return f[g.index(d)];
  };
  if (n == 1) return zero<T>();
  if (n == 2) return (at(1) - at(0)) / h;
  if (i == 0) return (-3.0 * at(0) + 4.0 * at(1) - at(2)) / (2.0 * h);
  if (i == n - 1) return (3.0 * at(n - 1) - 4.0 * at(n - 2) + at(n - 3)) / (2.0 * h);
  return (at(i + 1) - at(i - 1)) / (2.0 * h);
}

template <class Fn>
void for_cells(const FluidGrid& g, const Fn& fn) {
  parallel_for(g.size(), [&](std::size_t k) {
    const int nx = g.cells.x(), ny = g.cells.y();
    const Index3 c(int(k % nx), int(k / nx % ny), int(k / nx / ny));
    fn(k, c);
  });
}

}  // namespace

std::optional<Index3> FluidGrid::locate(const Vec3& x) const {
  const Vec3 s = (x - origin).cwiseQuotient(spacing);
  Index3 c;
  for (int a = 0; a < 3; ++a) {
    if (!(s[a] >= 0.0 && s[a] < cells[a])) return std::nullopt;  // also refuses NaN
    c[a] = std::min(int(s[a]), cells[a] - 1);
  }
  return c;
}

FluidGrid::Stencil FluidGrid::stencil(const Vec3& x) const {
  const Vec3 s = (x - origin).cwiseQuotient(spacing);
  Stencil st;
  if (!trilinear) {
    st.cell[0] = index(s.array().floor().cast<int>().min(cells.array() - 1).max(0).matrix());
    st.weight[0] = 1.0;
    st.count = 1;
    return st;
  }
  Index3 lo;
  Vec3 t;
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::max(0, std::min(int(std::floor(s[a] - 0.5)), cells[a] - 2));
    t[a] = cells[a] == 1 ? 0.0 : std::clamp(s[a] - 0.5 - lo[a], 0.0, 1.0);
  }
  for (int corner = 0; corner < 8; ++corner) {
    Index3 c = lo;
    double w = 1.0;
    for (int a = 0; a < 3; ++a) {
      const bool up = (corner >> a) & 1;
      c[a] += up;
      w *= up ? t[a] : 1.0 - t[a];
    }
    if (w == 0.0 && corner > 0) continue;  // also the corners past a one-cell axis
    st.cell[st.count] = index(c);
    st.weight[st.count++] = w;
  }
  return st;
}

void derive_fields(FluidGrid& g, bool grad_p, bool div_tau) {
  if (grad_p) {
    g.grad_p.resize(g.size());
    for_cells(g, [&](std::size_t k, const Index3& c) {
      for (int a = 0; a < 3; ++a) g.grad_p[k][a] = derivative(g, g.p, c, a);
    });
  }
  if (!div_tau) return;
  // A = mu (grad U + dev(grad(U)^T)) with (grad U)_ij = d_i U_j; div_tau_j = -d_i A_ij
  std::vector<Mat3> A(g.size());
  for_cells(g, [&](std::size_t k, const Index3& c) {
    Mat3 G;
    for (int a = 0; a < 3; ++a) G.row(a) = derivative(g, g.U, c, a).transpose();
    const Mat3 dev_t = G.transpose() - G.trace() / 3.0 * Mat3::Identity();
    A[k] = g.nu[k] * g.rho[k] * (G + dev_t);
  });
  g.div_tau.resize(g.size());
  for_cells(g, [&](std::size_t k, const Index3& c) {
    Vec3 d = Vec3::Zero();
    for (int a = 0; a < 3; ++a) d -= derivative(g, A, c, a).row(a).transpose();
    g.div_tau[k] = d;
  });
}

}  // namespace polydem
