// FaultSeries: SEAS-layout time series of a quasi-dynamic run (FaultSeries.hpp).
#include "friction/output/FaultSeries.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>

#include <Eigen/Geometry>

#include "friction/core/AtomicFile.hpp"
#include "friction/core/InputFile.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/dict/DictionaryWriter.hpp"
#include "friction/dict/Value.hpp"
#include "friction/fe/LagrangeSpace.hpp"
#include "friction/fe/Simplex.hpp"
#include "friction/fracture/FractureSystem.hpp"
#include "friction/law/RateState.hpp"

namespace fs = std::filesystem;

namespace friction {

namespace {

/// SEAS's recommended formats: 21.13E for the time, 14.6E for the values.
void appendTime(std::string& row, double t) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%21.13E", t);
  row += buf;
}
void appendValue(std::string& row, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, " %14.6E", v + 0.0);  // + 0.0: no "-0" for a zero
  row += buf;
}

/// The lines of an earlier run's file to keep on a restart at `limit`: comments and the
/// column line, and the rows whose first number (the time) is at or before it.
std::string keptLines(const std::string& path, double limit) {
  std::string kept;
  if (!fs::exists(path)) return kept;
  InputFileRole role;  // a FIFO put in its place must not block the restart
  role.what = "a fault output file frictionSolver writes";
  std::istringstream in(readInputFile(path, role));
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    const char* begin = line.c_str();
    char* end = nullptr;
    const double t = std::strtod(begin, &end);
    if (end == begin || t <= limit) kept += line + "\n";
  }
  return kept;
}

std::string shortNumber(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

/// "(x y z)" to 10 significant digits, round-off below 1e-9 of the largest component as 0:
/// a header names the node, not its last bits.
std::string shortPoint(const Eigen::Vector3d& x) {
  const double scale = x.cwiseAbs().maxCoeff();
  std::string out = "(";
  for (int c = 0; c < 3; ++c) {
    char buf[64];
    const double v = std::abs(x[c]) <= 1e-9 * scale ? 0.0 : x[c];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    out += (c > 0 ? " " : "") + std::string(buf);
  }
  return out + ")";
}

}  // namespace

FaultSeries::~FaultSeries() = default;

std::unique_ptr<FaultSeries> FaultSeries::read(const Dictionary& controlDict) {
  if (!controlDict.found("faultOutput")) return nullptr;
  if (!controlDict.isDict("faultOutput"))
    controlDict.fail("faultOutput",
                     "key 'faultOutput': expected a sub-dictionary { fracture ...; stations { name "
                     "s; ... } profiles { ... } }");
  const Dictionary& d = controlDict.subDict("faultOutput");
  auto out = std::unique_ptr<FaultSeries>(new FaultSeries);
  FaultSeries& o = *out;
  o.fracture_ = d.getWord("fracture");
  o.fractureAt_ = d.location("fracture");
  if (d.found("positiveSlip")) {
    const std::vector<double> v = d.getScalarList("positiveSlip");
    if (v.size() < 2 || v.size() > 3)
      d.fail("positiveSlip", "key 'positiveSlip': expected a vector (x y), or (x y z) in 3D");
    o.positive_ << v[0], v[1], v.size() == 3 ? v[2] : 0.0;
    if (!(o.positive_.norm() > 0) || !std::isfinite(o.positive_.norm()))
      d.fail("positiveSlip", "key 'positiveSlip': expected a non-zero vector");
    o.positive_.normalize();
    o.positiveGiven_ = true;
    o.positiveAt_ = d.location("positiveSlip");
  }
  if (d.found("strike")) {
    const std::vector<double> v = d.getScalarList("strike");
    if (v.size() != 3)
      d.fail("strike", "key 'strike': expected a vector (x y z), SEAS's along-strike direction 2");
    o.strike_ << v[0], v[1], v[2];
    if (!(o.strike_.norm() > 0) || !std::isfinite(o.strike_.norm()))
      d.fail("strike", "key 'strike': expected a non-zero vector");
    o.strike_.normalize();
    o.strikeGiven_ = true;
    o.strikeAt_ = d.location("strike");
  }
  o.seismicRate_ = d.getScalarOr("seismicSlipRate", 1e-3, Bounds::positive());
  o.stationInterval_ = d.getScalarOr("stationInterval", 0.0, Bounds::nonNegative());
  o.stationSeismic_ = d.getScalarOr("stationSeismicInterval", 0.0, Bounds::nonNegative());
  if (d.found("stations")) {
    if (!d.isDict("stations"))
      d.fail("stations", "key 'stations': expected a sub-dictionary of 'name arclength;' entries");
    const Dictionary& st = d.subDict("stations");
    for (const std::string& name : st.keys()) {
      o.checkStationName(st, name, "station");
      Station s;
      s.name = name;
      s.where = st.location(name);
      // A number is an arclength (2D); a list (x y z) a point on a fault surface (3D).
      const std::vector<Value>& v = st.values(name);
      if (v.size() == 1 && v[0].isList()) {
        const std::vector<double> x = st.getScalarList(name);
        if (x.size() != 3)
          st.fail(name, "station '" + name +
                            "': expected an arclength s [m] (2D) or a point (x y z) [m] (3D)");
        s.point = true;
        s.x << x[0], x[1], x[2];
      } else {
        s.s = st.getScalar(name);
      }
      o.stations_.push_back(s);
    }
    if (o.stations_.empty())
      d.fail("stations", "key 'stations': no station (expected entries 'name arclength;')");
  }
  if (d.found("profiles")) {
    if (!d.isDict("profiles"))
      d.fail("profiles",
             "key 'profiles': expected a sub-dictionary { from; to; spacing; "
             "interval; seismicInterval; }");
    const Dictionary& p = d.subDict("profiles");
    o.profiles_ = true;
    o.profilesAt_ = d.location("profiles");
    o.from_ = p.getScalarOr("from", 0.0);
    o.to_ = p.getScalar("to");
    o.spacing_ = p.getScalar("spacing", Bounds::positive());
    if (!(o.to_ >= o.from_)) p.fail("to", "key 'to': below 'from'");
    if ((o.to_ - o.from_) / o.spacing_ > 1e5)
      p.fail("spacing", "key 'spacing': more than 100 000 points from 'from' to 'to'");
    o.profileInterval_ = p.getScalar("interval", Bounds::nonNegative());
    o.profileSeismic_ = p.getScalarOr("seismicInterval", 0.0, Bounds::nonNegative());
  }
  if (d.found("surfaceStations")) {
    if (!d.isDict("surfaceStations"))
      d.fail("surfaceStations",
             "key 'surfaceStations': expected a sub-dictionary of 'name (x y);' entries");
    const Dictionary& st = d.subDict("surfaceStations");
    for (const std::string& name : st.keys()) {
      o.checkStationName(st, name, "surface station");
      Surface x;
      x.name = name;
      x.where = st.location(name);
      const std::vector<Value>& v = st.values(name);
      if (v.size() == 1 && v[0].isList() && v[0].items.size() == 3) {
        x.in3D = true;  // a 3D mesh's point (bind() checks the dimension)
        const std::vector<double> c = st.getScalarList(name);
        x.x = Eigen::Vector3d(c[0], c[1], c[2]);
      } else {
        x.x.head<2>() = st.getVector(name);
      }
      o.surface_.push_back(x);
    }
    if (o.surface_.empty())
      d.fail("surfaceStations", "key 'surfaceStations': no station (expected 'name (x y);')");
    o.surfaceAt_ = d.location("surfaceStations");
  }
  o.verticalDown_ = d.getBoolOr("verticalDown", false);
  o.ruptures_ = d.getBoolOr("ruptures", false);
  if (o.stations_.empty() && !o.profiles_ && o.surface_.empty() && !o.ruptures_)
    throw InputError(d.location(),
                     "faultOutput: give 'stations', 'profiles', 'surfaceStations', "
                     "'ruptures yes' or some of them");
  return out;
}

