// Dictionary: the OpenFOAM-syntax reader (one pass over each file, see Tokenizer.hpp), the
// entry store with file:line and read flags, typed and range-checked access, and the check for
// entries the program never read. Grammar and semantics: Dictionary.hpp.
#include "friction/dict/Dictionary.hpp"

#include "friction/core/InputFile.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/core/VisibleText.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <stdexcept>
#include <unordered_map>

#include "friction/dict/Number.hpp"
#include "friction/dict/Tokenizer.hpp"

namespace friction {

namespace fs = std::filesystem;

namespace detail {

/// One entry: a key with either value items or a sub-dictionary.
struct DictEntry {
  std::string key;
  SourceLocation where;
  std::vector<Value> items;
  std::unique_ptr<Dictionary> dict;  // set for dictionary entries
  mutable bool read = false;
  /// The text the entry was written in: one number per file read (each #include of a file is
  /// another), 0 for an entry copied by '$name' or set by code. Two entries with one key and
  /// one origin are a duplicate; a later one of another origin overrides.
  int origin = 0;

  DictEntry() = default;
  DictEntry(DictEntry&&) = default;
  DictEntry& operator=(DictEntry&&) = default;
  DictEntry(const DictEntry& o)
      : key(o.key),
        where(o.where),
        items(o.items),
        dict(o.dict ? std::make_unique<Dictionary>(*o.dict) : nullptr),
        read(o.read),
        origin(o.origin) {}
  DictEntry& operator=(const DictEntry& o) {
    DictEntry copy(o);
    return *this = std::move(copy);
  }
};

}  // namespace detail

using detail::DictEntry;
using detail::Token;
using detail::Tokenizer;

struct Dictionary::Impl {
  std::string scope;
  SourceLocation where;
  std::vector<DictEntry> entries;  // file order
  std::unordered_map<std::string, std::size_t> index;
  /// Keys the program asked about: the valid keys offered in "did you mean" suggestions.
  mutable std::set<std::string> asked;
  /// Keys other programs use that this one does not read, with the way forward
  /// (Dictionary::advise): what checkAllRead says when one is there.
  mutable std::map<std::string, std::string> advice;

  static Impl& of(Dictionary& d) { return *d.impl_; }
  static const Impl& of(const Dictionary& d) { return *d.impl_; }

  DictEntry* find(const std::string& key) {
    const auto it = index.find(key);
    return it == index.end() ? nullptr : &entries[it->second];
  }
  const DictEntry* find(const std::string& key) const { return const_cast<Impl*>(this)->find(key); }
  /// find() that records key as one the program asks for.
  const DictEntry* ask(const std::string& key) const {
    asked.insert(key);
    return find(key);
  }

  /// Adds an entry with OpenFOAM's rules for a repeated key: a dictionary repeated as a
  /// dictionary is merged into the first, anything else replaces the earlier entry in its
  /// place (the key keeps its first position, value and location come from the last).
  void add(DictEntry&& e) {
    DictEntry* old = find(e.key);
    if (!old) {
      index.emplace(e.key, entries.size());
      entries.push_back(std::move(e));
    } else if (old->dict && e.dict) {
      Impl& into = of(*old->dict);
      for (DictEntry& sub : of(*e.dict).entries) into.add(std::move(sub));
    } else {
      *old = std::move(e);
    }
  }

  /// Gives this dictionary (and its sub-dictionaries) the scope of a new place, after a copy.
  void rescope(const std::string& newScope) {
    scope = newScope;
    for (DictEntry& e : entries)
      if (e.dict) of(*e.dict).rescope(newScope + "/" + e.key);
  }

  /// Marks every entry (recursively) as copied rather than written here.
  void setCopied() {
    for (DictEntry& e : entries) {
      e.origin = 0;
      if (e.dict) of(*e.dict).setCopied();
    }
  }

  void setRead(bool read) const {
    for (const DictEntry& e : entries) {
      e.read = read;
      if (e.dict) of(*e.dict).setRead(read);
    }
    if (!read) asked.clear();
  }
};

namespace {

using Kind = Value::Kind;

// ---------------------------------------------------------------------------------------
// Messages
// ---------------------------------------------------------------------------------------

/// The candidate near enough to word to be a typo of it (closestMatch), or "".
template <typename Range>
std::string nearest(const std::string& word, const Range& candidates) {
  return closestMatch(word, std::vector<std::string>(std::begin(candidates), std::end(candidates)));
}

template <typename Range>
std::string joined(const Range& words) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : ", ") + w;
  return s;
}

/// A value for an error message, cut short: a 10^6-item list must not become the message.
std::string shown(const Value& v) {
  std::string s = v.kind == Kind::Word ? "'" + v.text + "'" : v.str();
  constexpr std::size_t kMax = 60;
  if (s.size() > kMax) s = s.substr(0, kMax) + " ...";
  return s;
}

/// "which has the invisible character U+200B ZERO WIDTH SPACE after 'nu'; delete it": what
/// hides in key (it has at least one invisible character).
std::string invisibleText(const std::string& key) {
  const std::vector<InvisibleChar> found = invisibleCharacters(key);
  const InvisibleChar& c = found.front();
  const std::string before = withoutInvisible(key.substr(0, c.offset));
  std::string s = "which has the invisible character " + c.name() +
                  (before.empty() ? " at its start" : " after '" + before + "'");
  if (found.size() > 1) s += " (and " + std::to_string(found.size() - 1) + " more)";
  return s + "; delete it, or type a plain space where one belongs";
}

/// True if written is wanted but for invisible characters: without them, or cut at the first
/// one ("nu\u00a00.3", a no-break space where a space belongs, starts with "nu").
bool looksLike(const std::string& written, const std::string& wanted) {
  const std::vector<InvisibleChar> found = invisibleCharacters(written);
  if (found.empty()) return false;
  return withoutInvisible(written) == wanted || written.substr(0, found.front().offset) == wanted;
}

/// What an entry holds, for "got ..." in messages. Items spread over several lines usually
/// mean a missing ';', so the message says where one probably belongs.
std::string shown(const std::vector<Value>& items) {
  if (items.empty()) return "nothing";
  if (items.size() == 1) return shown(items[0]);
  std::string s;
  for (const Value& v : items) {
    if (!s.empty()) s += ' ';
    s += v.str();
    if (s.size() > 60) {
      s = s.substr(0, 60) + " ...";
      break;
    }
  }
  s = "'" + s + "'";
  for (std::size_t i = 1; i < items.size(); ++i)
    if (items[i].line > items[i - 1].line && items[i - 1].line > 0)
      return s + " (missing ';' at the end of line " + std::to_string(items[i - 1].line) + "?)";
  return s;
}

