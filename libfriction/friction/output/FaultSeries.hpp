// FaultSeries: the time series of a quasi-dynamic run on one fracture, in the layout of the
// SEAS benchmarks (Erickson et al. 2023, BP3-QD; README.md, "SEAS outputs"), sampled at the
// Runge–Kutta steps of the integration (TimeIntegrator.hpp, RateSample), not only at the times
// of the case's grid:
//
//   faultOutput                                     // system/controlDict
//   {
//       fracture        fault;
//       positiveSlip    (-0.5 0.8660254);   // the direction of Ω⁺ relative to Ω⁻ counted as
//                                           // positive slip (default: t_Γ)
//       seismicSlipRate 1e-3;               // max |V| from which the fault is seismic [m/s]
//       stations        { fltst_dp000 0; fltst_dp075 7500; }   // name, arclength s [m]
//       stationInterval 0;  stationSeismicInterval 0;   // least time between rows [s]
//       profiles        { from 0; to 40000; spacing 500; interval 1.5768e8; seismicInterval 1; }
//       surfaceStations { srfst_fn+08 (8000 0); srfst_fn+00 (0.001 0); }   // points (x y) [m]
//                                           // (x y z) in 3D: disp1-3, vel1-3
//       verticalDown    yes;   // surface stations: disp2, vel2 positive downwards (SEAS's w)
//   }
//
// Stations: postProcessing/faultOutput/<name>.dat, columns t slip slip_rate shear_stress
// normal_stress state: the slip [m] along positiveSlip, log10 of the slip rate |V| [m/s], the
// driving shear φ = −τ [MPa] with the slip's sign, the effective compression σ̄ = −(σ_n + p)
// [MPa], log10 of the aging-law state θ = (L/V₀) e^((ψ − f₀)/b) [s]; each linear between the
// fracture's two nodes around s. Profiles: slip.dat, shearstress.dat, normalstress.dat with the
// first row "0 0 s_1 … s_m" and then per row "t log10(max|V|) value_1 … value_m". A row is
// written at an accepted step at least interval (seismic: seismicInterval) after the file's
// last one; seismic when the largest |V| on the fracture reaches seismicSlipRate. Surface
// stations (any point of the body): <name>.dat with columns t disp1 disp2 vel1 vel2, the
// displacement [m] and velocity [m/s] there, rows with the stations'; the body's response to
// the slip at the points (one solve per fault unknown, once per run) gives them between the
// solves of the grid's times. global.dat (whenever stations or surface stations are given),
// at the same times: t, log10 of the largest slip rate on the fracture [m/s], and its moment
// rate μ Σ w_i |V_i| over the fracture's nodes (lumped length w_i; per metre along strike
// in 2D) [N/s].
//
// The rows of a step are appended when the step ends (flush), with the case's other histories;
// a restart keeps the rows up to its time and the times of the last rows (uniform/
// frictionState), so the files go on as in an uninterrupted run.
//
// 3D (SEAS BP5-QD's layout, Jiang et al. 2022): a station is a point (x y z) on the fault and
// takes its nearest fault node (InputError naming the key if that node is farther than its own
// nearest neighbour, a cell); `strike (x y z)` gives SEAS's direction 2 (projected on each
// node's tangent plane), direction 3 is e1 × e2 with e1 the fault normal whose side makes it
// point downwards (SEAS's right-handed x1 x2 x3, x3 down), and the + side is the one e1
// points to. Columns t slip_2 slip_3 slip_rate_2 slip_rate_3 shear_stress_2 shear_stress_3
// state: the + side's motion relative to the − side along 2 and 3 [m], log10 of the absolute
// slip-rate components [m/s], the driving shear along 2 and 3 [MPa], log10 θ [s]. global.dat's
// moment rate is then G Σ A_i |V_i| [N m/s] (A_i the lumped areas). Profiles and surface
// stations: 2D only so far (refused in 3D, naming the key).
//
// Ruptures (`ruptures yes;`, 2D and 3D): an event runs from the first accepted step whose
// largest slip rate (creeping nodes left out) reaches seismicSlipRate to the first one below
// it. For each event k (counted from the run's start) rupture_k.dat holds, per node of the
// fracture that is not creeping, its position, its rupture time [s] since the event's onset
// (when its |V| first reached seismicSlipRate, interpolated in log10 |V| between the two
// steps around it; nan where it never did) and its slip over the event [m] (from the last step
// before the onset to the event's last; 3D: slip_2 slip_3 in SEAS's directions, 2D: slip with
// positiveSlip's sign). Written when the event ends (an event still running at the end time
// is not); a restart keeps the events ended before its time and the running one's state.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "friction/core/InputError.hpp"

