// InputFile: opening and reading the files a case names, regular files only (InputFile.hpp).
#include "friction/core/InputFile.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace friction {

namespace {

/// What a stat says a file is, when it is not a regular file.
std::string kindOf(const struct stat& st) {
  if (S_ISDIR(st.st_mode)) return "it is a folder, not a file";
  if (S_ISFIFO(st.st_mode))
    return "it is a FIFO (named pipe), not a regular file: reading it would wait for a writer";
  if (S_ISCHR(st.st_mode))
    return "it is a character device (such as /dev/zero or a terminal), not a regular file";
  if (S_ISBLK(st.st_mode)) return "it is a block device, not a regular file";
  if (S_ISSOCK(st.st_mode)) return "it is a socket, not a regular file";
  return "it is not a regular file";
}

[[noreturn]] void fail(const std::string& path, const InputFileRole& role,
                       const std::string& reason) {
  const std::string expected = role.what.empty() ? "" : " (expected " + role.what + ")";
  if (role.namedBy.empty()) throw InputError(path, "cannot open: " + reason + expected);
  throw InputError(role.namedAt,
                   role.namedBy + ": cannot open '" + path + "': " + reason + expected);
}

/// sizePhrase: "is 200 MiB (209715200 bytes), larger than", or how the file went beyond.
[[noreturn]] void failTooLarge(const std::string& path, const InputFileRole& role,
                               const std::string& sizePhrase) {
  std::string msg = sizePhrase + " the limit of " + formatBytes(role.maxBytes) +
                    (role.what.empty() ? "" : " for " + role.what);
  if (!role.tooLargeHint.empty()) msg += "; " + role.tooLargeHint;
  if (role.namedBy.empty()) throw InputError(path, msg);
  throw InputError(role.namedAt, role.namedBy + ": '" + path + "' " + msg);
}

std::string sizeText(std::uint64_t bytes) {
  const std::string exact = std::to_string(bytes) + " bytes";
  const std::string rounded = formatBytes(bytes);
  return rounded == exact ? exact : rounded + " (" + exact + ")";
}

}  // namespace

std::string formatBytes(std::uint64_t bytes) {
  static const char* const units[] = {"KiB", "MiB", "GiB", "TiB"};
  if (bytes < 1024) return std::to_string(bytes) + " bytes";
  double x = static_cast<double>(bytes);
  int u = -1;
  while (x >= 1024 && u < 3) {
    x /= 1024;
    ++u;
  }
  char buf[32];
  // Whole numbers as such ("8 MiB"), others with one decimal ("1.5 GiB").
  if (x == static_cast<double>(static_cast<std::uint64_t>(x)))
    std::snprintf(buf, sizeof buf, "%llu %s", static_cast<unsigned long long>(x), units[u]);
  else
    std::snprintf(buf, sizeof buf, "%.1f %s", x, units[u]);
  return buf;
}

InputFileHandle openInputFile(const std::string& path, const InputFileRole& role) {
  // stat first, so that a device is refused without being opened (opening some has effects);
  // fstat after, on what was opened, so that a file swapped in between is refused too.
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    fail(path, role, errno == ENOENT ? "no such file" : std::strerror(errno));
  if (!S_ISREG(st.st_mode)) fail(path, role, kindOf(st));
  if (static_cast<std::uint64_t>(st.st_size) > role.maxBytes)
    failTooLarge(path, role,
                 "is " + sizeText(static_cast<std::uint64_t>(st.st_size)) + ", larger than");
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) fail(path, role, std::strerror(errno));
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    const std::string reason = S_ISREG(st.st_mode) ? std::strerror(errno) : kindOf(st);
    ::close(fd);
    fail(path, role, reason);
  }
  // Regular files ignore O_NONBLOCK; clearing it keeps the stream's reads the usual ones.
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  std::FILE* f = ::fdopen(fd, "rb");
  if (!f) {
    const int e = errno;
    ::close(fd);
    fail(path, role, std::strerror(e));
  }
  return InputFileHandle(f, &std::fclose);
}

std::string readInputFile(const std::string& path, const InputFileRole& role) {
  const InputFileHandle f = openInputFile(path, role);
  struct stat st {};
  std::string text;
  if (::fstat(::fileno(f.get()), &st) == 0) text.reserve(static_cast<std::size_t>(st.st_size));
  char buffer[1 << 16];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, f.get())) > 0) {
    // A file that grows while it is read (a log being written) is held to the same bound.
    if (text.size() + n > role.maxBytes) failTooLarge(path, role, "grew while it was read, beyond");
    text.append(buffer, n);
  }
  if (std::ferror(f.get())) fail(path, role, std::string("read error: ") + std::strerror(errno));
  return text;
}

}  // namespace friction
