// Dictionary: reader for OpenFOAM-syntax dictionaries, with typed, range-checked access and
// detection of entries the program never reads.
//
// Grammar accepted (OpenFOAM's, restricted to what cases need):
//   file       := [FoamFile-dict] entry*
//   entry      := key value-item* ';'  |  key '{' entry* '}'  |  directive  |  '$' name ';'
//   value-item := word | number | "string" | list | '$' name
//   list       := [N] '(' value-item* ')'            N, if given, must equal the item count
//   directive  := '#include' "file"                  (relative to the including file)
//              |  '#includeIfPresent' "file"         (the same; nothing if the file is missing)
//   comments   := '//' to end of line, '/*... */'
// A word may contain letters, digits and _. : < >, - + (so "List<scalar>" and "uniform"
// are words); the reader also accepts any other character but whitespace, '"' and ; { } ( )
// (so constant/mesh.msh is a word). N is a list size when '(' follows it directly ("3(1 2 3)")
// or on a later line (OpenFOAM's layout for long lists); "0 (0 0)" on one line is a number and
// a list, as in table rows. In strings, \" is a quote and a backslash at the end of a line
// continues the string on the next (OpenFOAM's escapes). '$name' (or '${name}') expands to the
// value of entry 'name' defined before it in the current or an enclosing dictionary; 'key
// $name;' with a dictionary copies it and '$name;' merges its entries. An entry used by '$'
// counts as read. A key given twice in one dictionary of one file is an error naming both
// lines (OpenFOAM takes the last one; a case that says two things is ambiguous). An entry may
// override one that came from an #include file or a '$name;' merge, as in OpenFOAM: it replaces
// the earlier entry in its place, and a dictionary repeated so is merged into the earlier one
// (checked with foamDictionary v1912). A number is a whole finite decimal token (Number.hpp): "0,9"
// is a word, refused with the reason wherever a number is expected, and "1e400" is an error when
// read. Beyond OpenFOAM's rules, on purpose: the FoamFile header is optional (its 'format' must be
// ascii when given), and a UTF-8 byte-order mark at the start of a file is skipped.
//
// Files are opened with readInputFile (core/InputFile.hpp): only regular files, so a FIFO or a
// device named by #include is an error at the #include, not a read that never ends. What a
// dictionary may hold is bounded (DictionaryLimits): the reader keeps tens of bytes per item.
//
// Every entry keeps its file:line. Accessors mark an entry as read; checkAllRead() then
// reports the first entry the program never read, naming its file:line and the nearest
// valid key (the keys the program asked for in that dictionary).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "friction/core/InputError.hpp"
#include "friction/core/Types.hpp"
#include "friction/dict/Value.hpp"

namespace friction {

/// Closed interval [min, max] for range checks; use minExclusive for "> 0" bounds.
struct Bounds {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool minExclusive = false;
  bool maxExclusive = false;

  static Bounds positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Bounds nonNegative() { return {0.0, std::numeric_limits<double>::infinity()}; }
  static Bounds closed(double lo, double hi) { return {lo, hi}; }
  bool contains(double x) const;
  /// Human-readable description, e.g. "> 0", "in [0, 0.5)".
  std::string str() const;
};

/// Bounds on what one dictionary may hold; beyond them reading fails with the bound, the file
/// and the line. The reader keeps each item as a Value (its text, its line, its list): about 40
/// times the bytes of a list of numbers, so large data belongs in a values file (NumberRows.hpp),
/// which has its own bound and a compact reader.
struct DictionaryLimits {
  /// Bytes of text: the file and every file it #includes, together.
  std::uint64_t bytes = 0;
  /// Items in any one list.
  std::size_t listItems = 0;
  /// Items (words, numbers, strings, lists) the whole dictionary holds, '$name' copies included.
  std::size_t totalItems = 0;
  /// What to do instead, in the message when a bound is passed.
  const char* hint = "";

  /// The dictionaries of a case, written by hand: settings, tables, short lists.
  static DictionaryLimits caseFile();
  /// Dictionaries the programs write with one item per node or cell (constant/splitMesh, a
  /// time folder's uniform/frictionState): bounded by the size of the mesh they describe.
  static DictionaryLimits dataFile();
};

/// A table of (time, vector) rows, e.g. ((0 (0 0)) (1 (-0.02 -0.025))). Scalar rows
/// ((0 1) (1 2)) give vectors of size 1.
struct Table {
  std::vector<double> x;
  std::vector<std::vector<double>> y;
};

class Dictionary {
 public:
  Dictionary();
  ~Dictionary();
  Dictionary(Dictionary&&) noexcept;
  Dictionary& operator=(Dictionary&&) noexcept;
  Dictionary(const Dictionary&);
  Dictionary& operator=(const Dictionary&);

  /// Parse a file (following #include). Throws InputError naming file:line on syntax errors,
  /// "cannot open" when the file (or an included one) is missing or not a regular file, and
  /// the bound when one of limits is passed. The FoamFile header, if present, is kept as the
  /// sub-dictionary "FoamFile" and counts as read.
  static Dictionary read(const std::string& path,
                         const DictionaryLimits& limits = DictionaryLimits::caseFile());
  /// Parse text; sourceName stands in for the file name in messages; includes are resolved
  /// relative to baseDir.
  static Dictionary parse(const std::string& text, const std::string& sourceName,
                          const std::string& baseDir = ".",
                          const DictionaryLimits& limits = DictionaryLimits::caseFile());