namespace friction {

class AppendFile;
class Dictionary;
class DictionaryWriter;
class LagrangeSpace;
struct ControlNode;
struct RateState;

/// One accepted step of a quasi-dynamic integration, as the outputs sample it.
struct RateSample {
  double time = 0;
  const Eigen::VectorXd* slip = nullptr;  ///< k·n [m]
  const Eigen::VectorXd* psi = nullptr;   ///< n
  const Eigen::VectorXd* rate = nullptr;  ///< k·n [m/s]
  /// The tractions at control node i: τ (k components) [Pa] and the effective normal stress
  /// σ_n + p [Pa] (negative in compression). Costs one row of S per call.
  std::function<void(Eigen::Index i, Eigen::VectorXd& tau, double& sigmaEffective)> traction;
  /// The displacement u [m] and velocity v [m/s] at the surface stations, d per station in
  /// their order (FaultSeries::surfaceOperator()'s rows). Set by the case when it has them.
  std::function<void(Eigen::VectorXd& u, Eigen::VectorXd& v)> surface;
};

class FaultSeries {
 public:
  /// From system/controlDict's 'faultOutput' (nullptr without it).
  static std::unique_ptr<FaultSeries> read(const Dictionary& controlDict);
  ~FaultSeries();

  /// Resolves the fracture, stations and profile points on the case's control nodes (their
  /// per-node laws for θ). InputError naming the key where one does not lie on the fracture.
  /// `imposed`: per control node 1 where the slip rate is imposed (law rateState's
  /// creepSlipRate): such nodes are left out of global.dat's max slip rate and moment rate.
  void bind(const std::vector<ControlNode>& nodes, int dim, int k,
            const std::vector<std::string>& fractureNames, const std::vector<RateState>& laws,
            const LagrangeSpace& space, const Eigen::VectorXd& weights, double shearModulus,
            const Eigen::VectorXd& imposed);
  bool hasSurfaceStations() const { return !surface_.empty(); }
  const std::string& fracture() const { return fracture_; }
  /// W: the displacement at the surface stations (d rows per station) from the split space's
  /// dofs (the element's basis at the point, in the first cell found that holds it).
  const Eigen::SparseMatrix<double>& surfaceOperator() const { return W_; }
  /// Opens the files in caseDir/postProcessing/faultOutput: fresh ones with their headers, or
  /// (restart) those kept up to `restartTime`. Rank 0 only.
  void open(const std::string& caseDir, bool fresh, double restartTime);
  /// Adds the rows this accepted step calls for (buffered until flush()).
  void sample(const RateSample& s);
  /// Appends the buffered rows to the files (OutputError: disk full, ...).
  void flush();
  void sync();
  void writeState(DictionaryWriter& out) const;
  void readState(const Dictionary& in);

