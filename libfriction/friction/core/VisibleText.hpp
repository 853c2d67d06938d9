// VisibleText: user text shown in messages so that what cannot be seen can be read. A control
// byte (a NUL, \x01) would cut a message short or garble the terminal; an invisible Unicode
// character (a zero-width space, a no-break space pasted from a web page or a word processor)
// makes "nu" and "nu\u200b" look the same while they are different keys.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace friction {

/// s with control bytes written as escapes: NUL as \0, others (and DEL) as \xNN. Newlines and
/// tabs stay: messages use them.
std::string escapeControl(std::string_view s);

/// One invisible character of a UTF-8 text: a control character, a space other than ' ' (no-
/// break, thin, ideographic ...), or a zero-width or direction mark.
struct InvisibleChar {
  std::size_t offset = 0;  ///< byte offset in the text
  std::size_t length = 0;  ///< bytes
  char32_t code = 0;
  /// "U+200B ZERO WIDTH SPACE"
  std::string name() const;
};

/// The invisible characters of s, in order.
std::vector<InvisibleChar> invisibleCharacters(std::string_view s);
/// s without its invisible characters.
std::string withoutInvisible(std::string_view s);
/// s with each invisible character written as <U+200B> (control bytes too): for a word or key
/// quoted in a message.
std::string showInvisible(std::string_view s);

}  // namespace friction
