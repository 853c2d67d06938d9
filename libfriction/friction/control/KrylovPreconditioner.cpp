// Probing of the interface operator and the krylov variant's preconditioner
// (KrylovPreconditioner.hpp).
#include "friction/control/KrylovPreconditioner.hpp"

#include <algorithm>
#include <deque>

#include "friction/core/Assert.hpp"
#include "friction/core/StopRequest.hpp"
#include "friction/linalg/SparseFactorBackend.hpp"

namespace friction {

namespace {

using Graph = std::vector<std::vector<Eigen::Index>>;

// Breadth-first from `start` up to `depth` hops: f(node) for each node reached, start first.
template <class F>
void visitWithin(const Graph& graph, Eigen::Index start, int depth, std::vector<int>& hops, F&& f) {
  std::vector<Eigen::Index> seen{start};
  std::deque<Eigen::Index> queue{start};
  hops[static_cast<std::size_t>(start)] = 0;
  while (!queue.empty()) {
    const Eigen::Index v = queue.front();
    queue.pop_front();
    f(v);
    const int h = hops[static_cast<std::size_t>(v)];
    if (h == depth) continue;
    for (const Eigen::Index w : graph[static_cast<std::size_t>(v)])
      if (hops[static_cast<std::size_t>(w)] < 0) {
        hops[static_cast<std::size_t>(w)] = h + 1;
        seen.push_back(w);
        queue.push_back(w);
      }
  }
  for (const Eigen::Index v : seen) hops[static_cast<std::size_t>(v)] = -1;
}

}  // namespace

std::vector<int> colourByDistance(const Graph& graph, int separation, int& numColours) {
  FRICTION_ASSERT(separation >= 1, "nodes of one colour are at least one hop apart");
  const std::size_t n = graph.size();
  std::vector<int> colour(n, -1), hops(n, -1);
  std::vector<char> used;
  numColours = 0;
  for (std::size_t v = 0; v < n; ++v) {
    // The colours already taken closer than `separation` hops.
    std::fill(used.begin(), used.end(), 0);
    visitWithin(graph, static_cast<Eigen::Index>(v), separation - 1, hops, [&](Eigen::Index w) {
      const int c = colour[static_cast<std::size_t>(w)];
      if (c >= 0) used[static_cast<std::size_t>(c)] = 1;
    });
    int c = 0;
    while (c < numColours && used[static_cast<std::size_t>(c)]) ++c;
    if (c == numColours) {
      ++numColours;
      used.push_back(0);
    }
    colour[v] = c;
  }
  return colour;
}

int probingSeparation(int distance) {
  // 2·distance + 1, the least that keeps the kept entries apart: on a chain the colours then
  // repeat with that period, every node has one node of each colour within reach, and the
  // probed S keeps S's row sums (its action on a uniform slip) — measured on the inclined
  // crack (513 nodes), wider separations cost more solves and more GMRES products. The
  // block diagonal (distance 0) would be the row sums alone: it takes 3, so that a node's
  // own block is read apart from its neighbours'.
  return std::max(2 * distance + 1, 3);
}

Graph nodesWithin(const Graph& graph, int distance) {
  const std::size_t n = graph.size();
  Graph near(n);
  std::vector<int> hops(n, -1);
  for (std::size_t v = 0; v < n; ++v)
    visitWithin(graph, static_cast<Eigen::Index>(v), distance, hops,
                [&](Eigen::Index w) { near[v].push_back(w); });
  return near;
}

ProbedInterfaceOperator probeInterfaceOperator(SlipResponse& resp, const Graph& graph, int distance,
                                               int separation) {
  const Eigen::Index n = resp.size(), k = resp.blockSize();
  FRICTION_ASSERT(static_cast<Eigen::Index>(graph.size()) == n, "one adjacency list per node");
  // The probe is exact when separation ≥ 2·distance + 1 (one node of a colour within the kept
  // distance of any node); a smaller separation is allowed and mixes columns (the unit tests
  // show how much), so it is not a precondition.
  FRICTION_ASSERT(distance >= 0 && separation >= 1, "a distance and a separation of colours");
  ProbedInterfaceOperator op;
  const std::vector<int> colour = colourByDistance(graph, separation, op.colours);
  const Graph near = nodesWithin(graph, distance);
  const Eigen::VectorXd mask = resp.componentMask();
  // Per colour, the node of that colour within `distance` hops of each node (at most one).
  std::vector<std::vector<Eigen::Index>> byColour(static_cast<std::size_t>(op.colours));
  for (Eigen::Index i = 0; i < n; ++i) byColour[static_cast<std::size_t>(colour[i])].push_back(i);
  // The probes: one right-hand side per colour and tangential component with a free node,
  // all solved as one block (one multi-column back-substitution: with CHOLMOD's supernodal
  // factor much cheaper than as many single ones).
  std::vector<std::pair<int, Eigen::Index>> probes;  // (colour, component) of each column
  for (int c = 0; c < op.colours; ++c)
    for (Eigen::Index comp = 0; comp < k; ++comp)
      for (const Eigen::Index j : byColour[static_cast<std::size_t>(c)])
        if (mask[k * j + comp] != 0) {
          probes.emplace_back(c, comp);
          break;
        }
  const Eigen::Index m = static_cast<Eigen::Index>(probes.size());
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(k * n, m), T, SN;
  for (Eigen::Index p = 0; p < m; ++p) {
    const auto [c, comp] = probes[static_cast<std::size_t>(p)];
    for (const Eigen::Index j : byColour[static_cast<std::size_t>(c)])
      if (mask[k * j + comp] != 0) E(k * j + comp, p) = 1;
  }
  throwIfStopNow();
  if (m > 0) resp.dualBlock(E, Eigen::MatrixXd::Zero(n, m), T, &SN);
  op.solves += m;
  std::vector<Eigen::Triplet<double>> tt, nt;
  for (Eigen::Index p = 0; p < m; ++p) {
    const auto [c, comp] = probes[static_cast<std::size_t>(p)];
    for (Eigen::Index i = 0; i < n; ++i)
      for (const Eigen::Index j : near[static_cast<std::size_t>(i)]) {
        if (colour[j] != c || mask[k * j + comp] == 0) continue;
        const Eigen::Index col = k * j + comp;
        for (Eigen::Index r = 0; r < k; ++r)
          if (T(k * i + r, p) != 0) tt.emplace_back(k * i + r, col, T(k * i + r, p));
        if (SN(i, p) != 0) nt.emplace_back(i, col, SN(i, p));
      }
  }
  op.Stt.resize(k * n, k * n);
  op.Stt.setFromTriplets(tt.begin(), tt.end());
  op.Snt.resize(n, k * n);
  op.Snt.setFromTriplets(nt.begin(), nt.end());
  return op;
}

Eigen::VectorXd sampledDiagonal(SlipResponse& resp, const Graph& graph, int separation,
                                long& solves) {
  const Eigen::Index n = resp.size(), k = resp.blockSize();
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(k * n);
  if (static_cast<Eigen::Index>(graph.size()) != n) return diagonal;
  int colours = 0;
  const std::vector<int> colour = colourByDistance(graph, separation, colours);
  const Eigen::VectorXd mask = resp.componentMask();
  // The colour with the most unknowns (the first ones may lie on the held tip line).
  std::vector<int> unknowns(static_cast<std::size_t>(colours), 0);
  for (Eigen::Index j = 0; j < k * n; ++j)
    unknowns[static_cast<std::size_t>(colour[j / k])] += mask[j] != 0;
  const int chosen =
      static_cast<int>(std::max_element(unknowns.begin(), unknowns.end()) - unknowns.begin());
  // One column per tangential component with a free node of that colour, as one block.
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(k * n, k), T;
  std::vector<Eigen::Index> comps;
  for (Eigen::Index comp = 0; comp < k; ++comp) {
    const Eigen::Index p = static_cast<Eigen::Index>(comps.size());
    for (Eigen::Index i = 0; i < n; ++i)
      if (colour[i] == chosen && mask[k * i + comp] != 0) E(k * i + comp, p) = 1;
    if (E.col(p).squaredNorm() != 0) comps.push_back(comp);
  }
  const Eigen::Index m = static_cast<Eigen::Index>(comps.size());
  if (m == 0) return diagonal;
  resp.dualBlock(E.leftCols(m), Eigen::MatrixXd::Zero(n, m), T);
  solves += m;
  for (Eigen::Index p = 0; p < m; ++p)
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Index j = k * i + comps[static_cast<std::size_t>(p)];
      if (E(j, p) != 0) diagonal[j] = T(j, p);
    }
  return diagonal;
}

