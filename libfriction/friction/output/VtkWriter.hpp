// VtkWriter: ParaView-ready output in VTK's XML formats, written by hand (no VTK library in
// C++), as ASCII or as appended binary compressed with zlib (VtkFormat; ParaView's own form):
//  * writeVtu: the displacement and the stress on the SPLIT mesh (.vtu, an unstructured
//    grid). The fracture nodes are duplicated (coincident points), so the jump of the
//    displacement across a fracture shows when the mesh is warped by "displacement".
//  * writeFractureVtp: one fracture's table (FieldWriter.hpp, FractureRow) as poly data (.vtp)
//    with the fracture quantities as point data: a polyline in 2D, the fault surface's
//    triangles in 3D.
//  * writePvd: a .pvd collection tying, per time, the .vtu (part 0) and each fracture's
//    .vtp (parts 1, 2, ...), so that ParaView opens one file and gets the time series.
//  * VtkSeries: the folder layout and the .pvd of a run, for the solver to call once per
//    written time:
//        <case>/VTK/<caseName>_<time>.vtu
//        <case>/VTK/fractures/<fracture>_<time>.vtp
//        <case>/VTK/<caseName>.pvd            (rewritten after every time)
//        <case>/VTK/fractures/<fracture>.pvd  (each fracture's own series: ParaView shows
//                                              the fault, which the volume hides)
//
// Every file is written atomically (temporary file beside the target, then rename), like
// DictionaryWriter::writeAtomic: ParaView, or a crash, sees the old file or the new one whole.
// The .pvd is written last, so it never names a file that is not there yet.
//
// Units are those of the solver: coordinates and displacement [m], stresses [Pa]; signs of
// σ_n, τ and the slip: fracture/SignConventions.hpp.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/fe/LagrangeSpace.hpp"
#include "friction/output/FieldWriter.hpp"

namespace friction {

/// VTK cell type numbers used here (vtkCellType.h).
constexpr int kVtkPolyLine = 4;
constexpr int kVtkTriangle = 5;
constexpr int kVtkQuadraticTriangle = 22;
constexpr int kVtkTetra = 10;
constexpr int kVtkQuadraticTetra = 24;

/// How the data arrays are written: `ascii`, numbers as text (writePrecision digits), or
/// `binary`, VTK's appended raw form compressed by zlib (blocks of 32 KiB, UInt64 headers,
/// vtkZLibDataCompressor), full double precision, 5-15 times smaller.
enum class VtkFormat { ascii, binary };

/// Integer code of a fracture-node state in the .vtp "state" array: 0 stick, 1 slip,
/// 2 open, 3 tip, 4 junction (a branch's end held at a junction). Throws std::invalid_argument for
/// any other string (the solver writes only these).
int vtkStateCode(const std::string& state);

/// Write the displacement and stress of `u` on the mesh of `space` (2D or 3D) as a VTK XML
/// unstructured grid at `path` (`format`: ascii by default for this function; VtkSeries writes
/// binary unless told otherwise); the folder must exist (OutputError otherwise, naming
/// path).
///  * points: every node of `space` (P2: the vertices, then the edge midpoints), (x, y, z)
///    [m], z = 0 in 2D;
///  * cells: 2D: VTK_TRIANGLE (5) for P1, VTK_QUADRATIC_TRIANGLE (22) for P2 with its six
///    nodes in LagrangeSpace's local order v0 v1 v2 mid01 mid12 mid20, which is VTK's;
///    3D: VTK_TETRA (10) for P1, VTK_QUADRATIC_TETRA (24) for P2 with its ten nodes in
///    LagrangeSpace's local order v0 v1 v2 v3 mid01 mid12 mid20 mid03 mid13 mid23, which is
///    VTK's (fe/Simplex.hpp);
///  * point data "displacement" [m], 3 components (z = 0 in 2D);
///  * cell data "stress" [Pa], 6 components xx yy zz xy yz xz (VTK's symmetric-tensor order),
///    at the cell centroid. 3D: the full stress of 3D Hooke's law. 2D: σ_zz from
///    Material::outOfPlaneStress (λ tr ε in plane strain, 0 in plane stress), σ_yz = σ_xz = 0;
///    "vonMises" [Pa] of that 3D stress (so it includes σ_zz in plane strain); "region"
///    (Int32), the mesh's region number per cell.
/// `space` must be the space `assembler` was built on and `u` its interleaved dof vector
/// (dim · numNodes values [m]). `precision`: significant digits of every number.
/// `stressOffset`, if given, is what makes the stress of `u` the total stress [Pa] (symmetric
/// 3×3) in cell c at x: an in-situ stress σ⁰(x), a pore pressure's −α_B Δp_b I
/// (Effect::stressOffset), added at the centroid: 3D the whole tensor; 2D its upper-left 2×2
/// block to the in-plane stress and its zz entry to Material::outOfPlaneStress's σ_zz.
void writeVtu(const std::string& path, const LagrangeSpace& space,
              const ElasticityAssembler& assembler, const Eigen::VectorXd& u, int precision,
              const std::function<Eigen::Matrix3d(Index, const Point&)>& stressOffset = {},
              VtkFormat format = VtkFormat::ascii);

/// Write one fracture's rows (FieldWriter.hpp) as VTK XML poly data at `path` (`format` as
/// writeVtu's).
///  * 2D (`triangles` empty): the points (x, y, 0) [m] in row order (arclength order) joined by
///    one VTK_POLY_LINE, and point data s [m], slip [m], slipIncrement [m], sigmaN [Pa],
///    tau [Pa], ST [-], residual [Pa] (components [0] of the rows' arrays), normal and
///    tangent (3, n_Γ and t_Γ, z = 0).
///  * 3D: the fault surface. Points: the rows' positions in row order. `triangles`: row
///    indices of each fault triangle, v0 v1 v2 (nodesPerTriangle 3, P1) or v0 v1 v2 mid01
///    mid12 mid20 (6, P2). Cells: VTK_TRIANGLE (5), one per triangle for P1; VTK's poly data
///    has no quadratic cells, so a P2 triangle is written as its four sub-triangles at the
///    edge midpoints (v0 m01 m20, m01 v1 m12, m20 m12 v2, m01 m12 m20): every node's values
///    are shown and the surface is exact where it is flat. Point data: normal (3), slip [m]
///    (3, x y z: slip₁ t₁ + slip₂ t₂), slipMagnitude [m], slipIncrement [m] (3, x y z),
///    sigmaN [Pa], traction [Pa] (3, the tangential traction τ in x y z), tauMagnitude [Pa],
///    ST [-], residual [Pa] (|D|); with `intersection` (a fault that meets others: one code per
///    row, 0 past its end) also intersection (Int32: 0 no other fault, 1
///    passes through, 2 ends on another (held), 3 ends together with another, 4 tip;
///    intersectionCodes, SplitMesh.hpp).
/// Both: Float64 (tips: the rows' values, the body's stress there), and state
/// (Int32: 0 stick, 1 slip, 2 open, 3 tip, 4 junction; see vtkStateCode). The file also says the
/// state coding in an XML comment. No rows: an empty data set (no points, no cells). The folder
/// must exist.
void writeFractureVtp(const std::string& path, const std::vector<FractureRow>& rows, int precision,
                      const std::vector<std::array<Index, 6>>& triangles = {},
                      int nodesPerTriangle = 3, VtkFormat format = VtkFormat::ascii,
                      const std::vector<int>& intersection = {});

/// One time of a .pvd collection.
struct PvdTime {
  double time = 0.0;  ///< the time value ParaView shows (the solver's time [s or load])
  /// Files of this time, relative to the .pvd; files[k] is written as part k. A part's
  /// optional name (ParaView's block name) goes in names[k] when names has that entry.
  std::vector<std::string> files;
  std::vector<std::string> names;
};

/// Write a .pvd collection at `path`: for each time and each of its files one
/// <DataSet timestep=... part=k file=.../>, times in the order given. `precision`:
/// significant digits of the time values. The folder must exist.
void writePvd(const std::string& path, const std::vector<PvdTime>& times, int precision);

/// The VTK output of one run (layout in the file comment). Construct it once per run and call
/// write() at each written time; it creates <case>/VTK/ and <case>/VTK/fractures/ on the first
/// write and rewrites the .pvd with every time written so far by this object (a time name
/// written twice replaces its entry). A new object starts a new collection; resume() first
/// takes over the times of an earlier run that a restart keeps.
class VtkSeries {
 public:
  /// `caseDir`: the case folder; `caseName`: the base name of the .vtu and .pvd files
  /// (default: the case folder's own name).
  explicit VtkSeries(std::string caseDir, std::string caseName = "",
                     VtkFormat format = VtkFormat::binary);

