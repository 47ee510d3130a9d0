#include "contact/exact_sum.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <utility>

namespace polydem {

void ExactSum::add(const ExactSum& o) {
  for (int k = 0; k < kDigits; ++k) digit_[k] += o.digit_[k];
  pos_inf_ += o.pos_inf_;
  neg_inf_ += o.neg_inf_;
  nan_ += o.nan_;
  terms_ += o.terms_;  // each below 2^30: the sum still fits
  if (terms_ >= kTermsBeforeCarry) carry();
}

namespace {

// add_all's signed integer sums by exponent, zero between its calls; 16 KB a thread.
thread_local std::array<std::int64_t, 2048> t_bins{};

}  // namespace

void ExactSum::add_all(const double* x, std::size_t n) {
  constexpr std::size_t kChunk = 1024;  // each term adds below 2^53 to its bin: 2^10 of them stay below 2^63
  constexpr std::uint64_t kMantissa = (std::uint64_t(1) << 52) - 1;
  std::int64_t* bins = t_bins.data();
  for (std::size_t at = 0; at < n;) {
    const std::size_t end = std::min(n, at + kChunk);
    unsigned lo = 2048, hi = 0;  // the exponents used in this chunk
    for (; at < end; ++at) {
      const std::uint64_t u = std::bit_cast<std::uint64_t>(x[at]);
      if (u << 1 == 0) continue;  // +-0
      const unsigned exponent = unsigned(u >> 52) & 0x7ff;
      if (exponent == 0x7ff) {
        add_special(x[at]);
        continue;
      }
      const std::int64_t m = std::int64_t((u & kMantissa) | std::uint64_t(exponent != 0) << 52);  // a subnormal has no leading 1
      const std::int64_t sign = -std::int64_t(u >> 63);  // 0 or -1: (m ^ sign) - sign negates
      bins[exponent] += (m ^ sign) - sign;
      lo = std::min(lo, exponent);
      hi = std::max(hi, exponent);
    }
    for (unsigned e = lo; e <= hi; ++e)
      if (const std::int64_t v = std::exchange(bins[e], 0)) add_scaled(v < 0 ? -std::uint64_t(v) : std::uint64_t(v), int(e), v < 0);
  }
}

// Ogita, Rump and Oishi's Sum2 in two lanes (even and odd terms: packed instructions): exact =
// the lanes' sums + sum e_i (TwoSum's errors, exact); c their rounded sums. Met, the bound is
// below (n^2 / 4 + n) eps^2 sum |x| (1 + o(1)), eps = 2^-53; hi + lo = the lanes' s + c exactly.
// hi is the rounded exact sum when |lo| + that bound stays inside half hi's smaller gap.
double ExactSum::rounded_sum(const double* x, std::size_t n) {
  using Lanes = double __attribute__((vector_size(16)));  // two doubles: SSE2's packed instructions
  using LaneBits = std::int64_t __attribute__((vector_size(16)));
  const LaneBits magnitude = {std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::max()};
  Lanes s = {0.0, 0.0}, c = {0.0, 0.0}, a = {0.0, 0.0};  // running sums, their errors' sums, sums of |x|
  auto add = [&](Lanes v) {
    const Lanes t = s + v, z = t - s;
    c += (s - (t - z)) + (v - z);
    s = t;
    a += (Lanes)((LaneBits)v & magnitude);
  };
  std::size_t i = 0;
  for (Lanes v; i + 1 < n; i += 2) {
    std::memcpy(&v, x + i, sizeof v);
    add(v);
  }
  if (i < n) add(Lanes{x[i], 0.0});
  const double sum = s[0] + s[1], z0 = sum - s[0], e = (s[0] - (sum - z0)) + (s[1] - z0);
  const double err = c[0] + c[1] + e, a_all = a[0] + a[1];
  const double hi = sum + err, z = hi - sum, lo = (sum - (hi - z)) + (err - z);
  const double bound = 2.0 * (double(n) * double(n) * 0x1p-105 * a_all);  // 4 n^2 eps^2 sum |x|: above the bound
  // No overflow, no bound or gap below the normal range (a NaN or infinity fails the first test).
  const bool plain = a_all <= 0x1p900 && std::abs(hi) >= 0x1p-900 && n < (std::size_t(1) << 20);
  if (plain) {
    const double gap = std::abs(hi) - std::nextafter(std::abs(hi), 0.0);  // exact: the smaller of hi's two
    if (std::abs(lo) + bound <= 0.5 * gap * (1.0 - 0x1p-40)) return hi;
  }
  ExactSum exact;
  exact.add_all(x, n);
  return exact.value();
}

void ExactSum::add_scaled(std::uint64_t v, int exponent, bool negative) {
  const int bit = std::max(exponent, 1) - 1, k = bit >> 5;  // as add(): v 2^(bit - 1074)
  const unsigned __int128 w = static_cast<unsigned __int128>(v) << (bit & 31);  // < 2^94
  const std::int64_t sign = negative ? -1 : 0;
  digit_[k] += (std::int64_t(std::uint32_t(w)) ^ sign) - sign;
  digit_[k + 1] += (std::int64_t(std::uint32_t(w >> 32)) ^ sign) - sign;
  digit_[k + 2] += (std::int64_t(w >> 64) ^ sign) - sign;  // below 2^30: each digit gains less than 2^32, as a term's
  if (++terms_ == kTermsBeforeCarry) carry();
}

void ExactSum::add_special(double x) {
  if (std::isnan(x)) ++nan_;
  else if (x > 0) ++pos_inf_;
  else ++neg_inf_;
}

void ExactSum::carry_digits(std::int64_t* d, int count) {
  for (int k = 0; k + 1 < count; ++k) {
    const std::int64_t c = d[k] >> 32;  // floor: the digit left in [0, 2^32)
    d[k] -= c * (std::int64_t(1) << 32);
    d[k + 1] += c;
  }
}

void ExactSum::carry() {
  carry_digits(digit_.data(), kDigits);
  terms_ = 1;  // digits below 2^32, as after one term
}

// Normalises only the digits in use (a run's terms span a few of the 67) and the two above
// them that its carries can reach; the rounding sees the same integer as a full carry's.
double ExactSum::value() const {
  if (nan_ || (pos_inf_ && neg_inf_)) return std::numeric_limits<double>::quiet_NaN();
  if (pos_inf_ || neg_inf_) return pos_inf_ ? std::numeric_limits<double>::infinity()
                                            : -std::numeric_limits<double>::infinity();
  int high = kDigits - 1, low = 0;
  while (high >= 0 && digit_[high] == 0) --high;
  if (high < 0) return 0.0;
  while (digit_[low] == 0) ++low;
  // A digit below 2^63 carries below 2^31 + 1 into the next, which carries 0 or -1 into the one above.
  const int count = std::min(high + 2, kDigits - 1) - low + 1;
  std::array<std::int64_t, kDigits> d{};  // digit low + i
  std::copy(digit_.begin() + low, digit_.begin() + high + 1, d.begin());
  carry_digits(d.data(), count);
  const bool negative = d[count - 1] < 0;
  if (negative) {
    for (int i = 0; i < count; ++i) d[i] = -d[i];
    carry_digits(d.data(), count);
  }
  int top = count - 1;
  while (top >= 0 && d[top] == 0) --top;
  if (top < 0) return 0.0;
  auto digit = [&](int k) { return k >= 0 ? static_cast<unsigned __int128>(d[k]) : 0; };
  const unsigned __int128 bits = digit(top) << 64 | digit(top - 1) << 32 | digit(top - 2);
  bool sticky = false;  // a bit below the three top digits: decides a tie
  for (int k = 0; k < top - 2; ++k) sticky |= d[k] != 0;
  const std::uint64_t lead_word = std::uint64_t(bits >> 64);
  const int lead = lead_word ? 64 + std::bit_width(lead_word) - 1 : std::bit_width(std::uint64_t(bits)) - 1;
  const int shift = lead - 63;  // keep 64 bits: 11 below the double's 53 round it, sticky in the last
  std::uint64_t m;
  if (shift >= 0) {
    sticky |= (bits & ((static_cast<unsigned __int128>(1) << shift) - 1)) != 0;
    m = std::uint64_t(bits >> shift);
  } else {
    m = std::uint64_t(bits) << -shift;
  }
  const double r = std::ldexp(double(m | std::uint64_t(sticky)), 32 * (low + top - 2) - 1074 + shift);
  return negative ? -r : r;
}

std::vector<std::uint64_t> ExactSum::words() const {
  ExactSum s = *this;
  s.carry();
  std::vector<std::uint64_t> w(kWords);
  for (int k = 0; k < kDigits; ++k) w[k] = std::uint64_t(s.digit_[k]);
  w[kDigits] = std::uint64_t(pos_inf_);
  w[kDigits + 1] = std::uint64_t(neg_inf_);
  w[kDigits + 2] = std::uint64_t(nan_);
  return w;
}

ExactSum ExactSum::from_words(const std::uint64_t* w, std::uint64_t terms) {
  ExactSum s;
  for (int k = 0; k < kDigits; ++k) s.digit_[k] = std::int64_t(w[k]);
  s.pos_inf_ = std::int64_t(w[kDigits]);
  s.neg_inf_ = std::int64_t(w[kDigits + 1]);
  s.nan_ = std::int64_t(w[kDigits + 2]);
  s.terms_ = std::int64_t(terms);
  if (s.terms_ >= kTermsBeforeCarry) s.carry();
  return s;
}

std::vector<std::uint64_t> ExactEnergy::words() const {
  std::vector<std::uint64_t> w;
  for (const ExactSum* s : {&net, &sliding, &rolling, &patch}) {
    const std::vector<std::uint64_t> one = s->words();
    w.insert(w.end(), one.begin(), one.end());
  }
  return w;
}

ExactEnergy ExactEnergy::from_words(const std::vector<std::uint64_t>& w, std::uint64_t terms) {
  const std::uint64_t* at = w.data();
  ExactEnergy e;
  for (ExactSum* s : {&e.net, &e.sliding, &e.rolling, &e.patch}) {
    *s = ExactSum::from_words(at, terms);
    at += ExactSum::kWords;
  }
  return e;
}

}  // namespace polydem
