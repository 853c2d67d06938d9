// The 3D solver where fault surfaces meet (P1), the checks of issue #31 that need no gmsh, on
// Kuhn box meshes (TestBoxMeshes.hpp, every grid plane and the diagonal planes x_i = x_j are
// unions of tetrahedron faces): a symmetric X under a symmetric load slips symmetrically; a
// crossing case gives the same slips when the mesh is renumbered, the faults listed in the
// other order, or everything rotated; and the stability cases — three faults on one curve
// (all crossing, or one abutting), an intersection curve reaching the free outer boundary or
// Dirichlet patches — run, converge and stay finite.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <random>

#include "TestBoxMeshes.hpp"
#include "friction/control/ControlProblem.hpp"
#include "friction/control/Optimizer.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/fe/DirichletConditions.hpp"
#include "friction/fracture/FractureSystem.hpp"

using namespace friction;
using namespace friction::test;
using Eigen::Matrix3d;
using Eigen::VectorXd;

namespace {

constexpr int n = 6;

// The plane x = z through the cubes i = k (i in [i0, i1), j in [j0, j1)): in each cube the
// two triangles (000, 101, 111) and (000, 010, 111) of local corners, faces of its Kuhn
// tetrahedra.
void addDiagonalFault(Mesh& m, int i0, int i1, int j0, int j1, int label, const std::string& name) {
  for (int i = i0; i < i1; ++i)
    for (int j = j0; j < j1; ++j) {
      m.addFacet(
          {boxNode(n, i, j, i), boxNode(n, i + 1, j, i + 1), boxNode(n, i + 1, j + 1, i + 1)},
          label);
      m.addFacet({boxNode(n, i, j, i), boxNode(n, i, j + 1, i), boxNode(n, i + 1, j + 1, i + 1)},
                 label);
    }
  m.labelNames[label] = name;
}

// One solved friction problem: Coulomb μ = 0.3 on every fault, λ = μ_L = 1, the patches
// `fixed` held at u(x) = E x (a homogeneous strain), Newton to 1e-12; P1 or P2.
struct Solved {
  SplitMesh split;
  std::unique_ptr<FractureSystem> sys;
  VectorXd beta;
  ControlState state;
  bool converged = false;
  Solved(const Mesh& mesh, const std::vector<FractureSpec>& specs, const std::vector<int>& fixed,
         const Matrix3d& E, int degree = 1) {
    split = splitFractures(mesh, specs);
    sys = std::make_unique<FractureSystem>(split, degree, Material::fromLame(1.0, 1.0));
    for (int p : fixed) sys->dirichlet().fixPatch(p, FixedComponents::all);
    REQUIRE(sys->factor("cholmod") == FactorStatus::ok);
    for (int p : fixed)
      sys->dirichlet().setPatchValue(p,
                                     VectorField([E](const Point& x) -> Point { return E * x; }));
    sys->setStep(VectorXd::Zero(sys->splitSpace().numDofs()), VectorXd::Zero(2 * sys->size()));
    const Eigen::Index size = sys->size();
    ControlProblem p(*sys, VectorXd::Constant(size, 0.3), VectorXd::Zero(size), 4.0, 0.0,
                     GradientKind::exact);
    auto opt = Optimizer::New(Dictionary::parse(
        "type semismoothNewton; variant condensed; tolerance 1e-12; maxIterations 60;", "test"));
    beta = VectorXd::Zero(2 * size);
    converged = opt->minimize(p, beta).status == OptimizerStatus::converged;
    state = p.evaluate(beta);
  }
  // The slip vector β₁ t₁ + β₂ t₂ (x y z) of control node k.
  Point slip(std::size_t k) const {
    const ControlNode& v = sys->controlNodes()[k];
    return beta[2 * k] * v.tangent[0] + beta[2 * k + 1] * v.tangent[1];
  }
  // Per fault name: position -> slip vector, at its control nodes.
  std::map<std::string, std::vector<std::pair<Point, Point>>> slips() const {
    std::map<std::string, std::vector<std::pair<Point, Point>>> out;
    for (std::size_t k = 0; k < sys->controlNodes().size(); ++k) {
      const ControlNode& v = sys->controlNodes()[k];
      out[split.fractures[v.fracture].name].push_back({v.position, slip(k)});
    }
    return out;
  }
  double largestSlip() const {
    double m = 0;
    for (std::size_t k = 0; k < sys->controlNodes().size(); ++k) m = std::max(m, slip(k).norm());
    return m;
  }
  int slipping(const std::string& name) const {
    int count = 0;
    for (std::size_t k = 0; k < sys->controlNodes().size(); ++k)
      count += split.fractures[sys->controlNodes()[k].fracture].name == name &&
               state.node[k].state == SlipState::slip;
    return count;
  }
};

// The largest difference between fault `name`'s slips in a and, mapped by (x -> Q x, s -> Q s),
// in b, over the two signs of b's slip (a fault's orientation is a convention), relative to
// a's largest slip; every node of a must have one of b at its mapped position.
double mappedDifference(const Solved& a, const Solved& b, const std::string& name,
                        const Matrix3d& Q) {
  const auto sa = a.slips().at(name), sb = b.slips().at(name);
  REQUIRE(sa.size() == sb.size());
  double best = 1e300;
  for (double sign : {1.0, -1.0}) {
    double worst = 0;
    for (const auto& [x, s] : sa) {
      const Point y = Q * x;
      const auto it = std::find_if(sb.begin(), sb.end(), [&](const std::pair<Point, Point>& e) {
        return (e.first - y).norm() < 1e-9;
      });
      REQUIRE(it != sb.end());
      worst = std::max(worst, (sign * it->second - Q * s).norm());
    }
    best = std::min(best, worst);
  }
  return best / a.largestSlip();
}

// 'a' on z = 1/2 and 'b' on x = 1/2, both over [1/6, 5/6]² of their plane: they cross along
// x = z = 1/2, y in [1/6, 5/6].
Mesh crossingMesh() {
  Mesh m = boxMesh(n);
  addPlaneFault(m, n, 2, 3, 1, 5, 1, 5, 7, "a");
  addPlaneFault(m, n, 0, 3, 1, 5, 1, 5, 8, "b");
  return m;
}
const std::vector<FractureSpec> kCrossing{{"a", 7, {}}, {"b", 8, {}}};
const std::vector<int> kAllPatches{1, 2, 3, 4, 5, 6};

// A copy of m with its points renumbered by a random permutation and its cells and facets in
// reverse order (a new Mesh: nothing cached from m).
Mesh renumbered(const Mesh& m) {
  std::vector<Index> to(m.points.size());
  std::iota(to.begin(), to.end(), 0);
  std::shuffle(to.begin(), to.end(), std::mt19937(11));
  Mesh r;
  r.source = m.source + " renumbered";
  r.format = m.format;
  r.dim = 3;
  r.points.resize(m.points.size());
  for (std::size_t v = 0; v < m.points.size(); ++v) r.points[to[v]] = m.points[v];
  for (Index c = m.numCells() - 1; c >= 0; --c) {
    const auto t = m.cell(c);
    r.addCell({to[t[0]], to[t[1]], to[t[2]], to[t[3]]});
  }
  for (Index f = m.numFacets() - 1; f >= 0; --f) {
    const auto t = m.facet(f);
    r.addFacet({to[t[0]], to[t[1]], to[t[2]]}, m.facetLabel[f]);
  }
  r.labelNames = m.labelNames;
  return r;
}

Mesh rotated(const Mesh& m, const Matrix3d& R) {
  Mesh r = m;
  r.source = m.source + " rotated";
  for (Point& x : r.points) x = R * x;
  return Mesh(r);
}

}  // namespace