void FaultSeries::checkStationName(const Dictionary& d, const std::string& name,
                                   const std::string& what) const {
  // A station's name is its file's name, of one folder with the profiles' and global.dat.
  const bool taken = std::any_of(stations_.begin(), stations_.end(),
                                 [&](const Station& x) { return x.name == name; }) ||
                     std::any_of(surface_.begin(), surface_.end(),
                                 [&](const Surface& x) { return x.name == name; });
  if (name.find('/') != std::string::npos || name == "slip" || name == "shearstress" ||
      name == "normalstress" || name == "global" || taken)
    d.fail(name, what + " '" + name +
                     "': a station's name is its file's name: no '/', not one of the other "
                     "files (slip, shearstress, normalstress, global), not another station's");
}

FaultSeries::Station FaultSeries::locate(double s, const std::string& what,
                                         const SourceLocation& where,
                                         const std::vector<ControlNode>& nodes) const {
  const double s0 = nodes[static_cast<std::size_t>(onFracture_.front())].arclength;
  const double s1 = nodes[static_cast<std::size_t>(onFracture_.back())].arclength;
  const double tol = 1e-9 * std::max(1.0, std::abs(s1 - s0));
  if (!(s >= s0 - tol && s <= s1 + tol))
    throw InputError(where, what + " at arclength " + formatNumber(s) + " m: not on fracture '" +
                                fracture_ + "', whose arclength runs from " + formatNumber(s0) +
                                " to " + formatNumber(s1) + " m");
  Station st;
  st.s = s;
  st.where = where;
  std::size_t j = 1;
  while (j + 1 < onFracture_.size() &&
         nodes[static_cast<std::size_t>(onFracture_[j])].arclength < s)
    ++j;
  if (onFracture_.size() == 1) j = 0;
  st.i0 = onFracture_[j == 0 ? 0 : j - 1];
  st.i1 = onFracture_[j];
  const double a = nodes[static_cast<std::size_t>(st.i0)].arclength,
               b = nodes[static_cast<std::size_t>(st.i1)].arclength;
  st.w = b > a ? std::clamp((s - a) / (b - a), 0.0, 1.0) : 0.0;
  return st;
}

