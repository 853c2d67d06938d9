// Checks shared by the 2D and 3D stability suites: the fields of a solverStatus file, and
// "nothing non-finite written" over a time folder.
#pragma once

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../regression/CaseRunner.hpp"

namespace friction::regression {

/// Fields of a time folder's solverStatus ("key value;" lines).
inline std::map<std::string, std::string> readStatus(const fs::path& file) {
  std::map<std::string, std::string> m;
  std::istringstream in(readText(file));
  for (std::string line; std::getline(in, line);) {
    std::istringstream s(line);
    std::string k, v;
    if (s >> k >> v && !v.empty() && v.back() == ';') m[k] = v.substr(0, v.size() - 1);
  }
  return m;
}

/// No NaN or Inf in any file of the time folder `dir`: a tip's or a junction's row of a
/// fracture table holds the body's stress there, finite like every other value.
inline void checkWrittenFinite(const fs::path& dir) {
  for (const auto& f : fs::recursive_directory_iterator(dir)) {
    if (!f.is_regular_file()) continue;
    INFO(f.path().string());
    std::istringstream in(readText(f.path()));
    for (std::string line; std::getline(in, line);) {
      std::vector<std::string> items;
      std::istringstream s(line);
      for (std::string item; s >> item;) items.push_back(item);
      INFO(line);
      for (const std::string& item : items)
        for (const char* bad : {"nan", "NaN", "inf", "Inf"})
          CHECK(item.find(bad) == std::string::npos);
    }
  }
}

/// J never increases within a step of postProcessing/convergence.dat (Newton's merit line
/// search; Armijo's decrease rule), every J finite, and the history not empty.
inline void checkHistoryDecreasing(const fs::path& caseDir) {
  std::istringstream hist(readText(caseDir / "postProcessing" / "convergence.dat"));
  double lastTime = NAN, lastJ = 0;
  int records = 0;
  for (std::string line; std::getline(hist, line);) {
    if (line.empty() || line[0] == '#') continue;
    ++records;
    std::istringstream s(line);
    double t, k, J;
    s >> t >> k >> J;
    CHECK(std::isfinite(J));
    if (t == lastTime) CHECK(J <= lastJ * (1 + 1e-12) + 1e-300);
    lastTime = t;
    lastJ = J;
  }
  CHECK(records > 0);  // an empty history would check nothing
}

}  // namespace friction::regression
