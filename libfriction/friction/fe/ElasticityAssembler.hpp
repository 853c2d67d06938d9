// ElasticityAssembler: the global stiffness matrix, load vectors, facet mass matrices and
// point evaluation of stress and strain for P1 / P2 elasticity on triangles (plane strain or
// stress) and tetrahedra (docs/method.md §1, §4, §7; the facet mass is the M of the traction
// recovery (53); the pore pressure's load ∫ α_B p div v of §11). Each call dispatches once on
// the mesh's dimension to the element kernels of Simplex.hpp.
//
// Conventions: K u = F with u the interleaved nodal displacements of LagrangeSpace
// [m], F the nodal forces [N; N per m of thickness in 2D], K = ∫ ε(φ_i) : C : ε(φ_j) [N/m].
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
#include "friction/fe/MaterialMap.hpp"

namespace friction {

/// A vector field of position x [m], e.g. a body force [N/m³] or a traction [Pa]; in 2D it
/// is called with z = 0 and its z component is ignored.
using VectorField = std::function<Point(const Point&)>;
/// A scalar field of the cell and the position x [m] in it (z = 0 in 2D), e.g. a pore pressure
/// [Pa] that is constant per region (the cell says which) or smooth (x says where).
using CellScalarField = std::function<double(Index cell, const Point& x)>;
/// A tensor field of position, e.g. a displacement gradient G(i, j) = ∂u_i/∂x_j; in 2D its
/// top-left 2 × 2 block is used.
using TensorField = std::function<Eigen::Matrix3d(const Point&)>;

/// Errors of a discrete displacement against an exact one.
struct ErrorNorms {
  double l2 = 0.0;          ///< ‖u − u_h‖_{L²(Ω)} [m · m^(d/2)]
  double h1Seminorm = 0.0;  ///< ‖∇(u − u_h)‖_{L²(Ω)} [m^(d/2)]
};

class ElasticityAssembler {
 public:
  /// The assembler keeps a reference to the space (it must outlive it) and a copy of the
  /// materials: one Material for the whole body, or a MaterialMap of one per region (cell c
  /// of the space's mesh takes materials.ofCell(c)).
  ElasticityAssembler(const LagrangeSpace& space, const MaterialMap& materials);

  const LagrangeSpace& space() const { return *space_; }
  const MaterialMap& materials() const { return materials_; }
  /// The material of a cell.
  const Material& material(Index cell) const { return materials_.ofCell(cell); }

  /// Global stiffness matrix, numDofs × numDofs, symmetric, full storage. The sparsity
  /// pattern is built directly in compressed form from the node graph (no triplets), so the
  /// cost is linear in the mesh size.
  Eigen::SparseMatrix<double> stiffness() const;
  /// The same from the cells c with cells[c] != 0 only (a part of the body: the band of cells
  /// around the fractures, or one rank's own cells): its entries are the sums over those cells,
  /// in the same order as stiffness() adds them, and the pattern holds only their entries.
  Eigen::SparseMatrix<double> stiffness(const std::vector<char>& cells) const;

  /// Load vector of a constant body force f [N/m³]: F_i = ∫_Ω f · φ_i (any dimension; z
  /// ignored in 2D), and the same for 2D code.
  Eigen::VectorXd bodyForce(const Point& f) const;
  Eigen::VectorXd bodyForce(const Vector2& f) const;
  /// Load vector of a body force f(x) [N/m³], by a degree-5 rule per cell.
  Eigen::VectorXd bodyForce(const VectorField& f) const;
  /// Load vector of a body force constant in each cell, f(c) [N/m³] (a density per region,
  /// the divergence of a piecewise-linear in-situ stress): F_i = Σ_c f(c) · ∫_c φ_i.
  Eigen::VectorXd cellBodyForce(const std::function<Point(Index)>& f) const;

  /// Load vector of a pore pressure acting through a Biot coefficient (docs/method.md §12):
  /// F_i = ∫_Ω b · αp · div φ_i [N; N per m in 2D], with αp [Pa] = α_B p, given per cell and
  /// point by `alphaP` and integrated by a rule exact for αp linear in each cell (degree 1
  /// for P1, 2 for P2). It is the load of the total stress σ = C:ε − αp I: positive αp pushes
  /// outwards (a free body expands). b = 1 in 3D and in plane strain; in plane stress (σ_zz
  /// = 0 in a thin plate, so the pressure expands it across its thickness too) b = 2μ/(λ + 2μ)
  /// = (1 − 2ν)/(1 − ν) of the cell's material, the in-plane part of −αp I that remains once
  /// ε_zz is eliminated.
  Eigen::VectorXd pressureLoad(const CellScalarField& alphaP) const;
  /// The same for αp given at the mesh's points [Pa] (one value per mesh point, the
  /// vertices; a P2 space's midpoints are not used), interpolated linearly in each cell.
  Eigen::VectorXd pressureLoad(const Eigen::VectorXd& alphaPAtPoints) const;
  /// b of pressureLoad for a cell: 1, or (1 − 2ν)/(1 − ν) in plane stress.
  double pressureFactor(Index cell) const;

