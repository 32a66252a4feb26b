// Suggestions for a mistyped name (a scene key, a command-line option).
#pragma once
#include <string>
#include <vector>

namespace coolgas {

// Levenshtein distance: insertions, deletions and substitutions.
std::size_t edit_distance(const std::string& a, const std::string& b);

// " (did you mean 'X'?)" for the candidate closest to `name`, if it is
// within 3 edits; else "".
std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace coolgas