TEST_CASE("3D intersections: a symmetric X under a symmetric load slips symmetrically",
          "[fracture][fe][3d][intersection]") {
  // The swap x <-> z maps the mesh (Kuhn cubes) onto itself and 'a' onto 'b'; the strain E is
  // invariant under it (P E P = E): compression and shear in the x-z plane.
  Matrix3d P;
  P << 0, 0, 1, 0, 1, 0, 1, 0, 0;
  Matrix3d E;
  E << -0.01, 0.003, 0.02, 0.003, -0.012, 0.003, 0.02, 0.003, -0.01;
  REQUIRE((P * E * P - E).norm() == 0.0);
  const int degree = GENERATE(1, 2);
  INFO("P" << degree);
  const Solved s(crossingMesh(), kCrossing, kAllPatches, E, degree);
  REQUIRE(s.converged);
  REQUIRE(s.slipping("a") > 0);  // not a comparison of zeros
  // b's slip at P x is P times a's at x (up to the sign of b's orientation), to Newton's
  // tolerance: the splitter's and the lifting's choices (which sector keeps the node's
  // number, which fault is listed first) must not show in the answer.
  const auto sa = s.slips().at("a"), sb = s.slips().at("b");
  REQUIRE(sa.size() == sb.size());
  double worst = 1e300;
  for (double sign : {1.0, -1.0}) {
    double w = 0;
    for (const auto& [x, slip] : sa) {
      const auto it = std::find_if(sb.begin(), sb.end(), [&](const std::pair<Point, Point>& e) {
        return (e.first - P * x).norm() < 1e-12;
      });
      REQUIRE(it != sb.end());
      w = std::max(w, (sign * it->second - P * slip).norm());
    }
    worst = std::min(worst, w);
  }
  CHECK(worst < 1e-8 * s.largestSlip());
}

