// The exact sum the energy ledger uses (contact/exact_sum.hpp): the total of any terms, in any
// order and any split into merged partial sums, is one double, the exact sum rounded once.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "contact/exact_sum.hpp"

using namespace polydem;

namespace {

double exact(const std::vector<double>& terms) {
  ExactSum s;
  for (double x : terms) s.add(x);
  return s.value();
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

}  // namespace

TEST_CASE("exact sum: cancellations and ties a running double sum gets wrong", "[contact][energy]") {
  CHECK(exact({1e100, 1.0, -1e100}) == 1.0);  // a running sum gives 0
  CHECK(exact({DBL_MAX, DBL_MAX, -DBL_MAX}) == DBL_MAX);  // a running sum overflows
  const double tie = std::ldexp(1.0, -53);  // half an ulp of 1
  CHECK(exact({1.0, tie}) == 1.0);  // a tie rounds to even
  CHECK(exact({1.0, tie, std::ldexp(1.0, -200)}) == std::nextafter(1.0, 2.0));  // just past the tie: up
  CHECK(exact({-1.0, -tie, -std::ldexp(1.0, -200)}) == -std::nextafter(1.0, 2.0));
  const double tiny = std::numeric_limits<double>::denorm_min();
  CHECK(exact({tiny, tiny, tiny, -tiny}) == 2 * tiny);
  CHECK(exact({0.1, 0.2, -0.3}) == 0x1p-55);  // exact (Python Fraction); a running sum gives 0x1p-54
  CHECK(exact({}) == 0.0);
  CHECK(exact({2.5, -2.5}) == 0.0);
}

TEST_CASE("exact sum: infinities and NaN as a running sum gives them, in any order", "[contact][energy]") {
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(exact({1.0, inf, 2.0}) == inf);
  CHECK(exact({-inf, 1.0}) == -inf);
  CHECK(std::isnan(exact({inf, 1.0, -inf})));
  CHECK(std::isnan(exact({1.0, std::nan("")})));
}

TEST_CASE("exact sum: integers times powers of two against __int128 arithmetic", "[contact][energy]") {
  // Terms m 2^e with |m| < 2^53 and e in [-30, 20]: their sum times 2^30 is an integer, summed
  // exactly in __int128 and rounded once by the compiler's conversion (an independent rounding).
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> terms;
    __int128 scaled = 0;  // the sum times 2^30
    const int n = 1 + int(rng() % 300);
    for (int k = 0; k < n; ++k) {
      const std::int64_t m = std::int64_t(rng() >> 11) * (rng() & 1 ? 1 : -1);
      const int e = int(rng() % 51) - 30;
      terms.push_back(std::ldexp(double(m), e));
      scaled += static_cast<__int128>(m) << (e + 30);
    }
    const double reference = std::ldexp(double(scaled), -30);
    INFO("trial " << trial);
    CHECK(same_bits(exact(terms), reference));
  }
}

TEST_CASE("exact sum: the same bits for any order and any split into merged or reduced parts", "[contact][energy]") {
  // Terms over the whole exponent range, both signs, as a rank's energies never are: the worst case.
  std::mt19937_64 rng(3);
  std::vector<double> terms;
  for (int k = 0; k < 5000; ++k) {
    const double m = double(rng() >> 11) * 0x1.0p-53 * (rng() & 1 ? 1 : -1);
    terms.push_back(std::ldexp(m, int(rng() % 400) - 200));
  }
  const double whole = exact(terms);
  for (int shuffle = 0; shuffle < 5; ++shuffle) {
    std::shuffle(terms.begin(), terms.end(), rng);
    CHECK(same_bits(exact(terms), whole));
    // Three "threads" merged, and three "ranks" reduced as words (wrapping integer sums).
    ExactSum part[3], merged;
    for (std::size_t k = 0; k < terms.size(); ++k) part[k % 3].add(terms[k]);
    std::vector<std::uint64_t> reduced(ExactSum::kWords, 0);
    for (const ExactSum& p : part) {
      merged.add(p);
      const std::vector<std::uint64_t> w = p.words();
      for (int k = 0; k < ExactSum::kWords; ++k) reduced[k] += w[k];
    }
    CHECK(same_bits(merged.value(), whole));
    CHECK(same_bits(ExactSum::from_words(reduced.data(), 3).value(), whole));
  }
}

TEST_CASE("exact sum: add_all's binned terms give add's sum, word for word", "[contact][energy]") {
  std::mt19937_64 rng(11);
  std::vector<double> terms;
  for (int k = 0; k < 5000; ++k) {  // several chunks of 1,024, mixed signs and exponents, zeros, subnormals
    const double m = double(rng() >> 11) * 0x1.0p-53;
    const int e = int(rng() % 2100) - 1074;
    terms.push_back((k % 2 ? -1.0 : 1.0) * (k % 7 == 0 ? 0.0 : std::ldexp(m, std::min(e, 1000))));
  }
  for (int k = 0; k < 3000; ++k) terms.push_back(1.0 - 0x1p-53);  // one bin filled past a chunk: carries
  terms.push_back(std::numeric_limits<double>::denorm_min());
  ExactSum one_by_one, binned;
  for (double x : terms) one_by_one.add(x);
  binned.add_all(terms.data(), terms.size());
  CHECK(binned.words() == one_by_one.words());
  CHECK(same_bits(binned.value(), one_by_one.value()));
  terms.push_back(std::numeric_limits<double>::infinity());  // specials counted as add() counts them
  binned.add_all(&terms.back(), 1);
  one_by_one.add(terms.back());
  CHECK(binned.words() == one_by_one.words());
  CHECK(std::isinf(binned.value()));
}

