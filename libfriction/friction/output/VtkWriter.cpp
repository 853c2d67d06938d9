// VTK XML (ASCII) writers for ParaView: see VtkWriter.hpp.
//
// Format notes (VTK file formats, XML "version 1.0"): cell offsets are the END of each cell's
// connectivity (no leading 0); header_type only matters for binary data but is stated so
// that the files are unambiguous. A 6-component "Tensors" array is read by VTK as a
// symmetric tensor in the order xx yy zz xy yz xz.
#include "friction/output/VtkWriter.hpp"

#include "friction/core/AtomicFile.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "friction/core/InputFile.hpp"
#include "friction/core/OutputError.hpp"

namespace friction {

namespace fs = std::filesystem;

namespace {

// A reader (or a crash) sees either the old file or the complete new one: write a temporary
// file beside the target, flush it, rename it over the target (as DictionaryWriter does).

// Attribute values: file and fracture names are user words, but a name with & < > " must not
// break the XML.
std::string xmlEscape(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// VTK's ASCII parser reads "nan"/"inf" inconsistently across versions; a non-finite value is
// a solver failure the log already reports, so write it as a number ParaView can show.
double finite(double v) {
  if (std::isnan(v)) return 0.0;
  if (std::isinf(v)) return v > 0 ? 1e300 : -1e300;
  return v;
}

void openArray(std::ostream& s, const char* type, const std::string& name, int components,
               const char* extra = "") {
  s << "        <DataArray type=\"" << type << "\"";
  if (!name.empty()) s << " Name=\"" << name << "\"";
  if (components > 1) s << " NumberOfComponents=\"" << components << "\"";
  s << extra << " format=\"ascii\">\n";
}
void closeArray(std::ostream& s) { s << "        </DataArray>\n"; }

const char* const kHeader = "<?xml version=\"1.0\"?>\n";
const char* const kFileAttributes =
    " version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\"";

/// The state coding for the file's comment: the junction code only where a row has it (a
/// file without junctions reads as it always has).
std::string stateLegend(const std::vector<FractureRow>& rows) {
  const bool junction = std::any_of(rows.begin(), rows.end(),
                                    [](const FractureRow& r) { return r.state == "junction"; });
  return std::string("0 stick, 1 slip, 2 open, 3 tip") + (junction ? ", 4 junction" : "");
}

}  // namespace

int vtkStateCode(const std::string& state) {
  if (state == "stick") return 0;
  if (state == "slip") return 1;
  if (state == "open") return 2;
  if (state == "tip") return 3;
  if (state == "junction") return 4;
  throw std::invalid_argument("vtkStateCode: unknown fracture-node state '" + state +
                              "' (expected stick, slip, open, tip or junction)");
}

void writeVtu(const std::string& path, const LagrangeSpace& space,
              const ElasticityAssembler& assembler, const Eigen::VectorXd& u, int precision,
              const std::function<Eigen::Matrix3d(Index, const Point&)>& stressOffset) {
  if (u.size() != space.numDofs())
    throw std::invalid_argument("writeVtu: u has " + std::to_string(u.size()) +
                                " values, the space " + std::to_string(space.numDofs()) + " dofs");
  const Mesh& mesh = space.mesh();
  const bool is3d = space.dim() == 3;
  const Index numNodes = space.numNodes();
  const Index numCells = space.numCells();
  const int perCell = space.nodesPerCell();
  const int cellType = is3d ? (space.degree() == 1 ? kVtkTetra : kVtkQuadraticTetra)
                            : (space.degree() == 1 ? kVtkTriangle : kVtkQuadraticTriangle);

  std::ostringstream s;
  s.precision(precision);
  s << kHeader << "<VTKFile type=\"UnstructuredGrid\"" << kFileAttributes << ">\n"
    << "  <UnstructuredGrid>\n"
    << "    <Piece NumberOfPoints=\"" << numNodes << "\" NumberOfCells=\"" << numCells << "\">\n";

  s << "      <PointData Vectors=\"displacement\">\n";
  openArray(s, "Float64", "displacement", 3);
  for (Index n = 0; n < numNodes; ++n) {
    s << "          " << finite(u[space.dof(n, 0)]) << " " << finite(u[space.dof(n, 1)]);
    if (is3d)
      s << " " << finite(u[space.dof(n, 2)]) << "\n";
    else
      s << " 0\n";
  }
  closeArray(s);
  s << "      </PointData>\n";

  // Stress at the centroid: exact for P1 (constant per cell), the cell's mean value's best
  // single-point stand-in for P2.
  s << "      <CellData Tensors=\"stress\" Scalars=\"vonMises\">\n";
  std::ostringstream vm, region;
  vm.precision(precision);
  openArray(s, "Float64", "stress", 6,
            " ComponentName0=\"XX\" ComponentName1=\"YY\" ComponentName2=\"ZZ\""
            " ComponentName3=\"XY\" ComponentName4=\"YZ\" ComponentName5=\"XZ\"");
  for (Index c = 0; c < numCells; ++c) {
    const auto t = mesh.cell(c);
    double sxx, syy, szz, sxy, syz = 0.0, sxz = 0.0;
    if (is3d) {
      const Point centroid =
          (mesh.points[t[0]] + mesh.points[t[1]] + mesh.points[t[2]] + mesh.points[t[3]]) / 4.0;
      Eigen::Matrix3d sigma = assembler.stress(u, c, centroid);
      if (stressOffset) sigma += stressOffset(c, centroid);
      sxx = sigma(0, 0), syy = sigma(1, 1), szz = sigma(2, 2);
      sxy = sigma(0, 1), syz = sigma(1, 2), sxz = sigma(0, 2);
      s << "          " << finite(sxx) << " " << finite(syy) << " " << finite(szz) << " "
        << finite(sxy) << " " << finite(syz) << " " << finite(sxz) << "\n";
    } else {
      // The 2D types and formulas as before the 3D branch existed: the files stay the same
      // byte for byte.
      const Vector2 centroid = (mesh.points[t[0]].head<2>() + mesh.points[t[1]].head<2>() +
                                mesh.points[t[2]].head<2>()) /
                               3.0;
      Eigen::Matrix2d sigma = assembler.stress(u, c, centroid);
      szz = assembler.material(c).outOfPlaneStress(assembler.strain(u, c, centroid));
      if (stressOffset) {
        const Eigen::Matrix3d offset = stressOffset(c, Point(centroid.x(), centroid.y(), 0.0));
        sigma += offset.topLeftCorner<2, 2>();
        // Only a non-zero σ_zz is added: 0 + (−0) would turn a −0 of the files into 0.
        if (offset(2, 2) != 0.0) szz += offset(2, 2);
      }
      sxx = sigma(0, 0), syy = sigma(1, 1), sxy = sigma(0, 1);
      s << "          " << finite(sxx) << " " << finite(syy) << " " << finite(szz) << " "
        << finite(sxy) << " 0 0\n";
    }
    const double normal =
        0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx));
    // 2D: the expression (and so the rounding) of the files written before 3D existed.
    const double vonMises = is3d ? std::sqrt(normal + 3.0 * (sxy * sxy + syz * syz + sxz * sxz))
                                 : std::sqrt(normal + 3.0 * sxy * sxy);
    vm << "          " << finite(vonMises) << "\n";
    const int r = static_cast<std::size_t>(c) < mesh.cellRegion.size()
                      ? mesh.cellRegion[static_cast<std::size_t>(c)]
                      : 0;
    region << "          " << r << "\n";
  }
  closeArray(s);
  openArray(s, "Float64", "vonMises", 1);
  s << vm.str();
  closeArray(s);
  openArray(s, "Int32", "region", 1);
  s << region.str();
  closeArray(s);
  s << "      </CellData>\n";

