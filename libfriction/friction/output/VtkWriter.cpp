// VTK XML writers for ParaView (ASCII, or appended binary compressed with zlib): see
// VtkWriter.hpp.
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

#include <zlib.h>

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

const char* const kHeader = "<?xml version=\"1.0\"?>\n";
const char* const kFileAttributes =
    " version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\"";

/// How a Float64 array's non-finite values are written: Finite maps them to numbers (finite()),
/// KeepNan writes NaN as NaN (a value that is not known; the fracture rows have none) and the
/// rest as Finite, Raw as they are.
enum class Values { Finite, KeepNan, Raw };

/// The DataArrays of one file, in ASCII inline or binary appended form. ASCII: the values
/// inline, `perLine` per line, each line indented by 10 spaces (the files of before the binary
/// form, byte for byte). Binary: an empty element with its offset into the appended block,
/// whose data is VTK's zlib form: a header of UInt64 [blocks, block size, size of a partial
/// last block (0: full), compressed size of each block], then the compressed blocks of at most
/// 32 KiB of raw little-endian values each (vtkZLibDataCompressor's layout).
class ArraySink {
 public:
  ArraySink(VtkFormat format, int precision) : format_(format), precision_(precision) {}

  bool binary() const { return format_ == VtkFormat::binary; }
  /// The <VTKFile> attributes: byte order and header type, and the compressor when binary.
  std::string fileAttributes() const {
    return std::string(kFileAttributes) + (binary() ? " compressor=\"vtkZLibDataCompressor\"" : "");
  }

  void floats(std::ostream& s, const std::string& name, int components,
              const std::vector<double>& v, Values policy, const char* extra = "") {
    open(s, "Float64", name, components, extra);
    if (binary()) {
      std::vector<double> out(v);
      if (policy != Values::Raw)
        for (double& x : out)
          if (!(policy == Values::KeepNan && std::isnan(x))) x = finite(x);
      append(s, out.data(), out.size() * sizeof(double));
      return;
    }
    std::ostringstream line;
    line.precision(precision_);
    for (std::size_t i = 0; i < v.size(); ++i) {
      line << (i % static_cast<std::size_t>(components) == 0 ? "          " : " ");
      const double x = v[i];
      if (policy == Values::Raw)
        line << x;
      else if (policy == Values::KeepNan && std::isnan(x))
        line << "nan";
      else
        line << finite(x);
      if ((i + 1) % static_cast<std::size_t>(components) == 0) line << "\n";
    }
    s << line.str();
    close(s);
  }

  /// Integers: type "Int32", "Int64" or "UInt8"; `perLine` values per ASCII line.
  void integers(std::ostream& s, const char* type, const std::string& name,
                const std::vector<long long>& v, int perLine) {
    open(s, type, name, 1, "");
    if (binary()) {
      const std::string t(type);
      if (t == "Int64") {
        std::vector<std::int64_t> out(v.begin(), v.end());
        append(s, out.data(), out.size() * sizeof(std::int64_t));
      } else if (t == "Int32") {
        std::vector<std::int32_t> out(v.begin(), v.end());
        append(s, out.data(), out.size() * sizeof(std::int32_t));
      } else {
        std::vector<std::uint8_t> out(v.begin(), v.end());
        append(s, out.data(), out.size());
      }
      return;
    }
    for (std::size_t i = 0; i < v.size(); ++i) {
      s << (i % static_cast<std::size_t>(perLine) == 0 ? "          " : " ") << v[i];
      if ((i + 1) % static_cast<std::size_t>(perLine) == 0 || i + 1 == v.size()) s << "\n";
    }
    close(s);
  }

  /// The end of the file: </VTKFile> after the appended block when binary.
  void finish(std::ostream& s) const {
    if (binary()) {
      s << "  <AppendedData encoding=\"raw\">\n   _";
      s.write(appended_.data(), static_cast<std::streamsize>(appended_.size()));
      s << "\n  </AppendedData>\n";
    }
    s << "</VTKFile>\n";
  }

 private:
  void open(std::ostream& s, const char* type, const std::string& name, int components,
            const char* extra) {
    s << "        <DataArray type=\"" << type << "\"";
    if (!name.empty()) s << " Name=\"" << name << "\"";
    if (components > 1) s << " NumberOfComponents=\"" << components << "\"";
    if (binary())
      s << extra << " format=\"appended\" offset=\"" << appended_.size() << "\"/>\n";
    else
      s << extra << " format=\"ascii\">\n";
  }
  static void close(std::ostream& s) { s << "        </DataArray>\n"; }

