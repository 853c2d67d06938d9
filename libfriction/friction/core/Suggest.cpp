#include "friction/core/Suggest.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace friction {

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string suggestionText(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string* best = nullptr;
  std::size_t bestD = 0;
  for (const std::string& c : candidates) {
    const std::size_t d = editDistance(word, c);
    if (!best || d < bestD) best = &c, bestD = d;
  }
  // A suggestion further than about half the word away is noise, not help.
  if (!best || bestD > std::max<std::size_t>(2, word.size() / 2)) return "";
  return "; did you mean '" + *best + "'?";
}

std::string formatNumber(double x) {
  char buffer[32];
  for (int digits = 6; digits <= 17; ++digits) {  // the fewest digits that read back exactly
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
    if (std::strtod(buffer, nullptr) == x) break;
  }
  return buffer;
}

std::string joinWords(const std::vector<std::string>& words, const std::string& sep) {
  std::string s;
  for (std::size_t i = 0; i < words.size(); ++i) s += (i ? sep : "") + words[i];
  return s;
}

}  // namespace friction
