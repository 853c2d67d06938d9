// Number: strict parsing of user-written numbers, see Number.hpp.
#include "friction/dict/Number.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

namespace friction {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

/// text without one leading sign.
std::string_view unsigned_(std::string_view text) {
  if (!text.empty() && (text[0] == '+' || text[0] == '-')) text.remove_prefix(1);
  return text;
}

/// True if text starts the way a decimal number does after its sign: a digit, or a point and
/// a digit. from_chars would also take "inf" and "nan", which are not finite numbers.
bool startsNumeric(std::string_view body) {
  return !body.empty() &&
         (isDigit(body[0]) || (body.size() > 1 && body[0] == '.' && isDigit(body[1])));
}

std::string lower(std::string_view s) {
  std::string l(s);
  for (char& c : l)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return l;
}

}  // namespace

std::optional<double> parseNumber(std::string_view text) {
  const std::string_view body = unsigned_(text);
  if (!startsNumeric(body)) return std::nullopt;
  // from_chars takes '-' but not '+'; the body has no sign left, so "+-1" fails here.
  const char* first = text[0] == '+' ? body.data() : text.data();
  const char* last = text.data() + text.size();
  double x = 0;
  const auto r = std::from_chars(first, last, x);
  if (r.ec != std::errc() || r.ptr != last || !std::isfinite(x)) return std::nullopt;
  return x;
}

std::string whyNotANumber(std::string_view text) {
  const std::string_view body = unsigned_(text);
  const std::string l = lower(body);
  if (l == "nan" || l == "inf" || l == "infinity")
    return "is not a finite number (nan and inf are not accepted)";
  if (l.size() > 2 && l[0] == '0' && l[1] == 'x')
    return "is hexadecimal: write the number in decimal";
  if (!startsNumeric(body)) return "";
  const char* first = text[0] == '+' ? body.data() : text.data();
  const char* last = text.data() + text.size();
  double x = 0;
  const auto r = std::from_chars(first, last, x);
  if (r.ec == std::errc::result_out_of_range)
    return "is out of the range of a double (nonzero magnitudes from 4.9e-324 to 1.8e308)";
  if (text.find(',') != std::string_view::npos) {
    std::string dotted(text);
    for (char& c : dotted)
      if (c == ',') c = '.';
    if (parseNumber(dotted)) return "has a decimal comma: write " + dotted;
  }
  const std::string_view prefix(text.data(), static_cast<std::size_t>(r.ptr - text.data()));
  const std::string_view rest(r.ptr, static_cast<std::size_t>(last - r.ptr));
  std::string why =
      "is the number '" + std::string(prefix) + "' followed by '" + std::string(rest) + "'";
  if (!rest.empty() && (rest[0] == 'e' || rest[0] == 'E'))
    why += " (an exponent needs digits, e.g. 1e-3)";
  else if (!rest.empty() && !isDigit(rest[0]) && rest[0] != '.' && rest[0] != ',')
    why += " (numbers are written without a unit: values are in SI units)";
  return why;
}

}  // namespace friction
