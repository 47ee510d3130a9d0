#pragma once
// An exact sum of doubles (a fixed-point superaccumulator over the whole double range): the
// terms are added as integers, so the total does not depend on their order, on which thread
// or rank added which, or on how partial sums are merged; it is rounded once, at the end.
// The energy ledger sums its pairs with it, so energy.csv is the same for any thread count
// and any rank count, and ranks reduce a few kB a step instead of gathering every pair.
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "contact/law/types.hpp"

namespace polydem {

class ExactSum {
 public:
  // Digit k weighs 2^(32 k - 1074): 66 digits hold any double's 53 bits at their place, one
  // more the carries of 2^31 terms of the largest double.
  static constexpr int kDigits = 67;
  static constexpr int kWords = kDigits + 3;  // as words: the digits, then +inf, -inf, NaN counts

  void add(double x) {
    if (x == 0.0) return;  // most terms (pairs not touching, no slip)
    const std::uint64_t u = std::bit_cast<std::uint64_t>(x);
    int exponent = int(u >> 52) & 0x7ff;
    if (exponent == 0x7ff) return add_special(x);
    std::uint64_t mantissa = u & ((std::uint64_t(1) << 52) - 1);
    if (exponent) mantissa |= std::uint64_t(1) << 52;
    else exponent = 1;  // subnormal
    const int bit = exponent - 1, k = bit >> 5;  // x = mantissa 2^(bit - 1074)
    const unsigned __int128 w = static_cast<unsigned __int128>(mantissa) << (bit & 31);  // < 2^85
    const std::int64_t sign = -std::int64_t(u >> 63);  // 0 or -1: (v ^ sign) - sign negates
    digit_[k] += (std::int64_t(std::uint32_t(w)) ^ sign) - sign;
    digit_[k + 1] += (std::int64_t(std::uint32_t(w >> 32)) ^ sign) - sign;
    digit_[k + 2] += (std::int64_t(w >> 64) ^ sign) - sign;
    if (++terms_ == kTermsBeforeCarry) carry();
  }
  // The same sum as add() of each of x[0..n), ~3x fewer instructions a term: the terms'
  // mantissas are first summed as integers by sign and exponent, then each exponent's total
  // is added once (a long run of terms: drag and fluid forces' power, one a body a step).
  void add_all(const double* x, std::size_t n);
  // The sum of x[0..n) rounded once, the double add_all then value() gives, in ~3x fewer
  // instructions a term: a compensated sum whose error bound shows it rounds to that double,
  // else (near a tie, heavy cancellation, extreme exponents) the exact sum. One process's power.
  static double rounded_sum(const double* x, std::size_t n);
  void add(const ExactSum& o);
  // The sum rounded to the nearest double (once; a subnormal total may round twice).
  double value() const;
  // As integers whose sums over ranks (wrapping, any order) are the words of the sum.
  std::vector<std::uint64_t> words() const;
  static ExactSum from_words(const std::uint64_t* w, std::uint64_t terms);

 private:
  // Each term adds less than 2^32 to a digit: 2^30 of them leave an int64 room to spare.
  static constexpr std::int64_t kTermsBeforeCarry = std::int64_t(1) << 30;
  void add_special(double x);
  // Adds or takes (`negative`) v 2^(max(exponent, 1) - 1075), v < 2^63: add_all's bin totals.
  void add_scaled(std::uint64_t v, int exponent, bool negative);
  void carry();  // digits below the top into [0, 2^32)
  static void carry_digits(std::int64_t* d, int count);  // d[0..count-1) into [0, 2^32), the rest into d[count - 1]

  std::array<std::int64_t, kDigits> digit_{};
  std::int64_t terms_ = 0;                        // added since the last carry
  std::int64_t pos_inf_ = 0, neg_inf_ = 0, nan_ = 0;
};

// The ledger's four parts, each summed exactly.
struct ExactEnergy {
  ExactSum net, sliding, rolling, patch;
  void add(const EnergyParts& e) {
    net.add(e.net);
    sliding.add(e.sliding);
    rolling.add(e.rolling);
    patch.add(e.patch);
  }
  void add(const ExactEnergy& o) {
    net.add(o.net);
    sliding.add(o.sliding);
    rolling.add(o.rolling);
    patch.add(o.patch);
  }
  EnergyParts value() const { return {net.value(), sliding.value(), rolling.value(), patch.value()}; }
  std::vector<std::uint64_t> words() const;  // the four sums' words, in that order
  static ExactEnergy from_words(const std::vector<std::uint64_t>& w, std::uint64_t terms);
};

// The springs' stored energy by part (energy.csv's elastic_*), each summed exactly.
struct ExactStored {
  ExactSum normal, tangential, rolling;
  void add(const StoredParts& e) {
    normal.add(e.normal);
    tangential.add(e.tangential);
    rolling.add(e.rolling);
  }
  StoredParts value() const { return {normal.value(), tangential.value(), rolling.value()}; }
};

}  // namespace polydem