/// Why the first item that looks like a mistyped number is not one (" ('0,9' has a decimal
/// comma: write 0.9)"), or "": appended to "got ..." where numbers are expected.
std::string numberHint(const Value& v) {
  if (v.isWord()) {
    const std::string why = whyNotANumber(v.text);
    return why.empty() ? "" : " ('" + v.text + "' " + why + ")";
  }
  for (const Value& i : v.items)
    if (std::string h = numberHint(i); !h.empty()) return h;
  return "";
}
std::string numberHint(const std::vector<Value>& items) {
  for (const Value& v : items)
    if (std::string h = numberHint(v); !h.empty()) return h;
  return "";
}

/// "got ..." where numbers are expected: the items and, if one is a mistyped number, why.
std::string shownNumbers(const std::vector<Value>& items) {
  return shown(items) + numberHint(items);
}
std::string shownNumbers(const Value& v) { return shown(v) + numberHint(v); }

std::string withBounds(const std::string& what, const Bounds& b) {
  const std::string range = b.str();
  return range.empty() ? what : what + " " + range;
}

[[noreturn]] void failEntry(const DictEntry& e, const std::string& expected,
                            const std::string& got) {
  throw InputError(e.where, "key '" + e.key + "': expected " + expected + ", got " + got);
}

/// Error about item i of a list entry, located at the item's own line.
[[noreturn]] void failItem(const DictEntry& e, std::size_t i, const Value& item,
                           const std::string& expected) {
  throw InputError(SourceLocation{e.where.file, item.line > 0 ? item.line : e.where.line},
                   "key '" + e.key + "': item " + std::to_string(i) + ": expected " + expected +
                       ", got " + shownNumbers(item));
}

// ---------------------------------------------------------------------------------------
// Access helpers
// ---------------------------------------------------------------------------------------

/// The entry for key, marked read; InputError if missing or a dictionary.
const DictEntry& requireValue(const Dictionary::Impl& d, const std::string& key,
                              const std::string& expected) {
  const DictEntry* e = d.ask(key);
  if (!e) {
    std::string msg = "missing key '" + key + "' in " + d.scope + " (expected " + expected + ")";
    // A key that is this one but for an invisible character (a zero-width or no-break space
    // pasted in) looks right in any editor: name it and the character, at its line.
    for (const DictEntry& p : d.entries)
      if (!p.read && looksLike(p.key, key))
        throw InputError(p.where, msg + ": the key written here is '" + showInvisible(p.key) +
                                      "', " + invisibleText(p.key));
    // A near miss among the keys present is most likely a misspelling of this one.
    std::vector<std::string> present;
    for (const DictEntry& p : d.entries)
      if (!p.read && editDistance(key, p.key) <= typoDistance(key.size())) present.push_back(p.key);
    if (!present.empty()) {
      const DictEntry& p = *d.find(nearest(key, present));  // present: all within reach
      msg += "; is '" + p.key + "' at " + p.where.str() + " a misspelling of it?";
    }
    throw InputError(d.where, msg);
  }
  e->read = true;
  if (e->dict) failEntry(*e, expected, "a dictionary");
  return *e;
}

/// Items without the words OpenFOAM writes before a value: "uniform" before one number or
/// vector (a constant field); for a list (isList) also "nonuniform" and "List<type>", which
/// OpenFOAM writes before per-item lists. "nonuniform 3" is no constant: not stripped.
std::pair<const Value*, const Value*> stripped(const std::vector<Value>& items, bool isList) {
  const Value* b = items.data();
  const Value* e = b + items.size();
  if (!isList) {
    if (e - b == 2 && b->isWord() && b->text == "uniform") ++b;
    return {b, e};
  }
  while (e - b > 1 && b->isWord() &&
         (b->text == "uniform" || b->text == "nonuniform" || b->text.rfind("List<", 0) == 0))
    ++b;
  return {b, e};
}

/// The one list an entry holds (after a "uniform"/"List<...>" prefix).
const Value& singleList(const DictEntry& e, const std::string& expected) {
  const auto [b, end] = stripped(e.items, true);
  if (end - b != 1 || !b->isList()) failEntry(e, expected, shownNumbers(e.items));
  return *b;
}

bool toLong(const Value& v, long& out) {
  if (!v.isNumber()) return false;
  // Plain integers convert exactly; a double would round beyond 2^53.
  const std::string& t = v.text;
  if (!t.empty() && t.find_first_of(".eE") == std::string::npos) {
    const char* first = t[0] == '+' ? t.data() + 1 : t.data();
    const auto r = std::from_chars(first, t.data() + t.size(), out);
    return r.ec == std::errc() && r.ptr == t.data() + t.size();
  }
  // 2.0 or 1e3: accepted when the value is a whole number a double holds exactly.
  if (std::floor(v.number) != v.number || std::fabs(v.number) > 9007199254740992.0) return false;
  out = static_cast<long>(v.number);
  return true;
}

double scalarOf(const DictEntry& e, const Bounds& bounds) {
  const std::string expected = withBounds("a number", bounds);
  const auto [b, end] = stripped(e.items, false);
  if (end - b != 1 || !b->isNumber()) failEntry(e, expected, shownNumbers(e.items));
  if (!bounds.contains(b->number)) failEntry(e, expected, b->str());
  return b->number;
}

long intOf(const DictEntry& e, const Bounds& bounds) {
  const std::string expected = withBounds("an integer", bounds);
  long x = 0;
  if (e.items.size() != 1 || !toLong(e.items[0], x)) failEntry(e, expected, shownNumbers(e.items));
  if (!bounds.contains(static_cast<double>(x))) failEntry(e, expected, e.items[0].str());
  return x;
}

bool boolOf(const DictEntry& e) {
  static const char* const kTrue[] = {"true", "yes", "on"};
  static const char* const kFalse[] = {"false", "no", "off"};
  if (e.items.size() == 1 && e.items[0].isWord()) {
    for (const char* w : kTrue)
      if (e.items[0].text == w) return true;
    for (const char* w : kFalse)
      if (e.items[0].text == w) return false;
  }
  failEntry(e, "true/false, yes/no or on/off", shown(e.items));
}

std::string wordOf(const DictEntry& e, const std::string& expected) {
  if (e.items.size() != 1 || !(e.items[0].isWord() || e.items[0].isString()))
    failEntry(e, expected, shown(e.items));
  return e.items[0].text;
}

