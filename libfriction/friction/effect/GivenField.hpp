// GivenField: a field that the program running a case hands to the run instead of a file of
// the case. The FreeFEM plug-in's frictionSolve("case", pressure = P, pressureTimes = T) gives
// the rock's pore-pressure change that the script computed (README.md, "FreeFEM users: the
// plug-in"); an effect whose entry says its values come from the caller (porePressure's
// `data script;`) takes it (Effect::takeGivenFields). Values at the vertices of the mesh at
// listed times: per cell the mean of its vertices' values (the mean of the P1 interpolant),
// linear in time between the listed times and constant beyond, as porePressure's `data`.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "friction/core/Types.hpp"

namespace friction {

struct Mesh;
struct SplitMesh;

/// The key of the rock's pore-pressure change Δp_b [Pa] (porePressure's `data script;`).
inline constexpr const char* kPorePressureChange = "porePressureChange";

struct GivenField {
  std::string caller;         ///< who gives it, for the log and messages: "frictionSolve"
  std::string name;           ///< how the caller names the values: "pressure"
  std::string timesName;      ///< and their times: "pressureTimes"
  std::vector<double> times;  ///< [s], strictly increasing
  /// One row per vertex (of the split mesh, or of the unsplit mesh: onSplitMesh), one column
  /// per time.
  Eigen::MatrixXd values;

  /// InputError naming `timesName` or `name` (the caller's arguments) unless there is a time,
  /// the times are finite and strictly increasing, there is one column per time, a row, and
  /// every value is finite.
  void check() const;
  /// The values per vertex of the split mesh: as they are if there is a row per split-mesh
  /// vertex; if there is a row per vertex of the unsplit mesh, each copy of a split node takes
  /// its node's row. Otherwise an InputError naming `name` and both counts.
  GivenField onSplitMesh(const SplitMesh& split) const;
  /// Per time, the mean over each cell of its vertices' values (rows: mesh's vertices).
  std::vector<Eigen::VectorXd> cellMeans(const Mesh& mesh) const;
  /// "frictionSolve's pressure at 2 times", for the log.
  std::string describe() const;
};

/// The fields a run is given, by key (kPorePressureChange).
using GivenFields = std::map<std::string, GivenField>;

/// For the message when no effect takes a field of this key: what it is and what the case
/// needs to take it, e.g. "the rock's pore-pressure change Δp_b [Pa]" and "a porePressure
/// entry ... data script; ...".
std::string givenFieldMeaning(const std::string& key);
std::string givenFieldTaker(const std::string& key);

}  // namespace friction
