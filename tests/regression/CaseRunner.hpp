// Helpers for the regression tests: copy a case into the build tree, edit its dictionaries,
// (re)mesh it with the real FreeFEM/gmsh, run the real binaries, read the fracture tables.
// Tests never write into cases/.
#pragma once

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "friction/mesh/Mesh.hpp"

namespace friction::regression {

namespace fs = std::filesystem;

inline std::string readText(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void writeText(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

/// A 2D mesh as FreeFEM .msh: "nv nt ne", vertices "x y 0", triangles "a b c region"
/// (1-based, counter-clockwise), edges "a b label".
inline void writeFreeFem(const fs::path& path, const Mesh& m) {
  std::ofstream out(path);
  out.precision(17);
  out << m.points.size() << " " << m.cellRegion.size() << " " << m.facetLabel.size() << "\n";
  for (const auto& p : m.points) out << p.x() << " " << p.y() << " 0\n";
  for (std::size_t t = 0; t < m.cellRegion.size(); ++t)
    out << m.cell(t)[0] + 1 << " " << m.cell(t)[1] + 1 << " " << m.cell(t)[2] + 1 << " "
        << m.cellRegion[t] << "\n";
  for (std::size_t e = 0; e < m.facetLabel.size(); ++e)
    out << m.facet(e)[0] + 1 << " " << m.facet(e)[1] + 1 << " " << m.facetLabel[e] << "\n";
}

/// The "(x y z)" value lines of an OpenFOAM field file (e.g. <time>/D), in file order.
inline std::vector<std::string> vectorLines(const std::string& text) {
  std::vector<std::string> v;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);)
    if (!l.empty() && l[0] == '(' && l.back() == ')' && l.find(' ') != std::string::npos)
      v.push_back(l);
  return v;
}

/// Run a shell command; output goes to logFile. Returns the exit status.
inline int run(const std::string& command, const fs::path& logFile) {
  const std::string full = command + " > '" + logFile.string() + "' 2>&1";
  const int rc = std::system(full.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

/// A fracture table read by its header's column names (3D tables; see README, "Fracture
/// tables"): numbers per column, and the state column.
struct Table {
  std::vector<std::string> columns;       ///< numeric columns, in file order
  std::vector<std::vector<double>> rows;  ///< one value per column
  std::vector<std::string> state;         ///< per row
  std::vector<std::string> comments;      ///< the '#' lines after the header
  std::size_t column(const std::string& name) const {
    for (std::size_t i = 0; i < columns.size(); ++i)
      if (columns[i] == name) return i;
    FAIL("no column '" << name << "'");
    return 0;
  }
  double at(std::size_t row, const std::string& name) const { return rows[row][column(name)]; }
};

/// One row of <time>/fractures/<name>.dat.
struct Row {
  double s, x, y, slip, slipIncrement, sigmaN, tau, ST, residual;
  std::string state;  ///< stick, slip, open or tip (a tip's sigmaN, tau, ST: the body's stress)
};

class Case {
 public:
  /// Copy cases/<name> to <work>/<label> (fresh), without anything a run made: the case's
  /// own Allclean removes it (an earlier ./Allrun leaves time folders, VTK/, logs in cases/).
  /// A name "tests:<case>" copies tests/regression/cases/<case> (cases only the tests use).
  Case(const std::string& name, const std::string& label)
      : dir_(fs::path(FRICTION_WORK_DIR) / label) {
    fs::remove_all(dir_);
    fs::create_directories(dir_.parent_path());
    const fs::path source =
        name.rfind("tests:", 0) == 0
            ? fs::path(FRICTION_SOURCE_DIR) / "tests" / "regression" / "cases" / name.substr(6)
            : fs::path(FRICTION_SOURCE_DIR) / "cases" / name;
    REQUIRE(fs::is_directory(source));
    fs::copy(source, dir_, fs::copy_options::recursive);
    REQUIRE(std::system(("'" + (dir_ / "Allclean").string() + "' > /dev/null").c_str()) == 0);
  }

  const fs::path& dir() const { return dir_; }

  /// Replace the first match of regex `pattern` in a case file by `replacement`.
  void edit(const std::string& file, const std::string& pattern, const std::string& replacement) {
    const fs::path p = dir_ / file;
    const std::string text = readText(p);
    const std::string out = std::regex_replace(text, std::regex(pattern), replacement,
                                               std::regex_constants::format_first_only);
    REQUIRE(out != text);  // the edit must hit something, or the test tests nothing
    writeText(p, out);
  }

  /// Remesh with the case's own generator script and its options (e.g. "-n 20").
  void remesh(const std::string& options) {
    INFO(readText(dir_ / "log.mesh"));
    REQUIRE(run("cd '" + dir_.string() + "' && ./Allmesh " + options, dir_ / "log.mesh") == 0);
    fs::remove(dir_ / "log.mesh");
    for (const auto& e : fs::directory_iterator(dir_))
      if (e.path().filename().string().rfind("log.", 0) == 0) fs::remove(e.path());
  }

  /// splitFractureNodes then frictionSolver; returns the solver's exit status. The logs are
  /// kept in the case folder. ranks > 0: 'mpirun -np ranks frictionSolver -parallel'
  /// (oversubscribed; the case must select linearSolver mumps).
  int solve(int ranks = 0) {
    const fs::path bin = FRICTION_BIN_DIR;
    const int split = run(
        "'" + (bin / "splitFractureNodes").string() + "' -case '" + dir_.string() + "' -overwrite",
        dir_ / "log.splitFractureNodes");
    INFO(readText(dir_ / "log.splitFractureNodes"));
    REQUIRE(split == 0);
    const std::string launcher =
        ranks > 0 ? "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun "
                    "--oversubscribe -np " +
                        std::to_string(ranks) + " "
                  : "";
    return run(launcher + "'" + (bin / "frictionSolver").string() + "'" +
                   (ranks > 0 ? " -parallel" : "") + " -case '" + dir_.string() + "'",
               dir_ / "log.frictionSolver");
  }

  std::string log() const { return readText(dir_ / "log.frictionSolver"); }

  /// Any table by its header's column names (state last).
  Table namedTable(const std::string& time, const std::string& fracture) const {
    std::ifstream in(dir_ / time / "fractures" / (fracture + ".dat"));
    REQUIRE(in.good());
    Table t;
    std::string line;
    REQUIRE(std::getline(in, line));
    REQUIRE(line.rfind("# ", 0) == 0);
    std::istringstream header(line.substr(2));
    for (std::string c; header >> c;) t.columns.push_back(c);
    REQUIRE(t.columns.size() >= 2);
    REQUIRE(t.columns.back() == "state");
    t.columns.pop_back();
    while (std::getline(in, line)) {
      if (line.empty()) continue;
      if (line[0] == '#') {
        t.comments.push_back(line);
        continue;
      }
      std::istringstream s(line);
      std::vector<double> v;
      for (std::size_t i = 0; i < t.columns.size(); ++i) {
        std::string item;
        s >> item;
        char* end = nullptr;
        v.push_back(std::strtod(item.c_str(), &end));
        INFO(line);
        REQUIRE((!item.empty() && *end == '\0'));
      }
      std::string state;
      s >> state;
      INFO(line);
      REQUIRE(!state.empty());
      t.rows.push_back(std::move(v));
      t.state.push_back(state);
    }
    // An empty table would let every loop over its rows pass unseen.
    REQUIRE(t.rows.size() >= 3);
    return t;
  }

  std::vector<Row> table(const std::string& time, const std::string& fracture) const {
    std::ifstream in(dir_ / time / "fractures" / (fracture + ".dat"));
    REQUIRE(in.good());
    std::vector<Row> rows;
    std::string line;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      // strtod, not >>: a "nan" would be read as a value (the checks then fail on it), which
      // operator>> refuses. The state is the last item: columns such as opening, pressure,
      // sigmaNEffective and nx ny tx ty slipX slipY come between the residual and it (README,
      // "Fracture tables").
      std::istringstream s(line);
      std::string item[10];
      for (auto& i : item) s >> i;
      INFO(line);
      REQUIRE(!s.fail());
      for (std::string more; s >> more;) item[9] = more;
      double v[9];
      for (int i = 0; i < 9; ++i) {
        char* end = nullptr;
        v[i] = std::strtod(item[i].c_str(), &end);
        REQUIRE(*end == '\0');
      }
      rows.push_back({v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], item[9]});
    }
    // A fracture has two nodes at least: an empty table is a defect, and every check that
    // loops over its rows would pass on it unseen.
    REQUIRE(rows.size() >= 2);
    return rows;
  }

 private:
  fs::path dir_;
};

/// Every file below `dir` (relative path → content), skipping the logs.
inline std::map<std::string, std::string> outputs(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string rel = fs::relative(e.path(), dir).string();
    if (rel.rfind("log.", 0) == 0) continue;
    files[rel] = readText(e.path());
  }
  return files;
}