void FaultSeries::bind(const std::vector<ControlNode>& nodes, int dim, int k,
                       const std::vector<std::string>& fractureNames,
                       const std::vector<RateState>& laws, const LagrangeSpace& space,
                       const Eigen::VectorXd& weights, double shearModulus,
                       const Eigen::VectorXd& imposed) {
  shearModulus_ = shearModulus;
  dim_ = dim;
  if (dim == 3) {
    // What 3D does not write yet, and the 2D key that 3D replaces, before any work.
    if (profiles_)
      throw InputError(profilesAt_,
                       "faultOutput: 'profiles' run along a 2D fracture's arclength, which a "
                       "fault surface (3D) does not have: remove them (3D writes the stations "
                       "and global.dat)");
    for (const Surface& x : surface_)
      if (!x.in3D)
        throw InputError(x.where,
                         "surface station '" + x.name + "': expected a point (x y z) on a 3D mesh");
    if (positiveGiven_)
      throw InputError(positiveAt_,
                       "faultOutput: 'positiveSlip' is the 2D key; in 3D give 'strike (x y z)', "
                       "SEAS's along-strike direction 2 (slip_2 and slip_3 then follow SEAS's "
                       "signs)");
    if (!stations_.empty() && !strikeGiven_)
      throw InputError(fractureAt_,
                       "faultOutput: 3D stations need 'strike (x y z)', SEAS's along-strike "
                       "direction 2 (e.g. strike (1 0 0) for a fault in the plane y = 0)");
  } else {
    if (strikeGiven_)
      throw InputError(strikeAt_,
                       "faultOutput: 'strike' is for 3D faults; in 2D the slip's sign is "
                       "'positiveSlip (x y)'");
    for (const Surface& x : surface_)
      if (x.in3D)
        throw InputError(x.where,
                         "surface station '" + x.name + "': expected a point (x y) on a 2D mesh");
    for (const Station& st : stations_)
      if (st.point)
        throw InputError(st.where, "station '" + st.name +
                                       "': a point (x y z) is a 3D station; in 2D give the "
                                       "arclength s [m] along the fracture");
  }
  const auto it = std::find(fractureNames.begin(), fractureNames.end(), fracture_);
  if (it == fractureNames.end())
    throw InputError(fractureAt_, "faultOutput: '" + fracture_ + "' is not a fracture" +
                                      suggestionText(fracture_, fractureNames) +
                                      " (fractures: " + joinWords(fractureNames) + ")");
  const int f = static_cast<int>(it - fractureNames.begin());
  k_ = k;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].fracture == f) onFracture_.push_back(static_cast<Eigen::Index>(i));
  if (onFracture_.empty())
    throw InputError(fractureAt_, "faultOutput: fracture '" + fracture_ + "' has no node");
  if (dim == 2)
    std::stable_sort(onFracture_.begin(), onFracture_.end(), [&](Eigen::Index a, Eigen::Index b) {
      return nodes[static_cast<std::size_t>(a)].arclength <
             nodes[static_cast<std::size_t>(b)].arclength;
    });
  const std::size_t n = nodes.size();
  sign_.assign(n, 1.0);
  weight_.assign(n, 0.0);
  creeping_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    weight_[i] = weights[static_cast<Eigen::Index>(i)];
    creeping_[i] =
        static_cast<Eigen::Index>(i) < imposed.size() && imposed[static_cast<Eigen::Index>(i)] != 0;
  }
  L_.assign(n, 0.0), V0_.assign(n, 1.0), f0_.assign(n, 0.0), b_.assign(n, 1.0);
  for (const Eigen::Index i : onFracture_) {
    const auto u = static_cast<std::size_t>(i);
    const RateState& law = laws[u];
    if (!(law.L > 0))
      throw InputError(fractureAt_, "faultOutput: fracture '" + fracture_ +
                                        "' has no rate-and-state law (its state column needs "
                                        "law rateState)");
    L_[u] = law.L, V0_[u] = law.V0, f0_[u] = law.f0, b_[u] = law.b;
    if (positiveGiven_ && dim == 2) {
      const double d = positive_.dot(nodes[u].tangent[0]);
      if (std::abs(d) < 1e-6)
        throw InputError(fractureAt_, "faultOutput: positiveSlip is normal to fracture '" +
                                          fracture_ +
                                          "' at s = " + formatNumber(nodes[u].arclength) +
                                          " m: it gives the slip no sign there");
      sign_[u] = d > 0 ? 1.0 : -1.0;
    }
  }
  position_.assign(n, Eigen::Vector3d::Zero());
  for (const Eigen::Index i : onFracture_)
    position_[static_cast<std::size_t>(i)] = nodes[static_cast<std::size_t>(i)].position;
  if (dim == 3) {
    if (ruptures_ && !strikeGiven_)
      throw InputError(fractureAt_,
                       "faultOutput: 'ruptures' in 3D need 'strike (x y z)', SEAS's "
                       "along-strike direction 2 (the slip is written along 2 and 3)");
    bind3D(nodes);
    bindSurface3D(space);
    return;
  }
  for (Station& st : stations_) {
    const std::string name = st.name;
    st = locate(st.s, "station '" + name + "'", st.where, nodes);
    st.name = name;
  }
  // Surface stations: the cell holding the point (the first in the mesh's order) and the
  // element's basis there.
  std::vector<Eigen::Triplet<double>> w;
  for (std::size_t j = 0; j < surface_.size(); ++j) {
    const Eigen::Vector2d p = surface_[j].x.head<2>();
    bool found = false;
    for (Index c = 0; c < space.numCells() && !found; ++c) {
      const NodeList cell = space.cellNodes(c);
      const Eigen::Vector2d a = space.coordinate(cell[0]), b = space.coordinate(cell[1]),
                            e = space.coordinate(cell[2]);
      const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
        return u.x() * v.y() - u.y() * v.x();
      };
      const double area = cross(b - a, e - a);
      if (!(std::abs(area) > 0)) continue;
      Barycentric<2> l{cross(b - p, e - p) / area, cross(e - p, a - p) / area, 0.0};
      l[2] = 1.0 - l[0] - l[1];
      const double tol = 1e-9;
      if (l[0] < -tol || l[1] < -tol || l[2] < -tol) continue;
      double phi[SimplexNodes<2>::max];
      basisValues<2>(space.degree(), l, phi);
      for (int q = 0; q < cell.size; ++q)
        for (int comp = 0; comp < 2; ++comp)
          w.emplace_back(static_cast<Eigen::Index>(2 * j) + comp, space.dof(cell[q], comp), phi[q]);
      found = true;
    }
    if (!found)
      throw InputError(surface_[j].where, "surface station '" + surface_[j].name + "' at (" +
                                              formatNumber(p.x()) + ", " + formatNumber(p.y()) +
                                              "): not in the body (no cell holds it)");
  }
  W_.resize(static_cast<Eigen::Index>(2 * surface_.size()), space.numDofs());
  W_.setFromTriplets(w.begin(), w.end());
  if (profiles_) {
    const long m = static_cast<long>(std::floor((to_ - from_) / spacing_ * (1 + 1e-12))) + 1;
    for (long j = 0; j < m; ++j)
      points_.push_back(locate(from_ + static_cast<double>(j) * spacing_,
                               "faultOutput/profiles: the point", profilesAt_, nodes));
  }
}