  /// One fracture for write(): its name (file name and ParaView block name), table and, in
  /// 3D, its triangles as row indices (writeFractureVtp; empty in 2D).
  struct Fracture {
    std::string name;
    std::vector<FractureRow> rows;
    std::vector<std::array<Index, 6>> triangles = {};
    int nodesPerTriangle = 3;  ///< 3 (P1) or 6 (P2)
    /// 3D, a fault that meets others: the point array intersection (writeFractureVtp).
    std::vector<int> intersection = {};
  };

  /// Write the .vtu of (space, assembler, u) (see writeVtu), one .vtp per fracture (see
  /// writeFractureVtp), in the series' format, and then each fracture's .pvd and the case's.
  /// `time`: the time value [s or load parameter]; `timeName`: the time folder's name
  /// (TimeControl::timeName), used in the file names. Throws OutputError naming the file if a
  /// folder or file cannot be written.
  void write(double time, const std::string& timeName, const LagrangeSpace& space,
             const ElasticityAssembler& assembler, const Eigen::VectorXd& u,
             const std::vector<Fracture>& fractures, int precision,
             const std::function<Eigen::Matrix3d(Index, const Point&)>& stressOffset = {});

  /// Take over an earlier run's collection up to a restart: read the existing .pvd (if any),
  /// keep the times whose name `keep` accepts, and delete the files of this layout whose time
  /// name it rejects (dropped .pvd entries, and files of times the .pvd never listed because
  /// the run was killed before writing it), for the case's fractures `fractures`; then the
  /// temporary files of killed writes, the .pvd itself when nothing is kept and empty VTK
  /// folders. The .pvd is rewritten with the kept times as write() would have written it.
  /// Names that are not numbers are never touched. Returns the number of files deleted.
  int resume(const std::function<bool(const std::string& timeName)>& keep,
             const std::vector<std::string>& fractures, int precision);

  /// <case>/VTK/<caseName>.pvd
  std::string pvdPath() const;
  /// <case>/VTK/<caseName>_<timeName>.vtu
  std::string vtuPath(const std::string& timeName) const;
  /// <case>/VTK/fractures/<fracture>_<timeName>.vtp
  std::string vtpPath(const std::string& fracture, const std::string& timeName) const;
  /// <case>/VTK/fractures/<fracture>.pvd: that fracture's .vtp files alone, per time
  std::string fracturePvdPath(const std::string& fracture) const;
  const std::string& caseName() const { return caseName_; }

 private:
  std::string vtkDir_;
  std::string caseName_;
  VtkFormat format_;
  std::vector<std::pair<std::string, PvdTime>> times_;  ///< by time name, in write order

  /// Write the case's .pvd and each fracture's from times_.
  void writeCollections(int precision) const;
};

}  // namespace friction
