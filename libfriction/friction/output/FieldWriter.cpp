// Field and table files of a time folder: see FieldWriter.hpp.
#include "friction/output/FieldWriter.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/Geometry>

#include "friction/core/AtomicFile.hpp"
#include "friction/dict/DictionaryWriter.hpp"
#include "friction/fracture/SignConventions.hpp"

namespace friction {

void writeDisplacementField(const std::string& path, const std::vector<Point>& u, int precision) {
  DictionaryWriter w("pointVectorField", "D", "displacement [m] at the split-mesh points");
  w.setPrecision(precision);
  w.entryRaw("dimensions", "[0 1 0 0 0 0 0]");
  std::ostringstream s;
  s.precision(precision);
  s << "nonuniform List<vector>\n" << u.size() << "\n(\n";
  for (const Point& v : u) s << "(" << v.x() << " " << v.y() << " " << v.z() << ")\n";
  s << ")";
  w.entryRaw("internalField", s.str());
  w.beginDict("boundaryField");
  w.endDict();
  w.writeAtomic(path);
}

namespace {

// Every node has the first node's frame, to 1e-12 per component (a flat fault).
bool oneFrame(const std::vector<FractureRow>& rows) {
  if (rows.empty()) return false;
  const FractureRow& a = rows.front();
  for (const FractureRow& r : rows)
    if ((r.normal - a.normal).cwiseAbs().maxCoeff() > 1e-12 ||
        (r.tangent[0] - a.tangent[0]).cwiseAbs().maxCoeff() > 1e-12 ||
        (r.tangent[1] - a.tangent[1]).cwiseAbs().maxCoeff() > 1e-12)
      return false;
  return true;
}

// Some node's t₁ is not tangentBasis(n): a roller turned its basis (docs/method.md §4).
bool turnedFrame(const std::vector<FractureRow>& rows) {
  for (const FractureRow& r : rows)
    if ((r.tangent[0] - tangentBasis(r.normal)[0]).cwiseAbs().maxCoeff() > 1e-12) return true;
  return false;
}

}  // namespace

void strikeDipBasis(const Eigen::Vector3d& n, Eigen::Vector3d& strike, Eigen::Vector3d& dip) {
  // Down the plane: −e_z projected on it. Along strike: the fault dips to its right (seen from
  // above, dip is strike turned clockwise by 90°), so neither depends on n's side.
  const Eigen::Vector3d down = -Eigen::Vector3d::UnitZ() + n.z() * n;
  if (std::abs(n.z()) >= 1 - 1e-12 || down.norm() < 1e-12) {
    strike = Eigen::Vector3d::UnitX();
    dip = -Eigen::Vector3d::UnitY();
    return;
  }
  if (std::abs(n.z()) <= 1e-12) {
    // A vertical fault dips neither way: dip = −e_z, and strike the horizontal direction in
    // it with a positive x component (or +y): its angle from x towards y in (−90°, 90°].
    dip = -Eigen::Vector3d::UnitZ();
    strike = Eigen::Vector3d(-n.y(), n.x(), 0).normalized();
    if (strike.x() < 0 || (strike.x() == 0 && strike.y() < 0)) strike = -strike;
    return;
  }
  dip = down.normalized();
  strike = Eigen::Vector3d(-dip.y(), dip.x(), 0).normalized();
}

std::array<double, 4> strikeDipValues(const FractureRow& r) {
  Eigen::Vector3d strike, dip;
  strikeDipBasis(r.normal, strike, dip);
  // Ω⁺ is the hanging wall when n_Γ (from Ω⁺ to Ω⁻) points away from it: the jump and the
  // traction are then the hanging wall's; else both change sign.
  const double side = r.normal.dot(dip.cross(strike)) < 0 ? 1.0 : -1.0;
  const Eigen::Vector3d slip = side * (r.slip[0] * r.tangent[0] + r.slip[1] * r.tangent[1]);
  const Eigen::Vector3d tau = side * (r.tau[0] * r.tangent[0] + r.tau[1] * r.tangent[1]);
  return {slip.dot(strike), slip.dot(dip), tau.dot(strike), tau.dot(dip)};
}

std::vector<double> fractureTableValues(const FractureRow& r, int dim) {
  std::vector<double> v;
  if (dim != 3) {
    v = {r.s,      r.position.x(), r.position.y(), r.slip[0],    r.slipIncrement[0],
         r.sigmaN, r.tau[0],       r.ST,           r.residual[0]};
  } else {
    const Eigen::Vector3d slip = r.slip[0] * r.tangent[0] + r.slip[1] * r.tangent[1];
    v = {r.position.x(),
         r.position.y(),
         r.position.z(),
         r.normal.x(),
         r.normal.y(),
         r.normal.z(),
         r.slip[0],
         r.slip[1],
         slip.x(),
         slip.y(),
         slip.z(),
         std::hypot(r.slip[0], r.slip[1]),
         r.slipIncrement[0],
         r.slipIncrement[1],
         r.sigmaN,
         r.tau[0],
         r.tau[1],
         std::hypot(r.tau[0], r.tau[1]),
         r.ST,
         std::hypot(r.residual[0], r.residual[1])};
  }
  if (r.hasOpening) v.push_back(r.opening);
  if (r.hasPressure) {
    v.push_back(r.pressure);
    v.push_back(r.sigmaNEffective);
    v.push_back(r.deltaCFS);
    if (dim == 3)  // the hanging wall's slip and τ on strike and down dip
      for (const double x : strikeDipValues(r)) v.push_back(x);
  }
  if (r.hasRateState) {
    v.push_back(r.slipRate);
    v.push_back(r.psi);
  }
  if (r.hasWeakening) {
    v.push_back(r.slipPath);
    v.push_back(r.frictionCoefficient);
  }
  if (dim != 3) {
    // The frame and the slip vector last, so that every earlier column keeps its place.
    const Eigen::Vector3d slip = r.slip[0] * r.tangent[0];
    v.insert(v.end(),
             {r.normal.x(), r.normal.y(), r.tangent[0].x(), r.tangent[0].y(), slip.x(), slip.y()});
  }
  return v;
}

void writeFractureTable(const std::string& path, const std::vector<FractureRow>& rows,
                        const std::string& statusLine, int precision, int dim,
                        const std::vector<std::string>& notes) {
  std::ostringstream out;
  out.precision(precision);
  // The rows are finite (FrictionCase writes no diverged step); should one not be, one
  // spelling of NaN ("nan", never "-nan"), which numpy, pandas and VTK read.
  const auto value = [&out](double v) -> std::ostream& {
    return std::isnan(v) ? out << "nan" : out << v;
  };
  // Fractures that open: the opening g before the state.
  const bool opening = !rows.empty() && rows.front().hasOpening;
  const bool hasPressure = !rows.empty() && rows.front().hasPressure;
  const std::string weakening =
      std::string(!rows.empty() && rows.front().hasRateState ? "slipRate psi " : "") +
      (!rows.empty() && rows.front().hasWeakening ? "slipPath frictionCoefficient " : "");
  const std::string pressure =
      !hasPressure ? ""
      : dim == 3   ? "pressure sigmaNEffective deltaCFS slipStrike slipDip tauStrike tauDip "
                   : "pressure sigmaNEffective deltaCFS ";
  if (dim != 3) {
    out << "# s x y slip slipIncrement sigmaN tau ST residual " << (opening ? "opening " : "")
        << pressure << weakening << "nx ny tx ty slipX slipY state\n# " << statusLine << "\n";
    for (const std::string& note : notes) out << "# " << note << "\n";
    for (const FractureRow& r : rows) {
      for (const double v : fractureTableValues(r, dim)) value(v) << " ";
      out << r.state << "\n";
    }
    writeTextAtomic(path, out.str());
    return;
  }
  out << "# x y z nx ny nz slip1 slip2 slipX slipY slipZ slipMagnitude slipIncrement1 "
         "slipIncrement2 sigmaN tau1 tau2 tauMagnitude ST residual "
      << (opening ? "opening " : "") << pressure << weakening << "state\n# " << statusLine << "\n";
  const auto vector = [&out](const Eigen::Vector3d& v) {
    out << "(" << v.x() << " " << v.y() << " " << v.z() << ")";
  };
  if (oneFrame(rows)) {
    out << "# frame n ";
    vector(rows.front().normal);
    out << " t1 ";
    vector(rows.front().tangent[0]);
    out << " t2 ";
    vector(rows.front().tangent[1]);
    out << "\n";
  } else {
    out << "# frame per node: n in columns nx ny nz, t1 = tangentBasis(n), t2 = n x t1 "
           "(docs/method.md)"
        << (turnedFrame(rows) ? "; on roller patches t2 may be turned to the roller's held "
                                "direction (slipX slipY slipZ give the slip vector)"
                              : "")
        << "\n";
  }
  // 3D: where the fault meets others, after the frame line (line 3 stays the frame).
  for (const std::string& note : notes) out << "# " << note << "\n";
  for (const FractureRow& r : rows) {
    for (const double v : fractureTableValues(r, dim)) value(v) << " ";
    out << r.state << "\n";
  }
  writeTextAtomic(path, out.str());
}

}  // namespace friction
