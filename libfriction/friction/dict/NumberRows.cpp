// Values files: see NumberRows.hpp.
#include "friction/dict/NumberRows.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>

#include "friction/core/InputError.hpp"
#include "friction/core/InputFile.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/dict/Number.hpp"

namespace friction {

std::string readValuesFile(const Dictionary& d, const std::string& key, const std::string& caseDir,
                           std::string& path) {
  path = (std::filesystem::path(caseDir) / d.getFileName(key)).lexically_normal().string();
  InputFileRole role;
  role.what = "a values file, rows of numbers, relative to the case folder";
  role.maxBytes = kMaxValuesFileBytes;
  role.namedAt = d.location(key);
  role.namedBy = "key '" + key + "'";
  role.tooLargeHint = "give the values on a coarser grid";
  return readInputFile(path, role);
}

NumberRows parseNumberRows(const std::string& file, std::string_view text, std::size_t columns,
                           const std::string& expected, bool increasing,
                           const std::string& firstName, const std::string& empty) {
  NumberRows out;
  out.file = file;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // a UTF-8 byte-order mark
  int lineNo = 0;
  while (!text.empty()) {
    ++lineNo;
    const std::size_t eol = std::min(text.find('\n'), text.size());
    const std::string_view line = text.substr(0, eol);
    text.remove_prefix(std::min(eol + 1, text.size()));
    std::vector<std::string_view> items;
    for (std::size_t i = 0; i < line.size();) {
      const std::size_t b = line.find_first_not_of(" \t\r", i);
      if (b == std::string_view::npos) break;
      const std::size_t e = std::min(line.find_first_of(" \t\r", b), line.size());
      items.push_back(line.substr(b, e - b));
      i = e;
    }
    if (items.empty() || items[0][0] == '#') continue;
    const SourceLocation where{file, lineNo};
    const std::string got =
        ", got '" + std::string(line.substr(0, line.find_last_not_of(" \t\r") + 1)) + "'";
    if (items.size() != columns)
      throw InputError(where, expected + got + " (" + std::to_string(items.size()) +
                                  (items.size() == 1 ? " item)" : " items)"));
    std::vector<double> v(columns);
    for (std::size_t k = 0; k < columns; ++k) {
      const std::optional<double> x = parseNumber(items[k]);
      if (!x) {
        const std::string why = whyNotANumber(items[k]);
        throw InputError(where, expected + got + ": '" + std::string(items[k]) + "' " +
                                    (why.empty() ? "is not a number" : why));
      }
      v[k] = *x;
    }
    if (increasing && !out.rows.empty() && !(v[0] > out.rows.back()[0]))
      throw InputError(where, expected + " with " + firstName + " increasing" + got + " after " +
                                  firstName + " = " + formatNumber(out.rows.back()[0]));
    out.rows.push_back(std::move(v));
    out.lines.push_back(lineNo);
  }
  if (out.rows.empty()) throw InputError(file, empty);
  return out;
}

}  // namespace friction