  void append(std::ostream&, const void* data, std::size_t bytes) {
    constexpr std::size_t kBlock = 32768;
    const std::size_t blocks = (bytes + kBlock - 1) / kBlock;
    std::vector<std::uint64_t> header{blocks, kBlock, bytes % kBlock};
    std::string compressed;
    const auto* raw = static_cast<const Bytef*>(data);
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::size_t size = std::min(kBlock, bytes - b * kBlock);
      uLongf length = compressBound(static_cast<uLong>(size));
      std::string block(length, '\0');
      if (compress2(reinterpret_cast<Bytef*>(block.data()), &length, raw + b * kBlock,
                    static_cast<uLong>(size), Z_DEFAULT_COMPRESSION) != Z_OK)
        throw std::runtime_error("VTK output: zlib could not compress a data block");
      header.push_back(length);
      compressed.append(block.data(), length);
    }
    // Little-endian hosts only (the file says byte_order="LittleEndian"; x86-64, aarch64).
    appended_.append(reinterpret_cast<const char*>(header.data()),
                     header.size() * sizeof(std::uint64_t));
    appended_ += compressed;
  }

  VtkFormat format_;
  int precision_;
  std::string appended_;
};

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
              const std::function<Eigen::Matrix3d(Index, const Point&)>& stressOffset,
              VtkFormat format) {
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
  ArraySink sink(format, precision);

  std::ostringstream s;
  s.precision(precision);
  s << kHeader << "<VTKFile type=\"UnstructuredGrid\"" << sink.fileAttributes() << ">\n"
    << "  <UnstructuredGrid>\n"
    << "    <Piece NumberOfPoints=\"" << numNodes << "\" NumberOfCells=\"" << numCells << "\">\n";

  s << "      <PointData Vectors=\"displacement\">\n";
  std::vector<double> values;
  values.reserve(3 * static_cast<std::size_t>(numNodes));
  for (Index n = 0; n < numNodes; ++n) {
    values.push_back(u[space.dof(n, 0)]);
    values.push_back(u[space.dof(n, 1)]);
    values.push_back(is3d ? u[space.dof(n, 2)] : 0.0);
  }
  sink.floats(s, "displacement", 3, values, Values::Finite);
  s << "      </PointData>\n";

  // Stress at the centroid: exact for P1 (constant per cell), the cell's mean value's best
  // single-point stand-in for P2.
  s << "      <CellData Tensors=\"stress\" Scalars=\"vonMises\">\n";
  std::vector<double> stress, vm;
  std::vector<long long> region;
  stress.reserve(6 * static_cast<std::size_t>(numCells));
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
    }
    stress.insert(stress.end(), {sxx, syy, szz, sxy, syz, sxz});
    const double normal =
        0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx));
    // 2D: the expression (and so the rounding) of the files written before 3D existed.
    vm.push_back(is3d ? std::sqrt(normal + 3.0 * (sxy * sxy + syz * syz + sxz * sxz))
                      : std::sqrt(normal + 3.0 * sxy * sxy));
    region.push_back(static_cast<std::size_t>(c) < mesh.cellRegion.size()
                         ? mesh.cellRegion[static_cast<std::size_t>(c)]
                         : 0);
  }
  sink.floats(s, "stress", 6, stress, Values::Finite,
              " ComponentName0=\"XX\" ComponentName1=\"YY\" ComponentName2=\"ZZ\""
              " ComponentName3=\"XY\" ComponentName4=\"YZ\" ComponentName5=\"XZ\"");
  sink.floats(s, "vonMises", 1, vm, Values::Finite);
  sink.integers(s, "Int32", "region", region, 1);
  s << "      </CellData>\n";

  s << "      <Points>\n";
  values.clear();
  for (Index n = 0; n < numNodes; ++n) {
    const Point& x = space.point(n);
    values.insert(values.end(), {x.x(), x.y(), is3d ? x.z() : 0.0});
  }
  sink.floats(s, "", 3, values, Values::Raw);
  s << "      </Points>\n";

  s << "      <Cells>\n";
  std::vector<long long> connectivity, offsets, types;
  for (Index c = 0; c < numCells; ++c) {
    for (const Index n : space.cellNodes(c)) connectivity.push_back(n);
    offsets.push_back(static_cast<long long>(c + 1) * perCell);
    types.push_back(cellType);
  }
  sink.integers(s, "Int64", "connectivity", connectivity, perCell);
  sink.integers(s, "Int64", "offsets", offsets, 1);
  sink.integers(s, "UInt8", "types", types, 1);
  s << "      </Cells>\n"
    << "    </Piece>\n"
    << "  </UnstructuredGrid>\n";
  sink.finish(s);
  writeTextAtomic(path, s.str());
}

