// The FreeFEM plug-in (load "friction"): splitFractureNodes and frictionSolver called from an
// .edp script, on a mesh the script made, with the results back in the script, in 2D (mesh)
// and 3D (mesh3). README.md, "FreeFEM users", shows a whole script;
// cases/paperBenchmarkFreeFem/frictionSolve.edp is one.
//
//   int order = frictionOrder("case");
//     elementOrder of the case's system/frictionSolution (1 or 2): which fespace (P1 or P2)
//     the displacement needs.
//   mesh Ths = frictionSplit(Th, "case" [, overwrite = true]);      (mesh3 in 3D)
//     splitFractureNodes with Th as the mesh: writes Th to the file system/meshDict names
//     (FreeFEM's .msh format in 2D, Medit in 3D, full precision), splits it as meshDict says,
//     writes constant/splitMesh, and returns the split mesh: its vertices and cells in the
//     solver's numbering (the Ω⁺ copy of a fracture node keeps its number, the Ω⁻ copies come
//     after the unsplit vertices), the regions kept, the patches' boundary edges (triangles)
//     with their labels and both faces of each fracture with the fracture's label.
//   int status = frictionSolve("case" [, Vh, ux[], uy[] (, uz[])] [, overwrite = true,
//                              fracture = "name", table = T, slip = s,
//                              pressure = P, pressureTimes = times]);
//     frictionSolver on the case: the same log, time folders, VTK files and restart. Returns
//     frictionSolver's exit code when the run went through (0 converged, 3 a step did not);
//     every other outcome (bad input, a failed factorisation, an output error, a stop by
//     SIGINT/SIGTERM after the step was written) is a FreeFEM error with frictionSolver's
//     message. With Vh (a P1 or P2 fespace on
//     the mesh frictionSplit returned, of the case's elementOrder: P1/P2, or P13d/P23d) the
//     arrays get the displacement [m] of the last step. table (real[int,int]) gets the
//     fracture table of the last step, one row per control node: the numeric columns of
//     <time>/fractures/<name>.dat (FieldWriter.hpp) followed by the state as a number (0
//     stick, 1 slip, 2 open, 3 tip, 4 junction), at full precision; slip (real[int]) the slip
//     (3D: its magnitude). `fracture` names the fracture (needed when the case has several).
//     pressure (real[int,int]) gives the rock's pore-pressure change Δp_b [Pa] to the case's
//     porePressure effect, which must say `data script;`: one row per vertex of the mesh
//     frictionSplit returned (its numbering) or of the unsplit mesh (a copy of a split node then
//     takes its node's value), told apart by the row count; one column per time of
//     pressureTimes (real[int], [s], strictly increasing). Each cell takes the mean of its
//     vertices' values, linear in time between the listed times and constant beyond
//     (GivenField.hpp).
//
// `overwrite` is -overwrite of both tools: without it an existing constant/splitMesh, a mesh
// file that holds another mesh, or time folders of an earlier run are refused. What a call
// asks for is checked before anything is written, and a failed split puts the mesh file back.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "friction/case/FrictionCase.hpp"
#include "friction/case/MeshSettings.hpp"
#include "friction/case/RunCase.hpp"
#include "friction/case/SplitCase.hpp"
#include "friction/core/AtomicFile.hpp"
#include "friction/core/InputError.hpp"
#include "friction/core/InputFile.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/effect/GivenField.hpp"
#include "friction/mesh/MeshReader.hpp"

// FreeFEM's headers after ours: they bring macros and names into the global namespace.
#include <ff++.hpp>

