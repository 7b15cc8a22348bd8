#pragma once
// "Did you mean ...?" hints for misspelt names (plugins, parameters, ids).
// Shared by the plugin manager and the scene loader so every hint reads the same.
#include <string>
#include <vector>

namespace femto {

/// Levenshtein distance (insertions, deletions, substitutions; case-sensitive).
size_t editDistance(const std::string& a, const std::string& b);

/// Candidates close to `word`, best first: within an edit distance of about a
/// third of the word's length (at least 1, at most 3), or sharing it as a
/// case-insensitive prefix. At most `maxCount` results.
std::vector<std::string> closestMatches(const std::string& word, const std::vector<std::string>& candidates,
                                        size_t maxCount = 3);

/// " (did you mean \"a\" or \"b\"?)" for the closest matches, or "" when none;
/// meant to be appended to a sentence before its full stop.
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace femto