void FaultSeries::bind3D(const std::vector<ControlNode>& nodes) {
  const auto point = shortPoint;
  // SEAS's frame per node: e2 the strike on the tangent plane, e1 the normal whose side makes
  // e3 = e1 × e2 point downwards (x1 x2 x3 right-handed, x3 down: BP4, BP5); the + side is the
  // one e1 points to, Ω⁺ (the −n_Γ side) or Ω⁻.
  seas_.assign(nodes.size(), Eigen::Matrix2d::Zero());
  std::vector<Eigen::Vector3d> plusNormal(nodes.size(), Eigen::Vector3d::Zero());
  for (const Eigen::Index i : onFracture_) {
    const auto u = static_cast<std::size_t>(i);
    const ControlNode& node = nodes[u];
    const std::string at =
        "at the node at " + point(node.position) + " of fracture '" + fracture_ + "'";
    Eigen::Vector3d e2 = strike_ - strike_.dot(node.normal) * node.normal;
    if (!(e2.norm() > 1e-6))
      throw InputError(strikeAt_, "faultOutput: strike " + point(strike_) +
                                      " is normal to the fault " + at +
                                      ": it gives no direction along it");
    e2.normalize();
    Eigen::Vector3d e1 = -node.normal;
    Eigen::Vector3d e3 = e1.cross(e2);
    if (!(std::abs(e3.z()) > 1e-6))
      throw InputError(strikeAt_, "faultOutput: strike " + point(strike_) +
                                      " runs down the fault's dip " + at +
                                      " (SEAS's direction 3 = e1 x e2 would be horizontal): "
                                      "give the horizontal direction along the fault");
    double sign = 1.0;  // the + side is Ω⁺
    if (e3.z() > 0) e1 = -e1, e3 = -e3, sign = -1.0;
    for (int c = 0; c < 2; ++c) {
      seas_[u](0, c) = sign * e2.dot(node.tangent[c]);
      seas_[u](1, c) = sign * e3.dot(node.tangent[c]);
    }
    plusNormal[u] = e1;
  }
  // A station takes its nearest node of the fracture, which must lie within a cell of it: the
  // distance from that node to its own nearest neighbour on the fracture.
  for (Station& st : stations_) {
    if (!st.point)
      throw InputError(st.where, "station '" + st.name +
                                     "': in 3D a station is a point (x y z) [m] on the fault, not "
                                     "an arclength");
    Eigen::Index best = onFracture_.front();
    double d = std::numeric_limits<double>::infinity();
    for (const Eigen::Index i : onFracture_) {
      const double e = (nodes[static_cast<std::size_t>(i)].position - st.x).norm();
      if (e < d) d = e, best = i;
    }
    const Eigen::Vector3d& x = nodes[static_cast<std::size_t>(best)].position;
    double cell = std::numeric_limits<double>::infinity();
    for (const Eigen::Index i : onFracture_)
      if (i != best) {
        const double e = (nodes[static_cast<std::size_t>(i)].position - x).norm();
        if (e > 0) cell = std::min(cell, e);
      }
    if (d > cell)
      throw InputError(st.where, "station '" + st.name + "' at " + point(st.x) +
                                     ": not on fracture '" + fracture_ +
                                     "': its nearest node, at " + point(x) + ", is " +
                                     shortNumber(d) + " m away, farther than a cell (" +
                                     shortNumber(cell) + " m, that node's nearest neighbour)");
    st.i0 = st.i1 = best;
    st.w = 0;
    st.at = x;
    st.e1 = plusNormal[static_cast<std::size_t>(best)];
  }
}

std::string FaultSeries::header(const Station& st) const {
  std::ostringstream h;
  if (dim_ == 3) {
    const auto point = shortPoint;
    h << "# libfriction, frictionSolver: fault station '" << st.name << "' on fracture '"
      << fracture_ << "' at " << point(st.x) << " m: its nearest node, at " << point(st.at)
      << " m (" << shortNumber((st.at - st.x).norm()) << " m away)\n"
      << "# direction 2 along strike " << point(strike_)
      << ", 3 = e1 x e2 (down-dip), e1 = " << point(st.e1)
      << " pointing to the + side; slip is the + side's motion relative to the - side\n"
      << "# Column #1 = Time (s)\n"
      << "# Column #2 = Slip_2 (m)\n"
      << "# Column #3 = Slip_3 (m)\n"
      << "# Column #4 = Slip_rate_2 (log10 m/s), of the absolute value\n"
      << "# Column #5 = Slip_rate_3 (log10 m/s), of the absolute value\n"
      << "# Column #6 = Shear_stress_2 (MPa)\n"
      << "# Column #7 = Shear_stress_3 (MPa)\n"
      << "# Column #8 = State (log10 s), theta = (L/V0) exp((psi - f0)/b)\n"
      << "t slip_2 slip_3 slip_rate_2 slip_rate_3 shear_stress_2 shear_stress_3 state\n";
    return h.str();
  }
  h << "# libfriction, frictionSolver: fault station '" << st.name << "' on fracture '" << fracture_
    << "' at arclength " << formatNumber(st.s) << " m\n"
    << "# slip and shear stress count positive along "
    << (positiveGiven_ ? "positiveSlip (" + formatNumber(positive_.x()) + " " +
                             formatNumber(positive_.y()) + ")"
                       : std::string("the fracture's tangent t_Gamma"))
    << " (the motion of the side Omega+ relative to Omega-)\n"
    << "# Column #1 = Time (s)\n"
    << "# Column #2 = Slip (m)\n"
    << "# Column #3 = Slip rate (log10 m/s)\n"
    << "# Column #4 = Shear stress (MPa)\n"
    << "# Column #5 = Normal stress (MPa), effective, positive in compression\n"
    << "# Column #6 = State (log10 s), theta = (L/V0) exp((psi - f0)/b)\n"
    << "t slip slip_rate shear_stress normal_stress state\n";
  return h.str();
}

