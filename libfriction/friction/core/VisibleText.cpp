// VisibleText: escapes and the invisible characters of user text (VisibleText.hpp).
#include "friction/core/VisibleText.hpp"

#include <cstdio>

namespace friction {

namespace {

struct Named {
  char32_t code;
  const char* name;
};

// The characters that look like nothing or like a plain space. Letters of any script are not
// here: they are visible.
constexpr Named kInvisible[] = {
    {0x00A0, "NO-BREAK SPACE"},
    {0x00AD, "SOFT HYPHEN"},
    {0x034F, "COMBINING GRAPHEME JOINER"},
    {0x061C, "ARABIC LETTER MARK"},
    {0x115F, "HANGUL CHOSEONG FILLER"},
    {0x1160, "HANGUL JUNGSEONG FILLER"},
    {0x1680, "OGHAM SPACE MARK"},
    {0x180E, "MONGOLIAN VOWEL SEPARATOR"},
    {0x2000, "EN QUAD"},
    {0x2001, "EM QUAD"},
    {0x2002, "EN SPACE"},
    {0x2003, "EM SPACE"},
    {0x2004, "THREE-PER-EM SPACE"},
    {0x2005, "FOUR-PER-EM SPACE"},
    {0x2006, "SIX-PER-EM SPACE"},
    {0x2007, "FIGURE SPACE"},
    {0x2008, "PUNCTUATION SPACE"},
    {0x2009, "THIN SPACE"},
    {0x200A, "HAIR SPACE"},
    {0x200B, "ZERO WIDTH SPACE"},
    {0x200C, "ZERO WIDTH NON-JOINER"},
    {0x200D, "ZERO WIDTH JOINER"},
    {0x200E, "LEFT-TO-RIGHT MARK"},
    {0x200F, "RIGHT-TO-LEFT MARK"},
    {0x2028, "LINE SEPARATOR"},
    {0x2029, "PARAGRAPH SEPARATOR"},
    {0x202A, "LEFT-TO-RIGHT EMBEDDING"},
    {0x202B, "RIGHT-TO-LEFT EMBEDDING"},
    {0x202C, "POP DIRECTIONAL FORMATTING"},
    {0x202D, "LEFT-TO-RIGHT OVERRIDE"},
    {0x202E, "RIGHT-TO-LEFT OVERRIDE"},
    {0x202F, "NARROW NO-BREAK SPACE"},
    {0x205F, "MEDIUM MATHEMATICAL SPACE"},
    {0x2060, "WORD JOINER"},
    {0x2061, "FUNCTION APPLICATION"},
    {0x2062, "INVISIBLE TIMES"},
    {0x2063, "INVISIBLE SEPARATOR"},
    {0x2064, "INVISIBLE PLUS"},
    {0x2066, "LEFT-TO-RIGHT ISOLATE"},
    {0x2067, "RIGHT-TO-LEFT ISOLATE"},
    {0x2068, "FIRST STRONG ISOLATE"},
    {0x2069, "POP DIRECTIONAL ISOLATE"},
    {0x3000, "IDEOGRAPHIC SPACE"},
    {0x3164, "HANGUL FILLER"},
    {0xFEFF, "ZERO WIDTH NO-BREAK SPACE (byte-order mark)"},
};

const char* invisibleName(char32_t c) {
  for (const Named& n : kInvisible)
    if (n.code == c) return n.name;
  return nullptr;
}

bool isControl(unsigned char c) { return c < 0x20 || c == 0x7F; }

/// The code point of the well-formed UTF-8 sequence at s[i] (its length in len), or false.
bool decode(std::string_view s, std::size_t i, char32_t& code, std::size_t& len) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[i + k]); };
  const unsigned char c = b(0);
  if (c < 0x80) {
    code = c;
    len = 1;
    return true;
  }
  len = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
  if (len == 0 || i + len > s.size()) return false;
  code = c & (0xFF >> (len + 1));
  for (std::size_t k = 1; k < len; ++k) {
    if ((b(k) & 0xC0) != 0x80) return false;
    code = (code << 6) | (b(k) & 0x3F);
  }
  return true;
}

}  // namespace

std::string escapeControl(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (!isControl(c) || c == '\n' || c == '\t') {
      out += ch;
    } else if (c == 0) {
      out += "\\0";
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      out += buf;
    }
  }
  return out;
}

std::string InvisibleChar::name() const {
  char buf[16];
  std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(code));
  const char* n = invisibleName(code);
  if (n) return std::string(buf) + " " + n;
  return std::string(buf) + (code == 0 ? " NUL" : " control character");
}

std::vector<InvisibleChar> invisibleCharacters(std::string_view s) {
  std::vector<InvisibleChar> found;
  for (std::size_t i = 0; i < s.size();) {
    char32_t code = 0;
    std::size_t len = 0;
    if (!decode(s, i, code, len)) {
      ++i;  // not UTF-8: a byte of another encoding, visible as such
      continue;
    }
    if ((code < 0x80 && isControl(static_cast<unsigned char>(code))) || invisibleName(code))
      found.push_back({i, len, code});
    i += len;
  }
  return found;
}

std::string withoutInvisible(std::string_view s) {
  std::string out;
  std::size_t from = 0;
  for (const InvisibleChar& c : invisibleCharacters(s)) {
    out.append(s.substr(from, c.offset - from));
    from = c.offset + c.length;
  }
  out.append(s.substr(from));
  return out;
}

std::string showInvisible(std::string_view s) {
  std::string out;
  std::size_t from = 0;
  for (const InvisibleChar& c : invisibleCharacters(s)) {
    out.append(s.substr(from, c.offset - from));
    char buf[16];
    std::snprintf(buf, sizeof buf, "<U+%04X>", static_cast<unsigned>(c.code));
    out += buf;
    from = c.offset + c.length;
  }
  out.append(s.substr(from));
  return out;
}

}  // namespace friction
