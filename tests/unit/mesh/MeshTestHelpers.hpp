// Helpers for the mesh reader tests: a temporary folder that cleans up after itself (tests
// never write into the source tree), writing small files, running the real meshing tools,
// and checking that a malformed file is rejected with file:line and the expectation.
#pragma once

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <sys/wait.h>

#include "friction/core/InputError.hpp"
#include "friction/mesh/MeshReader.hpp"

namespace friction::test {

/// A fresh folder under the system's temporary folder, removed with its contents.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "frictionMeshXXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary folder");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string file(const std::string& name) const { return (path_ / name).string(); }

  /// Write `content` to `name` in this folder; returns the full path.
  std::string write(const std::string& name, const std::string& content) const {
    const std::string p = file(name);
    std::ofstream out(p, std::ios::binary);
    out << content;
    REQUIRE(out.good());
    return p;
  }

 private:
  std::filesystem::path path_;
};

/// Run a shell command in `dir`, output to a log file there; returns the exit code.
inline int run(const TempDir& dir, const std::string& command) {
  const std::string log = dir.file("tool.log");
  const int status =
      std::system(("cd '" + dir.file("") + "' && " + command + " > '" + log + "' 2>&1").c_str());
  if (status != 0) {
    std::ifstream in(log);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    UNSCOPED_INFO("output of `" << command << "`:\n" << text);
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Write `content` to `name` in `dir`, read it with `read` and require an InputError whose
/// message starts with "<dir>/<name>:<line>:" (line 0: the file as a whole) and contains every
/// string of `expected`.
template <typename Reader>
void requireReadError(const TempDir& dir, const std::string& name, const std::string& content,
                      int line, const std::vector<std::string>& expected, Reader read) {
  const std::string path = dir.write(name, content);
  bool thrown = false;
  try {
    read(path);
  } catch (const InputError& e) {
    thrown = true;
    const std::string what = e.what();
    INFO("message: " << what);
    CHECK(e.location().file == path);
    CHECK(e.location().line == line);
    const std::string where = line > 0 ? path + ":" + std::to_string(line) : path;
    CHECK(what.rfind(where + ": ", 0) == 0);
    for (const std::string& s : expected) {
      INFO("expected to contain: " << s);
      CHECK(what.find(s) != std::string::npos);
    }
  }
  INFO("reading " << name << " should have thrown an InputError");
  CHECK(thrown);
}

inline void requireReadError(const TempDir& dir, const std::string& name,
                             const std::string& content, int line,
                             const std::vector<std::string>& expected) {
  requireReadError(dir, name, content, line, expected,
                   [](const std::string& p) { return readMesh(p); });
}

/// A mesh with its node numbering taken out: each triangle and edge as the coordinates of
/// its vertices, in file order and orientation. Two readings of the same mesh written with
/// different node numbers give equal Geometry.
struct Geometry {
  using Point = std::pair<double, double>;
  std::vector<Point> points;  // sorted
  std::vector<std::tuple<Point, Point, Point, int>> triangles;
  std::vector<std::tuple<Point, Point, int>> edges;

  bool operator==(const Geometry& o) const {
    return points == o.points && triangles == o.triangles && edges == o.edges;
  }
};

inline Geometry geometryOf(const Mesh& m) {
  Geometry g;
  const auto p = [&](Index i) { return Geometry::Point(m.points[i].x(), m.points[i].y()); };
  for (Index i = 0; i < m.numPoints(); ++i) g.points.push_back(p(i));
  std::sort(g.points.begin(), g.points.end());
  for (Index t = 0; t < m.numCells(); ++t) {
    const auto& v = m.cell(t);
    g.triangles.emplace_back(p(v[0]), p(v[1]), p(v[2]), m.cellRegion[t]);
  }
  for (std::size_t e = 0; e < m.facetLabel.size(); ++e)
    g.edges.emplace_back(p(m.facet(e)[0]), p(m.facet(e)[1]), m.facetLabel[e]);
  return g;
}

}  // namespace friction::test