void FaultSeries::open(const std::string& caseDir, bool fresh, double restartTime) {
  const fs::path folder = fs::path(caseDir) / "postProcessing" / "faultOutput";
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec || !fs::is_directory(folder))
    throw OutputError(folder.string(),
                      "cannot create the folder" +
                          (ec ? " (" + ec.message() + ")" : std::string(": a file has its name")));
  removeTemporaryFiles(folder.string());
  if (fresh) lastStation_ = lastProfile_ = -1, haveStationRow_ = haveProfileRow_ = false;
  folder_ = folder.string();
  if (fresh) {
    events_ = 0, inEvent_ = false, previousTime_ = -1;
    pendingRuptures_.clear();
  }
  // The events a run has not reached yet (a fresh run: every one; a restart: those ended
  // after its time) are written again when they end: their earlier files go.
  if (ruptures_)
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
      const std::string name = entry.path().filename().string();
      int index = 0;
      char tail = 0;
      if (std::sscanf(name.c_str(), "rupture_%d.da%c", &index, &tail) == 2 && tail == 't' &&
          name == "rupture_" + std::to_string(index) + ".dat" && index > events_)
        fs::remove(entry.path(), ec);
    }
  stationFiles_.clear();
  for (const Station& st : stations_) {
    const std::string path = (folder / (st.name + ".dat")).string();
    const std::string kept = fresh ? "" : keptLines(path, restartTime);
    writeTextAtomic(path, kept.empty() ? header(st) : kept);
    stationFiles_.push_back(std::make_unique<AppendFile>(path, false));
  }
  stationRows_.assign(stations_.size(), "");
  surfaceFiles_.clear();
  for (const Surface& st : surface_) {
    const std::string path = (folder / (st.name + ".dat")).string();
    const std::string kept = fresh ? "" : keptLines(path, restartTime);
    const char* way = verticalDown_ ? "downwards" : "upwards";
    std::ostringstream h;
    if (dim_ == 3) {
      h << "# libfriction, frictionSolver: surface station '" << st.name << "' at ("
        << formatNumber(st.x.x()) << ", " << formatNumber(st.x.y()) << ", "
        << formatNumber(st.x.z()) << ") m\n"
        << "# Column #1 = Time (s)\n"
        << "# Column #2 = Displacement along x (m)\n"
        << "# Column #3 = Displacement along y (m)\n"
        << "# Column #4 = Displacement along z (m), positive " << way << "\n"
        << "# Column #5 = Velocity along x (m/s)\n"
        << "# Column #6 = Velocity along y (m/s)\n"
        << "# Column #7 = Velocity along z (m/s), positive " << way << "\n"
        << "t disp1 disp2 disp3 vel1 vel2 vel3\n";
    } else {
      h << "# libfriction, frictionSolver: surface station '" << st.name << "' at ("
        << formatNumber(st.x.x()) << ", " << formatNumber(st.x.y()) << ") m\n"
        << "# Column #1 = Time (s)\n"
        << "# Column #2 = Displacement along x (m)\n"
        << "# Column #3 = Displacement along y (m), positive " << way << "\n"
        << "# Column #4 = Velocity along x (m/s)\n"
        << "# Column #5 = Velocity along y (m/s), positive " << way << "\n"
        << "t disp1 disp2 vel1 vel2\n";
    }
    writeTextAtomic(path, kept.empty() ? h.str() : kept);
    surfaceFiles_.push_back(std::make_unique<AppendFile>(path, false));
  }
  surfaceRows_.assign(surface_.size(), "");
  globalFile_.reset();
  if (!stations_.empty() || !surface_.empty()) {
    const std::string path = (folder / "global.dat").string();
    const std::string kept = fresh ? "" : keptLines(path, restartTime);
    const std::string head =
        "# libfriction, frictionSolver: fracture '" + fracture_ +
        "' as a whole, at the stations' times\n"
        "# Column #1 = Time (s)\n"
        "# Column #2 = Max slip rate (log10 m/s)\n" +
        std::string(dim_ == 3 ? "# Column #3 = Moment rate (N m/s): G sum_i A_i |V_i| (A_i the "
                                "nodes' lumped areas; both columns without the nodes that creep, "
                                "creepSlipRate), G = "
                              : "# Column #3 = Moment rate (N/s, per metre along strike): G "
                                "sum_i w_i |V_i|, G = ") +
        formatNumber(shearModulus_) +
        " Pa\n"
        "t max_slip_rate moment_rate\n";
    writeTextAtomic(path, kept.empty() ? head : kept);
    globalFile_ = std::make_unique<AppendFile>(path, false);
  }
  if (profiles_) {
    std::string head = "# libfriction, frictionSolver: profiles along fracture '" + fracture_ +
                       "'; first row: 0 0 and the points' arclengths [m]; then per row the time "
                       "[s], log10 of the largest slip rate [m/s] and the values at the points\n";
    std::string coordinates = "0 0";
    for (const Station& p : points_) appendValue(coordinates, p.s);
    coordinates += "\n";
    const std::pair<const char*, std::unique_ptr<AppendFile>*> files[] = {
        {"slip", &slipFile_}, {"shearstress", &shearFile_}, {"normalstress", &normalFile_}};
    const char* what[] = {"# slip [m], positive as in the stations\n",
                          "# shear stress [MPa], positive as the slip\n",
                          "# normal stress [MPa], effective, positive in compression\n"};
    int j = 0;
    for (const auto& [name, file] : files) {
      const std::string path = (folder / (std::string(name) + ".dat")).string();
      const std::string kept = fresh ? "" : keptLines(path, restartTime);
      writeTextAtomic(path, kept.empty() ? head + what[j] + coordinates : kept);
      *file = std::make_unique<AppendFile>(path, false);
      ++j;
    }
  }
}