namespace {

namespace fs = std::filesystem;

// A FreeFEM error with the message a command-line tool would give.
[[noreturn]] void fail(const std::string& program, const std::string& message) {
  ExecError(program + ": error: " + message);
  throw 0;  // not reached: ExecError throws
}

// The log of the tools: on FreeFEM's standard output unless the script runs with -v 0.
std::ostream& logStream() {
  static std::ostringstream dropped;
  if (verbosity > 0) return std::cout;
  dropped.str("");
  return dropped;
}

// Th as FreeFEM's own .msh text ("nv nt nbe", then vertices "x y label", triangles "a b c
// region", boundary edges "a b label", 1-based), the coordinates to 17 digits so that
// reading it back gives Th's doubles.
std::string meshText(const Fem2D::Mesh& Th) {
  std::ostringstream s;
  s.precision(17);
  s << Th.nv << " " << Th.nt << " " << Th.neb << "\n";
  for (int i = 0; i < Th.nv; ++i)
    s << Th.vertices[i].x << " " << Th.vertices[i].y << " " << Th.vertices[i].lab << "\n";
  for (int k = 0; k < Th.nt; ++k) {
    const Fem2D::Triangle& t = Th.triangles[k];
    s << Th(t[0]) + 1 << " " << Th(t[1]) + 1 << " " << Th(t[2]) + 1 << " " << t.lab << "\n";
  }
  for (int e = 0; e < Th.neb; ++e) {
    const Fem2D::BoundaryEdge& b = Th.bedges[e];
    s << Th(b[0]) + 1 << " " << Th(b[1]) + 1 << " " << b.lab << "\n";
  }
  return s.str();
}

// Th as Medit text, as FreeFEM's savemesh writes a mesh3 and the solver reads it (Vertices
// "x y z label", Tetrahedra "a b c d region", Triangles "a b c label", 1-based), the
// coordinates to 17 digits.
std::string meshText(const Fem2D::Mesh3& Th) {
  std::ostringstream s;
  s.precision(17);
  s << "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n" << Th.nv << "\n";
  for (int i = 0; i < Th.nv; ++i) {
    const Fem2D::Vertex3& v = Th.vertices[i];
    s << v.x << " " << v.y << " " << v.z << " " << v.lab << "\n";
  }
  s << "\nTetrahedra\n" << Th.nt << "\n";
  for (int k = 0; k < Th.nt; ++k)
    s << Th(k, 0) + 1 << " " << Th(k, 1) + 1 << " " << Th(k, 2) + 1 << " " << Th(k, 3) + 1 << " "
      << Th[k].lab << "\n";
  s << "\nTriangles\n" << Th.nbe << "\n";
  for (int e = 0; e < Th.nbe; ++e) {
    const Fem2D::Triangle3& b = Th.be(e);
    s << Th(b[0]) + 1 << " " << Th(b[1]) + 1 << " " << Th(b[2]) + 1 << " " << b.lab << "\n";
  }
  s << "\nEnd\n";
  return s.str();
}

// The mesh file there now, through the library's reader of input files (regular files only).
std::string readWhole(const std::string& path) {
  friction::InputFileRole role;
  role.what = "the mesh file";
  role.maxBytes = friction::kMaxMeshFileBytes;
  return friction::readInputFile(path, role);
}

// The split mesh as a FreeFEM mesh, in the solver's numbering.
Fem2D::Mesh* toFreeFem(const friction::SplitMesh& split, const Fem2D::Mesh*) {
  const friction::Mesh& m = split.mesh;
  const int nv = static_cast<int>(m.numPoints()), nt = static_cast<int>(m.numCells());
  // Boundary edges: the patches (facetVertices holds the boundary patches only), then both
  // faces of every fracture, consecutive nodes being joined by an edge on either side.
  std::vector<std::array<int, 3>> edges;  // a, b, label
  for (friction::Index e = 0; e < m.numFacets(); ++e)
    edges.push_back({static_cast<int>(m.facetVertices[2 * e]),
                     static_cast<int>(m.facetVertices[2 * e + 1]), m.facetLabel[e]});
  for (const friction::FractureGeometry& g : split.fractures)
    for (friction::Index i = 0; i + 1 < g.numNodes(); ++i) {
      edges.push_back({static_cast<int>(g.plus[i]), static_cast<int>(g.plus[i + 1]), g.label});
      edges.push_back({static_cast<int>(g.minus[i]), static_cast<int>(g.minus[i + 1]), g.label});
    }
  auto* v = new Fem2D::Vertex[nv];
  auto* t = new Fem2D::Triangle[nt];
  auto* b = new Fem2D::BoundaryEdge[edges.size()];
  for (int i = 0; i < nv; ++i) {
    v[i].x = m.points[i].x();
    v[i].y = m.points[i].y();
    v[i].lab = 0;
  }
  for (const auto& e : edges) v[e[0]].lab = v[e[1]].lab = e[2];
  for (int k = 0; k < nt; ++k)
    t[k].set(v, static_cast<int>(m.cellVertices[3 * k]),
             static_cast<int>(m.cellVertices[3 * k + 1]),
             static_cast<int>(m.cellVertices[3 * k + 2]), m.cellRegion[k]);
  for (std::size_t e = 0; e < edges.size(); ++e) b[e].set(v, edges[e][0], edges[e][1], edges[e][2]);
  auto* Th = new Fem2D::Mesh(nv, nt, static_cast<int>(edges.size()), v, t, b);
  return Th;
}

// 3D: the boundary triangles are the patches' and both faces of every fault, the Ω⁻ face
// through the minus copies of its nodes.
Fem2D::Mesh3* toFreeFem(const friction::SplitMesh& split, const Fem2D::Mesh3*) {
  const friction::Mesh& m = split.mesh;
  const int nv = static_cast<int>(m.numPoints()), nt = static_cast<int>(m.numCells());
  std::vector<std::array<int, 4>> faces;  // a, b, c, label
  for (friction::Index e = 0; e < m.numFacets(); ++e)
    faces.push_back({static_cast<int>(m.facetVertices[3 * e]),
                     static_cast<int>(m.facetVertices[3 * e + 1]),
                     static_cast<int>(m.facetVertices[3 * e + 2]), m.facetLabel[e]});
  for (const friction::FractureGeometry& g : split.fractures) {
    std::map<friction::Index, friction::Index> minusOf;
    for (friction::Index i = 0; i < g.numNodes(); ++i) minusOf[g.node[i]] = g.minus[i];
    for (const auto& tri : g.triangles) {
      faces.push_back(
          {static_cast<int>(tri[0]), static_cast<int>(tri[1]), static_cast<int>(tri[2]), g.label});
      // the Ω⁻ face, the other way round (its outward normal is n_Γ)
      faces.push_back({static_cast<int>(minusOf.at(tri[0])), static_cast<int>(minusOf.at(tri[2])),
                       static_cast<int>(minusOf.at(tri[1])), g.label});
    }
  }
  auto* v = new Fem2D::Vertex3[nv];
  auto* t = new Fem2D::Tet[nt];
  auto* b = new Fem2D::Triangle3[faces.size()];
  for (int i = 0; i < nv; ++i) {
    v[i].x = m.points[i].x();
    v[i].y = m.points[i].y();
    v[i].z = m.points[i].z();
    v[i].lab = 0;
  }
  for (const auto& f : faces) v[f[0]].lab = v[f[1]].lab = v[f[2]].lab = f[3];
  for (int k = 0; k < nt; ++k) {
    int iv[4];
    for (int j = 0; j < 4; ++j) iv[j] = static_cast<int>(m.cellVertices[4 * k + j]);
    t[k].set(v, iv, m.cellRegion[k]);
  }
  for (std::size_t e = 0; e < faces.size(); ++e) {
    int iv[3] = {faces[e][0], faces[e][1], faces[e][2]};
    b[e].set(v, iv, faces[e][3]);
  }
  return new Fem2D::Mesh3(nv, nt, static_cast<int>(faces.size()), v, t, b);
}

// ---- frictionSplit(Th, "case", overwrite = bool) -------------------------------------------

// M: Fem2D::Mesh (mesh) or Fem2D::Mesh3 (mesh3).
template <class M>
class FrictionSplit : public E_F0mps {
 public:
  typedef const M* Result;
  static const int n_name_param = 1;
  static basicAC_F0::name_and_type name_param[];
  Expression nargs[n_name_param];
  Expression mesh, caseDir;

