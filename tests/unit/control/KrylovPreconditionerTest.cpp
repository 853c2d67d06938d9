// Probing of the interface operator (KrylovPreconditioner.hpp): the colouring's separation,
// and the probed entries against the dense S where S is zero beyond the kept distance.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include "friction/control/KrylovPreconditioner.hpp"

using namespace friction;
using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

using Graph = std::vector<std::vector<Index>>;

// An nx × ny grid of nodes, four neighbours each: the hop distance is |Δx| + |Δy|. Like a
// fault's triangulated surface, and a chain (2D fracture) when ny = 1.
Graph grid(int nx, int ny) {
  Graph g(static_cast<std::size_t>(nx * ny));
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      const Index v = x + nx * y;
      if (x + 1 < nx) g[v].push_back(v + 1), g[v + 1].push_back(v);
      if (y + 1 < ny) g[v].push_back(v + nx), g[v + nx].push_back(v);
    }
  return g;
}

int hops(int nx, Index a, Index b) {
  return static_cast<int>(std::abs(a % nx - b % nx) + std::abs(a / nx - b / nx));
}

// A response whose S is zero beyond `band` hops: random S_tt, S_nt within the band, k
// components per node; some nodes held (their columns zero, as FractureSystem's dual gives).
class BandedResponse : public SlipResponse {
 public:
  BandedResponse(int nx, int ny, int k, int band) : nx_(nx), k_(k), graph_(grid(nx, ny)) {
    const Index n = nx * ny;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    w_ = VectorXd::Ones(n);
    mask_ = VectorXd::Ones(n);
    mask_[0] = mask_[n - 1] = 0;  // held, as tips are
    Stt_ = MatrixXd::Zero(k * n, k * n);
    Snt_ = MatrixXd::Zero(n, k * n);
    for (Index i = 0; i < n; ++i)
      for (Index j = 0; j < n; ++j) {
        if (hops(nx, i, j) > band || mask_[j] == 0) continue;
        for (Index c = 0; c < k; ++c) {
          for (Index r = 0; r < k; ++r) Stt_(k * i + r, k * j + c) = u(rng) + (i == j) * 10;
          Snt_(i, k * j + c) = u(rng);
        }
      }
  }
  Index size() const override { return w_.size(); }
  int blockSize() const override { return k_; }
  const VectorXd& weights() const override { return w_; }
  const VectorXd& freeMask() const override { return mask_; }
  void primal(const VectorXd& beta, VectorXd& tau, VectorXd& sigmaN) override {
    tau = Stt_ * beta;
    sigmaN = Snt_ * beta;
  }
  void dual(const VectorXd& qt, const VectorXd&, VectorXd& tauDual, VectorXd* sigmaN) override {
    ++solves;
    tauDual = Stt_ * qt;
    if (sigmaN) *sigmaN = Snt_ * qt;
  }
  Graph nodeGraph() const override { return graph_; }
  const MatrixXd& Stt() const { return Stt_; }
  const MatrixXd& Snt() const { return Snt_; }
  int nx() const { return nx_; }
  long solves = 0;

 private:
  int nx_, k_;
  Graph graph_;
  VectorXd w_, mask_;
  MatrixXd Stt_, Snt_;
};

// The largest difference between the probed S and the dense S's entries within `distance`
// hops (zero beyond).
double probingError(const BandedResponse& b, const ProbedInterfaceOperator& op, int distance) {
  const Index n = b.size(), k = b.blockSize();
  const MatrixXd tt = MatrixXd(op.Stt), nt = MatrixXd(op.Snt);
  double err = 0;
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j) {
      const bool kept = hops(b.nx(), i, j) <= distance;
      for (Index c = 0; c < k; ++c) {
        for (Index r = 0; r < k; ++r)
          err = std::max(err, std::abs(tt(k * i + r, k * j + c) -
                                       (kept ? b.Stt()(k * i + r, k * j + c) : 0.0)));
        err = std::max(err, std::abs(nt(i, k * j + c) - (kept ? b.Snt()(i, k * j + c) : 0.0)));
      }
    }
  return err;
}

}  // namespace