namespace {

// An independent reference: Shewchuk's exact partials and their correctly rounded total, as
// Python's math.fsum computes it (exact while no partial overflows: exponents below ~1000 here).
double fsum(const std::vector<double>& terms) {
  std::vector<double> partials;
  for (double x : terms) {
    std::size_t used = 0;
    for (double y : partials) {
      if (std::abs(x) < std::abs(y)) std::swap(x, y);
      const double hi = x + y, lo = y - (hi - x);  // hi + lo == x + y exactly
      if (lo != 0.0) partials[used++] = lo;
      x = hi;
    }
    partials.resize(used);
    partials.push_back(x);
  }
  std::size_t n = partials.size();
  if (n == 0) return 0.0;
  double hi = partials[--n], lo = 0.0;
  while (n > 0) {
    const double x = hi, y = partials[--n];
    hi = x + y;
    lo = y - (hi - x);
    if (lo != 0.0) break;
  }
  // hi + lo rounded half-even; the partials below lo decide a tie
  if (n > 0 && ((lo < 0 && partials[n - 1] < 0) || (lo > 0 && partials[n - 1] > 0))) {
    const double y = lo * 2, x = hi + y;
    if (y == x - hi) hi = x;
  }
  return hi;
}

}  // namespace

TEST_CASE("exact sum: value() of runs of a few exponents, of wide runs and of cancellations, against fsum", "[contact][energy]") {
  // A step's power: tens of terms within a few digits of each other; value() normalises only the
  // digits in use, so the runs sit anywhere in the range, the subnormals and the top included.
  std::mt19937_64 rng(19);
  auto term = [&](int centre, int spread) {
    const double m = double(rng() >> 11) * 0x1.0p-53 * (rng() & 1 ? 1 : -1);
    return std::ldexp(m, centre + int(rng() % (2 * spread + 1)) - spread);
  };
  for (int trial = 0; trial < 3000; ++trial) {
    const int n = 1 + int(rng() % 120);
    const int spread = trial % 3 == 0 ? 400 : int(rng() % 70);
    const int centre = std::clamp(int(rng() % 2100) - 1074, -1074 + spread, 990 - spread);
    std::vector<double> terms;
    for (int k = 0; k < n; ++k) terms.push_back(term(centre, spread));
    if (trial % 4 == 1)  // cancel most of it: the total lies digits below the terms
      for (int k = 0; k < n; ++k) terms.push_back(-terms[k] * (k % 5 ? 1.0 : 1.0 - 0x1p-52));
    if (trial % 5 == 2) terms.push_back(-fsum(terms));  // the remainder below the rounding alone
    std::shuffle(terms.begin(), terms.end(), rng);
    ExactSum one_by_one, binned;
    for (double x : terms) one_by_one.add(x);
    binned.add_all(terms.data(), terms.size());
    const double reference = fsum(terms);
    INFO("trial " << trial << ", " << terms.size() << " terms about 2^" << centre);
    CHECK(same_bits(one_by_one.value(), reference));
    CHECK(same_bits(binned.value(), reference));
    CHECK(same_bits(ExactSum::rounded_sum(terms.data(), terms.size()), reference));
  }
  // Near the top of the range the carries reach the last digit.
  const double big = std::ldexp(1.0, 1021);
  CHECK(exact({big, big, big, -std::ldexp(1.0, 970)}) == std::nextafter(3 * big, 0.0));  // one ulp below
  CHECK(exact({-big, -big, -big, std::ldexp(1.0, 969)}) == -3 * big);  // a tie: to even
}

TEST_CASE("exact sum: rounded_sum gives value()'s double where a compensated sum cannot tell", "[contact][energy]") {
  auto rounded = [](std::vector<double> terms) { return ExactSum::rounded_sum(terms.data(), terms.size()); };
  const double tie = std::ldexp(1.0, -53);  // half an ulp of 1: the compensated sum sits on the tie
  CHECK(same_bits(rounded({1.0, tie}), 1.0));
  CHECK(same_bits(rounded({1.0, tie, std::ldexp(1.0, -200)}), std::nextafter(1.0, 2.0)));
  CHECK(same_bits(rounded({1e100, 1.0, -1e100}), 1.0));  // all but the error cancels
  CHECK(same_bits(rounded({0.1, 0.2, -0.3}), 0x1p-55));
  CHECK(same_bits(rounded({2.5, -2.5}), 0.0));  // +0, as value()
  CHECK(same_bits(rounded({}), 0.0));
  const double tiny = std::numeric_limits<double>::denorm_min();
  CHECK(same_bits(rounded({tiny, tiny, tiny, -tiny}), 2 * tiny));
  CHECK(same_bits(rounded({DBL_MAX, DBL_MAX, -DBL_MAX}), DBL_MAX));  // a compensated sum overflows
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(same_bits(rounded({1.0, inf}), inf));
  CHECK(std::isnan(rounded({inf, -inf})));
  // A short run of like terms (a step's drag power): the compensated path, exact to the bit.
  std::mt19937_64 rng(23);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<double> terms;
    for (int k = 0; k < 75; ++k) terms.push_back(-std::ldexp(double(rng() >> 11), -60 - int(rng() % 20)));
    ExactSum e;
    e.add_all(terms.data(), terms.size());
    CHECK(same_bits(rounded(terms), e.value()));
  }
}