std::string choiceOf(const DictEntry& e, const std::vector<std::string>& choices) {
  const std::string noun = e.key == "type" ? "type" : "value";
  const std::string w = wordOf(e, "one of: " + joined(choices));
  if (std::find(choices.begin(), choices.end(), w) != choices.end()) return w;
  throw InputError(e.where, "key '" + e.key + "': unknown " + noun + " '" + w + "'" +
                                suggestionText(w, choices) + " (valid " + noun +
                                "s are: " + joined(choices) + ")");
}

/// (x y) as a vector, or nullopt.
std::optional<Vector2> toVector(const Value& v) {
  if (!v.isList() || v.items.size() != 2 || !v.items[0].isNumber() || !v.items[1].isNumber())
    return std::nullopt;
  return Vector2(v.items[0].number, v.items[1].number);
}

/// Template for a required get: registers and reads key, converts with f.
template <typename F>
auto getRequired(const Dictionary::Impl& d, const std::string& key, const std::string& expected,
                 F f) {
  return f(requireValue(d, key, expected));
}

/// Template for an optional get: def when absent, otherwise as getRequired.
template <typename T, typename F>
T getOptional(const Dictionary::Impl& d, const std::string& key, const std::string& expected, T def,
              F f) {
  if (!d.ask(key)) return def;
  return f(requireValue(d, key, expected));
}

// ---------------------------------------------------------------------------------------
// Parser
// ---------------------------------------------------------------------------------------

/// Nesting deeper than this is an error rather than a stack overflow.
constexpr std::size_t kMaxDepth = 256;

/// Items a value holds, itself included (what copying it adds to a dictionary).
std::size_t itemCount(const Value& v) {
  std::size_t n = 1;
  for (const Value& i : v.items) n += itemCount(i);
  return n;
}
std::size_t itemCount(const Dictionary::Impl& d) {
  std::size_t n = 0;
  for (const DictEntry& e : d.entries) {
    n += 1;
    for (const Value& v : e.items) n += itemCount(v);
    if (e.dict) n += itemCount(Dictionary::Impl::of(*e.dict));
  }
  return n;
}

class Parser {
 public:
  using Impl = Dictionary::Impl;

  explicit Parser(const DictionaryLimits& limits) : limits_(limits) {}

  /// Parses the file at path (as named in messages) into dict. includedFrom is the
  /// '#include' that asked for it, or null for the file given to Dictionary::read.
  void parseFile(const std::string& path, Impl& dict, const SourceLocation* includedFrom,
                 bool optional) {
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(path, ec);
    const std::string id = ec ? path : canonical.string();
    const SourceLocation from = includedFrom ? *includedFrom : SourceLocation{path, 0};
    for (std::size_t i = 0; i < includeIds_.size(); ++i)
      if (includeIds_[i] == id) {
        std::string chain;
        for (std::size_t j = i; j < includeNames_.size(); ++j) chain += includeNames_[j] + " -> ";
        throw InputError(from, "#include cycle: " + chain + path);
      }
    if (optional && !fs::exists(path, ec)) return;
    InputFileRole role;
    role.what = "a dictionary";
    role.maxBytes = limits_.bytes;
    role.tooLargeHint = limits_.hint;
    if (includedFrom) {
      role.namedAt = *includedFrom;
      role.namedBy = optional ? "#includeIfPresent" : "#include";
    }
    const std::string text = readInputFile(path, role);
    bytes_ += text.size();
    if (bytes_ > limits_.bytes)
      throw InputError(from, "#include: '" + path + "' brings the text read for this dictionary " +
                                 "to " + formatBytes(bytes_) + ", beyond the limit of " +
                                 formatBytes(limits_.bytes) + " for a dictionary with the " +
                                 "files it includes; " + limits_.hint);

    includeIds_.push_back(id);
    includeNames_.push_back(path);
    fs::path dir = fs::path(path).parent_path();
    parseText(text, path, dir.empty() ? "." : dir.string(), dict, includedFrom != nullptr);
    includeIds_.pop_back();
    includeNames_.pop_back();
  }

  /// Parses text (from file, with #include relative to baseDir) into dict.
  void parseText(std::string_view text, const std::string& file, const std::string& baseDir,
                 Impl& dict, bool included) {
    Tokenizer tz(text, file);
    const bool outermost = scopes_.empty();
    if (outermost) scopes_.push_back(&dict);
    const Source src{tz, file, baseDir, included, ++origins_};
    parseEntries(src, dict, 0, "");
    if (outermost) scopes_.pop_back();
  }

 private:
  struct Source {
    Tokenizer& tz;
    const std::string& file;
    std::string baseDir;
    bool included;
    int origin;  // DictEntry::origin of the entries written in this text
  };

  /// Entries up to the '}' that closes the dictionary opened at openLine (0: to the end of
  /// the file).
  void parseEntries(const Source& src, Impl& dict, int openLine, const std::string& openKey) {
    Tokenizer& tz = src.tz;
    for (;;) {
      Token t = tz.next();
      switch (t.type) {
        case Token::Type::End:
          if (openLine)
            tz.fail(openLine, "unterminated dictionary '" + openKey +
                                  "': expected '}' to close the '{' opened here, got end of file");
          return;
        case Token::Type::Punct:
          if (t.isPunct('}')) {
            if (!openLine) tz.fail(t.line, "unexpected '}': no dictionary is open here");
            return;
          }
          if (t.isPunct(';')) continue;  // a stray ';' is harmless; OpenFOAM skips it too
          tz.fail(t.line, "expected a key (a word), got '" + std::string(t.text) + "'");
        case Token::Type::Directive:
          directive(src, t, dict);
          continue;
        case Token::Type::Variable:
          mergeVariable(src, t, dict);
          continue;
        case Token::Type::Word:
          entry(src, t, dict, openLine == 0 && src.included);
          continue;
        case Token::Type::Number:
          tz.fail(t.line, "expected a key (a word), got the number " + std::string(t.text));
        case Token::Type::String:
          tz.fail(t.line, "expected a key (a word), got the string \"" + t.string + "\"");
      }
    }
  }

