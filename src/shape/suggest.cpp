#include "shape/suggest.hpp"

#include <algorithm>
#include <cctype>

namespace polydem {
namespace {

// Levenshtein distance, case-insensitive (preCompDone vs precompdone is a near miss).
int distance(const std::string& a, const std::string& b) {
  std::vector<int> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(a[i - 1]) == std::tolower(b[j - 1]);
      const int next = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = row[j];
      row[j] = next;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string did_you_mean_key(const std::string& word, const std::vector<std::string>& keys) {
  std::string best;
  int best_distance = 4;
  for (const std::string& k : keys) {
    const int d = distance(word, k);
    if (d < best_distance && d < static_cast<int>(std::max(word.size(), k.size()))) {
      best_distance = d;
      best = k;
    }
  }
  return best.empty() ? "" : " (did you mean '" + best + "'?)";
}

}  // namespace polydem