// 3D surface stations: the tetrahedron holding the point (the first in the mesh's order; a
// point on a face or an edge takes that cell's side) and the element's basis there, three rows
// per station (x, y, z).
void FaultSeries::bindSurface3D(const LagrangeSpace& space) {
  std::vector<Eigen::Triplet<double>> w;
  for (std::size_t j = 0; j < surface_.size(); ++j) {
    const Eigen::Vector3d& p = surface_[j].x;
    bool found = false;
    for (Index c = 0; c < space.numCells() && !found; ++c) {
      const NodeList cell = space.cellNodes(c);
      std::array<SimplexPoint<3>, 4> v;
      for (int i = 0; i < 4; ++i) v[static_cast<std::size_t>(i)] = space.point(cell[i]);
      // A cheap rejection first: the point outside the cell's bounding box (with a margin).
      Eigen::Vector3d lo = v[0], hi = v[0];
      for (const auto& q : v) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
      const double margin = 1e-9 * (hi - lo).norm();
      if ((p.array() < lo.array() - margin).any() || (p.array() > hi.array() + margin).any())
        continue;
      const Simplex<3> tet(v);
      if (!(std::abs(tet.measure) > 0)) continue;
      const Barycentric<3> l = tet.barycentric(p);
      const double tol = 1e-9;
      if (l[0] < -tol || l[1] < -tol || l[2] < -tol || l[3] < -tol) continue;
      double phi[SimplexNodes<3>::max];
      basisValues<3>(space.degree(), l, phi);
      for (int q = 0; q < cell.size; ++q)
        for (int comp = 0; comp < 3; ++comp)
          w.emplace_back(static_cast<Eigen::Index>(3 * j) + comp, space.dof(cell[q], comp), phi[q]);
      found = true;
    }
    if (!found)
      throw InputError(surface_[j].where, "surface station '" + surface_[j].name + "' at (" +
                                              formatNumber(p.x()) + ", " + formatNumber(p.y()) +
                                              ", " + formatNumber(p.z()) +
                                              "): not in the body (no cell holds it)");
  }
  W_.resize(static_cast<Eigen::Index>(3 * surface_.size()), space.numDofs());
  W_.setFromTriplets(w.begin(), w.end());
}

void FaultSeries::sample(const RateSample& s) {
  const Eigen::VectorXd &slip = *s.slip, &psi = *s.psi, &rate = *s.rate;
  const auto speed = [&](Eigen::Index i) { return rate.segment(k_ * i, k_).norm(); };
  double maxV = 0;
  for (const Eigen::Index i : onFracture_)
    if (!creeping_[static_cast<std::size_t>(i)]) maxV = std::max(maxV, speed(i));
  const bool seismic = maxV >= seismicRate_;
  if (ruptures_) followRupture(s, maxV);
  const auto due = [&](bool have, double last, double interval) {
    return !have || (s.time > last && s.time - last >= interval);
  };
  const bool stationRow =
      (!stations_.empty() || !surface_.empty()) &&
      due(haveStationRow_, lastStation_, seismic ? stationSeismic_ : stationInterval_);
  const bool profileRow =
      profiles_ && due(haveProfileRow_, lastProfile_, seismic ? profileSeismic_ : profileInterval_);
  if (!stationRow && !profileRow) return;
  if (dim_ == 3) {
    sample3D(s, maxV);
    return;
  }

  // The values at a node, with the slip's sign: slip, |V|, φ = −τ along the slip, σ̄, log10 θ.
  Eigen::VectorXd tau(k_);
  struct Values {
    double slip, speed, shear, normal, logTheta;
  };
  const auto at = [&](Eigen::Index i) {
    const auto u = static_cast<std::size_t>(i);
    double sigmaEff = 0;
    s.traction(i, tau, sigmaEff);
    Values v;
    v.slip = sign_[u] * slip[k_ * i];
    v.speed = speed(i);
    v.shear = -sign_[u] * tau[0] / 1e6;
    v.normal = -sigmaEff / 1e6;
    v.logTheta = std::log10(L_[u] / V0_[u]) + (psi[i] - f0_[u]) / (b_[u] * std::log(10.0));
    return v;
  };
  const auto interpolate = [&](const Station& st) {
    const Values a = at(st.i0), b = st.i1 == st.i0 ? a : at(st.i1);
    const double w = st.w;
    return Values{(1 - w) * a.slip + w * b.slip, (1 - w) * a.speed + w * b.speed,
                  (1 - w) * a.shear + w * b.shear, (1 - w) * a.normal + w * b.normal,
                  (1 - w) * a.logTheta + w * b.logTheta};
  };
  // log10 of a rate: a node at rest (V = 0 exactly, a held one) reads as the smallest double.
  const auto logRate = [](double v) { return std::log10(std::max(v, 1e-300)); };
  if (stationRow) {
    for (std::size_t j = 0; j < stations_.size(); ++j) {
      const Values v = interpolate(stations_[j]);
      std::string& row = stationRows_[j];
      appendTime(row, s.time);
      appendValue(row, v.slip);
      appendValue(row, logRate(v.speed));
      appendValue(row, v.shear);
      appendValue(row, v.normal);
      appendValue(row, v.logTheta);
      row += "\n";
    }
    if (!surface_.empty() && s.surface) {
      Eigen::VectorXd u, v;
      s.surface(u, v);
      const double sy = verticalDown_ ? -1.0 : 1.0;
      for (std::size_t j = 0; j < surface_.size(); ++j) {
        std::string& row = surfaceRows_[j];
        const auto i = static_cast<Eigen::Index>(2 * j);
        appendTime(row, s.time);
        appendValue(row, u[i]);
        appendValue(row, sy * u[i + 1]);
        appendValue(row, v[i]);
        appendValue(row, sy * v[i + 1]);
        row += "\n";
      }
    }
    double momentRate = 0;
    for (const Eigen::Index i : onFracture_)
      if (!creeping_[static_cast<std::size_t>(i)])
        momentRate += weight_[static_cast<std::size_t>(i)] * speed(i);
    appendTime(globalRows_, s.time);
    appendValue(globalRows_, logRate(maxV));
    appendValue(globalRows_, shearModulus_ * momentRate);
    globalRows_ += "\n";
    lastStation_ = s.time;
    haveStationRow_ = true;
  }
  if (profileRow) {
    std::string slipRow, shearRow, normalRow;
    for (std::string* row : {&slipRow, &shearRow, &normalRow}) {
      appendTime(*row, s.time);
      appendValue(*row, logRate(maxV));
    }
    for (const Station& p : points_) {
      const Values v = interpolate(p);
      appendValue(slipRow, v.slip);
      appendValue(shearRow, v.shear);
      appendValue(normalRow, v.normal);
    }
    slipRows_ += slipRow + "\n";
    shearRows_ += shearRow + "\n";
    normalRows_ += normalRow + "\n";
    lastProfile_ = s.time;
    haveProfileRow_ = true;
  }
}