  void entry(const Source& src, const Token& keyToken, Impl& dict, bool includedFileLevel) {
    Tokenizer& tz = src.tz;
    DictEntry e;
    e.key = std::string(keyToken.text);
    e.where = {src.file, keyToken.line};
    e.origin = src.origin;
    count(1, src, keyToken.line);
    Token t = tz.next();
    if (t.isPunct('{')) {
      e.dict = std::make_unique<Dictionary>();
      Impl& sub = Impl::of(*e.dict);
      sub.scope = dict.scope + "/" + e.key;
      sub.where = {src.file, t.line};
      if (scopes_.size() >= kMaxDepth) tz.fail(t.line, "dictionaries nested too deeply");
      scopes_.push_back(&sub);
      parseEntries(src, sub, t.line, e.key);
      scopes_.pop_back();
    } else {
      valueItems(src, std::move(t), e, dict);
    }
    // An included file's header describes that file, not the dictionary it is included in.
    if (includedFileLevel && e.key == "FoamFile") return;
    if (const DictEntry* old = dict.find(e.key); old && old->origin == e.origin)
      tz.fail(e.where.line,
              "key '" + showInvisible(e.key) + "' is given twice in " + dict.scope +
                  " (first at line " + std::to_string(old->where.line) +
                  "): expected each key once; delete one (a key may override one that comes "
                  "from an #include file or a '$name;' merge, not one written beside it)");
    dict.add(std::move(e));
  }

  /// The items of a value entry, from token t up to ';'.
  void valueItems(const Source& src, Token t, DictEntry& e, const Impl& dict) {
    Tokenizer& tz = src.tz;
    for (;; t = tz.next()) {
      if (t.isPunct(';')) return;
      if (t.type == Token::Type::Variable) {
        const DictEntry& ref = lookup(src, t, e.key);
        if (ref.dict) {
          // 'key $dict;' makes key a copy of that dictionary.
          if (!e.items.empty() || !tz.peekPunct(';'))
            tz.fail(t.line, "key '" + e.key + "': '$" + std::string(t.text) +
                                "' is a dictionary; it can only stand alone ('" + e.key + " $" +
                                std::string(t.text) + ";')");
          e.dict = copyOf(*ref.dict, dict.scope + "/" + e.key);
          count(itemCount(Impl::of(*e.dict)), src, t.line);
          tz.next();
          return;
        }
        appendCopies(src, ref.items, t.line, e.items);
        continue;
      }
      if (item(src, t, e.items, e.key, 0)) continue;
      switch (t.type) {
        case Token::Type::End:
          tz.fail(e.where.line,
                  "key '" + e.key + "': expected ';' to end the entry, got end of file");
        case Token::Type::Directive:
          tz.fail(t.line, "key '" + e.key + "': unexpected directive '#" + std::string(t.text) +
                              "' inside a value (directives start an entry)");
        default:
          if (t.isPunct(')'))
            tz.fail(t.line, "key '" + e.key + "': unexpected ')': no list is open");
          tz.fail(e.where.line, "key '" + e.key + "': expected ';' to end the entry, got '" +
                                    std::string(t.text) + "' at line " + std::to_string(t.line));
      }
    }
  }

  /// Adds the item starting with token t to out; false if t does not start an item.
  bool item(const Source& src, Token& t, std::vector<Value>& out, const std::string& key,
            std::size_t depth) {
    if (t.type == Token::Type::Number || t.type == Token::Type::Word ||
        t.type == Token::Type::String || t.isPunct('('))
      count(1, src, t.line);
    switch (t.type) {
      case Token::Type::Number: {
        if (t.plainInteger && src.tz.sizedListFollows()) {
          long n = 0;
          const auto r = std::from_chars(t.text.data(), t.text.data() + t.text.size(), n);
          if (r.ec != std::errc())
            src.tz.fail(t.line, "key '" + key + "': list size " + std::string(t.text) +
                                    " is too large (expected the number of items before '(')");
          const Token open = src.tz.next();  // the '('
          Value& v = out.emplace_back();
          list(src, v, open.line, n, t.line, key, depth + 1);
          return true;
        }
        Value& v = out.emplace_back();
        v.kind = Kind::Number;
        v.text.assign(t.text.data(), t.text.size());
        v.number = t.number;
        v.line = t.line;
        return true;
      }
      case Token::Type::Word: {
        Value& v = out.emplace_back();
        v.text.assign(t.text.data(), t.text.size());
        v.line = t.line;
        return true;
      }
      case Token::Type::String: {
        Value& v = out.emplace_back();
        v.kind = Kind::String;
        v.text = std::move(t.string);
        v.line = t.line;
        return true;
      }
      case Token::Type::Variable: {
        const DictEntry& ref = lookup(src, t, key);
        if (ref.dict)
          src.tz.fail(t.line, "key '" + key + "': '$" + std::string(t.text) +
                                  "' is a dictionary and cannot be part of a list");
        appendCopies(src, ref.items, t.line, out);
        return true;
      }
      case Token::Type::Punct:
        if (!t.isPunct('(')) return false;
        list(src, out.emplace_back(), t.line, -1, t.line, key, depth + 1);
        return true;
      default:
        return false;
    }
  }

  /// A list after its '(' (opened at openLine) up to the matching ')'. size >= 0 is the
  /// item count given before the '(' at sizeLine.
  void list(const Source& src, Value& v, int openLine, long size, int sizeLine,
            const std::string& key, std::size_t depth) {
    Tokenizer& tz = src.tz;
    if (depth + scopes_.size() >= kMaxDepth) tz.fail(openLine, "lists nested too deeply");
    v.kind = Kind::List;
    v.line = size >= 0 ? sizeLine : openLine;
    // Items go straight into a list of known size (reserved, capped by what the rest of the
    // text can hold, so a wrong size costs an error, not the memory). A list of unknown size
    // collects its items in a buffer kept per depth and gets them in one exact allocation:
    // growing each of 10^6 small "(x y)" lists item by item would double the allocations.
    if (size >= 0 && static_cast<std::size_t>(size) > limits_.listItems)
      tooManyItems(src, sizeLine, key, "is declared with " + std::to_string(size));
    std::vector<Value>& items = size >= 0 ? v.items : scratch(depth);
    if (size > 0) items.reserve(std::min(static_cast<std::size_t>(size), tz.remaining() / 2 + 1));
    for (;;) {
      Token t = tz.next();
      if (t.isPunct(')')) break;
      if (item(src, t, items, key, depth)) {
        if (items.size() > limits_.listItems)
          tooManyItems(src, openLine, key, "has more than " + std::to_string(limits_.listItems));
        continue;
      }
      if (t.isPunct('{'))
        tz.fail(t.line, "key '" + key +
                            "': a dictionary inside a list is not supported "
                            "(expected a word, number, string or list, or ')' to close the list "
                            "opened at line " +
                            std::to_string(openLine) + ")");
      const std::string shownToken =
          (t.type == Token::Type::Directive ? "#" : "") + std::string(t.text);
      const std::string got = t.type == Token::Type::End
                                  ? "end of file"
                                  : "'" + shownToken + "' at line " + std::to_string(t.line);
      tz.fail(openLine, "key '" + key +
                            "': unterminated list: expected ')' to close the '(' "
                            "opened here, got " +
                            got);
    }
    if (&items != &v.items) {
      v.items.reserve(items.size());
      std::move(items.begin(), items.end(), std::back_inserter(v.items));
      items.clear();
    }
    if (size >= 0 && static_cast<std::size_t>(size) != v.items.size())
      tz.fail(sizeLine, "key '" + key + "': the list is declared with " + std::to_string(size) +
                            " items but has " + std::to_string(v.items.size()) +
                            " (the count before '(' must match)");
  }