  /// Scope name for messages: the file path, plus "/sub/dict" for sub-dictionaries.
  const std::string& scope() const;
  /// Where this dictionary starts (file:line of its '{', or the file).
  SourceLocation location() const;
  /// Where an entry starts. Throws std::out_of_range if absent (internal use).
  SourceLocation location(const std::string& key) const;

  /// Keys in file order (does not mark anything as read).
  std::vector<std::string> keys() const;

  /// True if the key exists. Registers the key as valid (for suggestions) but does not mark
  /// the entry as read.
  bool found(const std::string& key) const;
  bool isDict(const std::string& key) const;

  /// Required sub-dictionary; error if missing or not a dictionary.
  const Dictionary& subDict(const std::string& key) const;
  /// Optional sub-dictionary (nullptr if absent; error if present but not a dictionary).
  const Dictionary* findDict(const std::string& key) const;

  /// Raw items of a value entry (marks it read). Error if missing or if it is a dictionary.
  const std::vector<Value>& values(const std::string& key) const;

  // Typed access. Each marks the entry as read and throws InputError with file:line, the
  // key and what was expected. A single number or vector may follow "uniform" (a constant
  // field); a list may follow "uniform", "nonuniform" or "List<type>".
  double getScalar(const std::string& key, Bounds bounds = {}) const;
  double getScalarOr(const std::string& key, double def, Bounds bounds = {}) const;
  long getInt(const std::string& key, Bounds bounds = {}) const;
  long getIntOr(const std::string& key, long def, Bounds bounds = {}) const;
  bool getBool(const std::string& key) const;  // true/false, yes/no, on/off
  bool getBoolOr(const std::string& key, bool def) const;
  /// A single word (or quoted string).
  std::string getWord(const std::string& key) const;
  std::string getWordOr(const std::string& key, const std::string& def) const;
  /// A word that must be one of choices; error lists them ("valid types are:...").
  std::string getChoice(const std::string& key, const std::vector<std::string>& choices) const;
  std::string getChoiceOr(const std::string& key, const std::vector<std::string>& choices,
                          const std::string& def) const;
  /// A file name (quoted string or word).
  std::string getFileName(const std::string& key) const;
  /// (x y)
  Vector2 getVector(const std::string& key) const;
  std::vector<double> getScalarList(const std::string& key) const;
  std::vector<long> getIntList(const std::string& key) const;
  std::vector<std::string> getWordList(const std::string& key) const;
  std::vector<Vector2> getVectorList(const std::string& key) const;
  /// List of 3-vectors, e.g. ((0 0 0) (1 0 0)).
  std::vector<Point> getPointList(const std::string& key) const;
  /// List of fixed-size integer tuples, e.g. ((0 1 2) (2 3 4)).
  template <std::size_t N>
  std::vector<std::array<long, N>> getIntTupleList(const std::string& key) const;
  /// ((t0 y0) (t1 y1)...) with y a number or a list of numbers, all of the same size;
  /// x strictly increasing.
  Table getTable(const std::string& key) const;

  /// Which of several groups of alternative keys the dictionary uses, e.g. {{"E", "nu"},
  /// {"lambda", "mu"}}: the index of the group with a key present (the group's keys are then
  /// read by the caller), def when no key of any group is present. InputError when keys of two
  /// groups are present ("keys 'E' (line 9) and 'lambda' in <scope> belong to alternatives: give E
  /// and nu, or lambda and mu, not both"), or when none is and there is no def. Every key is
  /// registered as valid.
  std::size_t alternative(const std::vector<std::vector<std::string>>& groups,
                          std::optional<std::size_t> def = std::nullopt) const;

  /// Throws InputError for the first entry (depth first, file order) that no accessor read:
  /// "file:line: unknown key 'nus' in <scope>; did you mean 'nu'? (valid keys: E, nu)". The
  /// suggestion is made only when a valid key is within typing distance (Suggest.hpp). A key
  /// that another dictionary of the file (below this one, not a sibling) asked for is said to
  /// belong there: "unknown key 'tolerance' in <file>/control; it belongs in control/optimizer".
  /// Sub-dictionaries that were read are checked recursively.
  void checkAllRead() const;
  /// Mark everything in this dictionary (recursively) as read, e.g. for a block that
  /// belongs to another program.
  void markAllRead() const;
  /// A key that users bring from other codes and this dictionary does not read: if it is
  /// there, checkAllRead says "unknown key 'K' in <scope>: <advice>" (the way forward) instead
  /// of guessing a spelling.
  void advise(const std::string& key, const std::string& advice) const;

  // ---- building (used by tests and by code that assembles dictionaries) ----
  /// Add or replace a value entry.
  void set(const std::string& key, std::vector<Value> items, SourceLocation where = {});
  /// Add or replace a sub-dictionary; returns it.
  Dictionary& setDict(const std::string& key, SourceLocation where = {});

  /// Throw an InputError located at the entry 'key' (or at the dictionary if key is absent).
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace friction