namespace {

// A Float64 point-data array of one value per row, NaN kept (the rows have none: a tip's
// tractions are the body's stress there; VTK's ASCII reader (9.1) and ParaView read "nan").
template <class Value>
void rowArray(ArraySink& sink, std::ostream& s, const char* name,
              const std::vector<FractureRow>& rows, const Value& value) {
  std::vector<double> v;
  v.reserve(rows.size());
  for (const FractureRow& r : rows) v.push_back(value(r));
  sink.floats(s, name, 1, v, Values::KeepNan);
}

// A Float64 point-data array of one 3-vector per row, components as rowArray's values.
template <class Value>
void rowVectorArray(ArraySink& sink, std::ostream& s, const char* name,
                    const std::vector<FractureRow>& rows, const Value& value) {
  std::vector<double> v;
  v.reserve(3 * rows.size());
  for (const FractureRow& r : rows) {
    const Eigen::Vector3d x = value(r);
    v.insert(v.end(), {x[0], x[1], x[2]});
  }
  sink.floats(s, name, 3, v, Values::KeepNan);
}

void stateArray(ArraySink& sink, std::ostream& s, const std::vector<FractureRow>& rows) {
  std::vector<long long> v;
  for (const FractureRow& r : rows) v.push_back(vtkStateCode(r.state));
  sink.integers(s, "Int32", "state", v, 1);
}

// The arrays of what only some cases have, 2D and 3D alike: the opening (fractures that may
// open), the fluid pressure, σ'_n and ΔCFS (a fluid pressure).
void optionalArrays(ArraySink& sink, std::ostream& s, const std::vector<FractureRow>& rows) {
  if (!rows.empty() && rows.front().hasOpening)
    rowArray(sink, s, "opening", rows, [](const FractureRow& r) { return r.opening; });
  if (!rows.empty() && rows.front().hasPressure) {
    rowArray(sink, s, "pressure", rows, [](const FractureRow& r) { return r.pressure; });
    rowArray(sink, s, "sigmaNEffective", rows,
             [](const FractureRow& r) { return r.sigmaNEffective; });
    rowArray(sink, s, "deltaCFS", rows, [](const FractureRow& r) { return r.deltaCFS; });
  }
  if (!rows.empty() && rows.front().hasRateState) {
    rowArray(sink, s, "slipRate", rows, [](const FractureRow& r) { return r.slipRate; });
    rowArray(sink, s, "psi", rows, [](const FractureRow& r) { return r.psi; });
  }
  if (!rows.empty() && rows.front().hasWeakening) {
    rowArray(sink, s, "slipPath", rows, [](const FractureRow& r) { return r.slipPath; });
    rowArray(sink, s, "frictionCoefficient", rows,
             [](const FractureRow& r) { return r.frictionCoefficient; });
  }
}

void writeFracturePolyline(const std::string& path, const std::vector<FractureRow>& rows,
                           int precision, VtkFormat format) {
  const std::size_t n = rows.size();
  ArraySink sink(format, precision);
  std::ostringstream s;
  s.precision(precision);
  s << kHeader << "<!-- fracture table as a polyline; point array state: " << stateLegend(rows)
    << " -->\n"
    << "<VTKFile type=\"PolyData\"" << sink.fileAttributes() << ">\n"
    << "  <PolyData>\n"
    << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"0\" NumberOfLines=\""
    << (n > 0 ? 1 : 0) << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
    << "      <PointData Scalars=\"ST\">\n";
  rowArray(sink, s, "s", rows, [](const FractureRow& r) { return r.s; });
  rowArray(sink, s, "slip", rows, [](const FractureRow& r) { return r.slip[0]; });
  rowArray(sink, s, "slipIncrement", rows, [](const FractureRow& r) { return r.slipIncrement[0]; });
  rowArray(sink, s, "sigmaN", rows, [](const FractureRow& r) { return r.sigmaN; });
  rowArray(sink, s, "tau", rows, [](const FractureRow& r) { return r.tau[0]; });
  rowArray(sink, s, "ST", rows, [](const FractureRow& r) { return r.ST; });
  rowArray(sink, s, "residual", rows, [](const FractureRow& r) { return r.residual[0]; });
  optionalArrays(sink, s, rows);
  // The frame as the fault surface's normal, z = 0: the table's nx ny tx ty.
  rowVectorArray(sink, s, "normal", rows, [](const FractureRow& r) { return r.normal; });
  rowVectorArray(sink, s, "tangent", rows, [](const FractureRow& r) { return r.tangent[0]; });
  stateArray(sink, s, rows);
  s << "      </PointData>\n";

  s << "      <Points>\n";
  std::vector<double> points;
  for (const FractureRow& r : rows)
    points.insert(points.end(), {r.position.x(), r.position.y(), 0.0});
  sink.floats(s, "", 3, points, Values::Raw);
  s << "      </Points>\n";

  s << "      <Lines>\n";
  std::vector<long long> connectivity, offsets;
  for (std::size_t i = 0; i < n; ++i) connectivity.push_back(static_cast<long long>(i));
  if (n > 0) offsets.push_back(static_cast<long long>(n));
  sink.integers(s, "Int64", "connectivity", connectivity, 1);
  sink.integers(s, "Int64", "offsets", offsets, 1);
  s << "      </Lines>\n"
    << "    </Piece>\n"
    << "  </PolyData>\n";
  sink.finish(s);
  writeTextAtomic(path, s.str());
}

// The fault surface of a 3D fracture: see writeFractureVtp.
void writeFaultSurface(const std::string& path, const std::vector<FractureRow>& rows, int precision,
                       const std::vector<std::array<Index, 6>>& triangles, int nodesPerTriangle,
                       VtkFormat format, const std::vector<int>& intersection) {
  ArraySink sink(format, precision);
  if (nodesPerTriangle != 3 && nodesPerTriangle != 6)
    throw std::invalid_argument("writeFractureVtp: " + std::to_string(nodesPerTriangle) +
                                " nodes per triangle (expected 3 or 6)");
  const Index n = static_cast<Index>(rows.size());
  if (!intersection.empty() && intersection.size() > rows.size())
    throw std::invalid_argument("writeFractureVtp: " + std::to_string(intersection.size()) +
                                " intersection codes for " + std::to_string(rows.size()) + " rows");
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
    << stateLegend(rows)
    << (intersection.empty() ? ""
                             : "; point array intersection (where fault surfaces meet): 0 no "
                               "other fault, 1 passes through, 2 ends on another (held), 3 "
                               "ends together with another, 4 tip")
    << " -->\n"
    << "<VTKFile type=\"PolyData\"" << sink.fileAttributes() << ">\n"
    << "  <PolyData>\n"
    << "    <Piece NumberOfPoints=\"" << n
    << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\""
    << cells.size() << "\">\n"
    << "      <PointData Scalars=\"ST\" Vectors=\"slip\" Normals=\"normal\">\n";
  const auto inXyz = [](const std::array<double, 2>& c, const FractureRow& r) {
    return (c[0] * r.tangent[0] + c[1] * r.tangent[1]).eval();
  };
  rowVectorArray(sink, s, "normal", rows, [](const FractureRow& r) { return r.normal; });
  rowVectorArray(sink, s, "slip", rows, [&](const FractureRow& r) { return inXyz(r.slip, r); });
  rowArray(sink, s, "slipMagnitude", rows,
           [](const FractureRow& r) { return std::hypot(r.slip[0], r.slip[1]); });
  rowVectorArray(sink, s, "slipIncrement", rows,
                 [&](const FractureRow& r) { return inXyz(r.slipIncrement, r); });
  rowArray(sink, s, "sigmaN", rows, [](const FractureRow& r) { return r.sigmaN; });
  rowVectorArray(sink, s, "traction", rows, [&](const FractureRow& r) { return inXyz(r.tau, r); });
  rowArray(sink, s, "tauMagnitude", rows,
           [](const FractureRow& r) { return std::hypot(r.tau[0], r.tau[1]); });
  rowArray(sink, s, "ST", rows, [](const FractureRow& r) { return r.ST; });
  rowArray(sink, s, "residual", rows,
           [](const FractureRow& r) { return std::hypot(r.residual[0], r.residual[1]); });
  optionalArrays(sink, s, rows);
  if (!rows.empty() && rows.front().hasPressure) {
    // The hanging wall's slip and τ along strike and down dip (strikeDipValues(),
    // FieldWriter.hpp), as in the tables.
    const char* names[] = {"slipStrike", "slipDip", "tauStrike", "tauDip"};
    for (std::size_t c = 0; c < 4; ++c)
      rowArray(sink, s, names[c], rows,
               [c](const FractureRow& r) { return strikeDipValues(r)[c]; });
  }
  stateArray(sink, s, rows);
  if (!intersection.empty()) {
    // One code per fracture node; the P2 midpoints (rows after them) are 0.
    std::vector<long long> v(rows.size(), 0);
    std::copy(intersection.begin(), intersection.end(), v.begin());
    sink.integers(s, "Int32", "intersection", v, 1);
  }
  s << "      </PointData>\n";

  s << "      <Points>\n";
  std::vector<double> points;
  for (const FractureRow& r : rows)
    points.insert(points.end(), {r.position.x(), r.position.y(), r.position.z()});
  sink.floats(s, "", 3, points, Values::Raw);
  s << "      </Points>\n";

  s << "      <Polys>\n";
  std::vector<long long> connectivity, offsets;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    connectivity.insert(connectivity.end(), {cells[c][0], cells[c][1], cells[c][2]});
    offsets.push_back(static_cast<long long>(3 * (c + 1)));
  }
  sink.integers(s, "Int64", "connectivity", connectivity, 3);
  sink.integers(s, "Int64", "offsets", offsets, 1);
  s << "      </Polys>\n"
    << "    </Piece>\n"
    << "  </PolyData>\n";
  sink.finish(s);
  writeTextAtomic(path, s.str());
}

}  // namespace