TEST_CASE("3D intersections: renumbering, the faults' order and a rotation leave the slips",
          "[fracture][fe][3d][intersection]") {
  Matrix3d E;
  E << -0.01, 0.004, 0.02, 0.004, -0.015, -0.006, 0.02, -0.006, -0.008;
  const Mesh mesh = crossingMesh();
  const int degree = GENERATE(1, 2);
  INFO("P" << degree);
  const Solved base(mesh, kCrossing, kAllPatches, E, degree);
  REQUIRE(base.converged);
  REQUIRE(base.slipping("a") > 0);
  REQUIRE(base.slipping("b") > 0);
  const Matrix3d I = Matrix3d::Identity();
  SECTION("points renumbered, cells and facets reversed, 'b' listed first") {
    const Solved other(renumbered(mesh), {{"b", 8, {}}, {"a", 7, {}}}, kAllPatches, E, degree);
    REQUIRE(other.converged);
    CHECK(mappedDifference(base, other, "a", I) < 1e-8);
    CHECK(mappedDifference(base, other, "b", I) < 1e-8);
  }
  SECTION("rotated (the load with it)") {
    const Matrix3d R = Eigen::AngleAxisd(0.7, Point(1, 2, 3).normalized()).toRotationMatrix();
    const Solved other(rotated(mesh, R), kCrossing, kAllPatches, R * E * R.transpose(), degree);
    REQUIRE(other.converged);
    CHECK(mappedDifference(base, other, "a", R) < 1e-8);
    CHECK(mappedDifference(base, other, "b", R) < 1e-8);
  }
}

