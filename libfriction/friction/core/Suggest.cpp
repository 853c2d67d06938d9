// "Did you mean" helpers and number formatting for messages: see Suggest.hpp.
#include "friction/core/Suggest.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace friction {

std::size_t editDistance(const std::string& a, const std::string& b) {
  const auto lower = [](char c) {
    return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
  };
  // Three rows of the dynamic programme: a swap looks two rows back.
  std::vector<std::size_t> prev2(b.size() + 1), prev(b.size() + 1), row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const char ai = lower(a[i - 1]), bj = lower(b[j - 1]);
      row[j] = std::min({prev[j] + 1, row[j - 1] + 1, prev[j - 1] + (ai == bj ? 0 : 1)});
      if (i > 1 && j > 1 && ai == lower(b[j - 2]) && lower(a[i - 2]) == bj)
        row[j] = std::min(row[j], prev2[j - 2] + 1);
    }
    std::swap(prev2, prev);
    std::swap(prev, row);
  }
  return prev[b.size()];
}

std::size_t typoDistance(std::size_t n) { return std::max<std::size_t>(1, n / 3); }

std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string* best = nullptr;
  std::size_t bestD = 0;
  for (const std::string& c : candidates) {
    const std::size_t d = editDistance(word, c);
    if (!best || d < bestD) best = &c, bestD = d;
  }
  return best && bestD <= typoDistance(word.size()) ? *best : "";
}

std::string suggestionText(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string best = closestMatch(word, candidates);
  return best.empty() ? "" : "; did you mean '" + best + "'?";
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
