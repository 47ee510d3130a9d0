#pragma once
// "Did you mean" hints for misspelt keys and names, shared by shape files and scene files.
#include <string>
#include <vector>

namespace polydem {

// Levenshtein distance, case-insensitive (preCompDone vs precompdone is a near miss).
int edit_distance(const std::string& a, const std::string& b);

// " (did you mean 'NAME'?)" for the name nearest to `word`, or "" when even the nearest is
// too far to help (more than a third of the word, at least 2 edits, wrong).
std::string did_you_mean(const std::string& word, const std::vector<std::string>& names);

}  // namespace polydem
