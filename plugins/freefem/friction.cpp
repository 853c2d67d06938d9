// The FreeFEM plug-in (load "friction"): splitFractureNodes and frictionSolver called from an
// .edp script, on a mesh the script made, with the results back in the script. README.md,
// "FreeFEM users", shows a whole script; cases/paperBenchmark/frictionSolve.edp is one.
//
//   int order = frictionOrder("case");
//     elementOrder of the case's system/frictionSolution (1 or 2): which fespace (P1 or P2)
//     the displacement needs.
//   mesh Ths = frictionSplit(Th, "case" [, overwrite = true]);
//     splitFractureNodes with Th as the mesh: writes Th to the file system/meshDict names
//     (FreeFEM's .msh format, full precision), splits it as meshDict says, writes
//     constant/splitMesh, and returns the split mesh: its vertices and triangles in the
//     solver's numbering (the Ω⁺ copy of a fracture node keeps its number, the Ω⁻ copies come
//     after the unsplit vertices), the regions kept, the boundary edges of the patches with
//     their labels and both faces of each fracture with the fracture's label.
//   int status = frictionSolve("case" [, Vh, ux[], uy[]] [, overwrite = true,
//                              fracture = "name", table = T, slip = s]);
//     frictionSolver on the case: the same log, time folders, VTK files and restart. Returns
//     frictionSolver's exit code when the run went through (0 converged, 3 a step did not, 5
//     stopped by a signal); every other outcome (bad input, a failed factorisation, an output
//     error) is a FreeFEM error with frictionSolver's message. With Vh (a P1 or P2 fespace on
//     the mesh frictionSplit returned, of the case's elementOrder) ux[] and uy[] get the
//     displacement [m] of the last step. table (real[int,int]) gets the fracture table of
//     the last step, one row per control node, the columns of <time>/fractures/<name>.dat in
//     2D (s x y slip slipIncrement sigmaN tau ST residual, then opening with fractures that
//     open) followed by the state as a number (0 stick, 1 slip, 2 open, 3 tip, 4 junction),
//     at full precision; slip (real[int]) its slip column. `fracture` names the fracture
//     (needed when the case has several).
//
// `overwrite` is -overwrite of both tools: without it an existing constant/splitMesh, a mesh
// file that holds another mesh, or time folders of an earlier run are refused.
//
// 2D only for now: a 3D case is refused by frictionSplit (it takes a 2D mesh) and, with Vh,
// by frictionSolve; frictionSolve without Vh runs it.
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
#include <vector>

