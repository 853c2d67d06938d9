// A field the caller of a run gives it: see GivenField.hpp.
#include "friction/effect/GivenField.hpp"

#include <cmath>

#include "friction/core/InputError.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/mesh/Mesh.hpp"

namespace friction {

void GivenField::check() const {
  if (times.empty())
    throw InputError(timesName,
                     "expected at least one time [s] (one per column of " + name + "), got none");
  for (std::size_t j = 0; j < times.size(); ++j) {
    if (!std::isfinite(times[j]))
      throw InputError(timesName, "entry " + std::to_string(j) + " is " + formatNumber(times[j]) +
                                      "; expected finite times [s]");
    if (j > 0 && !(times[j] > times[j - 1]))
      throw InputError(timesName, "entry " + std::to_string(j) + " (" + formatNumber(times[j]) +
                                      ") does not follow entry " + std::to_string(j - 1) + " (" +
                                      formatNumber(times[j - 1]) +
                                      "); expected times [s] strictly increasing");
  }
  if (values.cols() != static_cast<Eigen::Index>(times.size()))
    throw InputError(name, "expected one column per time of " + timesName + " (" +
                               std::to_string(times.size()) + "), got " +
                               std::to_string(values.cols()) + " columns");
  if (values.rows() == 0) throw InputError(name, "expected one row per vertex, got no rows");
  for (Eigen::Index j = 0; j < values.cols(); ++j)
    for (Eigen::Index i = 0; i < values.rows(); ++i)
      if (!std::isfinite(values(i, j)))
        throw InputError(name, "row " + std::to_string(i) + ", column " + std::to_string(j) +
                                   " is " + formatNumber(values(i, j)) +
                                   "; expected finite values");
}

GivenField GivenField::onSplitMesh(const SplitMesh& split) const {
  const Index n = split.mesh.numPoints();
  const Index original = split.origin.empty() ? n : split.numOriginalPoints();
  if (values.rows() == n) return *this;
  if (values.rows() != original)
    throw InputError(name, "expected one row per vertex of the split mesh (" + std::to_string(n) +
                               ") or of the unsplit mesh (" + std::to_string(original) + "), got " +
                               std::to_string(values.rows()) + " rows");
  // The unsplit mesh's numbering: a copy of a split node (after the unsplit vertices) takes
  // its node's value.
  GivenField out = *this;
  out.values.resize(n, values.cols());
  for (Index i = 0; i < n; ++i) out.values.row(i) = values.row(split.origin[i]);
  return out;
}

std::vector<Eigen::VectorXd> GivenField::cellMeans(const Mesh& mesh) const {
  std::vector<Eigen::VectorXd> out;
  for (Eigen::Index j = 0; j < values.cols(); ++j) {
    Eigen::VectorXd v(mesh.numCells());
    for (Index c = 0; c < mesh.numCells(); ++c) {
      // v₀ + mean of the differences: a cell whose vertices hold one value gets that value to
      // the bit (a plain sum divided by d + 1 would not always).
      const auto cell = mesh.cell(c);
      const double first = values(cell[0], j);
      double sum = 0;
      for (int k = 1; k < cell.size(); ++k) sum += values(cell[k], j) - first;
      v[c] = first + sum / static_cast<double>(cell.size());
    }
    out.push_back(std::move(v));
  }
  return out;
}

std::string GivenField::describe() const {
  return caller + "'s " + name + " at " + std::to_string(times.size()) +
         (times.size() == 1 ? " time" : " times");
}

std::string givenFieldMeaning(const std::string& key) {
  if (key == kPorePressureChange) return "the rock's pore-pressure change [Pa]";
  return key;
}

std::string givenFieldTaker(const std::string& key) {
  if (key == kPorePressureChange)
    return "a porePressure entry that takes it, e.g. rock { type porePressure; "
           "biotCoefficient 1; initial 0; data script; }";
  return "an effect that takes '" + key + "'";
}

}  // namespace friction