void FaultSeries::sample3D(const RateSample& s, double maxV) {
  const Eigen::VectorXd &slip = *s.slip, &psi = *s.psi, &rate = *s.rate;
  const auto logRate = [](double v) { return std::log10(std::max(v, 1e-300)); };
  Eigen::VectorXd tau(k_);
  for (std::size_t j = 0; j < stations_.size(); ++j) {
    const Eigen::Index i = stations_[j].i0;
    const auto u = static_cast<std::size_t>(i);
    double sigmaEff = 0;
    s.traction(i, tau, sigmaEff);
    const Eigen::Matrix2d& P = seas_[u];
    const Eigen::Vector2d d = P * Eigen::Vector2d(slip[k_ * i], slip[k_ * i + 1]);
    const Eigen::Vector2d v = P * Eigen::Vector2d(rate[k_ * i], rate[k_ * i + 1]);
    const Eigen::Vector2d phi = -(P * Eigen::Vector2d(tau[0], tau[1])) / 1e6;
    std::string& row = stationRows_[j];
    appendTime(row, s.time);
    appendValue(row, d[0]);
    appendValue(row, d[1]);
    appendValue(row, logRate(std::abs(v[0])));
    appendValue(row, logRate(std::abs(v[1])));
    appendValue(row, phi[0]);
    appendValue(row, phi[1]);
    appendValue(row, std::log10(L_[u] / V0_[u]) + (psi[i] - f0_[u]) / (b_[u] * std::log(10.0)));
    row += "\n";
  }
  if (!surface_.empty() && s.surface) {
    Eigen::VectorXd du, dv;
    s.surface(du, dv);
    const double sz = verticalDown_ ? -1.0 : 1.0;
    for (std::size_t j = 0; j < surface_.size(); ++j) {
      std::string& row = surfaceRows_[j];
      const auto i = static_cast<Eigen::Index>(3 * j);
      appendTime(row, s.time);
      appendValue(row, du[i]);
      appendValue(row, du[i + 1]);
      appendValue(row, sz * du[i + 2]);
      appendValue(row, dv[i]);
      appendValue(row, dv[i + 1]);
      appendValue(row, sz * dv[i + 2]);
      row += "\n";
    }
  }
  double momentRate = 0;
  for (const Eigen::Index i : onFracture_)
    if (!creeping_[static_cast<std::size_t>(i)])
      momentRate += weight_[static_cast<std::size_t>(i)] * rate.segment(k_ * i, k_).norm();
  appendTime(globalRows_, s.time);
  appendValue(globalRows_, logRate(maxV));
  appendValue(globalRows_, shearModulus_ * momentRate);
  globalRows_ += "\n";
  lastStation_ = s.time;
  haveStationRow_ = true;
}

