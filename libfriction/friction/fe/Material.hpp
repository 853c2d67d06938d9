// Material: isotropic linear elasticity (docs/method.md §1). In 3D Hooke's law
// σ = λ tr(ε) I + 2μ ε. In 2D plane strain (the default) or plane stress:
// σ = λ* tr(ε) I + 2μ ε with λ* = λ in plane strain and λ* = 2λμ/(λ + 2μ) in plane stress
// (σ_zz = 0 eliminates ε_zz). Plane stress has no meaning in 3D: read() refuses it there.
//
// Units: E, λ, μ and stresses in Pa; strains dimensionless. In 2D every force is per unit
// thickness (N/m), so the stiffness matrix is in N/m² · m = N/m per unit thickness.
#pragma once

#include <Eigen/Core>

namespace friction {

class Dictionary;

class Material {
 public:
  /// From constant/mechanicalProperties: 'E' and 'nu', 'lambda' and 'mu', or 'K' and 'G' (bulk
  /// and shear moduli) (alternatives: keys of two pairs are an error that says so), and
  /// 'planeStress' (default no); other codes' names (youngModulus, planeStrain, ...) are
  /// refused with the name to use. Range
  /// checks are InputErrors naming file:line and key. `dim` is the mesh's dimension (2 or 3):
  /// in 3D the key 'planeStress' is refused (every strain component is resolved there).
  static Material read(const Dictionary& dict, int dim = 2);
  /// The constants alone (the pairs of read(), with the same checks),
  /// for a dictionary that does not hold 'planeStress' (one region's entry of MaterialMap).
  static Material readConstants(const Dictionary& dict, bool planeStress);
  /// From Young's modulus E [Pa] (> 0) and Poisson's ratio ν (−1 < ν < 1/2). Range checks
  /// with file and line belong to the dictionary layer; here they are debug asserts.
  static Material fromYoungPoisson(double youngModulus, double poissonRatio,
                                   bool planeStress = false);
  /// From the Lamé constants λ [Pa] and μ [Pa] (μ > 0, λ + 2μ/3 > 0) of the 3D material.
  static Material fromLame(double lambda, double mu, bool planeStress = false);

  /// Lamé λ of the 3D material [Pa] (not the plane-stress λ*).
  double lambda() const { return lambda_; }
  /// Shear modulus μ [Pa].
  double mu() const { return mu_; }
  double youngModulus() const;
  double poissonRatio() const;
  bool planeStress() const { return planeStress_; }

  /// λ* of the 2D law [Pa]: λ in plane strain, 2λμ/(λ + 2μ) in plane stress.
  double lambdaStar() const;

  /// In-plane stress [Pa] from a symmetric strain tensor.
  Eigen::Matrix2d stress(const Eigen::Matrix2d& strain) const;
  /// σ_zz [Pa]: λ tr(ε) in plane strain, 0 in plane stress.
  double outOfPlaneStress(const Eigen::Matrix2d& strain) const;

  /// Voigt matrix D with (σxx, σyy, σxy) = D (εxx, εyy, 2εxy) [Pa].
  Eigen::Matrix3d voigtMatrix() const;

  /// 3D stress [Pa] from a symmetric strain tensor: λ tr(ε) I + 2μ ε (not for plane stress).
  Eigen::Matrix3d stress3d(const Eigen::Matrix3d& strain) const;
  /// 3D Voigt matrix D with (σxx, σyy, σzz, σyz, σxz, σxy) = D (εxx, εyy, εzz, 2εyz, 2εxz,
  /// 2εxy) [Pa] (engineering shear strains; not for plane stress).
  Eigen::Matrix<double, 6, 6> voigtMatrix3d() const;

 private:
  Material(double lambda, double mu, bool planeStress);

  double lambda_;
  double mu_;
  bool planeStress_;
};

}  // namespace friction