double newtonGamma(const ControlProblem& p, const Eigen::VectorXd& diagonalStt) {
  const double gammaCase = p.gamma();
  if (p.blockSize() < 2) return gammaCase;
  // The tangential components only (k·n: an opening's normal components follow them in p).
  const Eigen::Index kn = p.blockSize() * p.numNodes();
  FRICTION_ASSERT(diagonalStt.size() == kn, "one diagonal entry per tangential component");
  double diagonal = 0;
  int count = 0;
  for (Eigen::Index j = 0; j < kn; ++j)
    if (p.componentMask()[j] != 0 && diagonalStt[j] > 0) diagonal += diagonalStt[j], ++count;
  // Far above the stiffness the same holds from the other side: N = τ − γβ is then γβ for
  // any β ≠ 0, so a node that must stick keeps being classed slip by the round-off left in
  // its β, and its direction N̂ is the step's, not the traction's (measured on a tilted penny,
  // warm-started, contact unilateral: gammaRelative 3, 10, 100 took 14, 31, 89 Newton
  // iterations against 9 at 1; 1e3 to 1e8 reached maxIterations with every state wrong).
  if (count > 0 && (gammaCase < 1e-2 * diagonal / count || gammaCase > 10 * diagonal / count))
    return diagonal / count;
  return gammaCase;
}

