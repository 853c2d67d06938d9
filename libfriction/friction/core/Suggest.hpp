// "Did you mean ...?" helpers for error messages: nearest word by edit distance.
#pragma once

#include <string>
#include <vector>

namespace friction {

/// Levenshtein distance between a and b.
std::size_t editDistance(const std::string& a, const std::string& b);

/// "; did you mean 'x'?" for the nearest candidate within a reasonable distance, else "".
std::string suggestionText(const std::string& word, const std::vector<std::string>& candidates);

/// A number as a message shows it: the shortest round-trip text ("1e-07", "0.25").
std::string formatNumber(double x);

/// "a, b, c"
std::string joinWords(const std::vector<std::string>& words, const std::string& sep = ", ");

}  // namespace friction
