// FrictionField: a friction parameter of a fracture (frictionCoefficient, cohesion, threshold)
// as a number or as a field along the fracture (issue #13), in constant/fractureProperties:
//
//   frictionCoefficient 0.6;                                          // a number, as before
//   frictionCoefficient { type arclength; table ((0 0.6) (0.1 0.8)); } // (s value) rows, 2D
//   frictionCoefficient { type arclength; file "constant/mu.dat"; }    // lines "s value", 2D
//   frictionCoefficient { type points; file "constant/mu.dat"; }       // lines "x y [z] value"
//   frictionCoefficient { type depth; value 0.6; gradient -0.01; reference 0; }
//
// arclength: linear interpolation in the arclength s of the fracture's table [m]; the rows
//   must cover every node's s (no extrapolation). A fault surface (3D) has no arclength.
// points: each fracture node takes the value of the nearest row, which must lie within
//   maxDistance [m] (default 1e-6 × the fracture's bounding-box diagonal: one row per node at
//   the node's coordinates, as the fracture table writes them); a larger maxDistance makes it a
//   nearest-neighbour lookup of scattered values. 2D rows "x y value", 3D "x y z value".
// depth: value + gradient (v − reference), v the vertical coordinate (y in 2D, z in 3D, as
//   initialStress has it; v grows upwards, so a value growing with depth has gradient < 0).
//
// The values are checked node by node against the key's bounds (μ ≥ 0, c ≥ 0, g > 0): an
// InputError names the dictionary's file and line, the key and the node.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "friction/core/InputError.hpp"
#include "friction/dict/Dictionary.hpp"

namespace friction {

struct ControlNode;

class FrictionField {
 public:
  /// The names of the field types (for messages and the README).
  static std::vector<std::string> typeNames();
  /// A constant (the form of a number in the dictionary).
  explicit FrictionField(double value = 0) : value_(value) {}
  /// Reads `key` of d: a number within bounds, or a sub-dictionary with its 'type'. caseDir:
  /// files are relative to it; dim: the mesh's dimension.
  static FrictionField read(const Dictionary& d, const std::string& key, Bounds bounds,
                            const std::string& caseDir, int dim);

  bool isConstant() const { return kind_ == Kind::constant; }
  /// The number (constant fields).
  double value() const { return value_; }
  /// The values at the given control nodes (all of one fracture), checked against the bounds.
  Eigen::VectorXd evaluate(const std::vector<const ControlNode*>& nodes) const;
  /// The values at the control nodes of fracture f among all of a system's `nodes`; `index`
  /// receives each value's position in `nodes`.
  Eigen::VectorXd evaluateOnFracture(const std::vector<ControlNode>& nodes, int f,
                                     std::vector<std::size_t>& index) const;
  /// "0.6", or the field's form for the log ("arclength table (3 rows)", "points from
  /// constant/mu.dat (41 rows)", "depth: 0.6 at y = 0 m, gradient -0.01 per m").
  std::string describe() const;

 private:
  enum class Kind { constant, arclength, points, depth };
  [[noreturn]] void failAt(const ControlNode& node, const std::string& what) const;

  Kind kind_ = Kind::constant;
  double value_ = 0;
  std::string key_, file_;
  SourceLocation where_;
  Bounds bounds_;
  int dim_ = 2;
  std::vector<std::vector<double>> rows_;  ///< arclength: (s value); points: (x y [z] value)
  std::vector<int> lines_;                 ///< the file line of each row (points files)
  double gradient_ = 0, reference_ = 0, maxDistance_ = -1;  ///< maxDistance < 0: the default
};

}  // namespace friction