  void directive(const Source& src, const Token& t, Impl& dict) {
    Tokenizer& tz = src.tz;
    const bool optional = t.text == "includeIfPresent";
    if (t.text != "include" && !optional)
      tz.fail(t.line, "unknown directive '#" + std::string(t.text) +
                          "' (expected #include or #includeIfPresent)");
    Token name = tz.next();
    std::string file;
    if (name.type == Token::Type::String)
      file = name.string;
    else if (name.type == Token::Type::Word)
      file = std::string(name.text);
    else
      tz.fail(t.line, "#" + std::string(t.text) + ": expected a file name in quotes after it");
    if (file.empty()) tz.fail(t.line, "#" + std::string(t.text) + ": empty file name");
    fs::path path(file);
    if (path.is_relative()) path = fs::path(src.baseDir) / path;
    const SourceLocation from{src.file, t.line};
    if (scopes_.size() + includeIds_.size() >= kMaxDepth)
      tz.fail(t.line, "#include nested too deeply");
    parseFile(path.lexically_normal().string(), dict, &from, optional);
  }

  /// '$name' at the start of an entry: merges dictionary 'name' into dict.
  void mergeVariable(const Source& src, const Token& t, Impl& dict) {
    const DictEntry& ref = lookup(src, t, "");
    if (!ref.dict)
      src.tz.fail(t.line, "'$" + std::string(t.text) +
                              "' at the start of an entry merges a dictionary, but '" + ref.key +
                              "' is a value (write 'key $" + ref.key + ";' to copy a value)");
    std::unique_ptr<Dictionary> copy = copyOf(*ref.dict, dict.scope);
    count(itemCount(Impl::of(*copy)), src, t.line);
    for (DictEntry& e : Impl::of(*copy).entries) dict.add(std::move(e));
    if (src.tz.peekPunct(';')) src.tz.next();
  }

  /// The entry '$name' refers to: in the dictionary being read or an enclosing one, defined
  /// before this point. It counts as read: it served its purpose by being copied.
  const DictEntry& lookup(const Source& src, const Token& t, const std::string& key) {
    const std::string name(t.text);
    const std::string where = key.empty() ? "" : "key '" + key + "': ";
    if (name.empty()) src.tz.fail(t.line, where + "expected a name after '$'");
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it)
      if (const DictEntry* e = (*it)->find(name)) {
        e->read = true;
        if (e->dict) Impl::of(*e->dict).setRead(true);
        return *e;
      }
    std::vector<std::string> known;
    for (const Impl* s : scopes_)
      for (const DictEntry& e : s->entries) known.push_back(e.key);
    std::string msg = where + "undefined variable '$" + name + "': no entry '" + name +
                      "' before it in this or an enclosing dictionary";
    if (const std::string guess = nearest(name, known); !guess.empty())
      msg += "; did you mean '$" + guess + "'?";
    src.tz.fail(t.line, msg);
  }

  /// A copy of d for a new place: unread (the copy's entries are checked where they are
  /// used) and scoped to its new place.
  static std::unique_ptr<Dictionary> copyOf(const Dictionary& d, const std::string& scope) {
    auto copy = std::make_unique<Dictionary>(d);
    Impl::of(*copy).setRead(false);
    Impl::of(*copy).rescope(scope);
    Impl::of(*copy).setCopied();
    return copy;
  }

  /// Appends copies of items, placed at line (the '$name' they replace), so that errors
  /// point into the file being read.
  void appendCopies(const Source& src, const std::vector<Value>& items, int line,
                    std::vector<Value>& out) {
    std::size_t n = 0;
    for (const Value& v : items) n += itemCount(v);
    count(n, src, line);  // before the copy: '$a' in '$a $a' doubles, and so on
    for (const Value& v : items) {
      Value& c = out.emplace_back(v);
      relocate(c, line);
    }
  }
  static void relocate(Value& v, int line) {
    v.line = line;
    for (Value& i : v.items) relocate(i, line);
  }

  /// Adds n to the items the dictionary holds; InputError at line beyond the bound.
  void count(std::size_t n, const Source& src, int line) {
    items_ += n;
    if (items_ > limits_.totalItems)
      src.tz.fail(line, "the dictionary holds more than " + std::to_string(limits_.totalItems) +
                            " items (words, numbers, strings and lists, '$' copies included) "
                            "here, the limit for a dictionary; " +
                            limits_.hint);
  }

  [[noreturn]] void tooManyItems(const Source& src, int line, const std::string& key,
                                 const std::string& what) {
    src.tz.fail(line, "key '" + key + "': the list opened here " + what +
                          " items, beyond the limit of " + std::to_string(limits_.listItems) +
                          " for a list in a dictionary; " + limits_.hint);
  }

  /// The (empty) item buffer for lists at depth; a deque keeps references stable as it grows.
  std::vector<Value>& scratch(std::size_t depth) {
    while (scratch_.size() <= depth) scratch_.emplace_back();
    return scratch_[depth];
  }

  DictionaryLimits limits_;
  std::uint64_t bytes_ = 0;  // text read, the file and its #includes
  std::size_t items_ = 0;    // items held, see count()
  int origins_ = 0;          // texts read, see DictEntry::origin
  std::deque<std::vector<Value>> scratch_;
  std::vector<Impl*> scopes_;              // dictionaries being read, innermost last
  std::vector<std::string> includeIds_;    // canonical paths of the files being read
  std::vector<std::string> includeNames_;  // the same, as named in messages
};