#include "friction/case/FrictionCase.hpp"
#include "friction/case/MeshSettings.hpp"
#include "friction/case/RunCase.hpp"
#include "friction/case/SplitCase.hpp"
#include "friction/core/AtomicFile.hpp"
#include "friction/core/InputError.hpp"
#include "friction/core/Suggest.hpp"

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
std::string freeFemMeshText(const Fem2D::Mesh& Th) {
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

std::string readWhole(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The split mesh as a FreeFEM mesh, in the solver's numbering.
Fem2D::Mesh* toFreeFem(const friction::SplitMesh& split) {
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

// ---- frictionSplit(Th, "case", overwrite = bool) -------------------------------------------

class FrictionSplit : public E_F0mps {
 public:
  typedef pmesh Result;
  static const int n_name_param = 1;
  static basicAC_F0::name_and_type name_param[];
  Expression nargs[n_name_param];
  Expression mesh, caseDir;

  explicit FrictionSplit(const basicAC_F0& args) {
    args.SetNameParam(n_name_param, name_param, nargs);
    mesh = to<pmesh>(args[0]);
    caseDir = to<string*>(args[1]);
  }
  static ArrayOfaType typeargs() { return ArrayOfaType(atype<pmesh>(), atype<string*>()); }
  static E_F0* f(const basicAC_F0& args) { return new FrictionSplit(args); }
  AnyType operator()(Stack stack) const override;
};

basicAC_F0::name_and_type FrictionSplit::name_param[] = {{"overwrite", &typeid(bool)}};

AnyType FrictionSplit::operator()(Stack stack) const {
  const std::string program = "frictionSplit";
  const pmesh Th = GetAny<pmesh>((*mesh)(stack));
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
    const std::string text = freeFemMeshText(*Th);
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
        << " triangles, " << Th->neb << " boundary edges, written to " << settings.meshFile
        << "\n\n";
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
  if (split.mesh.dim != 2) fail(program, "a 3D case: frictionSplit takes 2D meshes only");
  Fem2D::Mesh* out = toFreeFem(split);
  Add2StackOfPtr2FreeRC(stack, out);
  return SetAny<pmesh>(out);
}

// ---- frictionSolve("case" [, Vh, ux[], uy[]], overwrite =, fracture =, table =, slip =) ----

const char* stateNames[] = {"stick", "slip", "open", "tip", "junction"};

double stateNumber(const std::string& state) {
  for (int i = 0; i < 5; ++i)
    if (state == stateNames[i]) return i;
  return -1;
}

template <bool withField>
class FrictionSolve : public E_F0mps {
 public:
  typedef long Result;
  static const int n_name_param = 4;
  static basicAC_F0::name_and_type name_param[];
  Expression nargs[n_name_param];
  Expression caseDir, space = nullptr, ux = nullptr, uy = nullptr;

  explicit FrictionSolve(const basicAC_F0& args) {
    args.SetNameParam(n_name_param, name_param, nargs);
    caseDir = to<string*>(args[0]);
    if (withField) {
      space = to<pfes*>(args[1]);
      ux = to<KN<double>*>(args[2]);
      uy = to<KN<double>*>(args[3]);
    }
  }
  static ArrayOfaType typeargs() {
    return withField ? ArrayOfaType(atype<string*>(), atype<pfes*>(), atype<KN<double>*>(),
                                    atype<KN<double>*>())
                     : ArrayOfaType(atype<string*>());
  }
  static E_F0* f(const basicAC_F0& args) { return new FrictionSolve(args); }
  AnyType operator()(Stack stack) const override;
};

template <bool withField>
basicAC_F0::name_and_type FrictionSolve<withField>::name_param[] = {
    {"overwrite", &typeid(bool)},
    {"fracture", &typeid(string*)},
    {"table", &typeid(KNM<double>*)},
    {"slip", &typeid(KN<double>*)}};

// The displacement of the last step into the FreeFEM space Vh: its mesh must be the split
// mesh (same vertices in the same order), its element the case's (P1: a node per vertex; P2:
// vertices then edges, edge i opposite vertex i, as FreeFEM numbers a triangle's nodes).
void fillDisplacement(const std::string& program, const friction::FrictionCase& c,
                      const FESpace& Vh, KN<double>& ux, KN<double>& uy) {
  const friction::FractureSystem& sys = const_cast<friction::FrictionCase&>(c).system();
  const friction::LagrangeSpace& space = sys.splitSpace();
  const friction::Mesh& m = c.splitMesh().mesh;
  if (m.dim != 2) fail(program, "a 3D case: the displacement into a 2D fespace is not supported");
  const Fem2D::Mesh& Th = Vh.Th;
  std::ostringstream what;
  if (Th.nv != m.numPoints() || Th.nt != m.numCells())
    what << "the fespace's mesh has " << Th.nv << " vertices and " << Th.nt
         << " triangles, the split mesh " << m.numPoints() << " and " << m.numCells();
  const int nodes = space.degree() == 1 ? 3 : 6;
  if (what.str().empty() && (Vh.N != 1 || Vh.MaxNbNodePerElement != nodes ||
                             Vh.NbOfDF != static_cast<int>(space.numNodes())))
    what << "the fespace has " << Vh.NbOfDF << " degrees of freedom, " << Vh.MaxNbNodePerElement
         << " nodes per triangle and " << Vh.N << " component(s); elementOrder " << space.degree()
         << " needs a scalar P" << space.degree() << " space (" << space.numNodes() << " nodes)";
  // The same vertices at the same places (to round-off of the mesh's size).
  double worst = 0, size = 0;
  for (int i = 0; what.str().empty() && i < Th.nv; ++i) {
    worst = std::max(
        worst, std::hypot(Th.vertices[i].x - m.points[i].x(), Th.vertices[i].y - m.points[i].y()));
    size = std::max(size, m.points[i].head<2>().norm());
  }
  if (what.str().empty() && worst > 1e-12 * std::max(size, 1e-300))
    what << "the fespace's mesh is not the split mesh (a vertex " << worst << " away)";
  if (!what.str().empty())
    fail(program, "Vh: expected a P" + std::to_string(space.degree()) +
                      " fespace on the mesh frictionSplit returned: " + what.str());
  const Eigen::VectorXd u = sys.lastSplitDisplacement();
  ux.resize(Vh.NbOfDF);
  uy.resize(Vh.NbOfDF);
  for (int k = 0; k < Th.nt; ++k) {
    const friction::Index v[3] = {m.cellVertices[3 * k], m.cellVertices[3 * k + 1],
                                  m.cellVertices[3 * k + 2]};
    for (int i = 0; i < nodes; ++i) {
      const friction::Index node =
          i < 3 ? v[i] : space.midpointNode(v[(i - 3 + 1) % 3], v[(i - 3 + 2) % 3]);
      const int dof = Vh(k, i);
      ux[dof] = u[space.dof(node, 0)];
      uy[dof] = u[space.dof(node, 1)];
    }
  }
}

template <bool withField>
AnyType FrictionSolve<withField>::operator()(Stack stack) const {
  const std::string program = "frictionSolve";
  const std::string dir = *GetAny<string*>((*caseDir)(stack));
  friction::RunCaseOptions how;
  how.overwrite = nargs[0] ? GetAny<bool>((*nargs[0])(stack)) : false;
  how.program = program;
  const std::string fracture = nargs[1] ? *GetAny<string*>((*nargs[1])(stack)) : "";
  KNM<double>* table = nargs[2] ? GetAny<KNM<double>*>((*nargs[2])(stack)) : nullptr;
  KN<double>* slip = nargs[3] ? GetAny<KN<double>*>((*nargs[3])(stack)) : nullptr;

  // What the call asks for is checked before the run, so that a bad call writes nothing: the
  // fespace against the case's elementOrder, the fracture against system/meshDict.
  FESpace* Vh = nullptr;
  if (withField) {
    pfes* pVh = GetAny<pfes*>((*space)(stack));
    Vh = pVh ? static_cast<FESpace*>(**pVh) : nullptr;
    if (!Vh) fail(program, "Vh: the fespace is not built");
  }
  std::vector<std::string> names;
  try {
    if (withField) {
      const int order = friction::FrictionCase::elementOrder(dir);
      if (Vh->N != 1 || Vh->MaxNbNodePerElement != (order == 1 ? 3 : 6))
        fail(program, "Vh: expected a P" + std::to_string(order) +
                          " fespace on the mesh frictionSplit returned (elementOrder " +
                          std::to_string(order) + " in system/frictionSolution), got " +
                          std::to_string(Vh->N) + " component(s) and " +
                          std::to_string(Vh->MaxNbNodePerElement) + " nodes per triangle");
    }
    if (table || slip)
      for (const auto& g : friction::MeshSettings::read(dir).fractures) names.push_back(g.name);
  } catch (const friction::InputError& e) {
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
  if (status != 0 && status != 3 && status != 5) {
    std::string message = err.str();
    while (!message.empty() && message.front() == '\n') message.erase(0, 1);
    while (!message.empty() && message.back() == '\n') message.pop_back();
    ExecError(message);
  }
  if (!c) return SetAny<long>(status);

  if (withField)
    fillDisplacement(program, *c, *Vh, *GetAny<KN<double>*>((*ux)(stack)),
                     *GetAny<KN<double>*>((*uy)(stack)));
  if (table || slip) {
    if (c->splitMesh().mesh.dim != 2)
      fail(program, "table/slip: 3D fracture tables are not supported by the plug-in yet");
    // The fracture by name in the split mesh (its order need not be meshDict's).
    const auto& fractures = c->splitMesh().fractures;
    std::size_t at = 0;
    while (at < fractures.size() && fractures[at].name != names[f]) ++at;
    if (at == fractures.size())
      fail(program, "constant/splitMesh has no fracture '" + names[f] +
                        "', which system/meshDict lists: split the case again");
    const std::vector<friction::FractureRow> rows = c->fractureRows(at);
    const bool opening = !rows.empty() && rows.front().hasOpening;
    const long columns = opening ? 11 : 10;
    if (table) {
      table->resize(static_cast<long>(rows.size()), columns);
      for (std::size_t i = 0; i < rows.size(); ++i) {
        const friction::FractureRow& r = rows[i];
        const double values[11] = {r.s,
                                   r.position.x(),
                                   r.position.y(),
                                   r.slip[0],
                                   r.slipIncrement[0],
                                   r.sigmaN,
                                   r.tau[0],
                                   r.ST,
                                   r.residual[0],
                                   opening ? r.opening : stateNumber(r.state),
                                   stateNumber(r.state)};
        for (long j = 0; j < columns; ++j) (*table)(static_cast<long>(i), j) = values[j];
      }
    }
    if (slip) {
      slip->resize(static_cast<long>(rows.size()));
      for (std::size_t i = 0; i < rows.size(); ++i) (*slip)[static_cast<long>(i)] = rows[i].slip[0];
    }
  }
  return SetAny<long>(status);
}

// ---- frictionOrder("case"): elementOrder of system/frictionSolution -----------------------

long frictionOrder(string* const& caseDir) {
  try {
    return friction::FrictionCase::elementOrder(*caseDir);
  } catch (const friction::InputError& e) {
    fail("frictionOrder", e.what());
  }
}

void init() {
  Global.Add("frictionOrder", "(", new OneOperator1_<long, string*>(frictionOrder));
  Global.Add("frictionSplit", "(", new OneOperatorCode<FrictionSplit>());
  Global.Add("frictionSolve", "(", new OneOperatorCode<FrictionSolve<false>>());
  Global.Add("frictionSolve", "(", new OneOperatorCode<FrictionSolve<true>>());
}

}  // namespace

LOADFUNC(init)
