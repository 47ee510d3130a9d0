#include "contact/exact_sum.hpp"

#include <limits>

namespace polydem {

void ExactSum::add(const ExactSum& o) {
  for (int k = 0; k < kDigits; ++k) digit_[k] += o.digit_[k];
  pos_inf_ += o.pos_inf_;
  neg_inf_ += o.neg_inf_;
  nan_ += o.nan_;
  terms_ += o.terms_;  // each below 2^30: the sum still fits
  if (terms_ >= kTermsBeforeCarry) carry();
}

void ExactSum::add_special(double x) {
  if (std::isnan(x)) ++nan_;
  else if (x > 0) ++pos_inf_;
  else ++neg_inf_;
}

void ExactSum::carry() {
  for (int k = 0; k + 1 < kDigits; ++k) {
    const std::int64_t c = digit_[k] >> 32;  // floor: the digit left in [0, 2^32)
    digit_[k] -= c * (std::int64_t(1) << 32);
    digit_[k + 1] += c;
  }
  terms_ = 1;  // digits below 2^32, as after one term
}

double ExactSum::value() const {
  if (nan_ || (pos_inf_ && neg_inf_)) return std::numeric_limits<double>::quiet_NaN();
  if (pos_inf_ || neg_inf_) return pos_inf_ ? std::numeric_limits<double>::infinity()
                                            : -std::numeric_limits<double>::infinity();
  ExactSum s = *this;
  s.carry();  // one integer, one set of digits: the rounding below sees only the value
  const bool negative = s.digit_[kDigits - 1] < 0;
  if (negative) {
    for (std::int64_t& d : s.digit_) d = -d;
    s.carry();
  }
  int top = kDigits - 1;
  while (top >= 0 && s.digit_[top] == 0) --top;
  if (top < 0) return 0.0;
  auto digit = [&](int k) { return k >= 0 ? static_cast<unsigned __int128>(s.digit_[k]) : 0; };
  const unsigned __int128 bits = digit(top) << 64 | digit(top - 1) << 32 | digit(top - 2);
  bool sticky = false;  // a bit below the three top digits: decides a tie
  for (int k = 0; k < top - 2; ++k) sticky |= s.digit_[k] != 0;
  const std::uint64_t high = std::uint64_t(bits >> 64);
  const int lead = high ? 64 + std::bit_width(high) - 1 : std::bit_width(std::uint64_t(bits)) - 1;
  const int shift = lead - 63;  // keep 64 bits: 11 below the double's 53 round it, sticky in the last
  std::uint64_t m;
  if (shift >= 0) {
    sticky |= (bits & ((static_cast<unsigned __int128>(1) << shift) - 1)) != 0;
    m = std::uint64_t(bits >> shift);
  } else {
    m = std::uint64_t(bits) << -shift;
  }
  const double r = std::ldexp(double(m | std::uint64_t(sticky)), 32 * (top - 2) - 1074 + shift);
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