void finishTopLevel(Dictionary::Impl& d) {
  // The header is for OpenFOAM's tools; it counts as read so that checkAllRead passes it.
  // Its 'format' is the one entry that changes how a file reads: binary lists are not text.
  if (const DictEntry* header = d.find("FoamFile")) {
    header->read = true;
    if (header->dict) {
      const Dictionary::Impl& h = Dictionary::Impl::of(*header->dict);
      h.setRead(true);
      const DictEntry* format = h.find("format");
      if (format && !(format->items.size() == 1 && format->items[0].text == "ascii"))
        throw InputError(format->where, "FoamFile: format " + shown(format->items) +
                                            " is not read (expected 'ascii')");
    }
  }
}

/// The dictionaries under d (d included) that asked for key, except d and its siblings, as
/// paths relative to root ("control/optimizer", or "the top level").
void askedElsewhere(const Dictionary::Impl& root, const Dictionary::Impl& d,
                    const Dictionary::Impl* parentOfD, const Dictionary::Impl& here,
                    const Dictionary::Impl* parent, const std::string& key,
                    std::vector<std::string>& out) {
  // A sibling asks for other keys because it is another instance of the same family (a
  // patch, an effect) with another type: "belongs in boundaryField/top" would mislead there.
  const bool sibling = parent == parentOfD;
  if (&here != &d && !sibling && here.asked.count(key)) {
    const bool top = here.scope.size() <= root.scope.size();
    out.push_back(top ? "the top level of " + root.scope
                      : here.scope.substr(root.scope.size() + 1));
  }
  for (const DictEntry& e : here.entries)
    if (e.dict && e.read)
      askedElsewhere(root, d, parentOfD, Dictionary::Impl::of(*e.dict), &here, key, out);
}

void checkRead(const Dictionary::Impl& root, const Dictionary::Impl& d,
               const Dictionary::Impl* parent) {
  for (const DictEntry& e : d.entries) {
    if (!e.read) {
      if (d.asked.count(e.key))
        throw InputError(e.where, "key '" + e.key + "' in " + d.scope +
                                      " is never used (the program checks that it is there "
                                      "but does not read it)");
      std::string msg = "unknown key '" + showInvisible(e.key) + "' in " + d.scope;
      if (const auto a = d.advice.find(e.key); a != d.advice.end())
        throw InputError(e.where, msg + ": " + a->second);
      if (!invisibleCharacters(e.key).empty()) {
        // In an editor the key looks like a valid one; say what hides in it.
        msg += ", " + invisibleText(e.key);
        for (const std::string& k : d.asked)
          if (looksLike(e.key, k)) throw InputError(e.where, msg + " (it reads as '" + k + "')");
      }
      std::vector<std::string> places;
      askedElsewhere(root, d, parent, root, nullptr, e.key, places);
      if (!places.empty()) {
        // A key of another dictionary of the file: the fix is to move it, not to rename it.
        msg += "; it belongs in " + joinWords(places, " or ");
        if (!d.asked.empty()) msg += " (valid keys here: " + joined(d.asked) + ")";
      } else if (d.asked.empty()) {
        msg += " (no keys are read from " + d.scope + ")";
      } else {
        // Prefer the keys the program asked for and did not find: the likely intended ones.
        std::vector<std::string> missing;
        for (const std::string& k : d.asked)
          if (!d.find(k)) missing.push_back(k);
        std::string guess = nearest(e.key, missing);
        if (guess.empty()) guess = nearest(e.key, d.asked);
        if (!guess.empty()) msg += "; did you mean '" + guess + "'?";
        msg += " (valid keys: " + joined(d.asked) + ")";
      }
      throw InputError(e.where, msg);
    }
    if (e.dict) checkRead(root, Dictionary::Impl::of(*e.dict), &d);
  }
}

}  // namespace

// -----------------------------------------------------------------------------------------
// Bounds
// -----------------------------------------------------------------------------------------

bool Bounds::contains(double x) const {
  const bool aboveMin = minExclusive ? x > min : x >= min;
  const bool belowMax = maxExclusive ? x < max : x <= max;
  return aboveMin && belowMax;  // false for NaN
}

std::string Bounds::str() const {
  const bool hasMin = min > -std::numeric_limits<double>::infinity();
  const bool hasMax = max < std::numeric_limits<double>::infinity();
  const std::string lo = detail::shortestNumber(min);
  const std::string hi = detail::shortestNumber(max);
  if (hasMin && hasMax)
    return "in " + std::string(minExclusive ? "(" : "[") + lo + ", " + hi +
           (maxExclusive ? ")" : "]");
  if (hasMin) return (minExclusive ? "> " : ">= ") + lo;
  if (hasMax) return (maxExclusive ? "< " : "<= ") + hi;
  return "";
}

// -----------------------------------------------------------------------------------------
// Dictionary
// -----------------------------------------------------------------------------------------

Dictionary::Dictionary() : impl_(std::make_unique<Impl>()) {}
Dictionary::~Dictionary() = default;
Dictionary::Dictionary(Dictionary&&) noexcept = default;
Dictionary& Dictionary::operator=(Dictionary&&) noexcept = default;
Dictionary::Dictionary(const Dictionary& o) : impl_(std::make_unique<Impl>(*o.impl_)) {}
Dictionary& Dictionary::operator=(const Dictionary& o) {
  if (this != &o) impl_ = std::make_unique<Impl>(*o.impl_);
  return *this;
}

DictionaryLimits DictionaryLimits::caseFile() {
  // 8 MiB of settings is far more than any case needs, and at most a few hundred MB in memory.
  return {8u << 20, 100'000, 2'000'000,
          "data this large belongs in a values file (a 'file' or 'values' key: one row of "
          "numbers per line, read compactly), not in a dictionary"};
}

DictionaryLimits DictionaryLimits::dataFile() {
  // A split mesh of ~10^7 points; one list per node or cell, of Index-sized counts.
  return {std::uint64_t{4} << 30, 2'147'483'647, std::numeric_limits<std::size_t>::max(),
          "a mesh this large is beyond what this text format can hold"};
}

Dictionary Dictionary::read(const std::string& path, const DictionaryLimits& limits) {
  Dictionary d;
  d.impl_->scope = path;
  d.impl_->where = {path, 0};
  Parser(limits).parseFile(path, *d.impl_, nullptr, false);
  finishTopLevel(*d.impl_);
  return d;
}

Dictionary Dictionary::parse(const std::string& text, const std::string& sourceName,
                             const std::string& baseDir, const DictionaryLimits& limits) {
  Dictionary d;
  d.impl_->scope = sourceName;
  d.impl_->where = {sourceName, 0};
  Parser(limits).parseText(text, sourceName, baseDir.empty() ? "." : baseDir, *d.impl_, false);
  finishTopLevel(*d.impl_);
  return d;
}