TEST_CASE("3D intersections: three faults on one curve run, converge and stay finite",
          "[fracture][fe][3d][intersection]") {
  Matrix3d E;
  // A load under which each of the three planes alone would slip (uniform |τ| / −σ_n 1.3, 0.36
  // and 0.56 on z = 1/2, x = 1/2 and x = z against μ = 0.3).
  E << -0.03, 0.012, 0.012, 0.012, -0.01, -0.008, 0.012, -0.008, 0.006;
  const bool abutting = GENERATE(false, true);
  INFO((abutting ? "'c' ends on the curve" : "all three cross"));
  Mesh m = crossingMesh();
  // 'c' on x = z through the same line x = z = 1/2: across it, or from it upwards only.
  addDiagonalFault(m, abutting ? 3 : 1, 5, 1, 5, 9, "c");
  const int degree = GENERATE(1, 2);
  INFO("P" << degree);
  const Solved s(m, {{"a", 7, {}}, {"b", 8, {}}, {"c", 9, {}}}, kAllPatches, E, degree);
  CHECK(s.converged);
  CHECK(s.beta.allFinite());
  CHECK(s.state.tau.allFinite());
  // The curve's inner nodes: 6 sectors where all cross, 5 where 'c' ends (it splits one of
  // the four), and 'c' held there when it ends (in P2 also at the 4 mid-edge nodes there).
  std::map<Index, int> copies;
  for (Index v : s.split.origin) ++copies[v];
  const Index inner = boxNode(n, 3, 3, 3);
  CHECK(copies[inner] == (abutting ? 5 : 6));
  int held = 0;
  for (const ControlNode& v : s.sys->controlNodes()) held += v.junction;
  CHECK(held == (abutting ? (degree == 1 ? 3 : 3 + 4) : 0));
  for (const char* f : {"a", "b", "c"}) CHECK(s.slipping(f) > 0);
}

TEST_CASE(
    "3D intersections: a curve reaching the free outer boundary or Dirichlet patches runs, "
    "converges and stays finite",
    "[fracture][fe][3d][intersection]") {
  // 'a' (z = 1/2) and 'b' (x = 1/2) across the whole box: they cut it into four blocks, and
  // their curve runs from y = 0 to y = 1. The x and z faces are held at u = E x; the y faces
  // are free (the curve ends on the free outer boundary) or held too (it ends on them).
  Matrix3d E;
  E << -0.01, 0.004, 0.02, 0.004, -0.015, -0.006, 0.02, -0.006, -0.008;
  const bool yHeld = GENERATE(false, true);
  INFO((yHeld ? "y faces held" : "y faces free"));
  Mesh m = boxMesh(n);
  addPlaneFault(m, n, 2, 3, 0, n, 0, n, 7, "a");
  addPlaneFault(m, n, 0, 3, 0, n, 0, n, 8, "b");
  const int degree = GENERATE(1, 2);
  INFO("P" << degree);
  const Solved s(m, kCrossing, yHeld ? kAllPatches : std::vector<int>{1, 2, 5, 6}, E, degree);
  CHECK(s.converged);
  CHECK(s.beta.allFinite());
  CHECK(s.state.tau.allFinite());
  // The curve's end nodes on y = 0: four copies (one per block).
  std::map<Index, int> copies;
  for (Index v : s.split.origin) ++copies[v];
  CHECK(copies[boxNode(n, 3, 0, 3)] == 4);
  CHECK(s.slipping("a") > 0);
  CHECK(s.slipping("b") > 0);
  // Held y faces: the jumps there are zero (the patch holds both sides).
  if (yHeld)
    for (std::size_t k = 0; k < s.sys->controlNodes().size(); ++k) {
      const Point x = s.sys->controlNodes()[k].position;
      if (x.y() < 1e-12 || x.y() > 1 - 1e-12) CHECK(s.slip(k).norm() == 0.0);
    }
}