TEST_CASE("colourByDistance: two nodes of one colour are at least 'separation' hops apart",
          "[control][krylov]") {
  for (const int ny : {1, 9})
    for (const int separation : {1, 2, 3, 5}) {
      const int nx = 12;
      const Graph g = grid(nx, ny);
      int colours = 0;
      const std::vector<int> colour = colourByDistance(g, separation, colours);
      INFO("ny " << ny << ", separation " << separation);
      int closest = 1 << 30;
      for (Index a = 0; a < nx * ny; ++a)
        for (Index b = a + 1; b < nx * ny; ++b)
          if (colour[a] == colour[b]) closest = std::min(closest, hops(nx, a, b));
      CHECK(closest >= separation);
      // On a chain the greedy colouring needs exactly 'separation' colours (period).
      if (ny == 1) CHECK(colours == separation);
    }
}

TEST_CASE("probing: where S is zero beyond r hops, the entries within r hops are S's",
          "[control][krylov]") {
  // The condition: S(i, j) = 0 beyond r hops and the nodes of one colour ≥ 2r + 1 hops apart.
  // Then node i has at most one node j of each colour within r hops, and every other node j'
  // of that colour is > r hops from i (else j, j' would be ≤ 2r apart), S(i, j') = 0: the
  // probe's entry i is S(i, j) exactly. Round-off: each entry is a sum of one nonzero term
  // and exact zeros, so the tolerance is the products' own (|S| ≤ 11, 1e-13).
  for (const int ny : {1, 7})
    for (const int k : {1, 2})
      for (const int r : {0, 1, 2}) {
        INFO("ny " << ny << ", k " << k << ", r " << r);
        BandedResponse b(15, ny, k, r);
        const ProbedInterfaceOperator op = probeInterfaceOperator(b, b.nodeGraph(), r, 2 * r + 1);
        CHECK(probingError(b, op, r) <= 1e-13);
        CHECK(op.solves == b.solves);
        CHECK(op.solves <= k * op.colours);
        // One separation less: two nodes of a colour within 2r hops, whose columns mix.
        if (r > 0) {
          const ProbedInterfaceOperator mixed = probeInterfaceOperator(b, b.nodeGraph(), r, 2 * r);
          CHECK(probingError(b, mixed, r) > 1e-2);
        }
      }
}

TEST_CASE("probing: the sparse Jacobian is the dense one where S is within the band",
          "[control][krylov]") {
  // With an exactly probed S (band r, separation 2r + 1), the preconditioner is the inverse of
  // the Newton system itself: G̃⁻¹ G v = v to the round-off of the LU (cond(G) ~ 10).
  for (const int k : {1, 2}) {
    BandedResponse b(9, 5, k, 1);
    const Index n = b.size();
    ControlProblem p(b, VectorXd::Constant(n, 0.6), VectorXd::Zero(n), 5.0, 0.0,
                     GradientKind::exact);
    // Shear well above friction at every node (σ_n = −1 from the offset): all slip.
    VectorXd beta = VectorXd::Zero(k * n);
    ControlState s = p.stateFrom(beta, VectorXd::Constant(k * n, 3.0), VectorXd::Constant(n, -1));
    std::vector<Index> active;
    for (Index i = 0; i < n; ++i)
      if (b.freeMask()[i] != 0)
        for (Index c = 0; c < k; ++c) {
          REQUIRE(s.node[i].state == SlipState::slip);
          active.push_back(k * i + c);
        }
    KrylovPreconditioner pre(probeInterfaceOperator(b, b.nodeGraph(), 1, 3));
    REQUIRE(pre.factor(p, s, active));
    const Index m = static_cast<Index>(active.size());
    MatrixXd G(m, m);
    for (Index a = 0; a < m; ++a)
      for (Index c = 0; c < m; ++c)
        G(a, c) = p.jacobianEntry(s, b.Stt(), b.Snt(), active[a], active[c]);
    const VectorXd v = VectorXd::LinSpaced(m, -1, 2);
    CHECK((pre.apply(G * v) - v).norm() <= 1e-12 * v.norm());
  }
}

