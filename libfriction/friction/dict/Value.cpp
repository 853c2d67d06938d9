// Value: text form and kind names of parsed dictionary items, see Value.hpp. The text form
// follows the lexical rules in Tokenizer.hpp, so str() reads back as the same value.
#include "friction/dict/Value.hpp"

#include "friction/dict/Tokenizer.hpp"

namespace friction {

namespace {

void appendTo(std::string& out, const Value& v) {
  switch (v.kind) {
    case Value::Kind::Word:
      out += v.text;
      break;
    case Value::Kind::Number:
      // Values built in code (Dictionary::set) may carry the number only.
      out += v.text.empty() ? detail::shortestNumber(v.number) : v.text;
      break;
    case Value::Kind::String:
      out += detail::quoted(v.text);
      break;
    case Value::Kind::List:
      out += '(';
      for (std::size_t i = 0; i < v.items.size(); ++i) {
        if (i) out += ' ';
        appendTo(out, v.items[i]);
      }
      out += ')';
      break;
  }
}

}  // namespace

std::string Value::str() const {
  std::string s;
  appendTo(s, *this);
  return s;
}

std::string Value::kindName() const {
  switch (kind) {
    case Kind::Word:
      return "word";
    case Kind::Number:
      return "number";
    case Kind::String:
      return "string";
    case Kind::List:
      return "list";
  }
  return "value";
}

}  // namespace friction