  s << "      <Points>\n";
  openArray(s, "Float64", "", 3);
  for (Index n = 0; n < numNodes; ++n) {
    const Point& x = space.point(n);
    s << "          " << x.x() << " " << x.y() << " ";
    if (is3d)
      s << x.z() << "\n";
    else
      s << "0\n";
  }
  closeArray(s);
  s << "      </Points>\n";

  s << "      <Cells>\n";
  openArray(s, "Int64", "connectivity", 1);
  for (Index c = 0; c < numCells; ++c) {
    s << "         ";
    for (const Index n : space.cellNodes(c)) s << " " << n;
    s << "\n";
  }
  closeArray(s);
  openArray(s, "Int64", "offsets", 1);
  for (Index c = 0; c < numCells; ++c)
    s << "          " << static_cast<long long>(c + 1) * perCell << "\n";
  closeArray(s);
  openArray(s, "UInt8", "types", 1);
  for (Index c = 0; c < numCells; ++c) s << "          " << cellType << "\n";
  closeArray(s);
  s << "      </Cells>\n"
    << "    </Piece>\n"
    << "  </UnstructuredGrid>\n"
    << "</VTKFile>\n";
  writeTextAtomic(path, s.str());
}

namespace {

// A Float64 point-data array of one value per row, NaN written as "nan": a tip has no
// traction, and VTK's ASCII reader (9.1) and ParaView read "nan" as NaN.
template <class Value>
void rowArray(std::ostream& s, const char* name, const std::vector<FractureRow>& rows,
              const Value& value) {
  openArray(s, "Float64", name, 1);
  for (const FractureRow& r : rows) {
    const double v = value(r);
    if (std::isnan(v))
      s << "          nan\n";
    else
      s << "          " << finite(v) << "\n";
  }
  closeArray(s);
}

// A Float64 point-data array of one 3-vector per row, components as rowArray's values.
template <class Value>
void rowVectorArray(std::ostream& s, const char* name, const std::vector<FractureRow>& rows,
                    const Value& value) {
  openArray(s, "Float64", name, 3);
  for (const FractureRow& r : rows) {
    const Eigen::Vector3d v = value(r);
    s << "         ";
    for (int i = 0; i < 3; ++i) {
      if (std::isnan(v[i]))
        s << " nan";
      else
        s << " " << finite(v[i]);
    }
    s << "\n";
  }
  closeArray(s);
}

void stateArray(std::ostream& s, const std::vector<FractureRow>& rows) {
  openArray(s, "Int32", "state", 1);
  for (const FractureRow& r : rows) s << "          " << vtkStateCode(r.state) << "\n";
  closeArray(s);
}

void writeFracturePolyline(const std::string& path, const std::vector<FractureRow>& rows,
                           int precision) {
  const std::size_t n = rows.size();
  std::ostringstream s;
  s.precision(precision);
  s << kHeader << "<!-- fracture table as a polyline; point array state: " << stateLegend(rows)
    << " (no traction: nan) -->\n"
    << "<VTKFile type=\"PolyData\"" << kFileAttributes << ">\n"
    << "  <PolyData>\n"
    << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"0\" NumberOfLines=\""
    << (n > 0 ? 1 : 0) << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
    << "      <PointData Scalars=\"ST\">\n";
  rowArray(s, "s", rows, [](const FractureRow& r) { return r.s; });
  rowArray(s, "slip", rows, [](const FractureRow& r) { return r.slip[0]; });
  rowArray(s, "slipIncrement", rows, [](const FractureRow& r) { return r.slipIncrement[0]; });
  rowArray(s, "sigmaN", rows, [](const FractureRow& r) { return r.sigmaN; });
  rowArray(s, "tau", rows, [](const FractureRow& r) { return r.tau[0]; });
  rowArray(s, "ST", rows, [](const FractureRow& r) { return r.ST; });
  rowArray(s, "residual", rows, [](const FractureRow& r) { return r.residual[0]; });
  if (!rows.empty() && rows.front().hasOpening)
    rowArray(s, "opening", rows, [](const FractureRow& r) { return r.opening; });
  if (!rows.empty() && rows.front().hasPressure) {
    rowArray(s, "pressure", rows, [](const FractureRow& r) { return r.pressure; });
    rowArray(s, "sigmaNEffective", rows, [](const FractureRow& r) { return r.sigmaNEffective; });
    rowArray(s, "deltaCFS", rows, [](const FractureRow& r) { return r.deltaCFS; });
  }
  stateArray(s, rows);
  s << "      </PointData>\n";

  s << "      <Points>\n";
  openArray(s, "Float64", "", 3);
  for (const FractureRow& r : rows)
    s << "          " << r.position.x() << " " << r.position.y() << " 0\n";
  closeArray(s);
  s << "      </Points>\n";

  s << "      <Lines>\n";
  openArray(s, "Int64", "connectivity", 1);
  for (std::size_t i = 0; i < n; ++i) s << "          " << i << "\n";
  closeArray(s);
  openArray(s, "Int64", "offsets", 1);
  if (n > 0) s << "          " << n << "\n";
  closeArray(s);
  s << "      </Lines>\n"
    << "    </Piece>\n"
    << "  </PolyData>\n"
    << "</VTKFile>\n";
  writeTextAtomic(path, s.str());
}

// The fault surface of a 3D fracture: see writeFractureVtp.
void writeFaultSurface(const std::string& path, const std::vector<FractureRow>& rows, int precision,
                       const std::vector<std::array<Index, 6>>& triangles, int nodesPerTriangle) {
  if (nodesPerTriangle != 3 && nodesPerTriangle != 6)
    throw std::invalid_argument("writeFractureVtp: " + std::to_string(nodesPerTriangle) +
                                " nodes per triangle (expected 3 or 6)");
  const Index n = static_cast<Index>(rows.size());
  std::vector<std::array<Index, 3>> cells;
  for (const auto& t : triangles) {
    for (int i = 0; i < nodesPerTriangle; ++i)
      if (t[i] < 0 || t[i] >= n)
        throw std::invalid_argument("writeFractureVtp: triangle node " + std::to_string(t[i]) +
                                    " is not a row (" + std::to_string(n) + " rows)");
    if (nodesPerTriangle == 3) {
      cells.push_back({t[0], t[1], t[2]});
    } else {
      // The same orientation as the triangle: each corner with its two edge midpoints, then
      // the middle one.
      cells.push_back({t[0], t[3], t[5]});
      cells.push_back({t[3], t[1], t[4]});
      cells.push_back({t[5], t[4], t[2]});
      cells.push_back({t[3], t[4], t[5]});
    }
  }
  std::ostringstream s;
  s.precision(precision);
  s << kHeader
    << "<!-- fault surface (P2: four triangles per fault triangle, at its edge midpoints); point "
       "array state: "
    << stateLegend(rows) << " (no traction: nan) -->\n"
    << "<VTKFile type=\"PolyData\"" << kFileAttributes << ">\n"
    << "  <PolyData>\n"
    << "    <Piece NumberOfPoints=\"" << n
    << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\""
    << cells.size() << "\">\n"
    << "      <PointData Scalars=\"ST\" Vectors=\"slip\" Normals=\"normal\">\n";
  const auto inXyz = [](const std::array<double, 2>& c, const FractureRow& r) {
    return (c[0] * r.tangent[0] + c[1] * r.tangent[1]).eval();
  };
  rowVectorArray(s, "normal", rows, [](const FractureRow& r) { return r.normal; });
  rowVectorArray(s, "slip", rows, [&](const FractureRow& r) { return inXyz(r.slip, r); });
  rowArray(s, "slipMagnitude", rows,
           [](const FractureRow& r) { return std::hypot(r.slip[0], r.slip[1]); });
  rowVectorArray(s, "slipIncrement", rows,
                 [&](const FractureRow& r) { return inXyz(r.slipIncrement, r); });
  rowArray(s, "sigmaN", rows, [](const FractureRow& r) { return r.sigmaN; });
  rowVectorArray(s, "traction", rows, [&](const FractureRow& r) { return inXyz(r.tau, r); });
  rowArray(s, "tauMagnitude", rows,
           [](const FractureRow& r) { return std::hypot(r.tau[0], r.tau[1]); });
  rowArray(s, "ST", rows, [](const FractureRow& r) { return r.ST; });
  rowArray(s, "residual", rows,
           [](const FractureRow& r) { return std::hypot(r.residual[0], r.residual[1]); });
  if (!rows.empty() && rows.front().hasOpening)
    rowArray(s, "opening", rows, [](const FractureRow& r) { return r.opening; });
  if (!rows.empty() && rows.front().hasPressure) {
    rowArray(s, "pressure", rows, [](const FractureRow& r) { return r.pressure; });
    rowArray(s, "sigmaNEffective", rows, [](const FractureRow& r) { return r.sigmaNEffective; });
    rowArray(s, "deltaCFS", rows, [](const FractureRow& r) { return r.deltaCFS; });
    // The hanging wall's slip and τ along strike and down dip (strikeDipValues(),
    // FieldWriter.hpp), as in the tables.
    const char* names[] = {"slipStrike", "slipDip", "tauStrike", "tauDip"};
    for (std::size_t c = 0; c < 4; ++c)
      rowArray(s, names[c], rows, [c](const FractureRow& r) { return strikeDipValues(r)[c]; });
  }
  stateArray(s, rows);
  s << "      </PointData>\n";

  s << "      <Points>\n";
  openArray(s, "Float64", "", 3);
  for (const FractureRow& r : rows)
    s << "          " << r.position.x() << " " << r.position.y() << " " << r.position.z() << "\n";
  closeArray(s);
  s << "      </Points>\n";

  s << "      <Polys>\n";
  openArray(s, "Int64", "connectivity", 1);
  for (const auto& c : cells) s << "          " << c[0] << " " << c[1] << " " << c[2] << "\n";
  closeArray(s);
  openArray(s, "Int64", "offsets", 1);
  for (std::size_t c = 0; c < cells.size(); ++c) s << "          " << 3 * (c + 1) << "\n";
  closeArray(s);
  s << "      </Polys>\n"
    << "    </Piece>\n"
    << "  </PolyData>\n"
    << "</VTKFile>\n";
  writeTextAtomic(path, s.str());
}

}  // namespace

