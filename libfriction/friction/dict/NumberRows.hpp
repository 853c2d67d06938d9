// NumberRows: the one reader of the plain values files a case may name (fracturePressure's
// "s p" file, the friction fields' "s value" and "x y [z] value" files): rows of numbers, one
// per line, read as strictly as a dictionary's numbers (Number.hpp), since a misread value
// changes a load or a friction bound silently.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace friction {

class Dictionary;

/// The rows of a values file, each with the line it came from.
struct NumberRows {
  std::string file;
  std::vector<std::vector<double>> rows;
  std::vector<int> lines;
};

/// The largest values file read: a few million rows, a few hundred MB once parsed.
constexpr std::uint64_t kMaxValuesFileBytes = std::uint64_t{64} << 20;

/// Read the file named by `key` (relative to caseDir) with readInputFile: InputError at the key
/// when it is missing, not a regular file (a FIFO, a device, a folder) or larger than
/// kMaxValuesFileBytes. The path is normalised (as it appears in messages).
std::string readValuesFile(const Dictionary& d, const std::string& key, const std::string& caseDir,
                           std::string& path);

/// Parse text as rows of exactly `columns` numbers. Blank lines and lines starting with '#' are
/// skipped, a UTF-8 byte-order mark is ignored. InputError at file:line otherwise, the message
/// starting with `expected` (e.g. "expected two numbers 's p' (arclength [m], pressure [Pa])").
/// increasing: the first column must increase strictly, named `firstName` in the message.
/// empty: the message when the file has no rows.
NumberRows parseNumberRows(const std::string& file, std::string_view text, std::size_t columns,
                           const std::string& expected, bool increasing,
                           const std::string& firstName, const std::string& empty);

}  // namespace friction
