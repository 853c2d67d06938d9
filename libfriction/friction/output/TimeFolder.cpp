// Atomic time folders: see TimeFolder.hpp.
#include "friction/output/TimeFolder.hpp"

#include <cstdio>
#include <filesystem>
#include <system_error>

#include "friction/core/InputError.hpp"

namespace friction {

namespace fs = std::filesystem;

TimeFolder::TimeFolder(const std::string& caseDir, const std::string& name)
    : partial_((fs::path(caseDir) / ("." + name + ".partial")).string()),
      final_((fs::path(caseDir) / name).string()) {
  std::error_code ec;
  fs::remove_all(partial_, ec);  // left over from a killed run
  fs::create_directories(partial_, ec);
  if (ec)
    throw InputError(partial_, "cannot create the time folder being written (" + ec.message() +
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
    throw InputError(p.parent_path().string(),
                     "cannot create folder (" + ec.message() + "); expected a writable case folder");
  return p.string();
}

void TimeFolder::commit() {
  std::error_code ec;
  // rename() cannot replace a non-empty folder: move the old one aside first, so that at any
  // instant one complete folder of this name exists or is recoverable (.old).
  const fs::path finalPath(final_);
  const std::string old = (finalPath.parent_path() / ("." + finalPath.filename().string() + ".old")).string();
  fs::remove_all(old, ec);
  if (fs::exists(final_)) {
    fs::rename(final_, old, ec);
    if (ec) throw InputError(final_, "cannot replace the existing time folder (" + ec.message() + ")");
  }
  fs::rename(partial_, final_, ec);
  if (ec) throw InputError(final_, "cannot create the time folder (" + ec.message() + ")");
  committed_ = true;
  fs::remove_all(old, ec);
}

}  // namespace friction
