// Material: isotropic linear elasticity, 3D, plane strain or plane stress (docs/method.md §1).
#include "friction/fe/Material.hpp"

#include <initializer_list>
#include <utility>

#include "friction/core/Assert.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"

namespace friction {

Material Material::read(const Dictionary& dict, int dim) {
  FRICTION_ASSERT(dim == 2 || dim == 3, "the dimension is 2 or 3");
  if (dim == 3 && dict.found("planeStress"))
    dict.fail("planeStress",
              "key 'planeStress' has no meaning in 3D (the mesh is 3D: every strain component is "
              "resolved, there is no plane); remove it");
  return readConstants(dict, dict.getBoolOr("planeStress", false));
}

Material Material::readConstants(const Dictionary& dict, bool planeStress) {
  // The names other codes give these constants: the way forward rather than a spelling guess.
  for (const auto& [key, use] :
       std::initializer_list<std::pair<const char*, const char*>>{{"youngModulus", "E"},
                                                                  {"YoungModulus", "E"},
                                                                  {"poissonRatio", "nu"},
                                                                  {"PoissonRatio", "nu"},
                                                                  {"bulkModulus", "K"},
                                                                  {"shearModulus", "G"},
                                                                  {"lameLambda", "lambda"}})
    // At once, not at the end: the pair it belongs to would be reported missing first.
    if (dict.found(key))
      dict.fail(key, std::string("unknown key '") + key + "': libfriction names it '" + use +
                         "'; the constants are E and nu, lambda and mu, or K and G (bulk and "
                         "shear moduli) [Pa]");
  dict.advise("planeStrain",
              "plane strain is the default in 2D (planeStress no); remove the key, or write "
              "'planeStress yes;' for a thin plate");
  const std::size_t form = dict.alternative({{"E", "nu"}, {"lambda", "mu"}, {"K", "G"}});
  if (form == 0) {
    const double E = dict.getScalar("E", Bounds::positive());
    const double nu = dict.getScalar("nu", {-1.0, 0.5, true, true});
    return fromYoungPoisson(E, nu, planeStress);
  }
  if (form == 2) {
    // K and G (GEOS's bulk and shear moduli): λ = K − 2G/3, μ = G.
    const double K = dict.getScalar("K", Bounds::positive());
    const double G = dict.getScalar("G", Bounds::positive());
    return fromLame(K - 2.0 * G / 3.0, G, planeStress);
  }
  const double mu = dict.getScalar("mu", Bounds::positive());
  const double lambda = dict.getScalar("lambda");
  if (lambda + 2 * mu / 3 <= 0)
    dict.fail("lambda", "key 'lambda': expected λ + 2μ/3 > 0 (a positive bulk modulus), got λ = " +
                            formatNumber(lambda));
  return fromLame(lambda, mu, planeStress);
}

Material::Material(double lambda, double mu, bool planeStress)
    : lambda_(lambda), mu_(mu), planeStress_(planeStress) {
  // Positive definiteness of the 3D law (bulk modulus λ + 2μ/3 > 0, μ > 0); this also makes
  // both 2D laws positive definite.
  FRICTION_ASSERT(mu > 0.0, "shear modulus must be positive");
  FRICTION_ASSERT(lambda + 2.0 * mu / 3.0 > 0.0, "bulk modulus must be positive");
}

Material Material::fromYoungPoisson(double youngModulus, double poissonRatio, bool planeStress) {
  FRICTION_ASSERT(youngModulus > 0.0, "Young's modulus must be positive");
  FRICTION_ASSERT(poissonRatio > -1.0 && poissonRatio < 0.5, "Poisson's ratio out of (-1, 1/2)");
  const double e = youngModulus, nu = poissonRatio;
  return Material(e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), e / (2.0 * (1.0 + nu)), planeStress);
}

Material Material::fromLame(double lambda, double mu, bool planeStress) {
  return Material(lambda, mu, planeStress);
}

double Material::youngModulus() const {
  // The quotient first: μ(3λ + 2μ) alone overflows for E beyond ~1e154 Pa.
  return mu_ * ((3.0 * lambda_ + 2.0 * mu_) / (lambda_ + mu_));
}

double Material::poissonRatio() const { return lambda_ / (2.0 * (lambda_ + mu_)); }

double Material::lambdaStar() const {
  return planeStress_ ? 2.0 * lambda_ * mu_ / (lambda_ + 2.0 * mu_) : lambda_;
}

Eigen::Matrix2d Material::stress(const Eigen::Matrix2d& strain) const {
  return lambdaStar() * strain.trace() * Eigen::Matrix2d::Identity() + 2.0 * mu_ * strain;
}

double Material::outOfPlaneStress(const Eigen::Matrix2d& strain) const {
  return planeStress_ ? 0.0 : lambda_ * strain.trace();
}

Eigen::Matrix3d Material::voigtMatrix() const {
  const double l = lambdaStar(), m = mu_;
  Eigen::Matrix3d d;
  d << l + 2 * m, l, 0, l, l + 2 * m, 0, 0, 0, m;
  return d;
}

Eigen::Matrix3d Material::stress3d(const Eigen::Matrix3d& strain) const {
  FRICTION_ASSERT(!planeStress_, "plane stress has no 3D stress");
  return lambda_ * strain.trace() * Eigen::Matrix3d::Identity() + 2.0 * mu_ * strain;
}

Eigen::Matrix<double, 6, 6> Material::voigtMatrix3d() const {
  FRICTION_ASSERT(!planeStress_, "plane stress has no 3D Voigt matrix");
  const double l = lambda_, m = mu_;
  Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
  d.topLeftCorner<3, 3>().setConstant(l);
  for (int i = 0; i < 3; ++i) {
    d(i, i) = l + 2 * m;
    d(3 + i, 3 + i) = m;
  }
  return d;
}

}  // namespace friction
