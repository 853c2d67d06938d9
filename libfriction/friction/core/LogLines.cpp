// LogLines: see LogLines.hpp.
#include "friction/core/LogLines.hpp"

#include <cstring>
#include <ctime>
#include <iomanip>
#include <sstream>

namespace friction {

int LineFlushBuffer::overflow(int c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  if (traits_type::eq_int_type(target_->sputc(traits_type::to_char_type(c)), traits_type::eof()))
    return traits_type::eof();
  if (c == '\n' && target_->pubsync() == -1) return traits_type::eof();
  return c;
}

std::streamsize LineFlushBuffer::xsputn(const char* s, std::streamsize n) {
  std::streamsize done = 0;
  while (done < n) {
    // Up to and including the next newline, then flush; the rest as it comes.
    const char* from = s + done;
    const void* nl = std::memchr(from, '\n', static_cast<std::size_t>(n - done));
    const std::streamsize length = nl ? static_cast<const char*>(nl) - from + 1 : n - done;
    const std::streamsize put = target_->sputn(from, length);
    done += put;
    if (put < length) return done;  // the target refused part of it
    if (nl && target_->pubsync() == -1) return done;
  }
  return done;
}

FlushEachLine::FlushEachLine(std::ostream& stream)
    : stream_(stream), previous_(stream.rdbuf()), buffer_(stream.rdbuf()) {
  const auto state = stream_.rdstate();
  stream_.rdbuf(&buffer_);
  stream_.clear(state);  // rdbuf() clears the state: keep the caller's
}

FlushEachLine::~FlushEachLine() {
  stream_.flush();
  const auto state = stream_.rdstate();
  stream_.rdbuf(previous_);
  stream_.clear(state);
}

std::string localDateTime() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  std::ostringstream s;
  s << std::put_time(&local, "%Y-%m-%d %H:%M:%S");
  return s.str();
}

std::string formatSeconds(double seconds) {
  std::ostringstream s;
  s << std::setprecision(3) << seconds << " s";
  return s.str();
}

}  // namespace friction