  explicit FrictionSplit(const basicAC_F0& args) {
    args.SetNameParam(n_name_param, name_param, nargs);
    mesh = to<const M*>(args[0]);
    caseDir = to<string*>(args[1]);
  }
  static ArrayOfaType typeargs() { return ArrayOfaType(atype<const M*>(), atype<string*>()); }
  static E_F0* f(const basicAC_F0& args) { return new FrictionSplit(args); }
  AnyType operator()(Stack stack) const override;
};

template <class M>
basicAC_F0::name_and_type FrictionSplit<M>::name_param[] = {{"overwrite", &typeid(bool)}};

template <class M>
AnyType FrictionSplit<M>::operator()(Stack stack) const {
  const std::string program = "frictionSplit";
  constexpr int dimension = std::is_same<M, Fem2D::Mesh3>::value ? 3 : 2;
  const M* Th = GetAny<const M*>((*mesh)(stack));
  const std::string dir = *GetAny<string*>((*caseDir)(stack));
  const bool overwrite = nargs[0] ? GetAny<bool>((*nargs[0])(stack)) : false;
  if (!Th) fail(program, "the mesh is empty (a mesh variable that was never given a mesh)");
  std::ostream& log = logStream();
  friction::SplitMesh split;
  std::function<void()> restore;  // undoes the write of the mesh file
  const auto failed = [&](const std::string& message) {
    if (restore) {
      try {
        restore();
      } catch (const std::exception&) {
        // the error reported is the first one
      }
    }
    fail(program, message);
  };
  try {
    const friction::MeshSettings settings = friction::MeshSettings::read(dir, false);
    // The mesh file system/meshDict names gets Th; another mesh there is not replaced
    // silently.
    const std::string text = meshText(*Th);
    const bool exists = fs::exists(settings.meshFile);
    const std::string before = exists ? readWhole(settings.meshFile) : "";
    if (!exists || before != text) {
      if (exists && !overwrite)
        throw friction::InputError(settings.meshFile,
                                   "holds another mesh than the one given to frictionSplit, "
                                   "which writes its mesh there (the 'mesh' entry of " +
                                       settings.dictPath +
                                       "); call it with overwrite = true to replace it");
      fs::create_directories(fs::path(settings.meshFile).parent_path());
      friction::writeTextAtomic(settings.meshFile, text);
      // A split that fails leaves the folder as it was: the mesh file put back.
      restore = [path = settings.meshFile, exists, before] {
        std::error_code ignored;
        if (exists)
          friction::writeTextAtomic(path, before);
        else
          fs::remove(path, ignored);
      };
    }
    log << program << "\nCase: " << dir << "\nMesh: " << Th->nv << " vertices, " << Th->nt
        << (dimension == 2 ? " triangles, " : " tetrahedra, ") << Th->nbBrdElmts()
        << (dimension == 2 ? " boundary edges" : " boundary triangles") << ", written to "
        << settings.meshFile << "\n\n";
    friction::SplitCaseOptions how;
    how.overwrite = overwrite;
    how.program = program;
    how.overwriteHint = "Call it with overwrite = true";
    split = friction::splitCase(dir, how, log);
    log << "\nEnd\n";
  } catch (const friction::InputError& e) {
    failed(e.what());
  } catch (const fs::filesystem_error& e) {
    failed(e.what());
  } catch (const std::bad_alloc&) {
    failed("out of memory");
  } catch (const std::exception& e) {
    failed(std::string("internal error: ") + e.what());
  }
  if (split.mesh.dim != dimension)
    fail(program, "the case's mesh is " + std::to_string(split.mesh.dim) + "D, the mesh given " +
                      std::to_string(dimension) + "D");
  M* out = toFreeFem(split, static_cast<const M*>(nullptr));
  Add2StackOfPtr2FreeRC(stack, out);
  return SetAny<const M*>(out);
}

// ---- frictionSolve("case" [, Vh, ux[], uy[]], overwrite =, fracture =, table =, slip =) ----

const char* stateNames[] = {"stick", "slip", "open", "tip", "junction"};

double stateNumber(const std::string& state) {
  for (int i = 0; i < 5; ++i)
    if (state == stateNames[i]) return i;
  return -1;
}

// FreeFEM's types and its element numbering per dimension.
template <int d>
struct FreeFem;
template <>
struct FreeFem<2> {
  using Space = FESpace;
  using SpaceVariable = pfes;
  static constexpr int vertices = 3;
  static constexpr const char* cell = "triangle";
  // P2's edge node e of a triangle: between these vertices (edge e is opposite vertex e).
  static int edgeVertex(int e, int j) { return (e + 1 + j) % 3; }
  static double vertex(const Fem2D::Mesh& Th, int i, int c) {
    return c == 0 ? Th.vertices[i].x : Th.vertices[i].y;
  }
};
template <>
struct FreeFem<3> {
  using Space = FESpace3;
  using SpaceVariable = pfes3;
  static constexpr int vertices = 4;
  static constexpr const char* cell = "tetrahedron";
  static int edgeVertex(int e, int j) { return Fem2D::Tet::nvedge[e][j]; }
  static double vertex(const Fem2D::Mesh3& Th, int i, int c) {
    return c == 0 ? Th.vertices[i].x : c == 1 ? Th.vertices[i].y : Th.vertices[i].z;
  }
};

// frictionSolve("case" [, Vh, ux[], uy[] (, uz[] in 3D)], named ...): d the dimension of Vh.
template <int d, bool withField>
class FrictionSolve : public E_F0mps {
 public:
  typedef long Result;
  static const int n_name_param = 6;
  static basicAC_F0::name_and_type name_param[];
  Expression nargs[n_name_param];
  Expression caseDir, space = nullptr;
  Expression u[3] = {nullptr, nullptr, nullptr};

