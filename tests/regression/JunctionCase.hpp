// A copy of the tests-only case tests/regression/cases/junctions (fractures meeting at
// junctions; see its junctions.geo) for the regression and stability tests: its fractures
// and their friction, its mesh from gmsh or written by the test, its load.
#pragma once

#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "CaseRunner.hpp"
#include "friction/mesh/Mesh.hpp"

namespace friction::regression {

/// A copy of tests/regression/cases/junctions with the given fractures (Coulomb, their
/// friction coefficients) and mesh (made by `makeMesh` into constant/mesh/junctions.msh).
class JunctionCase {
 public:
  JunctionCase(const std::string& label,
               const std::vector<std::pair<std::string, double>>& fractures)
      : c_("tests:junctions", "junctions/" + label) {
    for (const auto& [name, mu] : fractures) names_ += (names_.empty() ? "" : " ") + name;
    writeMeshDict("");
    std::ostringstream fp;
    fp << "FoamFile { version 2.0; format ascii; class dictionary; object fractureProperties; }\n";
    for (const auto& [name, mu] : fractures)
      fp << name << " { law coulomb; frictionCoefficient " << std::setprecision(17) << mu
         << "; }\n";
    writeText(c_.dir() / "constant" / "fractureProperties", fp.str());
  }

  const fs::path& dir() const { return c_.dir(); }
  /// Replace every fracture's entry in constant/fractureProperties by `entry` (the body of
  /// its braces, e.g. "law tresca; threshold 2e6;").
  void properties(const std::string& entry) {
    std::string fp =
        "FoamFile { version 2.0; format ascii; class dictionary; object fractureProperties; }\n";
    std::istringstream in(names_);
    for (std::string name; in >> name;) fp += name + " { " + entry + " }\n";
    writeText(c_.dir() / "constant" / "fractureProperties", fp);
  }

  /// The case runner itself (for the stability suite's checks).
  Case& runner() { return c_; }
  fs::path meshFile() const { return c_.dir() / "constant" / "mesh" / "junctions.msh"; }

  /// gmsh on junctions.geo with `-setnumber` options ("branch 1 theta 120").
  void gmsh(const std::string& options) {
    std::istringstream in(options);
    std::string args;
    for (std::string name, value; in >> name >> value;) args += " -setnumber " + name + " " + value;
    const fs::path geo = c_.dir() / "constant" / "mesh" / "junctions.geo";
    const std::string cmd =
        "gmsh -2 -format msh41" + args + " '" + geo.string() + "' -o '" + meshFile().string() + "'";
    INFO(cmd << "\n" << readText(c_.dir() / "log.gmsh"));
    REQUIRE(run(cmd, c_.dir() / "log.gmsh") == 0);
    fs::remove(c_.dir() / "log.gmsh");
  }

  /// FreeFEM on junctions.edp (the T), writing the mesh; meshDict names its labels.
  void freefemScript() {
    const fs::path dir = c_.dir() / "constant" / "mesh";
    const std::string cmd = "cd '" + dir.string() +
                            "' && FF_LOADPATH='/usr/lib/freefem++;./' FreeFem++ -nw -ns -v 0 "
                            "junctions.edp -out junctions.msh";
    INFO(cmd << "\n" << readText(c_.dir() / "log.FreeFem++"));
    REQUIRE(run(cmd, c_.dir() / "log.FreeFem++") == 0);
    fs::remove(c_.dir() / "log.FreeFem++");
    writeMeshDict("patches { outer 1; main 5; branch 7; }\n");
  }

  /// Replace the mesh by a FreeFEM .msh of `m` (which names its patches in meshDict).
  void freefem(const friction::Mesh& m) {
    fs::remove(meshFile());
    writeFreeFem(meshFile(), m);
    std::string patches = "patches {";
    for (const auto& [label, name] : m.labelNames)
      patches += " " + name + " " + std::to_string(label) + ";";
    writeMeshDict(patches + " }\n");
  }

  void shear(double sxy) {
    std::ostringstream s;
    s << "stress      (-1e7 -1e7 " << sxy << ");";
    c_.edit("constant/effects", "stress +\\(-1e7 -1e7 5e6\\);", s.str());
  }
  void order(int p) {
    c_.edit("system/frictionSolution", "elementOrder +1;",
            "elementOrder " + std::to_string(p) + ";");
  }

  void solve() {
    const int rc = c_.solve();
    INFO(c_.log());
    REQUIRE(rc == 0);
    REQUIRE(c_.log().find("converged") != std::string::npos);
  }
  Table table(const std::string& fracture) const { return c_.namedTable("1", fracture); }
  std::string splitLog() const { return readText(c_.dir() / "log.splitFractureNodes"); }
  std::string log() const { return c_.log(); }

 private:
  /// system/meshDict: the mesh, the patches (a FreeFEM mesh has no names), the fractures.
  void writeMeshDict(const std::string& patches) {
    writeText(c_.dir() / "system" / "meshDict",
              "FoamFile { version 2.0; format ascii; class dictionary; object meshDict; }\n"
              "mesh \"constant/mesh/junctions.msh\";\n" +
                  patches + "fractures (" + names_ + ");\n");
  }

  Case c_;
  std::string names_;
};

}  // namespace friction::regression
