// Number: the one rule for what counts as a number in anything a user writes (dictionaries,
// tables, values files): the whole token is a finite decimal number. "0,9", "1.5.3", "1e",
// "nan", "inf", "0x10" and "2m" are not numbers, and 1e400 is not infinity.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace friction {

/// The value of text if all of it is a decimal number (optional sign, digits with at most one
/// point, optional exponent) within the range of a double, else nullopt. A value below the
/// smallest double (1e-400) is nullopt too: silently reading it as 0 would hide a typo in an
/// exponent just as reading 1e400 as infinity would.
std::optional<double> parseNumber(std::string_view text);

/// Why text (not a number by parseNumber) is not one, as words to follow it in a message; ""
/// when text does not look like an attempt at a number (a plain word). E.g. "0,9" gives "has a
/// decimal comma: write 0.9"; "1e400" gives "is out of the range of a double (...)".
std::string whyNotANumber(std::string_view text);

}  // namespace friction