void writeFractureVtp(const std::string& path, const std::vector<FractureRow>& rows, int precision,
                      const std::vector<std::array<Index, 6>>& triangles, int nodesPerTriangle) {
  if (triangles.empty())
    writeFracturePolyline(path, rows, precision);
  else
    writeFaultSurface(path, rows, precision, triangles, nodesPerTriangle);
}

void writePvd(const std::string& path, const std::vector<PvdTime>& times, int precision) {
  std::ostringstream s;
  s.precision(precision);
  s << kHeader << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "  <Collection>\n";
  for (const PvdTime& t : times)
    for (std::size_t k = 0; k < t.files.size(); ++k) {
      s << "    <DataSet timestep=\"" << t.time << "\" group=\"\" part=\"" << k << "\"";
      if (k < t.names.size() && !t.names[k].empty())
        s << " name=\"" << xmlEscape(t.names[k]) << "\"";
      s << " file=\"" << xmlEscape(t.files[k]) << "\"/>\n";
    }
  s << "  </Collection>\n"
    << "</VTKFile>\n";
  writeTextAtomic(path, s.str());
}

VtkSeries::VtkSeries(std::string caseDir, std::string caseName)
    : vtkDir_((fs::path(caseDir) / "VTK").string()), caseName_(std::move(caseName)) {
  if (caseName_.empty()) {
    // "cases/paperBenchmark/" and "." must give the folder's own name too.
    const fs::path p = fs::absolute(fs::path(caseDir)).lexically_normal();
    caseName_ = p.has_filename() ? p.filename().string() : p.parent_path().filename().string();
    if (caseName_.empty()) caseName_ = "case";
  }
}

