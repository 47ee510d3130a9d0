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

void StateEnergy::add_body_sums(const StateEnergy& o) {
  kinetic.add(o.kinetic);
  rotational.add(o.rotational);
  for (int d = 0; d < 3; ++d) moment[d].add(o.moment[d]);
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
