// Atomic file writes: see AtomicFile.hpp.
#include "friction/core/AtomicFile.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "friction/core/InputError.hpp"

namespace friction {

namespace fs = std::filesystem;

void writeTextAtomic(const std::string& path, const std::string& text) {
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw InputError(path, "cannot write: the folder '" + folder.string() + "' does not exist");

  // A reader (or a crash) sees either the old file or the complete new one: write a temporary
  // file beside the target, flush it to disk, then rename it over the target.
  std::string temp = (folder / ("." + target.filename().string() + ".tmpXXXXXX")).string();
  const int fd = ::mkstemp(temp.data());
  if (fd < 0)
    throw InputError(path, "cannot write: cannot create a file in the folder '" + folder.string() +
                               "' (" + std::strerror(errno) + ")");
  const auto failAndClean = [&](const std::string& what) {
    const int err = errno;
    ::close(fd);
    ::unlink(temp.c_str());
    throw InputError(path, "cannot write: " + what + " (" + std::strerror(err) + ")");
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
    throw InputError(path, std::string("cannot write: ") + std::strerror(err));
  }
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    throw InputError(
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