std::string VtkSeries::pvdPath() const {
  return (fs::path(vtkDir_) / (caseName_ + ".pvd")).string();
}

std::string VtkSeries::vtuPath(const std::string& timeName) const {
  return (fs::path(vtkDir_) / (caseName_ + "_" + timeName + ".vtu")).string();
}

std::string VtkSeries::vtpPath(const std::string& fracture, const std::string& timeName) const {
  return (fs::path(vtkDir_) / "fractures" / (fracture + "_" + timeName + ".vtp")).string();
}

namespace {

std::string xmlUnescape(const std::string& s) {
  static const std::pair<std::string, char> entities[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}};
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    bool matched = false;
    for (const auto& [entity, c] : entities)
      if (s.compare(i, entity.size(), entity) == 0) {
        out += c;
        i += entity.size();
        matched = true;
        break;
      }
    if (!matched) out += s[i++];
  }
  return out;
}

// The time name in a file name "<prefix>_<time><suffix>", or "" if it does not have that form
// or the time is not a number.
std::string timeNameIn(const std::string& file, const std::string& prefix,
                       const std::string& suffix) {
  if (file.size() <= prefix.size() + 1 + suffix.size() ||
      file.compare(0, prefix.size(), prefix) != 0 || file[prefix.size()] != '_' ||
      file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0)
    return "";
  const std::string name =
      file.substr(prefix.size() + 1, file.size() - prefix.size() - 1 - suffix.size());
  char* end = nullptr;
  std::strtod(name.c_str(), &end);
  return end != name.c_str() && *end == '\0' ? name : "";
}

}  // namespace

