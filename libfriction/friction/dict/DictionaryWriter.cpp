// DictionaryWriter: OpenFOAM-syntax output that both Dictionary::read and OpenFOAM's
// foamDictionary read back, and the atomic file write. See DictionaryWriter.hpp.
//
// Layout, chosen to keep files diff-friendly: keys padded to a column as OpenFOAM does, short
// lists on one line ("3(1 2 3)"), long lists as OpenFOAM writes them (size, then '(' on its own
// line, one item per line), so that changing one item changes one line.
#include "friction/dict/DictionaryWriter.hpp"

#include "friction/core/AtomicFile.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "friction/core/InputError.hpp"
#include "friction/dict/Tokenizer.hpp"

namespace friction {

namespace fs = std::filesystem;

namespace {

constexpr int kIndent = 4;
constexpr std::size_t kKeyColumn = 12;
// A list goes on one line when it has at most this many items and fits in kOneLineChars.
constexpr std::size_t kOneLineItems = 10;
constexpr std::size_t kOneLineChars = 72;
constexpr double kLargestNumber = 1e300;

void checkWord(const std::string& word, const char* what) {
  if (!detail::isSafeWord(word))
    throw std::invalid_argument("DictionaryWriter: " + std::string(what) + " '" + word +
                                "' is not a valid OpenFOAM word (letters, digits and _ . : < > , "
                                "- +, starting with a letter or '_')");
}

}  // namespace

DictionaryWriter::DictionaryWriter(const std::string& className, const std::string& object,
                                   const std::string& note) {
  out_ << "// OpenFOAM-syntax dictionary written by libfriction\n";
  beginDict("FoamFile");
  entryRaw("version", "2.0");
  entryWord("format", "ascii");
  entryWord("class", className);
  if (detail::isSafeWord(object))
    entryWord("object", object);
  else
    entryString("object", object);
  if (!note.empty()) entryString("note", note);
  endDict();
  out_ << '\n';
}

void DictionaryWriter::setPrecision(int digits) {
  if (digits < 1 || digits > 17)
    throw std::invalid_argument("DictionaryWriter::setPrecision: " + std::to_string(digits) +
                                " digits (expected 1 to 17)");
  precision_ = digits;
}

void DictionaryWriter::indent() {
  for (int i = 0; i < depth_ * kIndent; ++i) out_ << ' ';
}

std::string DictionaryWriter::number(double x) const {
  // OpenFOAM's reader fails on inf, nan and magnitudes above its VGREAT = 1e300.
  if (!(std::fabs(x) <= kLargestNumber))
    throw std::domain_error("DictionaryWriter: cannot write " + detail::shortestNumber(x) +
                            ": OpenFOAM reads numbers up to 1e300 in magnitude, no inf or nan");
  // At full precision the shortest text that reads back exactly: 0.1 rather than
  // 0.10000000000000001, with the same value.
  if (precision_ >= 17) return detail::shortestNumber(x);
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", precision_, x);
  return buf;
}

void DictionaryWriter::beginDict(const std::string& key) {
  checkWord(key, "key");
  indent();
  out_ << key << '\n';
  indent();
  out_ << "{\n";
  ++depth_;
}

void DictionaryWriter::endDict() {
  if (depth_ == 0) throw std::logic_error("DictionaryWriter::endDict: no dictionary is open");
  --depth_;
  indent();
  out_ << "}\n";
}

namespace {

/// "key" padded to the value column, after the indentation.
void writeKey(std::ostream& out, int depth, const std::string& key) {
  checkWord(key, "key");
  out << std::string(static_cast<std::size_t>(depth * kIndent), ' ') << key;
  out << std::string(key.size() < kKeyColumn ? kKeyColumn - key.size() : 1, ' ');
}

/// Writes "key N(a b c);" or the long form; item(i, buf) appends item i to buf.
template <typename ItemFn>
void writeList(std::ostream& out, int depth, const std::string& key, std::size_t n, ItemFn item) {
  writeKey(out, depth, key);
  std::string buf;
  if (n <= kOneLineItems) {
    for (std::size_t i = 0; i < n; ++i) {
      if (i) buf += ' ';
      item(i, buf);
    }
    if (buf.size() <= kOneLineChars) {
      out << n << '(' << buf << ");\n";
      return;
    }
  }
  const std::string pad(static_cast<std::size_t>(depth * kIndent), ' ');
  const std::string itemPad = pad + std::string(kIndent, ' ');
  out << n << '\n' << pad << "(\n";
  for (std::size_t i = 0; i < n; ++i) {
    buf = itemPad;
    item(i, buf);
    buf += '\n';
    out << buf;
  }
  out << pad << ");\n";
}

}  // namespace

void DictionaryWriter::entry(const std::string& key, double value) { entryRaw(key, number(value)); }

void DictionaryWriter::entry(const std::string& key, int value) {
  entryRaw(key, std::to_string(value));
}

void DictionaryWriter::entry(const std::string& key, long value) {
  entryRaw(key, std::to_string(value));
}

void DictionaryWriter::entryWord(const std::string& key, const std::string& word) {
  checkWord(word, "word");
  entryRaw(key, word);
}

void DictionaryWriter::entryString(const std::string& key, const std::string& text) {
  entryRaw(key, detail::quoted(text));
}

void DictionaryWriter::entry(const std::string& key, const Vector2& value) {
  entryRaw(key, "(" + number(value.x()) + " " + number(value.y()) + ")");
}

void DictionaryWriter::entry(const std::string& key, const std::vector<double>& list) {
  writeList(out_, depth_, key, list.size(),
            [&](std::size_t i, std::string& buf) { buf += number(list[i]); });
}

void DictionaryWriter::entry(const std::string& key, const std::vector<int>& list) {
  writeList(out_, depth_, key, list.size(),
            [&](std::size_t i, std::string& buf) { buf += std::to_string(list[i]); });
}

void DictionaryWriter::entry(const std::string& key, const std::vector<Vector2>& list) {
  writeList(out_, depth_, key, list.size(), [&](std::size_t i, std::string& buf) {
    buf += '(';
    buf += number(list[i].x());
    buf += ' ';
    buf += number(list[i].y());
    buf += ')';
  });
}

void DictionaryWriter::entry(const std::string& key, const std::vector<Point>& list) {
  writeList(out_, depth_, key, list.size(), [&](std::size_t i, std::string& buf) {
    buf += '(';
    for (int c = 0; c < 3; ++c) {
      if (c) buf += ' ';
      buf += number(list[i][c]);
    }
    buf += ')';
  });
}

void DictionaryWriter::entryWords(const std::string& key, const std::vector<std::string>& words) {
  for (const std::string& w : words) checkWord(w, "word");
  writeList(out_, depth_, key, words.size(),
            [&](std::size_t i, std::string& buf) { buf += words[i]; });
}

template <std::size_t N>
void DictionaryWriter::entry(const std::string& key,
                             const std::vector<std::array<int, N>>& tuples) {
  writeList(out_, depth_, key, tuples.size(), [&](std::size_t i, std::string& buf) {
    buf += '(';
    for (std::size_t k = 0; k < N; ++k) {
      if (k) buf += ' ';
      buf += std::to_string(tuples[i][k]);
    }
    buf += ')';
  });
}

template void DictionaryWriter::entry<2>(const std::string&,
                                         const std::vector<std::array<int, 2>>&);
template void DictionaryWriter::entry<3>(const std::string&,
                                         const std::vector<std::array<int, 3>>&);
template void DictionaryWriter::entry<4>(const std::string&,
                                         const std::vector<std::array<int, 4>>&);

void DictionaryWriter::entryRaw(const std::string& key, const std::string& raw) {
  writeKey(out_, depth_, key);
  out_ << raw << ";\n";
}

void DictionaryWriter::comment(const std::string& text) {
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = text.find('\n', start);
    indent();
    out_ << "// " << text.substr(start, end - start) << '\n';
    if (end == std::string::npos) break;
    start = end + 1;
  }
}

std::string DictionaryWriter::str() const {
  if (depth_ != 0)
    throw std::logic_error("DictionaryWriter::str: " + std::to_string(depth_) +
                           " dictionaries still open (missing endDict)");
  return out_.str();
}

void DictionaryWriter::writeAtomic(const std::string& path) const { writeTextAtomic(path, str()); }

}  // namespace friction