  explicit FrictionSolve(const basicAC_F0& args) {
    args.SetNameParam(n_name_param, name_param, nargs);
    caseDir = to<string*>(args[0]);
    if (withField) {
      space = to<typename FreeFem<d>::SpaceVariable*>(args[1]);
      for (int c = 0; c < d; ++c) u[c] = to<KN<double>*>(args[2 + c]);
    }
  }
  static ArrayOfaType typeargs() {
    if (!withField) return ArrayOfaType(atype<string*>());
    if (d == 2)
      return ArrayOfaType(atype<string*>(), atype<typename FreeFem<d>::SpaceVariable*>(),
                          atype<KN<double>*>(), atype<KN<double>*>());
    return ArrayOfaType(atype<string*>(), atype<typename FreeFem<d>::SpaceVariable*>(),
                        atype<KN<double>*>(), atype<KN<double>*>(), atype<KN<double>*>());
  }
  static E_F0* f(const basicAC_F0& args) { return new FrictionSolve(args); }
  AnyType operator()(Stack stack) const override;
};

template <int d, bool withField>
basicAC_F0::name_and_type FrictionSolve<d, withField>::name_param[] = {
    {"overwrite", &typeid(bool)},        {"fracture", &typeid(string*)},
    {"table", &typeid(KNM<double>*)},    {"slip", &typeid(KN<double>*)},
    {"pressure", &typeid(KNM<double>*)}, {"pressureTimes", &typeid(KN<double>*)}};

// pressure = P, pressureTimes = T: the rock's pore-pressure change for the case's porePressure
// (`data script;`), checked here as far as the call alone allows (both given, the times, the
// columns, finite values); the rows against the split mesh when the case is read, before
// anything is written.
friction::GivenField givenPressure(const std::string& program, const KNM<double>* P,
                                   const KN<double>* T) {
  const std::string use =
      "pressure = P (the rock's pore-pressure change [Pa], a real[int,int] with one row per "
      "vertex and one column per time) and pressureTimes = T (their times [s], a real[int])";
  if (!P) fail(program, "pressureTimes: given without pressure; expected both, " + use);
  if (!T) fail(program, "pressure: given without pressureTimes; expected both, " + use);
  friction::GivenField f;
  f.caller = program;
  f.name = "pressure";
  f.timesName = "pressureTimes";
  for (long j = 0; j < T->N(); ++j) f.times.push_back((*T)[j]);
  f.values.resize(P->N(), P->M());
  for (long i = 0; i < P->N(); ++i)
    for (long j = 0; j < P->M(); ++j) f.values(i, j) = (*P)(i, j);
  try {
    f.check();
  } catch (const friction::InputError& e) {
    fail(program, e.what());
  }
  return f;
}

// The displacement of the last step into the FreeFEM space Vh: its mesh must be the split
// mesh (same vertices in the same order), its element the case's (P1: a node per vertex; P2:
// the vertices, then the edges in FreeFEM's order of a cell's edges).
template <int d>
void fillDisplacement(const std::string& program, const friction::FrictionCase& c,
                      const typename FreeFem<d>::Space& Vh, KN<double>* u[d]) {
  using F = FreeFem<d>;
  const friction::FractureSystem& sys = const_cast<friction::FrictionCase&>(c).system();
  const friction::LagrangeSpace& space = sys.splitSpace();
  const friction::Mesh& m = c.splitMesh().mesh;
  if (m.dim != d)
    fail(program,
         "Vh: a " + std::to_string(d) + "D fespace for a " + std::to_string(m.dim) + "D case");
  const auto& Th = Vh.Th;
  const int nodes = space.degree() == 1 ? F::vertices : F::vertices * (F::vertices + 1) / 2;
  std::ostringstream what;
  if (Th.nv != m.numPoints() || Th.nt != m.numCells())
    what << "the fespace's mesh has " << Th.nv << " vertices and " << Th.nt << " cells, the "
         << "split mesh " << m.numPoints() << " and " << m.numCells();
  else if (Vh.N != 1 || Vh.MaxNbNodePerElement != nodes ||
           Vh.NbOfDF != static_cast<int>(space.numNodes()))
    what << "the fespace has " << Vh.NbOfDF << " degrees of freedom and " << Vh.MaxNbNodePerElement
         << " nodes per " << F::cell << "; elementOrder " << space.degree() << " needs "
         << space.numNodes() << " and " << nodes;
  // The same vertices at the same places (to round-off of the mesh's size).
  double worst = 0, size = 0;
  for (int i = 0; what.str().empty() && i < Th.nv; ++i)
    for (int k = 0; k < d; ++k) {
      worst = std::max(worst, std::abs(F::vertex(Th, i, k) - m.points[i][k]));
      size = std::max(size, std::abs(m.points[i][k]));
    }
  if (what.str().empty() && worst > 1e-12 * std::max(size, 1e-300))
    what << "the fespace's mesh is not the split mesh (a vertex " << worst << " away)";
  if (!what.str().empty())
    fail(program, "Vh: expected a P" + std::to_string(space.degree()) +
                      " fespace on the mesh frictionSplit returned: " + what.str());
  const Eigen::VectorXd values = sys.lastSplitDisplacement();
  for (int k = 0; k < d; ++k) u[k]->resize(Vh.NbOfDF);
  for (int k = 0; k < Th.nt; ++k) {
    const friction::Index* v = &m.cellVertices[static_cast<std::size_t>(F::vertices) * k];
    for (int i = 0; i < nodes; ++i) {
      const int e = i - F::vertices;
      const friction::Index node =
          i < F::vertices ? v[i]
                          : space.midpointNode(v[F::edgeVertex(e, 0)], v[F::edgeVertex(e, 1)]);
      const int dof = Vh(k, i);
      for (int comp = 0; comp < d; ++comp) (*u[comp])[dof] = values[space.dof(node, comp)];
    }
  }
}

template <int d, bool withField>
AnyType FrictionSolve<d, withField>::operator()(Stack stack) const {
  using F = FreeFem<d>;
  const std::string program = "frictionSolve";
  const std::string dir = *GetAny<string*>((*caseDir)(stack));
  friction::RunCaseOptions how;
  how.overwrite = nargs[0] ? GetAny<bool>((*nargs[0])(stack)) : false;
  how.program = program;
  how.overwriteHint = "frictionSolve(\"" + dir + "\", overwrite = true)";
  const std::string fracture = nargs[1] ? *GetAny<string*>((*nargs[1])(stack)) : "";
  KNM<double>* table = nargs[2] ? GetAny<KNM<double>*>((*nargs[2])(stack)) : nullptr;
  KN<double>* slip = nargs[3] ? GetAny<KN<double>*>((*nargs[3])(stack)) : nullptr;
  KNM<double>* pressure = nargs[4] ? GetAny<KNM<double>*>((*nargs[4])(stack)) : nullptr;
  KN<double>* pressureTimes = nargs[5] ? GetAny<KN<double>*>((*nargs[5])(stack)) : nullptr;
  if (pressure || pressureTimes)
    how.given[friction::kPorePressureChange] = givenPressure(program, pressure, pressureTimes);

  // What the call asks for is checked before the run, so that a bad call writes nothing: the
  // fespace against the case's elementOrder, the fracture against system/meshDict.
  const typename F::Space* Vh = nullptr;
  if (withField) {
    auto* pVh = GetAny<typename F::SpaceVariable*>((*space)(stack));
    Vh = pVh ? static_cast<typename F::Space*>(**pVh) : nullptr;
    if (!Vh) fail(program, "Vh: the fespace is not built");
  }
  std::vector<std::string> names;
  try {
    if (withField) {
      const int order = friction::FrictionCase::elementOrder(dir);
      const int nodes = order == 1 ? F::vertices : F::vertices * (F::vertices + 1) / 2;
      if (Vh->N != 1 || Vh->MaxNbNodePerElement != nodes)
        fail(program, "Vh: expected a P" + std::to_string(order) +
                          " fespace on the mesh frictionSplit returned (elementOrder " +
                          std::to_string(order) + " in system/frictionSolution), got " +
                          std::to_string(Vh->N) + " component(s) and " +
                          std::to_string(Vh->MaxNbNodePerElement) + " nodes per " + F::cell);
    }
    if (table || slip)
      for (const auto& g : friction::MeshSettings::read(dir).fractures) names.push_back(g.name);
  } catch (const Error&) {
    throw;  // FreeFEM's own errors (fail above) go through as they are
  } catch (const friction::InputError& e) {
    fail(program, e.what());
  } catch (const std::exception& e) {
    fail(program, e.what());
  }
  std::size_t f = 0;
  if (table || slip) {
    if (fracture.empty()) {
      if (names.size() != 1)
        fail(program, "table/slip: the case has " + std::to_string(names.size()) + " fractures (" +
                          friction::joinWords(names) + "): say which with fracture = \"name\"");
    } else {
      while (f < names.size() && names[f] != fracture) ++f;
      if (f == names.size())
        fail(program, "fracture = \"" + fracture + "\": not a fracture of the case; expected " +
                          (names.empty() ? std::string("none (the case has no fractures)")
                                         : "one of " + friction::joinWords(names)) +
                          friction::suggestionText(fracture, names));
    }
  }

  std::ostringstream err;
  std::unique_ptr<friction::FrictionCase> c;
  const int status = friction::runCase(dir, how, logStream(), err, &c);
  if (status == 5 && c)
    // Stopped by SIGINT or SIGTERM (the step written, as frictionSolver does): the user wants
    // the script to stop too.
    // (stoppedEarly says which signal, and whether a second one abandoned the step)
    fail(program, "stopped by " + c->stoppedEarly() +
                      (c->stoppedEarly().find("abandoned") == std::string::npos
                           ? " after writing the current step"
                           : "") +
                      "; continue with startFrom latestTime");
  if (status != 0 && status != 3) {
    std::string message = err.str();
    while (!message.empty() && message.front() == '\n') message.erase(0, 1);
    while (!message.empty() && message.back() == '\n') message.pop_back();
    if (message.empty())
      message = program + ": error: the run ended with exit status " + std::to_string(status) +
                " (see the log)";
    ExecError(message);
  }
  if (!c) return SetAny<long>(status);

  try {
    if (withField) {
      KN<double>* fields[d];
      for (int k = 0; k < d; ++k) fields[k] = GetAny<KN<double>*>((*u[k])(stack));
      fillDisplacement<d>(program, *c, *Vh, fields);
    }
    if (table || slip) {
      // The fracture by name in the split mesh (its order need not be meshDict's).
      const auto& fractures = c->splitMesh().fractures;
      std::size_t at = 0;
      while (at < fractures.size() && fractures[at].name != names[f]) ++at;
      if (at == fractures.size())
        fail(program, "constant/splitMesh has no fracture '" + names[f] +
                          "', which system/meshDict lists: split the case again");
      const int dim = c->splitMesh().mesh.dim;
      const std::vector<friction::FractureRow> rows = c->fractureRows(at);
      // The file's columns, then the state as a number.
      const long columns =
          rows.empty() ? 0
                       : static_cast<long>(friction::fractureTableValues(rows[0], dim).size()) + 1;
      if (table) {
        table->resize(static_cast<long>(rows.size()), columns);
        for (std::size_t i = 0; i < rows.size(); ++i) {
          const std::vector<double> values = friction::fractureTableValues(rows[i], dim);
          for (std::size_t j = 0; j < values.size(); ++j)
            (*table)(static_cast<long>(i), static_cast<long>(j)) = values[j];
          (*table)(static_cast<long>(i), columns - 1) = stateNumber(rows[i].state);
        }
      }
      if (slip) {
        // 2D: the slip; 3D: its magnitude (the table has both components).
        slip->resize(static_cast<long>(rows.size()));
        for (std::size_t i = 0; i < rows.size(); ++i)
          (*slip)[static_cast<long>(i)] =
              dim == 2 ? rows[i].slip[0] : std::hypot(rows[i].slip[0], rows[i].slip[1]);
      }
    }
  } catch (const Error&) {
    throw;  // FreeFEM's own errors (fail) go through as they are
  } catch (const std::exception& e) {
    fail(program, std::string("internal error: ") + e.what());
  }
  return SetAny<long>(status);
}

// ---- frictionOrder("case"): elementOrder of system/frictionSolution -----------------------

long frictionOrder(string* const& caseDir) {
  try {
    return friction::FrictionCase::elementOrder(*caseDir);
  } catch (const friction::InputError& e) {
    fail("frictionOrder", e.what());
  } catch (const std::exception& e) {
    fail("frictionOrder", e.what());
  }
}

void init() {
  Global.Add("frictionOrder", "(", new OneOperator1_<long, string*>(frictionOrder));
  Global.Add("frictionSplit", "(", new OneOperatorCode<FrictionSplit<Fem2D::Mesh>>());
  Global.Add("frictionSplit", "(", new OneOperatorCode<FrictionSplit<Fem2D::Mesh3>>());
  Global.Add("frictionSolve", "(", new OneOperatorCode<FrictionSolve<2, false>>());
  Global.Add("frictionSolve", "(", new OneOperatorCode<FrictionSolve<2, true>>());
  Global.Add("frictionSolve", "(", new OneOperatorCode<FrictionSolve<3, true>>());
}

}  // namespace

LOADFUNC(init)