TEST_CASE("3D intersections: a fault cut along a line into two equals the uncut one",
          "[fracture][fe][3d][intersection]") {
  // The same mesh, the fault's triangles labelled once (7) or in two pieces (7, 8) that end
  // together along a grid line (joined there: one control node, the first piece's, with the
  // normal of both). Cases: a flat fault (z = 1/2) cut along x = 1/2 from tip line to tip line,
  // or across the box in y so that the cut line reaches the free outer boundary (y faces
  // free); and a fault kinked along the cut line (z = 1/2 for x <= 1/2, then x = z), whose
  // second piece alone is oriented against the first (its normal's largest component, a tie
  // of x and z, taken negative), so that it carries the first's jump turned. The load of the
  // three-faults case: both planes slip.
  Matrix3d E;
  E << -0.03, 0.012, 0.012, 0.012, -0.01, -0.008, 0.012, -0.008, 0.006;
  const int shape = GENERATE(0, 1, 2);
  const int degree = GENERATE(1, 2);
  const char* names[] = {"flat, cut from tip line to tip line",
                         "flat, cut line reaching the outer boundary", "kinked along the cut"};
  INFO(names[shape] << ", P" << degree);
  std::vector<Solved> runs;
  for (bool cut : {false, true}) {
    Mesh m = boxMesh(n);
    const int second = cut ? 8 : 7;
    const int y0 = shape == 1 ? 0 : 1, y1 = shape == 1 ? n : 5;
    addPlaneFault(m, n, 2, 3, 1, 3, y0, y1, 7, "a");
    if (shape == 2)
      addDiagonalFault(m, 3, 5, y0, y1, second, "b");
    else
      addPlaneFault(m, n, 2, 3, 3, 5, y0, y1, second, "b");
    std::vector<FractureSpec> specs{{"a", 7, {}}};
    if (cut) specs.push_back({"b", 8, {}});
    runs.emplace_back(m, specs, shape == 1 ? std::vector<int>{1, 2, 5, 6} : kAllPatches, E, degree);
    REQUIRE(runs.back().converged);
  }
  const Solved &uncut = runs[0], &pieces = runs[1];
  // The cut line's inner nodes are joined (3 tip to tip, 7 across), and both pieces slip.
  const auto& kinds = pieces.split.fractures[1].kind;
  CHECK(std::count(kinds.begin(), kinds.end(), FractureNodeKind::joined) == (shape == 1 ? 7 : 3));
  REQUIRE(pieces.slipping("a") > 0);
  REQUIRE(pieces.slipping("b") > 0);
  CHECK(pieces.sys->size() == uncut.sys->size());
  // Every control node of the pieces at an uncut one's position, with its weight and slip
  // (per piece up to the sign of its orientation against the uncut fault's).
  double worst[2] = {0, 0}, worstFlipped[2] = {0, 0};
  int joinedSlipping = 0;
  for (std::size_t k = 0; k < pieces.sys->controlNodes().size(); ++k) {
    const ControlNode& v = pieces.sys->controlNodes()[k];
    std::size_t u = 0;
    while (u < uncut.sys->controlNodes().size() &&
           (uncut.sys->controlNodes()[u].position - v.position).norm() > 1e-12)
      ++u;
    REQUIRE(u < uncut.sys->controlNodes().size());
    CHECK(pieces.sys->weights()[k] == Approx(uncut.sys->weights()[u]).epsilon(1e-13));
    CHECK(std::abs(std::abs(v.normal.dot(uncut.sys->controlNodes()[u].normal)) - 1) < 1e-14);
    worst[v.fracture] = std::max(worst[v.fracture], (pieces.slip(k) - uncut.slip(u)).norm());
    worstFlipped[v.fracture] =
        std::max(worstFlipped[v.fracture], (pieces.slip(k) + uncut.slip(u)).norm());
    joinedSlipping += std::abs(v.position.x() - 0.5) < 1e-12 &&
                      std::abs(v.position.z() - 0.5) < 1e-12 && pieces.slip(k).norm() > 0;
  }
  CHECK(joinedSlipping > 0);
  // Same mesh, same operators summed in another order: equal to round-off (measured at most
  // 6e-16 of the largest slip in P1, 2.6e-15 in P2; bound 1e-13).
  for (int f : {0, 1}) {
    INFO("piece " << f);
    CHECK(std::min(worst[f], worstFlipped[f]) < 1e-13 * uncut.largestSlip());
  }
}
