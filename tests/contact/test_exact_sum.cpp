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
