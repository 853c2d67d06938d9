// FaultDiffusion: fluid pressure diffusing along a fault (METHOD.md §11, "Computed on the
// fault"), the general case that the closed forms (flow/ClosedForms.hpp) verify.
//
// Design note
// -----------
// * FaultFlowMesh (flow/FaultFlowMesh.hpp): the fault's own mesh (segments in 2D, triangles
//   in 3D; junction nodes shared) with P1 mass and stiffness; FlowCoefficient: S or κ as a
//   constant, per node or per element. StepSchedule (flow/StepSchedule.hpp): piecewise-
//   constant rates and held pressures. ClosedForms: the known answers. FaultDiffusion (this
//   file): the time stepping, sources and state.
// * Equation, on the fault Γ:  S ∂p/∂t − ∇_Γ·(κ ∇_Γ p) = q.
//   p [Pa]: the change Δp over the initial state p₀ (the caller adds p₀), positive for a rise
//   in pore pressure (injection). S [m/Pa]: storage per unit fault area (βφ·w for a fault zone
//   of width w, compressibility β, porosity φ). κ = k w_h/η [m³/(Pa·s)]: transmissivity.
//   α = κ/S [m²/s]: hydraulic diffusivity. q [m/s]: volume injected per unit fault area and
//   time; a well is q = Q δ(x − x_w), Q > 0 injection, Q < 0 production, in m³/s in 3D and in
//   m²/s (per metre out of the plane) in 2D. Edges of the fault are no-flow unless held.
// * Closed forms ↔ (S, κ, Q): 2D held pressure: α = κ/S. 2D flux (BP6): q₀/(βφ) = Q₀/S, i.e.
//   S = βφ, Q₀ = q₀ (ClosedForms.hpp). 3D rate: Δp* = Q/(4πκ).
// * Space: P1 on the fault mesh; M the (lumped by default, or consistent) mass with S, A the
//   stiffness with κ. Time: θ-scheme on substeps of length Δt,
//     (SM + θΔt A) p^{n+1} = (SM − (1−θ)Δt A) p^n + V_n,  V_n = ∫_{t_n}^{t_{n+1}} q φ dA dt,
//   θ = 1 backward Euler, θ = ½ Crank–Nicolson. Each well's volume is integrated exactly over
//   the substep, so injected volume = ∫ S p dA to round-off with no-flow edges, and a rate
//   change inside a substep costs O(Δt²) away from the well (the volume is right, only its
//   timing within the substep is not; measured CN order 1.86 for a shut-in inside substeps).
// * Crank–Nicolson damps nothing at high frequencies: a held pressure switched on or changed
//   (a jump in the data) leaves slowly decaying oscillations near it, and the error falls
//   only as Δt (measured: 2D erfc case, 1.6e-2 → 2.0e-3 for Δt/8). A few backward Euler
//   steps after each such jump restore second order (Rannacher, Numer. Math. 43, 1984):
//   `dampingSteps` of them (2 by default) follow every change of a held pressure. A change of
//   a rate keeps p continuous; damping it only adds backward Euler's error (measured 5× the
//   undamped error on the BP6 case), so rates are not damped. Which substeps are damped
//   depends only on their times, so a restart repeats them.
// * Held pressures (Dirichlet nodes) are eliminated symmetrically; their value at the end of
//   a substep is the schedule's value just before that time (a change at t_n acts from the
//   substep that starts at t_n; one inside a substep, from its end: align changes with the
//   solver's times). A held node is held at all times (Δp = 0 before its first time).
// * Factorisation: SM + θΔt A changes only with Δt and θ, so its SimplicialLDLT is cached,
//   keyed by (Δt, θ) (a few entries: CN with damping uses two). Δt is rounded to 40 bits of
//   mantissa (relative 1e-12) before use, so that steps whose lengths differ by round-off
//   (times accumulated as t += Δt) share one factor, and the matrix depends on the step's
//   times only, not on the history: a restarted run uses bitwise the same one.
// * State: the nodal p. state()/setState() are all a restart needs: advancing 0→1→2 and
//   advancing 0→1, setState, 1→2 give the same bits.
#pragma once

#include <Eigen/SparseCholesky>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "friction/flow/FaultFlowMesh.hpp"
#include "friction/flow/StepSchedule.hpp"

