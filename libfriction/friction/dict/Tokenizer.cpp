// Tokenizer: lexical rules of OpenFOAM-syntax dictionaries, see Tokenizer.hpp.
//
// Speed matters here: split-mesh files hold lists of ~10^6 numbers. Every character is looked
// at once, character classes come from a table, and numbers are converted with
// std::from_chars straight from the input (no intermediate string).
#include "friction/dict/Tokenizer.hpp"

#include "friction/dict/Number.hpp"

#include <array>
#include <charconv>
#include <stdexcept>
#include <system_error>

namespace friction::detail {

namespace {

enum CharClass : unsigned char { kWord = 1, kSpace = 2, kDigit = 4 };

constexpr std::array<unsigned char, 256> makeClasses() {
  std::array<unsigned char, 256> t{};
  for (int c = 0; c < 256; ++c) t[c] = kWord;
  for (char c : {' ', '\t', '\n', '\r', '\f', '\v'}) t[static_cast<unsigned char>(c)] = kSpace;
  for (char c : {'"', ';', '{', '}', '(', ')'}) t[static_cast<unsigned char>(c)] = 0;
  for (int c = '0'; c <= '9'; ++c) t[c] = kWord | kDigit;
  return t;
}
constexpr std::array<unsigned char, 256> kClasses = makeClasses();

inline unsigned char classOf(char c) { return kClasses[static_cast<unsigned char>(c)]; }
inline bool isSpace(char c) { return classOf(c) & kSpace; }
inline bool isDigit(char c) { return classOf(c) & kDigit; }

}  // namespace

bool isWordChar(char c) { return classOf(c) & kWord; }

bool isSafeWord(std::string_view s) {
  if (s.empty()) return false;
  const auto letter = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
  };
  if (!letter(s[0])) return false;
  for (char c : s)
    if (!letter(c) && !isDigit(c) && std::string_view(".:<>,-+").find(c) == std::string_view::npos)
      return false;
  return true;
}