void writeFractureVtp(const std::string& path, const std::vector<FractureRow>& rows, int precision,
                      const std::vector<std::array<Index, 6>>& triangles, int nodesPerTriangle,
                      VtkFormat format, const std::vector<int>& intersection) {
  if (triangles.empty())
    writeFracturePolyline(path, rows, precision, format);
  else
    writeFaultSurface(path, rows, precision, triangles, nodesPerTriangle, format, intersection);
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

VtkSeries::VtkSeries(std::string caseDir, std::string caseName, VtkFormat format)
    : vtkDir_((fs::path(caseDir) / "VTK").string()),
      caseName_(std::move(caseName)),
      format_(format) {
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

std::string VtkSeries::fracturePvdPath(const std::string& fracture) const {
  return (fs::path(vtkDir_) / "fractures" / (fracture + ".pvd")).string();
}

void VtkSeries::writeCollections(int precision) const {
  // Time values need enough digits to stay distinct and ordered even when the files'
  // precision is low.
  precision = std::max(precision, 12);
  std::vector<PvdTime> all;
  all.reserve(times_.size());
  // Each fracture's own series: its .vtp of every time, by the name write() gave its part.
  std::map<std::string, std::vector<PvdTime>> perFracture;
  std::vector<std::string> order;
  for (const auto& nt : times_) {
    all.push_back(nt.second);
    const PvdTime& t = nt.second;
    for (std::size_t k = 1; k < t.files.size(); ++k) {
      const std::string name = k < t.names.size() ? t.names[k] : "";
      const std::string prefix = "fractures/";
      if (name.empty() || t.files[k].compare(0, prefix.size(), prefix) != 0) continue;
      if (!perFracture.count(name)) order.push_back(name);
      perFracture[name].push_back(PvdTime{t.time, {t.files[k].substr(prefix.size())}, {name}});
    }
  }
  // The fractures' first: the case's .pvd, written last, never names a file not yet there.
  for (const std::string& name : order)
    writePvd(fracturePvdPath(name), perFracture[name], precision);
  writePvd(pvdPath(), all, precision);
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

  // The fractures' own collections go with the case's: rewritten from the kept times, or
  // removed (this layout's names only) where the kept times have none of that fracture.
  for (const std::string& f : fractures) {
    bool listed = false;
    for (const auto& nt : times_)
      for (std::size_t k = 1; k < nt.second.names.size(); ++k) listed |= nt.second.names[k] == f;
    if (!listed && fs::remove(fracturePvdPath(f), ec)) ++removed;
  }
  if (!times_.empty()) {
    writeCollections(precision);
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
    writeVtu(vtuPath(timeName), space, assembler, u, precision, stressOffset, format_);
    written.push_back(vtuPath(timeName));
    entry.files.push_back(fs::path(vtuPath(timeName)).filename().string());
    entry.names.push_back("mesh");
    for (const Fracture& f : fractures) {
      writeFractureVtp(vtpPath(f.name, timeName), f.rows, precision, f.triangles,
                       f.nodesPerTriangle, format_, f.intersection);
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

  writeCollections(precision);
}

}  // namespace friction
