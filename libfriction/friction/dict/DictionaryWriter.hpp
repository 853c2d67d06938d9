// DictionaryWriter: writes OpenFOAM-syntax dictionaries (FoamFile header, nested
// sub-dictionaries, scalars, vectors, sized lists) that OpenFOAM's foamDictionary reads back,
// and that Dictionary::read reads back to the same values.
//
// What OpenFOAM cannot read is refused with an exception (a programming error, not user input):
// std::invalid_argument for a key or word outside [A-Za-z_][A-Za-z0-9_.:<>,+-]* or a string with
// an odd run of backslashes before a quote, a newline or its end; std::domain_error for inf,
// nan or a magnitude above 1e300 (OpenFOAM's VGREAT).
#pragma once

#include <array>
#include <sstream>
#include <string>
#include <vector>

#include "friction/core/Types.hpp"

namespace friction {

class DictionaryWriter {
 public:
  /// Starts the text with a FoamFile header: version 2.0; format ascii; class; object.
  /// note, if non-empty, goes in as the header's "note" string.
  DictionaryWriter(const std::string& className, const std::string& object,
                   const std::string& note = "");

  /// Significant digits for scalars, 1 to 17 (default 17: round-trips a double exactly, written
  /// as the shortest text that does, e.g. 0.1).
  void setPrecision(int digits);

  void beginDict(const std::string& key);
  void endDict();

  void entry(const std::string& key, double value);
  void entry(const std::string& key, int value);
  void entry(const std::string& key, long value);
  void entryWord(const std::string& key, const std::string& word);
  void entryString(const std::string& key, const std::string& text);  // quoted
  void entry(const std::string& key, const Vector2& value);
  void entry(const std::string& key, const std::vector<double>& list);
  void entry(const std::string& key, const std::vector<int>& list);
  void entry(const std::string& key, const std::vector<Vector2>& list);
  void entry(const std::string& key, const std::vector<Point>& list);  // (x y z) each
  void entryWords(const std::string& key, const std::vector<std::string>& words);
  template <std::size_t N>
  void entry(const std::string& key, const std::vector<std::array<int, N>>& tuples);
  /// A verbatim value (already in OpenFOAM syntax), e.g. "nonuniform List<vector> 2((0 0) (1 1))".
  void entryRaw(const std::string& key, const std::string& raw);
  /// A "// text" comment line.
  void comment(const std::string& text);

  /// The complete text (all dictionaries must be closed).
  std::string str() const;
  /// Write to path atomically: a temporary file in the same folder, then rename. Throws
  /// InputError naming the path if the folder is missing or not writable.
  void writeAtomic(const std::string& path) const;

 private:
  void indent();
  std::string number(double x) const;

  std::ostringstream out_;
  int depth_ = 0;
  int precision_ = 17;
};

}  // namespace friction