namespace friction {

enum class TimeScheme { backwardEuler, crankNicolson };
/// "backwardEuler", "crankNicolson" (the dictionary's words).
const char* toString(TimeScheme scheme);
/// The scheme of that name; InputError at `where` listing the valid names otherwise.
TimeScheme timeSchemeNamed(const std::string& name, const SourceLocation& where = {});

struct FaultDiffusionOptions {
  TimeScheme scheme = TimeScheme::backwardEuler;
  /// Longest substep [s]: advance(t0, t1) takes ceil((t1 − t0)/maxStep) equal substeps.
  double maxStep = std::numeric_limits<double>::infinity();
  /// Lumped (row-sum) mass: monotone backward Euler on non-obtuse meshes; else consistent.
  bool lumpedMass = true;
  /// Crank–Nicolson: backward Euler substeps after each change of a held pressure.
  int dampingSteps = 2;
};

class FaultDiffusion {
 public:
  /// S = storage [m/Pa] (> 0), κ = transmissivity [m³/(Pa·s)] (≥ 0) on `mesh`. Refuses bad
  /// values and options with an InputError at `where`. The state starts at p = 0.
  FaultDiffusion(FaultFlowMesh mesh, FlowCoefficient storage, FlowCoefficient transmissivity,
                 FaultDiffusionOptions options = {}, SourceLocation where = {});

  /// A well at x injecting the volume rate `rate` (m³/s in 3D, m²/s in 2D; < 0 produces).
  /// Its source is the P1 point load at the closest point of the fault: shared among that
  /// element's nodes by their weights there (so a well between nodes is where it is, and the
  /// volume is exact). Refuses (InputError at `where`) a well farther than maxDistance [m]
  /// from the fault. Volume given to a held node leaves through it. Returns the well's number.
  int addRateWell(const Point& x, StepSchedule rate, double maxDistance, SourceLocation where = {});
  /// Holds Δp = deltaP(t) [Pa] at the fault node nearest x (a pressure is held at a node: the
  /// nearest one, not interpolated). Refuses a node farther than maxDistance [m] or one that
  /// is held already. In 3D a pressure held at one node is a point value whose flux depends
  /// on h (as ln h): no closed form compares with it.
  void addHeldPressure(const Point& x, StepSchedule deltaP, double maxDistance,
                       SourceLocation where = {});
  /// Holds Δp = deltaP(t) at the given mesh nodes (e.g. mesh().edgeNodes(), the fault's
  /// outer edge): refuses an index out of range or a node already held.
  void holdNodes(const std::vector<Index>& nodes, StepSchedule deltaP, SourceLocation where = {});

  /// Advances the state from tFrom to tTo [s] (tTo ≥ tFrom), in equal substeps no longer
  /// than options.maxStep.
  void advance(double tFrom, double tTo);

  /// Nodal Δp [Pa], by mesh node.
  const Eigen::VectorXd& state() const { return p_; }
  /// Replaces the state (a restart, an initial Δp); InputError if the size is not numNodes.
  void setState(const Eigen::VectorXd& p, SourceLocation where = {});

  /// ∫ S Δp dA [m³ in 3D; m² in 2D]: the stored volume, with the mass the scheme uses.
  double storedVolume() const;
  /// Σ over wells of ∫_{t0}^{t1} Q dt: the volume injected by the rate wells.
  double injectedVolume(double t0, double t1) const;
  /// Number of matrix factorisations so far (one per distinct (Δt, θ) while cached).
  int numFactorisations() const { return numFactorisations_; }
  /// Number of substeps taken so far.
  long numSubsteps() const { return numSubsteps_; }
  const FaultFlowMesh& mesh() const { return mesh_; }
  const FaultDiffusionOptions& options() const { return options_; }

 private:
  struct Well {
    std::vector<std::pair<Index, double>> weights;
    StepSchedule rate;
  };
  struct Held {
    std::vector<Index> nodes;
    StepSchedule value;
  };
  struct Factor {
    double dt = 0.0;
    double theta = 1.0;
    std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> ldlt;
  };

  void hold(const std::vector<Index>& nodes, StepSchedule deltaP, const SourceLocation& where);
  const Factor& factor(double dt, double theta);
  bool damped(double t0, double t1, double dt) const;
  void substep(double t0, double t1, double dt);

  FaultFlowMesh mesh_;
  FaultDiffusionOptions options_;
  Eigen::SparseMatrix<double> storageMass_;  // SM
  Eigen::SparseMatrix<double> stiffness_;    // A
  std::vector<Well> wells_;
  std::vector<Held> held_;
  std::vector<int> heldBy_;  // per node, the Held group holding it, or −1
  std::vector<Factor> factors_;
  int numFactorisations_ = 0;
  long numSubsteps_ = 0;
  Eigen::VectorXd p_;
};

}  // namespace friction
