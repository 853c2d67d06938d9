// "Did you mean ...?" helpers for error messages: the nearest word, offered only when it is
// near enough to be a typo of the word written.
#pragma once

#include <string>
#include <vector>

namespace friction {

/// Typing distance between a and b: insertions, deletions, substitutions and swaps of two
/// adjacent letters cost 1 each (the optimal-string-alignment distance); letter case is
/// ignored. "tolerence"/"tolerance" and "fractrues"/"fractures" are 1 apart.
std::size_t editDistance(const std::string& a, const std::string& b);

/// The largest distance at which a candidate still counts as a typo of a word of n letters:
/// max(1, n/3). Up to one slip per three letters leaves two thirds of the word in place; at
/// larger distances unrelated names of the same length match ("tolerance"/"zeta" are 7 apart,
/// "adjoint"/"exact" 6), and a suggestion that has nothing to do with the word misleads.
std::size_t typoDistance(std::size_t n);

/// The candidate nearest to word (the first on ties) if it is within typoDistance of word,
/// else "".
std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates);

/// "; did you mean 'x'?" for closestMatch(word, candidates), or "" when no candidate is near.
std::string suggestionText(const std::string& word, const std::vector<std::string>& candidates);

/// A number as a message shows it: the shortest round-trip text ("1e-07", "0.25").
std::string formatNumber(double x);

/// "a, b, c"
std::string joinWords(const std::vector<std::string>& words, const std::string& sep = ", ");

}  // namespace friction
