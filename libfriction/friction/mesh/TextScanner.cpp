// TextScanner and LineFields: allocation-free line and field reading for the mesh readers.
#include "friction/mesh/TextScanner.hpp"

#include <charconv>
#include <cstring>

namespace friction {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

}  // namespace

void LineFields::skipSpace() {
  while (pos_ < end_ && isSpace(*pos_)) ++pos_;
}

bool LineFields::integer(long long& value) {
  bool overflow = false;
  std::string_view text;
  return integer(value, overflow, text);
}

bool LineFields::integer(long long& value, bool& overflow, std::string_view& text) {
  skipSpace();
  const char* p = pos_;
  // from_chars rejects a leading '+', which C's printf never writes but people do.
  if (p < end_ && *p == '+' && p + 1 < end_ && p[1] != '-') ++p;
  const auto [next, ec] = std::from_chars(p, end_, value);
  const bool whole = next > p && (next == end_ || isSpace(*next));
  overflow = ec == std::errc::result_out_of_range && whole;
  if (ec != std::errc() || !whole) {
    if (overflow) text = std::string_view(pos_, static_cast<std::size_t>(next - pos_));
    return false;
  }
  pos_ = next;
  return true;
}

bool LineFields::real(double& value) {
  skipSpace();
  const char* p = pos_;
  if (p < end_ && *p == '+' && p + 1 < end_ && p[1] != '-') ++p;
  const auto [next, ec] = std::from_chars(p, end_, value);
  if (ec != std::errc() || (next < end_ && !isSpace(*next))) return false;
  pos_ = next;
  return true;
}

bool LineFields::token(std::string_view& value) {
  skipSpace();
  if (pos_ == end_) return false;
  const char* b = pos_;
  while (pos_ < end_ && !isSpace(*pos_)) ++pos_;
  value = std::string_view(b, static_cast<std::size_t>(pos_ - b));
  return true;
}

bool LineFields::skip() {
  std::string_view ignored;
  return token(ignored);
}

bool LineFields::done() {
  skipSpace();
  return pos_ == end_;
}

std::string_view LineFields::rest() {
  skipSpace();
  return {pos_, static_cast<std::size_t>(end_ - pos_)};
}

TextScanner::TextScanner(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)) {
  pos_ = text_.data();
  lineBegin_ = lineEnd_ = pos_;
  // A UTF-8 byte-order mark is not part of the first token.
  if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ += 3;
}

bool TextScanner::next() {
  const char* end = text_.data() + text_.size();
  while (pos_ < end) {
    const char* nl = static_cast<const char*>(std::memchr(pos_, '\n', end - pos_));
    const char* lineEnd = nl ? nl : end;
    ++lineNumber_;
    const char* b = pos_;
    pos_ = nl ? nl + 1 : end;
    while (b < lineEnd && (isSpace(*b))) ++b;
    if (b == lineEnd) continue;  // blank line
    const char* e = lineEnd;
    while (e > b && isSpace(e[-1])) --e;
    lineBegin_ = b;
    lineEnd_ = e;
    return true;
  }
  lineBegin_ = lineEnd_ = end;
  return false;
}

std::string TextScanner::quotedLine() const {
  constexpr std::size_t maxLength = 60;
  std::string_view l = line();
  std::string s = "\"" + std::string(l.substr(0, maxLength));
  if (l.size() > maxLength) s += "...";
  return s + "\"";
}

void TextScanner::fail(const std::string& message) const { failAt(lineNumber_, message); }

void TextScanner::failAt(int line, const std::string& message) const {
  throw InputError(SourceLocation{path_, line}, message);
}

}  // namespace friction
