#include "sim/state_energy.hpp"

namespace polydem {

namespace {

// Every exact sum of `s`, in words order (the open energies' four last).
template <class S, class F>
void each_sum(S& s, F&& f) {
  for (auto* x : {&s.kinetic, &s.rotational, &s.moment[0], &s.moment[1], &s.moment[2], &s.elastic.normal,
                  &s.elastic.tangential, &s.elastic.rolling, &s.open.net, &s.open.sliding, &s.open.rolling,
                  &s.open.patch})
    f(*x);
}

}  // namespace

void StateEnergy::add_body(const Bodies& bodies, std::size_t b) {
  const double m = bodies.mass[b];  // kg
  kinetic.add(0.5 * m * bodies.velocity[b].squaredNorm());
  const Vec3& L = bodies.angular_momentum[b];
  rotational.add(0.5 * L.cwiseProduct(L).cwiseQuotient(bodies.inertia[b]).sum());
  for (int a = 0; a < 3; ++a) moment[a].add(m * bodies.position[b][a]);
}

std::vector<std::uint64_t> StateEnergy::words() const {
  std::vector<std::uint64_t> w;
  each_sum(*this, [&](const ExactSum& s) {
    const std::vector<std::uint64_t> one = s.words();
    w.insert(w.end(), one.begin(), one.end());
  });
  return w;
}

StateEnergy StateEnergy::from_words(const std::vector<std::uint64_t>& w, std::uint64_t terms) {
  StateEnergy e;
  const std::uint64_t* at = w.data();
  each_sum(e, [&](ExactSum& s) {
    s = ExactSum::from_words(at, terms);
    at += ExactSum::kWords;
  });
  return e;
}

}  // namespace polydem
