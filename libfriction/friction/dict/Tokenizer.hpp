// Tokenizer: the lexical rules of OpenFOAM-syntax dictionaries in one place (private to dict/).
// The reader (Dictionary.cpp) splits text into tokens with it in one linear pass; the writer
// and Value::str use the same rules to produce text that reads back unchanged.
//
// Tokens: words, numbers, "strings", $variables, #directives and the punctuation ; { } ( ).
// Comments (// to end of line, /* ... */) and whitespace separate tokens. A token never owns
// a copy of the text except a string with escapes; words and numbers are views into the input.
#pragma once

#include <string>
#include <string_view>

#include "friction/core/InputError.hpp"

namespace friction::detail {

struct Token {
  enum class Type { End, Word, Number, String, Variable, Directive, Punct };

  Type type = Type::End;
  /// Word or number as written; variable name without '$'; directive name without '#';
  /// the punctuation character. A view into the input text.
  std::string_view text;
  /// String contents with escapes resolved (Type::String only).
  std::string string;
  /// Value of a Type::Number token.
  double number = 0.0;
  /// True for a number written as plain digits (no sign, point or exponent): a list size.
  bool plainInteger = false;
  int line = 0;

  bool isPunct(char c) const { return type == Type::Punct && text[0] == c; }
};

/// Splits text into tokens. The text must outlive the tokenizer and its tokens.
class Tokenizer {
 public:
  /// file names the source in error messages.
  Tokenizer(std::string_view text, const std::string& file);

  /// The next token (Type::End at the end). Throws InputError at an unterminated comment or
  /// string, or a number out of the range of a double.
  Token next();
  /// True if the next token is the punctuation c (skips whitespace and comments, consumes
  /// nothing else).
  bool peekPunct(char c);
  /// Called right after a plain-integer token: true if a '(' follows that makes it the size
  /// of a list, either directly ("3(1 2 3)") or on a following line, as OpenFOAM writes long
  /// lists. "0 (0 0)" on one line stays a number followed by a list (a table row).
  bool sizedListFollows() const;
  /// Bytes not yet read, to cap reservations made from a list size given in the file.
  std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }

  const std::string& file() const { return file_; }
  [[noreturn]] void fail(int line, const std::string& message) const;

 private:
  void skipSpaceAndComments();
  Token readString();

  const char* p_;
  const char* end_;
  int line_ = 1;
  const std::string& file_;
};

/// True for characters that may appear in a word token (anything but whitespace, quotes,
/// ; { } ( ); a '/' that starts a comment also ends a word).
bool isWordChar(char c);
/// True if s reads back as one word token: letters, digits and _ . : < > , - + starting with a
/// letter or '_' (the words that OpenFOAM's reader also accepts).
bool isSafeWord(std::string_view s);
/// Shortest decimal text that reads back to exactly x (x finite).
std::string shortestNumber(double x);
/// s in double quotes, with '"' and newlines escaped the way OpenFOAM reads them back.
std::string quoted(std::string_view s);

}  // namespace friction::detail