const std::string& Dictionary::scope() const { return impl_->scope; }

SourceLocation Dictionary::location() const { return impl_->where; }

SourceLocation Dictionary::location(const std::string& key) const {
  const DictEntry* e = impl_->find(key);
  if (!e) throw std::out_of_range("Dictionary::location: no key '" + key + "' in " + impl_->scope);
  return e->where;
}

std::vector<std::string> Dictionary::keys() const {
  std::vector<std::string> k;
  k.reserve(impl_->entries.size());
  for (const DictEntry& e : impl_->entries) k.push_back(e.key);
  return k;
}

bool Dictionary::found(const std::string& key) const { return impl_->ask(key) != nullptr; }

bool Dictionary::isDict(const std::string& key) const {
  const DictEntry* e = impl_->ask(key);
  return e && e->dict;
}

const Dictionary& Dictionary::subDict(const std::string& key) const {
  const Dictionary* d = findDict(key);
  if (!d)
    throw InputError(impl_->where, "missing sub-dictionary '" + key + "' in " + impl_->scope +
                                       " (expected '" + key + " { ... }')");
  return *d;
}

const Dictionary* Dictionary::findDict(const std::string& key) const {
  const DictEntry* e = impl_->ask(key);
  if (!e) return nullptr;
  e->read = true;
  if (!e->dict) failEntry(*e, "a dictionary { ... }", shown(e->items));
  return e->dict.get();
}

const std::vector<Value>& Dictionary::values(const std::string& key) const {
  return requireValue(*impl_, key, "a value").items;
}

double Dictionary::getScalar(const std::string& key, Bounds bounds) const {
  return getRequired(*impl_, key, withBounds("a number", bounds),
                     [&](const DictEntry& e) { return scalarOf(e, bounds); });
}

double Dictionary::getScalarOr(const std::string& key, double def, Bounds bounds) const {
  return getOptional(*impl_, key, withBounds("a number", bounds), def,
                     [&](const DictEntry& e) { return scalarOf(e, bounds); });
}

long Dictionary::getInt(const std::string& key, Bounds bounds) const {
  return getRequired(*impl_, key, withBounds("an integer", bounds),
                     [&](const DictEntry& e) { return intOf(e, bounds); });
}

long Dictionary::getIntOr(const std::string& key, long def, Bounds bounds) const {
  return getOptional(*impl_, key, withBounds("an integer", bounds), def,
                     [&](const DictEntry& e) { return intOf(e, bounds); });
}

bool Dictionary::getBool(const std::string& key) const {
  return getRequired(*impl_, key, "true/false, yes/no or on/off", boolOf);
}

bool Dictionary::getBoolOr(const std::string& key, bool def) const {
  return getOptional(*impl_, key, "true/false, yes/no or on/off", def, boolOf);
}

std::string Dictionary::getWord(const std::string& key) const {
  return getRequired(*impl_, key, "a word", [](const DictEntry& e) { return wordOf(e, "a word"); });
}

std::string Dictionary::getWordOr(const std::string& key, const std::string& def) const {
  return getOptional(*impl_, key, "a word", def,
                     [](const DictEntry& e) { return wordOf(e, "a word"); });
}

std::string Dictionary::getChoice(const std::string& key,
                                  const std::vector<std::string>& choices) const {
  return getRequired(*impl_, key, "one of: " + joined(choices),
                     [&](const DictEntry& e) { return choiceOf(e, choices); });
}

std::string Dictionary::getChoiceOr(const std::string& key, const std::vector<std::string>& choices,
                                    const std::string& def) const {
  return getOptional(*impl_, key, "one of: " + joined(choices), def,
                     [&](const DictEntry& e) { return choiceOf(e, choices); });
}

std::string Dictionary::getFileName(const std::string& key) const {
  const std::string expected = "a file name (in quotes if it has spaces)";
  return getRequired(*impl_, key, expected,
                     [&](const DictEntry& e) { return wordOf(e, expected); });
}

Vector2 Dictionary::getVector(const std::string& key) const {
  const std::string expected = "a vector (x y)";
  return getRequired(*impl_, key, expected, [&](const DictEntry& e) {
    const auto [b, end] = stripped(e.items, false);
    std::optional<Vector2> v;
    if (end - b == 1) v = toVector(*b);
    if (!v) failEntry(e, expected, shownNumbers(e.items));
    return *v;
  });
}

std::vector<double> Dictionary::getScalarList(const std::string& key) const {
  const std::string expected = "a list of numbers, e.g. (1 2 3)";
  return getRequired(*impl_, key, expected, [&](const DictEntry& e) {
    const Value& list = singleList(e, expected);
    std::vector<double> out;
    out.reserve(list.items.size());
    for (std::size_t i = 0; i < list.items.size(); ++i) {
      if (!list.items[i].isNumber()) failItem(e, i, list.items[i], "a number");
      out.push_back(list.items[i].number);
    }
    return out;
  });
}

std::vector<long> Dictionary::getIntList(const std::string& key) const {
  const std::string expected = "a list of integers, e.g. (1 2 3)";
  return getRequired(*impl_, key, expected, [&](const DictEntry& e) {
    const Value& list = singleList(e, expected);
    std::vector<long> out(list.items.size());
    for (std::size_t i = 0; i < list.items.size(); ++i)
      if (!toLong(list.items[i], out[i])) failItem(e, i, list.items[i], "an integer");
    return out;
  });
}

std::vector<std::string> Dictionary::getWordList(const std::string& key) const {
  const std::string expected = "a list of words, e.g. (a b c)";
  return getRequired(*impl_, key, expected, [&](const DictEntry& e) {
    const Value& list = singleList(e, expected);
    std::vector<std::string> out;
    out.reserve(list.items.size());
    for (std::size_t i = 0; i < list.items.size(); ++i) {
      const Value& v = list.items[i];
      if (!v.isWord() && !v.isString()) failItem(e, i, v, "a word");
      out.push_back(v.text);
    }
    return out;
  });
}

std::vector<Vector2> Dictionary::getVectorList(const std::string& key) const {
  const std::string expected = "a list of vectors, e.g. ((0 0) (1 0))";
  return getRequired(*impl_, key, expected, [&](const DictEntry& e) {
    const Value& list = singleList(e, expected);
    std::vector<Vector2> out;
    out.reserve(list.items.size());
    for (std::size_t i = 0; i < list.items.size(); ++i) {
      const std::optional<Vector2> v = toVector(list.items[i]);
      if (!v) failItem(e, i, list.items[i], "a vector (x y)");
      out.push_back(*v);
    }
    return out;
  });
}

