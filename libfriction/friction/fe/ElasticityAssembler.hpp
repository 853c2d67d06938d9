// ElasticityAssembler: the global stiffness matrix, load vectors, boundary-edge mass
// matrices and point evaluation of stress and strain for P1 / P2 plane elasticity
// (docs/method.md §1, §4; the edge mass is the M of the traction recovery (53)).
//
// Conventions: K u = F with u the interleaved nodal displacements of LagrangeSpace
// [m], F the nodal forces [N per m of thickness], K = ∫ ε(φ_i) : C : ε(φ_j) [N/m per m].
// K is returned in full symmetric storage (both triangles, column-major, compressed), so it
// can be multiplied directly and handed to either SparseFactor backend (which read the lower
// triangle).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <functional>
#include <vector>

#include "friction/core/Types.hpp"
#include "friction/fe/LagrangeSpace.hpp"
#include "friction/fe/Material.hpp"

namespace friction {

/// A vector field of position x [m], e.g. a body force [N/m³] or a traction [Pa].
using VectorField = std::function<Vector2(const Vector2&)>;
/// A tensor field of position, e.g. a displacement gradient G(i, j) = ∂u_i/∂x_j.
using TensorField = std::function<Eigen::Matrix2d(const Vector2&)>;

/// Errors of a discrete displacement against an exact one.
struct ErrorNorms {
  double l2 = 0.0;          ///< ‖u − u_h‖_{L²(Ω)} [m²] (displacement [m] times √area)
  double h1Seminorm = 0.0;  ///< ‖∇(u − u_h)‖_{L²(Ω)} [m]
};

class ElasticityAssembler {
 public:
  /// The assembler keeps references to both: they must outlive it.
  ElasticityAssembler(const LagrangeSpace& space, const Material& material);

  const LagrangeSpace& space() const { return *space_; }
  const Material& material() const { return *material_; }

  /// Global stiffness matrix, numDofs × numDofs, symmetric, full storage. The sparsity
  /// pattern is built directly in compressed form from the node graph (no triplets), so the
  /// cost is linear in the mesh size.
  Eigen::SparseMatrix<double> stiffness() const;

  /// Load vector of a constant body force f [N/m³]: F_i = ∫_Ω f · φ_i.
  Eigen::VectorXd bodyForce(const Vector2& f) const;
  /// Load vector of a body force f(x) [N/m³], by a degree-5 triangle rule.
  Eigen::VectorXd bodyForce(const VectorField& f) const;

  /// Load vector of a constant traction g [Pa] on the edges with this label:
  /// F_i = ∫_patch g · φ_i. The traction is the force per area applied to the body (for an
  /// outward normal n and a stress σ at the boundary, g = σ n).
  Eigen::VectorXd traction(int label, const Vector2& g) const;
  /// Same for a traction g(x) [Pa], by a 4-point Gauss–Legendre rule on each edge.
  Eigen::VectorXd traction(int label, const VectorField& g) const;

  /// Lumped (nodal-quadrature) scalar mass of a set of triangle sides (a, b), one weight per
  /// space node [m]: trapezoid weights L/2 at the ends for P1, Simpson weights L/6, 4L/6, L/6
  /// at (a, mid, b) for P2; zero at nodes off the edges. The weights of each edge sum to its
  /// length L. Apply it per displacement component.
  Eigen::VectorXd lumpedEdgeMass(const std::vector<std::array<Index, 2>>& edges) const;
  /// Consistent scalar mass M_ij = ∫ φ_i φ_j over the same edges, numNodes × numNodes [m],
  /// full symmetric storage. Its row sums equal lumpedEdgeMass.
  Eigen::SparseMatrix<double> consistentEdgeMass(
      const std::vector<std::array<Index, 2>>& edges) const;

  /// u_h(x) [m] for x [m] in (or on) triangle `cell`; u is the full dof vector.
  Vector2 displacement(const Eigen::VectorXd& u, Index cell, const Vector2& x) const;
  /// ∇u_h(x), G(i, j) = ∂u_i/∂x_j.
  Eigen::Matrix2d displacementGradient(const Eigen::VectorXd& u, Index cell,
                                       const Vector2& x) const;
  /// Small strain ε = sym ∇u_h at x.
  Eigen::Matrix2d strain(const Eigen::VectorXd& u, Index cell, const Vector2& x) const;
  /// In-plane stress σ [Pa] at x (σ_zz: Material::outOfPlaneStress of the strain).
  Eigen::Matrix2d stress(const Eigen::VectorXd& u, Index cell, const Vector2& x) const;

  /// ‖u − u_h‖_{L²} and |u − u_h|_{H¹} against an exact displacement and its gradient, by a
  /// degree-8 rule per triangle (so that quadrature error stays well below the P2 error).
  ErrorNorms errorNorms(const Eigen::VectorXd& u, const VectorField& exact,
                        const TensorField& exactGradient) const;

 private:
  const LagrangeSpace* space_;
  const Material* material_;
};

}  // namespace friction