std::string shortestNumber(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string quoted(std::string_view s) {
  // OpenFOAM's reader toggles an escape flag at each backslash; a quote or newline after an
  // odd run of backslashes is escaped (the last backslash dropped), after an even run it ends
  // the string. So a quote or newline is written after one more backslash, which needs an even
  // run before it in s; an odd run right before a quote, a newline or the end cannot be written.
  std::string q = "\"";
  std::size_t run = 0;
  bool writable = true;
  for (char c : s) {
    if (c == '"' || c == '\n') {
      writable = writable && run % 2 == 0;
      q += '\\';
    }
    run = c == '\\' ? run + 1 : 0;
    q += c;
  }
  if (!writable || run % 2)
    throw std::invalid_argument("the string '" + std::string(s) +
                                "' cannot be written in OpenFOAM syntax (an odd number of "
                                "backslashes before a quote, a newline or its end)");
  return q + '"';
}

Tokenizer::Tokenizer(std::string_view text, const std::string& file)
    : p_(text.data()), end_(text.data() + text.size()), file_(file) {
  // Editors on Windows may start a UTF-8 file with a byte-order mark; it is no part of the
  // text (left in, it would become part of the first key).
  if (text.substr(0, 3) == "\xEF\xBB\xBF") p_ += 3;
}

void Tokenizer::fail(int line, const std::string& message) const {
  throw InputError(SourceLocation{file_, line}, message);
}

void Tokenizer::skipSpaceAndComments() {
  while (p_ < end_) {
    const char c = *p_;
    if (isSpace(c)) {
      if (c == '\n') ++line_;
      ++p_;
    } else if (c == '/' && p_ + 1 < end_ && p_[1] == '/') {
      while (p_ < end_ && *p_ != '\n') ++p_;
    } else if (c == '/' && p_ + 1 < end_ && p_[1] == '*') {
      const int start = line_;
      p_ += 2;
      for (;;) {
        if (p_ + 1 >= end_)
          fail(start, "unterminated comment: expected '*/' to close the '/*' opened here");
        if (p_[0] == '*' && p_[1] == '/') break;
        if (*p_ == '\n') ++line_;
        ++p_;
      }
      p_ += 2;
    } else {
      return;
    }
  }
}

bool Tokenizer::peekPunct(char c) {
  skipSpaceAndComments();
  return p_ < end_ && *p_ == c;
}

bool Tokenizer::sizedListFollows() const {
  if (p_ < end_ && *p_ == '(') return true;
  bool newline = false;
  for (const char* q = p_; q < end_; ++q) {
    if (*q == '\n')
      newline = true;
    else if (!isSpace(*q))
      return newline && *q == '(';
  }
  return false;
}

Token Tokenizer::readString() {
  Token t;
  t.type = Token::Type::String;
  t.line = line_;
  const char* start = ++p_;
  // Fast path: no escapes, the contents are one copy of the input.
  while (p_ < end_ && *p_ != '"' && *p_ != '\\' && *p_ != '\n') ++p_;
  t.string.assign(start, p_);
  // OpenFOAM's escapes: after an odd run of backslashes a quote or newline is part of the
  // string and replaces the last backslash; every other backslash stays as written.
  bool escaped = false;
  for (;; ++p_) {
    if (p_ >= end_)
      fail(t.line, "unterminated string: expected '\"' to close the string opened here");
    const char c = *p_;
    if ((c == '"' || c == '\n') && escaped) {
      if (c == '\n') ++line_;
      t.string.back() = c;
      escaped = false;
      continue;
    }
    if (c == '"') break;
    if (c == '\n')
      fail(t.line,
           "unterminated string: expected '\"' before the end of the line (a string "
           "continues on the next line only after a '\\')");
    escaped = c == '\\' && !escaped;
    t.string += c;
  }
  ++p_;
  return t;
}

Token Tokenizer::next() {
  skipSpaceAndComments();
  Token t;
  t.line = line_;
  if (p_ >= end_) return t;

  const char c = *p_;
  if (c == '"') return readString();
  if (!isWordChar(c)) {
    t.type = Token::Type::Punct;
    t.text = std::string_view(p_++, 1);
    return t;
  }

  // A word-like run: a word, a number, $variable or #directive. A '/' followed by '/' or '*'
  // starts a comment and so ends the run ("1// note").
  const char* start = p_;
  if (c == '$' && p_ + 1 < end_ && p_[1] == '{') {
    // ${name}: the braces delimit the name.
    const char* q = p_ + 2;
    while (q < end_ && *q != '}' && isWordChar(*q)) ++q;
    if (q >= end_ || *q != '}') fail(line_, "expected '}' to close '${'");
    t.type = Token::Type::Variable;
    t.text = std::string_view(p_ + 2, static_cast<std::size_t>(q - p_ - 2));
    p_ = q + 1;
    return t;
  }
  ++p_;
  while (p_ < end_ && isWordChar(*p_) &&
         !(*p_ == '/' && p_ + 1 < end_ && (p_[1] == '/' || p_[1] == '*')))
    ++p_;
  t.text = std::string_view(start, static_cast<std::size_t>(p_ - start));

  if (c == '$' || c == '#') {
    t.type = c == '$' ? Token::Type::Variable : Token::Type::Directive;
    t.text.remove_prefix(1);
    return t;
  }

  const bool numberStart = isDigit(c) || ((c == '-' || c == '+' || c == '.') && t.text.size() > 1 &&
                                          (isDigit(t.text[1]) || (t.text[1] == '.' && c != '.')));
  t.type = Token::Type::Word;
  if (numberStart) {
    const char* first = c == '+' ? start + 1 : start;
    const auto r = std::from_chars(first, p_, t.number);
    if (r.ptr == p_) {
      if (r.ec == std::errc::result_out_of_range)
        fail(t.line, "number " + std::string(t.text) + " " + whyNotANumber(t.text));
      if (r.ec == std::errc()) {
        t.type = Token::Type::Number;
        t.plainInteger = true;
        for (char d : t.text) t.plainInteger = t.plainInteger && isDigit(d);
      }
    }
  }
  return t;
}

}  // namespace friction::detail
