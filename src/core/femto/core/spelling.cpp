#include <femto/core/spelling.h>

#include <algorithm>
#include <cctype>
#include <numeric>

namespace femto {

size_t editDistance(const std::string& a, const std::string& b) {
  // Two-row dynamic programme (Wagner & Fischer 1974).
  std::vector<size_t> previous(b.size() + 1), current(b.size() + 1);
  std::iota(previous.begin(), previous.end(), size_t(0));
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

namespace {

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

}  // namespace

std::vector<std::string> closestMatches(const std::string& word, const std::vector<std::string>& candidates,
                                        size_t maxCount) {
  // A third of the length catches typical typos ("difuse", "max_detph")
  // without suggesting unrelated short names.
  const size_t limit = std::clamp<size_t>(word.size() / 3, 1, 3);
  const std::string lowerWord = lowercase(word);
  std::vector<std::pair<size_t, std::string>> scored;
  for (const std::string& candidate : candidates) {
    if (candidate == word) continue;
    const std::string lowerCandidate = lowercase(candidate);
    size_t distance = editDistance(lowerWord, lowerCandidate);
    bool prefix = !lowerWord.empty() && (lowerCandidate.starts_with(lowerWord) || lowerWord.starts_with(lowerCandidate));
    if (distance <= limit || (prefix && std::min(word.size(), candidate.size()) >= 3)) scored.emplace_back(distance, candidate);
  }
  std::sort(scored.begin(), scored.end());
  scored.erase(std::unique(scored.begin(), scored.end()), scored.end());
  std::vector<std::string> result;
  for (size_t i = 0; i < scored.size() && i < maxCount; ++i) result.push_back(scored[i].second);
  return result;
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates) {
  std::vector<std::string> matches = closestMatches(word, candidates);
  if (matches.empty()) return {};
  std::string hint = " (did you mean ";
  for (size_t i = 0; i < matches.size(); ++i) {
    if (i > 0) hint += (i + 1 == matches.size()) ? " or " : ", ";
    hint += '"' + matches[i] + '"';
  }
  return hint + "?)";
}

}  // namespace femto