TEST_CASE("newtonGamma: the mean diagonal in 3D where the case's gamma is far below it",
          "[control][krylov]") {
  BandedResponse b2(6, 1, 1, 1), b3(6, 1, 2, 1);
  const VectorXd mu = VectorXd::Constant(6, 0.6), c = VectorXd::Zero(6);
  ControlProblem p2(b2, mu, c, 1e-3, 0, GradientKind::exact);
  ControlProblem p3(b3, mu, c, 1e-3, 0, GradientKind::exact);
  // 2D keeps the case's gamma; 3D takes the mean of the known positive diagonal entries of
  // the unknown components (held nodes 0 and 5 and zero entries are left out).
  CHECK(newtonGamma(p2, VectorXd::Constant(6, 10.0)) == 1e-3);
  VectorXd d = VectorXd::Zero(12);
  d.segment(2, 4) << 10, 12, 0, -1;
  d.segment(10, 2) << 1000, 1000;  // node 5 is held
  CHECK(newtonGamma(p3, d) == Approx(11.0));
  ControlProblem stiff(b3, mu, c, 1.0, 0, GradientKind::exact);  // not < 1e-2 × 11
  CHECK(newtonGamma(stiff, d) == 1.0);
}

TEST_CASE("the preconditioner's ordering: a permutation, and less fill than COLAMD on a surface",
          "[control][krylov]") {
  // A fault-like pattern: an nx × ny grid, two components per node, coupled to the nodes
  // within one hop (the probed S̃'s pattern at probingDistance 1), diagonally dominant.
  const int nx = 60, ny = 50, k = 2;
  const Graph g = grid(nx, ny);
  const Index n = static_cast<Index>(g.size()), size = k * n;
  std::vector<Eigen::Triplet<double>> t;
  for (Index i = 0; i < n; ++i)
    for (Index a = 0; a < k; ++a) {
      t.emplace_back(k * i + a, k * i + a, 10.0);
      t.emplace_back(k * i + a, k * i + (a + 1) % k, 0.5);
      for (const Index j : g[static_cast<std::size_t>(i)])
        for (Index b = 0; b < k; ++b) t.emplace_back(k * i + a, k * j + b, a == b ? -1.0 : 0.2);
    }
  Eigen::SparseMatrix<double> A(size, size);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  NestedDissectionOrdering::PermutationType perm;
  NestedDissectionOrdering()(A, perm);
  REQUIRE(perm.size() == size);
  std::vector<int> seen(static_cast<std::size_t>(size), 0);
  for (Index c = 0; c < size; ++c) {
    const int to = perm.indices()[c];
    REQUIRE(to >= 0);
    REQUIRE(to < size);
    ++seen[static_cast<std::size_t>(to)];
  }
  CHECK(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
  Eigen::SparseLU<Eigen::SparseMatrix<double>, NestedDissectionOrdering> nd;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> colamd;
  nd.compute(A);
  colamd.compute(A);
  REQUIRE(nd.info() == Eigen::Success);
  REQUIRE(colamd.info() == Eigen::Success);
  const VectorXd x = VectorXd::LinSpaced(size, -1, 1);
  const VectorXd b = A * x;
  CHECK((nd.solve(b) - x).norm() <= 1e-12 * x.norm());
  // The fill: measured 2.2 against 3.7 kB per node on a 4 178-node fault (README); on this
  // grid too nested dissection must leave fewer entries than COLAMD.
  INFO("nested dissection " << nd.nnzL() + nd.nnzU() << ", COLAMD "
                            << colamd.nnzL() + colamd.nnzU());
  CHECK(nd.nnzL() + nd.nnzU() < colamd.nnzL() + colamd.nnzU());
}