void FaultSeries::followRupture(const RateSample& s, double maxV) {
  const Eigen::VectorXd &slip = *s.slip, &rate = *s.rate;
  const Eigen::Index n = static_cast<Eigen::Index>(position_.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (previousTime_ < 0) {
    previousSpeed_ = Eigen::VectorXd::Zero(n);
    previousSlip_ = slip;
  }
  if (!inEvent_ && maxV >= seismicRate_) {
    inEvent_ = true;
    onset_ = s.time;
    peak_ = 0;
    ruptureTime_ = Eigen::VectorXd::Constant(n, nan);
    eventStartSlip_ = previousSlip_;
  }
  if (inEvent_) {
    peak_ = std::max(peak_, maxV);
    const double lt = std::log10(seismicRate_);
    for (const Eigen::Index i : onFracture_) {
      if (creeping_[static_cast<std::size_t>(i)] || !std::isnan(ruptureTime_[i])) continue;
      const double v = rate.segment(k_ * i, k_).norm();
      if (!(v >= seismicRate_)) continue;
      // Between the previous step (below the threshold) and this one, linear in log10 |V|.
      const double v0 = previousSpeed_[i], t0 = previousTime_;
      double t = s.time;
      if (t0 >= 0 && t0 < s.time && v0 > 0 && v0 < seismicRate_ && v > v0)
        t = t0 + (s.time - t0) * (lt - std::log10(v0)) / (std::log10(v) - std::log10(v0));
      ruptureTime_[i] = std::max(t, onset_);
    }
  }
  if (inEvent_ && maxV < seismicRate_) {
    ++events_;
    pendingRuptures_.emplace_back("rupture_" + std::to_string(events_) + ".dat",
                                  ruptureFile(s.time, slip));
    inEvent_ = false;
  }
  for (const Eigen::Index i : onFracture_) previousSpeed_[i] = rate.segment(k_ * i, k_).norm();
  previousSlip_ = slip;
  previousTime_ = s.time;
}

std::string FaultSeries::ruptureFile(double end, const Eigen::VectorXd& slip) const {
  std::ostringstream h;
  long ruptured = 0, nodes = 0;
  for (const Eigen::Index i : onFracture_) {
    if (creeping_[static_cast<std::size_t>(i)]) continue;
    ++nodes;
    if (!std::isnan(ruptureTime_[i])) ++ruptured;
  }
  h << "# libfriction, frictionSolver: event " << events_ << " on fracture '" << fracture_
    << "': onset " << formatNumber(onset_) << " s, end " << formatNumber(end)
    << " s, peak slip rate " << formatNumber(peak_) << " m/s; " << ruptured << " of " << nodes
    << " nodes reached " << formatNumber(seismicRate_) << " m/s (creeping nodes left out)\n";
  if (dim_ == 3) {
    h << "# Columns: the node's position x y z (m); rupture_time (s): since the onset, when its "
         "slip rate first reached the threshold (nan: never in this event); slip_2 slip_3 (m): "
         "its slip over the event along SEAS's directions 2 (strike) and 3 (down dip)\n"
      << "x y z rupture_time slip_2 slip_3\n";
  } else {
    h << "# Columns: the node's position x y (m); rupture_time (s): since the onset, when its "
         "slip rate first reached the threshold (nan: never in this event); slip (m): its slip "
         "over the event, positive as in the stations\n"
      << "x y rupture_time slip\n";
  }
  std::string rows = h.str();
  for (const Eigen::Index i : onFracture_) {
    const auto u = static_cast<std::size_t>(i);
    if (creeping_[u]) continue;
    std::string row;
    for (int c = 0; c < dim_; ++c) appendValue(row, position_[u][c]);
    if (std::isnan(ruptureTime_[i]))
      row += "            nan";  // as wide as appendValue's, and Python's float() reads it
    else
      appendValue(row, ruptureTime_[i] - onset_);
    if (dim_ == 3) {
      const Eigen::Vector2d d =
          seas_[u] * Eigen::Vector2d(slip[k_ * i] - eventStartSlip_[k_ * i],
                                     slip[k_ * i + 1] - eventStartSlip_[k_ * i + 1]);
      appendValue(row, d[0]);
      appendValue(row, d[1]);
    } else {
      appendValue(row, sign_[u] * (slip[k_ * i] - eventStartSlip_[k_ * i]));
    }
    rows += row.substr(1) + "\n";  // appendValue's leading space off the first column
  }
  return rows;
}

void FaultSeries::flush() {
  for (const auto& [name, text] : pendingRuptures_)
    writeTextAtomic((fs::path(folder_) / name).string(), text);
  pendingRuptures_.clear();
  for (std::size_t j = 0; j < stationFiles_.size(); ++j) {
    if (!stationRows_[j].empty()) stationFiles_[j]->append(stationRows_[j]);
    stationRows_[j].clear();
  }
  for (std::size_t j = 0; j < surfaceFiles_.size(); ++j) {
    if (!surfaceRows_[j].empty()) surfaceFiles_[j]->append(surfaceRows_[j]);
    surfaceRows_[j].clear();
  }
  if (globalFile_ && !globalRows_.empty()) globalFile_->append(globalRows_);
  globalRows_.clear();
  if (slipFile_ && !slipRows_.empty()) {
    slipFile_->append(slipRows_);
    shearFile_->append(shearRows_);
    normalFile_->append(normalRows_);
  }
  slipRows_.clear(), shearRows_.clear(), normalRows_.clear();
}

void FaultSeries::sync() {
  for (const auto& f : stationFiles_) f->sync();
  for (const auto& f : surfaceFiles_) f->sync();
  if (globalFile_) globalFile_->sync();
  for (const auto* f : {&slipFile_, &shearFile_, &normalFile_})
    if (*f) (*f)->sync();
}

void FaultSeries::writeState(DictionaryWriter& out) const {
  out.entry("lastStationRow", haveStationRow_ ? lastStation_ : -1.0);
  out.entry("lastProfileRow", haveProfileRow_ ? lastProfile_ : -1.0);
  if (!ruptures_) return;
  // The rupture that is being followed, so that a restart writes its file as the
  // uninterrupted run does.
  out.entry("rupturesEnded", static_cast<long>(events_));
  out.entryWord("ruptureRunning", inEvent_ ? "yes" : "no");
  out.entry("ruptureOnset", onset_);
  out.entry("rupturePeak", peak_);
  out.entry("rupturePreviousTime", previousTime_);
  const auto vector = [&](const char* key, const Eigen::VectorXd& v) {
    out.entry(key, std::vector<double>(v.data(), v.data() + v.size()));
  };
  vector("rupturePreviousSpeed", previousSpeed_);
  vector("rupturePreviousSlip", previousSlip_);
  // The nodes that have ruptured in the running event and when (the others: nan).
  std::vector<int> ruptured;
  std::vector<double> times;
  for (Eigen::Index i = 0; i < ruptureTime_.size(); ++i)
    if (!std::isnan(ruptureTime_[i]))
      ruptured.push_back(static_cast<int>(i)), times.push_back(ruptureTime_[i]);
  out.entry("rupturedNodes", ruptured);
  out.entry("ruptureTimes", times);
  vector("ruptureStartSlip", eventStartSlip_);
}

void FaultSeries::readState(const Dictionary& in) {
  lastStation_ = in.getScalar("lastStationRow");
  lastProfile_ = in.getScalar("lastProfileRow");
  haveStationRow_ = lastStation_ >= 0;
  haveProfileRow_ = lastProfile_ >= 0;
  if (!ruptures_) return;
  if (!in.found("rupturesEnded")) {  // written without ruptures: they start here
    events_ = 0, inEvent_ = false, previousTime_ = -1;
    return;
  }
  events_ = static_cast<int>(in.getIntOr("rupturesEnded", 0, {0, 1000000000}));
  inEvent_ = in.getBool("ruptureRunning");
  onset_ = in.getScalar("ruptureOnset");
  peak_ = in.getScalar("rupturePeak");
  previousTime_ = in.getScalar("rupturePreviousTime");
  const auto vector = [&](const char* key) {
    const std::vector<double> v = in.getScalarList(key);
    return Eigen::VectorXd(
        Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size())));
  };
  previousSpeed_ = vector("rupturePreviousSpeed");
  previousSlip_ = vector("rupturePreviousSlip");
  eventStartSlip_ = vector("ruptureStartSlip");
  const Eigen::Index n = static_cast<Eigen::Index>(position_.size());
  if (previousSpeed_.size() != (previousTime_ < 0 ? previousSpeed_.size() : n))
    in.fail("rupturePreviousSpeed", "key 'rupturePreviousSpeed': expected " + std::to_string(n) +
                                        " values, one per control node");
  ruptureTime_ = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN());
  const std::vector<double> nodes = in.getScalarList("rupturedNodes"),
                            times = in.getScalarList("ruptureTimes");
  if (nodes.size() != times.size())
    in.fail("ruptureTimes", "key 'ruptureTimes': expected one time per entry of rupturedNodes");
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    const auto i = static_cast<Eigen::Index>(nodes[j]);
    if (!(nodes[j] >= 0 && i < n && static_cast<double>(i) == nodes[j]))
      in.fail("rupturedNodes",
              "key 'rupturedNodes': expected control node indices below " + std::to_string(n));
    ruptureTime_[i] = times[j];
  }
}

}  // namespace friction
