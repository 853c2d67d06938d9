// Atomic time folders: see TimeFolder.hpp.
#include "friction/output/TimeFolder.hpp"

#include <filesystem>
#include <set>
#include <system_error>
#include <vector>

#include "friction/core/OutputError.hpp"

namespace friction {

namespace fs = std::filesystem;

TimeFolder::TimeFolder(const std::string& caseDir, const std::string& name)
    : partial_((fs::path(caseDir) / ("." + name + ".partial")).string()),
      final_((fs::path(caseDir) / name).string()) {
  std::error_code ec;
  fs::remove_all(partial_, ec);  // left over from a killed run
  fs::create_directories(partial_, ec);
  if (ec)
    throw OutputError(partial_, "cannot create the time folder being written (" + ec.message() +
                                    "); expected a writable case folder");
}

TimeFolder::~TimeFolder() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(partial_, ec);
  }
}

std::string TimeFolder::file(const std::string& relative) const {
  const fs::path p = fs::path(partial_) / relative;
  std::error_code ec;
  fs::create_directories(p.parent_path(), ec);
  if (ec)
    throw OutputError(p.parent_path().string(), "cannot create folder (" + ec.message() +
                                                    "); expected a writable case folder");
  return p.string();
}

void TimeFolder::commit() {
  std::error_code ec;
  // rename() cannot replace a non-empty folder: move the old one aside first, so that at any
  // instant one complete folder of this name exists or is recoverable (.old).
  const fs::path finalPath(final_);
  const std::string old =
      (finalPath.parent_path() / ("." + finalPath.filename().string() + ".old")).string();
  fs::remove_all(old, ec);
  if (fs::exists(final_)) {
    // What the user put under a time's name is theirs (issue 26: a folder of notes replaced).
    const std::string foreign = notWrittenBySolver(final_);
    if (!foreign.empty())
      throw OutputError(final_, "a folder of this time's name that frictionSolver did not write (" +
                                    foreign +
                                    "): not replaced; move it out of the case, then continue "
                                    "with startFrom latestTime");
    fs::rename(final_, old, ec);
    if (ec)
      throw OutputError(final_, "cannot replace the existing time folder (" + ec.message() + ")");
  }
  fs::rename(partial_, final_, ec);
  if (ec) throw OutputError(final_, "cannot create the time folder (" + ec.message() + ")");
  committed_ = true;
  fs::remove_all(old, ec);
}

int TimeFolder::removeLeftovers(const std::string& caseDir) {
  const auto endsWith = [](const std::string& s, const std::string& end) {
    return s.size() > end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
  };
  std::error_code ec;
  std::vector<fs::path> leftovers;
  for (const auto& e : fs::directory_iterator(caseDir, ec)) {
    const std::string name = e.path().filename().string();
    if (name[0] == '.' && e.is_directory(ec) &&
        (endsWith(name, ".partial") || endsWith(name, ".old")))
      leftovers.push_back(e.path());
  }
  for (const auto& p : leftovers) fs::remove_all(p, ec);
  return static_cast<int>(leftovers.size());
}

std::string TimeFolder::notWrittenBySolver(const std::string& path) {
  std::error_code ec;
  if (!fs::is_directory(path, ec)) return "it is not a folder";
  // The files of a time folder (FrictionCase::writeTimeFolder), and the folders they sit in.
  static const std::set<std::string> files = {"D", "solverStatus", "uniform/frictionState"};
  static const std::set<std::string> folders = {"uniform", "fractures"};
  const fs::path root(path);
  for (auto it = fs::recursive_directory_iterator(root, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    const fs::path rel = it->path().lexically_relative(root);
    const std::string name = rel.generic_string();
    const bool isFolder = it->is_directory(ec) && !it->is_symlink(ec);
    const bool isFile = it->is_regular_file(ec) && !it->is_symlink(ec);
    const bool table = isFile && rel.parent_path() == "fractures" && rel.extension() == ".dat";
    if ((isFolder && folders.count(name)) || (isFile && (files.count(name) || table))) continue;
    return "it holds '" + name + "', which frictionSolver does not write";
  }
  if (ec) return "it cannot be read (" + ec.message() + ")";
  if (!fs::is_regular_file(root / "uniform" / "frictionState", ec))
    return "it has no uniform/frictionState";
  return "";
}

}  // namespace friction
