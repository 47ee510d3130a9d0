#pragma once
// "Did you mean" hints for misspelt keys in shape files.
#include <string>
#include <vector>

namespace polydem {

// " (did you mean 'KEY'?)" for the valid key nearest to `word` (edit distance <= 3 and less
// than the word's length), else "".
std::string did_you_mean_key(const std::string& word, const std::vector<std::string>& keys);

}  // namespace polydem