void NestedDissectionOrdering::operator()(const Eigen::SparseMatrix<double>& A,
                                          PermutationType& perm) const {
  const Eigen::Index n = A.cols();
  // METIS on the pattern of A + Aᵀ (the factorisation's own ordering, metisOrdering); where
  // CHOLMOD cannot order, Eigen's COLAMD, SparseLU's default.
  Eigen::SparseMatrix<double> pattern = A.cwiseAbs();
  const Eigen::SparseMatrix<double> transposed = pattern.transpose();
  pattern += transposed;
  std::vector<long> order;
  if (!metisOrdering(pattern, order)) {
    Eigen::COLAMDOrdering<int>()(A, perm);
    return;
  }
  // order[k] is the column placed k-th; SparseLU wants perm.indices()(column) = position.
  perm.resize(n);
  for (Eigen::Index k = 0; k < n; ++k)
    perm.indices()[static_cast<Eigen::Index>(order[static_cast<std::size_t>(k)])] =
        static_cast<int>(k);
}

bool KrylovPreconditioner::factor(const ControlProblem& p, const ControlState& s,
                                  const std::vector<Eigen::Index>& active) {
  const Eigen::Index k = p.blockSize(), m = static_cast<Eigen::Index>(active.size());
  std::vector<Eigen::Index> where(static_cast<std::size_t>(p.size()), -1);
  for (Eigen::Index a = 0; a < m; ++a) where[static_cast<std::size_t>(active[a])] = a;
  // Row r of node i: Σ_j (δ_rj − P'_N,rj) S̃_tt(k·i + j, ·) + μ_i P'_ρ,r S̃_nt(i, ·) + γ P'_N,r·,
  // as ControlProblem::jacobianEntry, on the probed sparsity.
  std::vector<Eigen::Triplet<double>> g;
  for (Eigen::Index a = 0; a < m; ++a) {
    const Eigen::Index row = active[a], i = row / k, r = row % k;
    const NodeComplementarity& c = s.node[static_cast<std::size_t>(i)];
    for (Eigen::Index j = 0; j < k; ++j) {
      if (c.dPdN(r, j) != 0 && where[static_cast<std::size_t>(k * i + j)] >= 0)
        g.emplace_back(a, where[static_cast<std::size_t>(k * i + j)], p.gamma() * c.dPdN(r, j));
      const double f = (r == j ? 1.0 : 0.0) - c.dPdN(r, j);
      if (f == 0) continue;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(S_.Stt, k * i + j); it;
           ++it)
        if (where[static_cast<std::size_t>(it.col())] >= 0)
          g.emplace_back(a, where[static_cast<std::size_t>(it.col())], f * it.value());
    }
    const double f = p.mu()[i] * c.dPdRho[r];
    if (f != 0)
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(S_.Snt, i); it; ++it)
        if (where[static_cast<std::size_t>(it.col())] >= 0)
          g.emplace_back(a, where[static_cast<std::size_t>(it.col())], f * it.value());
  }
  Eigen::SparseMatrix<double> G(m, m);
  G.setFromTriplets(g.begin(), g.end());  // sums the duplicates
  G.makeCompressed();
  lu_.compute(G);
  ok_ = lu_.info() == Eigen::Success;
  if (ok_)
    largestFactorBytes_ =
        std::max(largestFactorBytes_,
                 static_cast<double>(lu_.nnzL() + lu_.nnzU()) * (sizeof(double) + sizeof(int)));
  return ok_;
}

double KrylovPreconditioner::probedBytes() const {
  const auto bytes = [](const Eigen::SparseMatrix<double, Eigen::RowMajor>& m) {
    return static_cast<double>(m.nonZeros()) * (sizeof(double) + sizeof(int)) +
           static_cast<double>(m.outerSize() + 1) * sizeof(int);
  };
  return bytes(S_.Stt) + bytes(S_.Snt);
}

Eigen::VectorXd KrylovPreconditioner::apply(const Eigen::VectorXd& v) const {
  if (!ok_) return v;
  Eigen::VectorXd x = lu_.solve(v);
  return x.allFinite() ? x : v;
}

}  // namespace friction
