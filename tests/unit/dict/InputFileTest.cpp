// The files a case names are read only when they are regular files (core/InputFile.hpp), by
// every reader: a dictionary and its #include, a values file (fracturePressure), a friction
// field's file, a mesh (by path and through system/meshDict). A FIFO would block the reader for
// ever, /dev/zero never ends (or read as empty), a folder or a socket is no text. Each read runs
// in a child process with an alarm, so that a reader that blocks fails the test instead of
// hanging the suite.
#include <catch2/catch.hpp>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>

#include <cstring>
#include <string>
#include <vector>

#include "DictTestSupport.hpp"
#include "friction/case/MeshSettings.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/effect/Effect.hpp"
#include "friction/law/FrictionField.hpp"
#include "friction/mesh/MeshReader.hpp"

using namespace friction;
using namespace friction::dicttest;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

/// A socket bound at path (unlinked, with its descriptor, at the end).
class BoundSocket {
 public:
  explicit BoundSocket(const std::string& path) : path_(path) {
    fd_ = ::socket(AF_UNIX, SOCK_STREAM, 0);
    REQUIRE(fd_ >= 0);
    sockaddr_un a{};
    a.sun_family = AF_UNIX;
    REQUIRE(path.size() < sizeof a.sun_path);
    std::strcpy(a.sun_path, path.c_str());
    REQUIRE(::bind(fd_, reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0);
  }
  ~BoundSocket() {
    ::close(fd_);
    ::unlink(path_.c_str());
  }
  BoundSocket(const BoundSocket&) = delete;
  BoundSocket& operator=(const BoundSocket&) = delete;

 private:
  std::string path_;
  int fd_ = -1;
};

struct Kind {
  std::string name;    // the section's name: the same in every run of the test case
  std::string path;    // absolute
  std::string reason;  // what the message says it is
};

}  // namespace

TEST_CASE("every file a case names is refused unless it is a regular file, naming who named it",
          "[dict][files]") {
  TempDir dir;
  const std::string fifo = (dir.path() / "fifo").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::filesystem::create_directories(dir.path() / "folder");
  const std::string socket = (dir.path() / "socket").string();
  const BoundSocket bound(socket);
  const std::vector<Kind> kinds = {
      {"a FIFO", fifo, "it is a FIFO (named pipe), not a regular file"},
      {"/dev/zero", "/dev/zero",
       "it is a character device (such as /dev/zero or a terminal), not a regular "
       "file"},
      {"a folder", (dir.path() / "folder").string(), "it is a folder, not a file"},
      {"a socket", socket, "it is a socket, not a regular file"},
  };
  const std::string caseDir = dir.path().string();
  // A quoted absolute path: every reader takes it as it is.
  const auto q = [](const std::string& p) { return "\"" + p + "\""; };

  for (const Kind& k : kinds) {
    DYNAMIC_SECTION(k.name) {
      INFO(k.path);
      // The dictionary itself (the case's layout names it: the message is at the path).
      CHECK_THAT(outcomeInChild([&] { Dictionary::read(k.path); }),
                 StartsWith("InputError: " + k.path + ": cannot open: " + k.reason));

      // #include and #includeIfPresent, at the line of the directive.
      for (const std::string directive : {"include", "includeIfPresent"}) {
        const std::string main =
            dir.write("main-" + directive, "a 1;\n#" + directive + " " + q(k.path) + "\n");
        CHECK_THAT(outcomeInChild([&] { Dictionary::read(main); }),
                   StartsWith("InputError: " + main + ":2: #" + directive + ": cannot open '" +
                              k.path + "': " + k.reason) &&
                       Contains("(expected a dictionary)"));
      }

      // A fracturePressure values file, at its key.
      const Dictionary effect = Dictionary::parse(
          "type fracturePressure;\nfracture crack;\nvalues " + q(k.path) + ";\n", "effects");
      CHECK_THAT(outcomeInChild([&] { Effect::New("pore", effect, {"crack"}, caseDir, 2); }),
                 StartsWith("InputError: effects:3: key 'values': cannot open '" + k.path +
                            "': " + k.reason));

      // A friction field's file (arclength and points), at its key.
      for (const std::string type : {"arclength", "points"}) {
        const Dictionary law = Dictionary::parse(
            "mu\n{\n    type " + type + ";\n    file " + q(k.path) + ";\n}\n", "friction");
        CHECK_THAT(outcomeInChild(
                       [&] { FrictionField::read(law, "mu", Bounds::nonNegative(), caseDir, 2); }),
                   StartsWith("InputError: friction:4: key 'file': cannot open '" + k.path +
                              "': " + k.reason));
      }

      // A mesh: read by path, and named by system/meshDict.
      CHECK_THAT(outcomeInChild([&] { readMesh(k.path); }),
                 StartsWith("InputError: " + k.path + ": cannot open: " + k.reason) &&
                     Contains("expected the mesh file"));
      const std::string meshDict =
          dir.write("case/system/meshDict", "mesh " + q(k.path) + ";\nfractures (crack);\n");
      CHECK_THAT(outcomeInChild([&] { MeshSettings::read((dir.path() / "case").string()); }),
                 StartsWith("InputError: " + meshDict + ":1: key 'mesh': cannot open '" + k.path +
                            "': " + k.reason));
    }
  }
  SECTION("a missing optional #include is still nothing, and a regular file still reads") {
    const std::string main =
        dir.write("main", "#includeIfPresent \"absent\"\n#include \"inc\"\nb 2;\n");
    dir.write("inc", "a 1;\n");
    CHECK(outcomeInChild([&] { Dictionary::read(main).getScalar("a"); }) == "no error");
  }
}
