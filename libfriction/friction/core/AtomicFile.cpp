// Atomic file writes: see AtomicFile.hpp.
#include "friction/core/AtomicFile.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "friction/core/OutputError.hpp"

namespace friction {

namespace fs = std::filesystem;

void writeTextAtomic(const std::string& path, const std::string& text) {
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw OutputError(path, "cannot write: the folder '" + folder.string() + "' does not exist");

  // A reader (or a crash) sees either the old file or the complete new one: write a temporary
  // file beside the target, flush it to disk, then rename it over the target.
  std::string temp = (folder / ("." + target.filename().string() + ".tmpXXXXXX")).string();
  const int fd = ::mkstemp(temp.data());
  if (fd < 0)
    throw OutputError(path, "cannot write: cannot create a file in the folder '" + folder.string() +
                                "' (" + std::strerror(errno) + ")");
  const auto failAndClean = [&](const std::string& what) {
    const int err = errno;
    ::close(fd);
    ::unlink(temp.c_str());
    throw OutputError(path, "cannot write: " + what + " (" + std::strerror(err) + ")");
  };
  // mkstemp creates the file private (0600); give it the permissions a new file would get.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  if (::fchmod(fd, 0666 & ~mask) != 0) failAndClean("cannot set permissions");
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      failAndClean("write error");
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) failAndClean("cannot flush to disk");
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    throw OutputError(path, std::string("cannot write: ") + std::strerror(err));
  }
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    throw OutputError(
        path, "cannot write: cannot replace the file (" + std::string(std::strerror(err)) + ")");
  }
  // Make the rename itself durable.
  const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

}  // namespace friction

namespace friction {

namespace {

bool isTemporaryName(const std::string& name) {
  // ".<target>.tmpXXXXXX" (mkstemp's six characters)
  const std::size_t at = name.rfind(".tmp");
  return name.size() > 1 && name[0] == '.' && at != std::string::npos && at > 0 &&
         name.size() == at + 4 + 6;
}

}  // namespace

int removeTemporaryFiles(const std::string& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return 0;
  int removed = 0;
  for (const auto& e : fs::directory_iterator(folder, ec))
    if (e.is_regular_file(ec) && isTemporaryName(e.path().filename().string()) &&
        fs::remove(e.path(), ec))
      ++removed;
  return removed;
}

AppendFile::AppendFile(const std::string& path, bool truncate) : path_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | (truncate ? O_TRUNC : 0),
               0666);
  if (fd_ < 0)
    throw OutputError(path, std::string("cannot open for writing (") + std::strerror(errno) + ")");
  struct stat st {};
  if (::fstat(fd_, &st) != 0) {
    const int err = errno;
    ::close(fd_);
    throw OutputError(path, std::string("cannot write (") + std::strerror(err) + ")");
  }
  size_ = st.st_size;
}

AppendFile::~AppendFile() {
  if (fd_ >= 0) ::close(fd_);
}

void AppendFile::append(const std::string& text) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : ENOSPC;
      // Cut back to the last whole record: a file that ends mid-line would be read as data.
      const bool cut = ::ftruncate(fd_, size_) == 0;
      throw OutputError(path_, std::string("cannot write (") + std::strerror(err) + ")" +
                                   (cut ? "" : "; its last line may be incomplete"));
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  size_ += static_cast<off_t>(text.size());
}

void AppendFile::sync() {
  if (::fsync(fd_) != 0)
    throw OutputError(path_, std::string("cannot flush to disk (") + std::strerror(errno) + ")");
}

}  // namespace friction
