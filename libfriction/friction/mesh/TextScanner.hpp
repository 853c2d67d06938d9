// TextScanner: line-by-line reading of a text file held in memory, for the mesh readers.
// Private to friction/mesh (not part of the library's interface).
//
// Mesh files can hold millions of lines, so the scanner does no allocation per line:
// lines are string_views into the file's text, numbers are parsed with std::from_chars,
// and messages are only built when something is wrong. Every failure is an InputError at
// file:line.
#pragma once

#include <string>
#include <string_view>

#include "friction/core/InputError.hpp"

namespace friction {

/// Cursor over the whitespace-separated fields of one line.
class LineFields {
 public:
  LineFields(const char* begin, const char* end) : pos_(begin), end_(end) {}

  /// Next field as an integer; false if there is none or it is not an integer.
  bool integer(long long& value);
  /// Next field as an integer, as integer(); when it is a whole number beyond the range of
  /// long long, false with `overflow` set and `text` the field (nothing consumed otherwise).
  bool integer(long long& value, bool& overflow, std::string_view& text);
  /// Next field as a real number (NaN and Inf are parsed: the caller decides about them).
  bool real(double& value);
  /// Next field as text; false if there is none.
  bool token(std::string_view& value);
  /// Skip the next field, whatever it is; false if there is none.
  bool skip();
  /// True if nothing but whitespace is left.
  bool done();
  /// The rest of the line, leading whitespace removed.
  std::string_view rest();

 private:
  void skipSpace();

  const char* pos_;
  const char* end_;
};

class TextScanner {
 public:
  /// `path` is for messages only; `text` is the whole file.
  TextScanner(std::string path, std::string text);

  const std::string& path() const { return path_; }
  const std::string& text() const { return text_; }

  /// Move to the next line that is not blank; false at the end of the file.
  bool next();
  /// The current line without trailing whitespace (and without a trailing '\r').
  std::string_view line() const {
    return {lineBegin_, static_cast<std::size_t>(lineEnd_ - lineBegin_)};
  }
  LineFields fields() const { return {lineBegin_, lineEnd_}; }
  /// 1-based number of the current line; after next() returned false, the number of the
  /// last line of the file (where "unexpected end of file" is reported).
  int lineNumber() const { return lineNumber_; }
  /// The current line shortened for a message.
  std::string quotedLine() const;

  /// Throw InputError at the current line.
  [[noreturn]] void fail(const std::string& message) const;
  /// Throw InputError at the given line (0 = the file as a whole).
  [[noreturn]] void failAt(int line, const std::string& message) const;

 private:
  std::string path_;
  std::string text_;
  const char* pos_;
  const char* lineBegin_;
  const char* lineEnd_;
  int lineNumber_ = 0;
};

}  // namespace friction