  /// Load vector of a constant traction g [Pa] on the facets with this label:
  /// F_i = ∫_patch g · φ_i. The traction is the force per area applied to the body (for an
  /// outward normal n and a stress σ at the boundary, g = σ n).
  Eigen::VectorXd traction(int label, const Point& g) const;
  Eigen::VectorXd traction(int label, const Vector2& g) const;
  /// Same for a traction g(x) [Pa], by a 4-point Gauss–Legendre rule on each edge (2D) or a
  /// degree-7 rule on each triangle (3D).
  Eigen::VectorXd traction(int label, const VectorField& g) const;

  /// Lumped (nodal-quadrature) scalar mass of a set of facets, one weight per space node
  /// [m^(d−1)], given by their vertices (d per facet, each a facet of some cell): the weights
  /// of Simplex.hpp's facetLumpedMass times the facet's measure — trapezoid / Simpson on 2D
  /// edges; 1/3 each (P1) or A/12 per vertex and A/4 per mid-edge node (P2, P1-iso-P2
  /// nodal quadrature, all positive) on triangles. Zero at nodes off the facets; the weights
  /// of each facet sum to its measure. Apply it per displacement component.
  Eigen::VectorXd lumpedFacetMass(const std::vector<Index>& facetVertices) const;
  /// Consistent scalar mass M_ij = ∫ φ_i φ_j over the same facets, numNodes × numNodes
  /// [m^(d−1)], full symmetric storage.
  Eigen::SparseMatrix<double> consistentFacetMass(const std::vector<Index>& facetVertices) const;

  /// 2D: the lumped mass of a set of triangle sides (a, b) [m]: trapezoid weights L/2 at the
  /// ends for P1, Simpson weights L/6, 4L/6, L/6 at (a, mid, b) for P2. Its row sums equal
  /// those of consistentEdgeMass.
  Eigen::VectorXd lumpedEdgeMass(const std::vector<std::array<Index, 2>>& edges) const;
  /// 2D: the consistent mass over the same edges [m], full symmetric storage.
  Eigen::SparseMatrix<double> consistentEdgeMass(
      const std::vector<std::array<Index, 2>>& edges) const;

  /// u_h(x) [m] for x [m] in (or on) cell `cell`; u is the full dof vector. Any dimension:
  /// z = 0 in 2D.
  Point displacement(const Eigen::VectorXd& u, Index cell, const Point& x) const;
  /// ∇u_h(x), G(i, j) = ∂u_i/∂x_j (the third row and column 0 in 2D).
  Eigen::Matrix3d displacementGradient(const Eigen::VectorXd& u, Index cell, const Point& x) const;
  /// Small strain ε = sym ∇u_h at x (ε_zz = 0 in 2D: plane strain's, and the in-plane part
  /// in plane stress).
  Eigen::Matrix3d strain(const Eigen::VectorXd& u, Index cell, const Point& x) const;
  /// Stress σ [Pa] at x: 3D Hooke's law; in 2D the in-plane stress with
  /// σ_zz = Material::outOfPlaneStress. The cell's material.
  Eigen::Matrix3d stress(const Eigen::VectorXd& u, Index cell, const Point& x) const;

  /// The same on a 2D mesh with 2D types (σ in-plane only).
  Vector2 displacement(const Eigen::VectorXd& u, Index cell, const Vector2& x) const;
  Eigen::Matrix2d displacementGradient(const Eigen::VectorXd& u, Index cell,
                                       const Vector2& x) const;
  Eigen::Matrix2d strain(const Eigen::VectorXd& u, Index cell, const Vector2& x) const;
  Eigen::Matrix2d stress(const Eigen::VectorXd& u, Index cell, const Vector2& x) const;

  /// ‖u − u_h‖_{L²} and |u − u_h|_{H¹} against an exact displacement and its gradient, by a
  /// degree-8 rule per cell (so that quadrature error stays well below the P2 error).
  ErrorNorms errorNorms(const Eigen::VectorXd& u, const VectorField& exact,
                        const TensorField& exactGradient) const;

 private:
  const LagrangeSpace* space_;
  MaterialMap materials_;
};

}  // namespace friction
