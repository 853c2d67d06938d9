// A preloaded library (LD_PRELOAD) that kills its process at a chosen point of writing, for
// noDataLoss.sh: every file and time folder the solver writes appears by rename(), so "the
// N-th rename whose 'old -> new' contains S" names an exact instant (after the data, before
// it becomes visible). FRICTION_KILL_AT_RENAME="S|N": on that rename the process sends
// itself SIGKILL instead of renaming. Without the variable rename() is untouched.
#include <dlfcn.h>
#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <string>

extern "C" int rename(const char* oldPath, const char* newPath) {
  using Rename = int (*)(const char*, const char*);
  static const Rename real = reinterpret_cast<Rename>(dlsym(RTLD_NEXT, "rename"));
  static int seen = 0;
  if (const char* spec = std::getenv("FRICTION_KILL_AT_RENAME")) {
    const std::string s(spec);
    const std::size_t bar = s.rfind('|');
    const std::string what = s.substr(0, bar);
    const int n = bar == std::string::npos ? 1 : std::atoi(s.c_str() + bar + 1);
    const std::string both = std::string(oldPath) + " -> " + newPath;
    if (both.find(what) != std::string::npos && ++seen == n) ::kill(::getpid(), SIGKILL);
  }
  return real(oldPath, newPath);
}