/// The files two runs of one case wrote, byte for byte: `whole` ran uninterrupted, `restarted`
/// was stopped and continued with startFrom latestTime. The controlDict (edited for the stop)
/// and the split mesh (it names its case folder) are inputs and left out; `mustHave` lists
/// outputs that must be there, so that the comparison cannot pass on empty folders.
inline void checkSameOutputs(const fs::path& whole, const fs::path& restarted,
                             const std::vector<std::string>& mustHave) {
  auto a = outputs(whole), b = outputs(restarted);
  for (const char* input : {"system/controlDict", "constant/splitMesh"}) {
    REQUIRE(a.erase(input) == 1);
    REQUIRE(b.erase(input) == 1);
  }
  for (const std::string& f : mustHave) REQUIRE(a.count(f) == 1);
  std::set<std::string> names;
  for (const auto& [k, v] : a) names.insert(k);
  for (const auto& [k, v] : b) names.insert(k);
  for (const std::string& k : names) {
    INFO(k);
    CHECK(a.count(k) == 1);
    CHECK(b.count(k) == 1);
    if (a.count(k) && b.count(k)) CHECK((a[k] == b[k]));
  }
}

/// Run a case's own checking script (e.g. cases/pennyCrack/pennyError.py, relative to the
/// source tree) on the solved case with `options`; returns its output. Exit 0 required: its
/// --max checks passed.
inline std::string runCaseScript(const fs::path& caseDir, const std::string& script,
                                 const std::string& options) {
  const fs::path path = fs::path(FRICTION_SOURCE_DIR) / script;
  const fs::path log = caseDir / ("log." + path.stem().string() + "Test");
  const int rc = run(
      "/usr/bin/python3 '" + path.string() + "' -case '" + caseDir.string() + "' " + options, log);
  const std::string out = readText(log);
  INFO(out);
  CHECK(rc == 0);
  return out;
}

/// One number of such a script's output ("name   value ...").
inline double scriptValue(const std::string& out, const std::string& name) {
  std::smatch m;
  const std::regex r("(^|\n)" + name + " +([-+0-9.eE]+)");
  INFO(out);
  REQUIRE(std::regex_search(out, m, r));
  return std::stod(m[2].str());
}

/// Trapezoid weights along the arclength of the table's rows (the L²(Γ) inner product).
inline std::vector<double> trapezoid(const std::vector<Row>& rows) {
  std::vector<double> w(rows.size(), 0.0);
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
    const double h = rows[i + 1].s - rows[i].s;
    w[i] += h / 2;
    w[i + 1] += h / 2;
  }
  return w;
}

}  // namespace friction::regression