std::vector<Point> Dictionary::getPointList(const std::string& key) const {
  const std::string expected = "a list of 3-vectors, e.g. ((0 0 0) (1 0 0))";
  return getRequired(*impl_, key, expected, [&](const DictEntry& e) {
    const Value& list = singleList(e, expected);
    std::vector<Point> out;
    out.reserve(list.items.size());
    for (std::size_t i = 0; i < list.items.size(); ++i) {
      const Value& v = list.items[i];
      if (!v.isList() || v.items.size() != 3 || !v.items[0].isNumber() || !v.items[1].isNumber() ||
          !v.items[2].isNumber())
        failItem(e, i, v, "a vector (x y z)");
      out.emplace_back(v.items[0].number, v.items[1].number, v.items[2].number);
    }
    return out;
  });
}

template <std::size_t N>
std::vector<std::array<long, N>> Dictionary::getIntTupleList(const std::string& key) const {
  const std::string tuple = "(" + std::to_string(N) + " integers)";
  const std::string expected = "a list of tuples of " + std::to_string(N) + " integers";
  return getRequired(*impl_, key, expected, [&](const DictEntry& e) {
    const Value& list = singleList(e, expected);
    std::vector<std::array<long, N>> out(list.items.size());
    for (std::size_t i = 0; i < list.items.size(); ++i) {
      const Value& t = list.items[i];
      if (!t.isList() || t.items.size() != N) failItem(e, i, t, "a tuple " + tuple);
      for (std::size_t k = 0; k < N; ++k)
        if (!toLong(t.items[k], out[i][k])) failItem(e, i, t, "a tuple " + tuple);
    }
    return out;
  });
}

template std::vector<std::array<long, 2>> Dictionary::getIntTupleList<2>(const std::string&) const;
template std::vector<std::array<long, 3>> Dictionary::getIntTupleList<3>(const std::string&) const;
template std::vector<std::array<long, 4>> Dictionary::getIntTupleList<4>(const std::string&) const;

Table Dictionary::getTable(const std::string& key) const {
  const std::string expected = "a table ((x0 y0) (x1 y1) ...)";
  return getRequired(*impl_, key, expected, [&](const DictEntry& e) {
    const Value& list = singleList(e, expected);
    if (list.items.empty()) failEntry(e, "a table with at least one row", "()");
    const std::string row = "a row (x y) with y a number or a list of numbers";
    Table table;
    for (std::size_t i = 0; i < list.items.size(); ++i) {
      const Value& r = list.items[i];
      if (!r.isList() || r.items.size() != 2 || !r.items[0].isNumber()) failItem(e, i, r, row);
      const Value& y = r.items[1];
      std::vector<double> values;
      if (y.isNumber()) {
        values.push_back(y.number);
      } else if (y.isList() && !y.items.empty()) {
        for (const Value& c : y.items) {
          if (!c.isNumber()) failItem(e, i, r, row);
          values.push_back(c.number);
        }
      } else {
        failItem(e, i, r, row);
      }
      if (i > 0 && values.size() != table.y[0].size())
        failItem(e, i, r,
                 "y with " + std::to_string(table.y[0].size()) + " components like the first row");
      const double x = r.items[0].number;
      if (i > 0 && !(x > table.x.back()))
        failItem(e, i, r,
                 "x greater than " + detail::shortestNumber(table.x.back()) +
                     " (x must increase strictly from row to row)");
      table.x.push_back(x);
      table.y.push_back(std::move(values));
    }
    return table;
  });
}

void Dictionary::checkAllRead() const { checkRead(*impl_, *impl_, nullptr); }

std::size_t Dictionary::alternative(const std::vector<std::vector<std::string>>& groups,
                                    std::optional<std::size_t> def) const {
  std::string options;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    options += g == 0 ? "" : g + 1 == groups.size() ? ", or " : ", ";
    options += joinWords(groups[g], " and ");
  }
  // The first entry in file order of each group that has one.
  std::vector<const DictEntry*> first(groups.size(), nullptr);
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (const std::string& k : groups[g])
      if (const DictEntry* e = impl_->ask(k);
          e && (!first[g] || e->where.line < first[g]->where.line))
        first[g] = e;
  std::optional<std::size_t> chosen;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (!first[g]) continue;
    if (chosen) {
      const DictEntry* a = first[*chosen];
      const DictEntry* b = first[g];
      if (b->where.line < a->where.line) std::swap(a, b);
      const bool single = groups[*chosen].size() == 1 && groups[g].size() == 1;
      throw InputError(b->where, "keys '" + a->key + "' (line " + std::to_string(a->where.line) +
                                     ") and '" + b->key + "' in " + impl_->scope +
                                     (single ? " are alternatives" : " belong to alternatives") +
                                     ": give " + options + ", not both");
    }
    chosen = g;
  }
  if (chosen) return *chosen;
  if (!def) throw InputError(impl_->where, "missing keys in " + impl_->scope + ": give " + options);
  return *def;
}

void Dictionary::markAllRead() const { impl_->setRead(true); }

void Dictionary::advise(const std::string& key, const std::string& advice) const {
  impl_->advice[key] = advice;
}

void Dictionary::set(const std::string& key, std::vector<Value> items, SourceLocation where) {
  DictEntry e;
  e.key = key;
  e.where = where.file.empty() ? impl_->where : std::move(where);
  e.items = std::move(items);
  impl_->add(std::move(e));
}

Dictionary& Dictionary::setDict(const std::string& key, SourceLocation where) {
  DictEntry e;
  e.key = key;
  e.where = where.file.empty() ? impl_->where : std::move(where);
  e.dict = std::make_unique<Dictionary>();
  Impl& sub = Impl::of(*e.dict);
  sub.scope = impl_->scope + "/" + key;
  sub.where = e.where;
  // Replace, not merge: the caller asked for a fresh sub-dictionary.
  if (DictEntry* old = impl_->find(key)) {
    *old = std::move(e);
    return *old->dict;
  }
  impl_->add(std::move(e));
  return *impl_->find(key)->dict;
}

void Dictionary::fail(const std::string& key, const std::string& message) const {
  const DictEntry* e = impl_->find(key);
  throw InputError(e ? e->where : impl_->where, message);
}

}  // namespace friction