 private:
  struct Station {
    std::string name;
    double s = 0;
    SourceLocation where;
    Eigen::Index i0 = 0, i1 = 0;                   ///< control nodes around s
    double w = 0;                                  ///< weight of i1
    bool point = false;                            ///< given as a point (x y z): 3D
    Eigen::Vector3d x = Eigen::Vector3d::Zero();   ///< the point given (3D)
    Eigen::Vector3d at = Eigen::Vector3d::Zero();  ///< 3D: the node taken, and its e1 (+ side)
    Eigen::Vector3d e1 = Eigen::Vector3d::Zero();
  };
  std::string fracture_;
  SourceLocation fractureAt_, profilesAt_;
  Eigen::Vector3d positive_ = Eigen::Vector3d::Zero();  ///< zero: t_Γ
  bool positiveGiven_ = false;
  Eigen::Vector3d strike_ = Eigen::Vector3d::Zero();  ///< 3D: SEAS's direction 2
  bool strikeGiven_ = false;
  SourceLocation strikeAt_, surfaceAt_, positiveAt_;
  int dim_ = 2;
  /// 3D, per control node: row j (SEAS's directions 2, 3) of the map from the node's tangent
  /// components (t₁, t₂) to the + side's motion relative to the − side (sign included).
  std::vector<Eigen::Matrix2d> seas_;
  double seismicRate_ = 1e-3, stationInterval_ = 0, stationSeismic_ = 0;
  std::vector<Station> stations_;
  bool profiles_ = false;
  double from_ = 0, to_ = 0, spacing_ = 0, profileInterval_ = 0, profileSeismic_ = 0;
  std::vector<Station> points_;  ///< the profiles' points (name unused)
  struct Surface {
    std::string name;
    Eigen::Vector3d x = Eigen::Vector3d::Zero();  ///< z = 0 for a point (x y)
    SourceLocation where;
    bool in3D = false;  ///< given as (x y z): a 3D mesh's point
  };
  std::vector<Surface> surface_;
  bool verticalDown_ = false;
  Eigen::SparseMatrix<double> W_;
  std::vector<std::unique_ptr<AppendFile>> surfaceFiles_;
  std::vector<std::string> surfaceRows_;
  double shearModulus_ = 0;     ///< G of the rock at the fracture [Pa]
  std::vector<double> weight_;  ///< per control node: its lumped length [m]
  std::vector<char> creeping_;  ///< per control node: its slip rate is imposed
  std::unique_ptr<AppendFile> globalFile_;
  std::string globalRows_;
  // Ruptures: the event being followed and the previous step's rates and slip.
  bool ruptures_ = false;
  std::vector<Eigen::Vector3d> position_;  ///< per control node of the fracture
  int events_ = 0;                         ///< events ended (files written or pending)
  bool inEvent_ = false;
  double onset_ = 0, peak_ = 0;
  double previousTime_ = -1;        ///< < 0: no step sampled yet
  Eigen::VectorXd previousSpeed_;   ///< n: |V| at the previous step
  Eigen::VectorXd previousSlip_;    ///< k·n: slip at the previous step
  Eigen::VectorXd ruptureTime_;     ///< n: absolute rupture times of this event (nan: none)
  Eigen::VectorXd eventStartSlip_;  ///< k·n: slip at the step before the onset
  std::vector<std::pair<std::string, std::string>> pendingRuptures_;  ///< name, text: flush()
  std::string folder_;
  void followRupture(const RateSample& s, double maxV);
  std::string ruptureFile(double end, const Eigen::VectorXd& slip) const;

  // Bound to the case:
  int k_ = 1;
  std::vector<Eigen::Index> onFracture_;  ///< control nodes of the fracture
  std::vector<double> sign_;              ///< per control node: +1 where t₁ is positiveSlip's way
  std::vector<double> L_, V0_, f0_, b_;   ///< per control node, for θ
  double lastStation_ = -1, lastProfile_ = -1;  ///< times of the last rows (< 0: none yet)
  bool haveStationRow_ = false, haveProfileRow_ = false;
  std::vector<std::string> stationRows_;
  std::string slipRows_, shearRows_, normalRows_;
  std::vector<std::unique_ptr<AppendFile>> stationFiles_;
  std::unique_ptr<AppendFile> slipFile_, shearFile_, normalFile_;

  Station locate(double s, const std::string& what, const SourceLocation& where,
                 const std::vector<ControlNode>& nodes) const;
  std::string header(const Station& st) const;
  void bind3D(const std::vector<ControlNode>& nodes);
  void bindSurface3D(const LagrangeSpace& space);
  void sample3D(const RateSample& s, double maxV);
  /// InputError naming the key unless `name` can be a file of its own in the output folder.
  void checkStationName(const Dictionary& d, const std::string& name,
                        const std::string& what) const;
};

}  // namespace friction