int VtkSeries::resume(const std::function<bool(const std::string&)>& keep,
                      const std::vector<std::string>& fractures, int precision) {
  std::error_code ec;
  const fs::path vtk(vtkDir_), vtp = vtk / "fractures";
  times_.clear();
  // The earlier collection, entry by entry; part 0 (the .vtu) starts a time.
  if (fs::exists(pvdPath(), ec)) {
    InputFileRole role;  // something else put in its place (a FIFO) is refused, not waited on
    role.what = "the ParaView collection frictionSolver writes";
    std::istringstream in(readInputFile(pvdPath(), role));
    const std::regex attribute("(\\w+)=\"([^\"]*)\"");
    for (std::string line; std::getline(in, line);) {
      if (line.find("<DataSet") == std::string::npos) continue;
      std::map<std::string, std::string> a;
      for (std::sregex_iterator m(line.begin(), line.end(), attribute), e; m != e; ++m)
        a[(*m)[1]] = xmlUnescape((*m)[2]);
      if (a["part"] == "0") {
        const std::string name = timeNameIn(a["file"], caseName_, ".vtu");
        times_.emplace_back(name, PvdTime{std::strtod(a["timestep"].c_str(), nullptr), {}, {}});
      }
      if (times_.empty()) continue;
      times_.back().second.files.push_back(a["file"]);
      times_.back().second.names.push_back(a["name"]);
    }
  }
  std::vector<std::pair<std::string, PvdTime>> kept;
  for (auto& t : times_)
    if (!t.first.empty() && keep(t.first)) kept.push_back(std::move(t));
  times_ = std::move(kept);

  // Every file of this layout whose time is dropped (whether or not the .pvd listed it).
  int removed = 0;
  const auto sweep = [&](const fs::path& folder, const std::string& prefix,
                         const std::string& suffix) {
    std::vector<fs::path> doomed;
    for (const auto& e : fs::directory_iterator(folder, ec)) {
      const std::string name = timeNameIn(e.path().filename().string(), prefix, suffix);
      if (!name.empty() && !keep(name)) doomed.push_back(e.path());
    }
    for (const auto& p : doomed) removed += fs::remove(p, ec) ? 1 : 0;
  };
  if (fs::is_directory(vtk, ec)) sweep(vtk, caseName_, ".vtu");
  if (fs::is_directory(vtp, ec))
    for (const std::string& f : fractures) sweep(vtp, f, ".vtp");
  removed += removeTemporaryFiles(vtk.string()) + removeTemporaryFiles(vtp.string());

  if (!times_.empty()) {
    std::vector<PvdTime> all;
    for (const auto& nt : times_) all.push_back(nt.second);
    writePvd(pvdPath(), all, std::max(precision, 12));
  } else if (fs::remove(pvdPath(), ec)) {
    ++removed;
  }
  if (fs::is_empty(vtp, ec) && !ec) fs::remove(vtp, ec);
  if (fs::is_empty(vtk, ec) && !ec) fs::remove(vtk, ec);
  return removed;
}

