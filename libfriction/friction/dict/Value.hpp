// Value: one parsed item of an OpenFOAM-syntax entry (a word, a number, a quoted string or a
// parenthesised list of items). See Dictionary.hpp for the grammar.
#pragma once

#include <string>
#include <vector>

namespace friction {

struct Value {
  enum class Kind { Word, Number, String, List };

  Kind kind = Kind::Word;
  /// Word text, string contents (without quotes) or the number as written.
  std::string text;
  /// Numeric value when kind == Number.
  double number = 0.0;
  /// Items when kind == List ("3(1 2 3)" and "(1 2 3)" both give three items; the count is
  /// checked by the parser).
  std::vector<Value> items;
  /// Source line of the first character of this item.
  int line = 0;

  bool isWord() const { return kind == Kind::Word; }
  bool isNumber() const { return kind == Kind::Number; }
  bool isString() const { return kind == Kind::String; }
  bool isList() const { return kind == Kind::List; }

  /// The value as it would be written back ("(1 2)", "\"a b\"", "word", "1.5").
  std::string str() const;
  /// Kind name for error messages: "word", "number", "string", "list".
  std::string kindName() const;
};

}  // namespace friction