void VtkSeries::write(double time, const std::string& timeName, const LagrangeSpace& space,
                      const ElasticityAssembler& assembler, const Eigen::VectorXd& u,
                      const std::vector<Fracture>& fractures, int precision,
                      const std::function<Eigen::Matrix3d(Index, const Point&)>& stressOffset) {
  std::error_code ec;
  fs::create_directories(fs::path(vtkDir_) / "fractures", ec);
  if (ec)
    throw OutputError((fs::path(vtkDir_) / "fractures").string(),
                      "cannot create the VTK output folder (" + ec.message() + ")");

  PvdTime entry;
  entry.time = time;
  std::vector<std::string> written;
  try {
    writeVtu(vtuPath(timeName), space, assembler, u, precision, stressOffset);
    written.push_back(vtuPath(timeName));
    entry.files.push_back(fs::path(vtuPath(timeName)).filename().string());
    entry.names.push_back("mesh");
    for (const Fracture& f : fractures) {
      writeFractureVtp(vtpPath(f.name, timeName), f.rows, precision, f.triangles,
                       f.nodesPerTriangle);
      written.push_back(vtpPath(f.name, timeName));
      entry.files.push_back("fractures/" + fs::path(vtpPath(f.name, timeName)).filename().string());
      entry.names.push_back(f.name);
    }
  } catch (...) {
    // A time is written whole or not at all: no .vtu without its .vtp files (full disk).
    for (const std::string& w : written) fs::remove(w, ec);
    throw;
  }

  bool replaced = false;
  for (auto& [name, t] : times_)
    if (name == timeName) {
      t = entry;
      replaced = true;
    }
  if (!replaced) times_.emplace_back(timeName, entry);

  std::vector<PvdTime> all;
  all.reserve(times_.size());
  for (const auto& nt : times_) all.push_back(nt.second);
  // Time values need enough digits to stay distinct and ordered even when the files'
  // precision is low (resume() writes the same).
  writePvd(pvdPath(), all, std::max(precision, 12));
}

}  // namespace friction
