// The computed fault diffusion (flow/FaultDiffusion.hpp) against the closed forms of METHOD.md
// §11 away from the source, with the observed orders in h and Δt; conservation of the
// injected volume; one factorisation per (Δt, θ); bitwise restart; a junction of three
// curves; invariance under a rigid motion of a 3D fault; refusal of bad input.
//
// Observed orders are log2 of error ratios when h or Δt halves. Errors in h are against the
// closed form with a Δt small enough that the time error is < 3% of the space error; errors
// in Δt are against the same mesh's solution with 16× smaller Δt (Crank–Nicolson), so that
// the space error (which does not change with Δt) does not hide the time error.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>

#include "FlowTestMeshes.hpp"
#include "friction/flow/ClosedForms.hpp"
#include "friction/flow/FaultDiffusion.hpp"

using namespace friction;

namespace {

constexpr double kT = 0.25;  // end time [s]; with α = 1, √(4αT) = 1 m

enum class Source { held, heldChange, rate, rateShutIn };

// 2D: a line on [−8, 8] m (2n segments), S = κ = 1, the source at s = 0. The far ends see
// erfc(8) ~ 1e-29 of the source: no-flow there is no error.
// The changes at 0.15 fall on substep ends for every Δt used (T/20 … T/1280, and T/500).
const StepSchedule& schedule(Source source) {
  static const StepSchedule on = StepSchedule::constant(1.0);
  static const StepSchedule heldChange({0.0, 0.15}, {1.0, 0.4});
  static const StepSchedule shutIn({0.0, 0.15}, {1.0, 0.0});
  return source == Source::rateShutIn ? shutIn : source == Source::heldChange ? heldChange : on;
}

Eigen::VectorXd run(FaultFlowMesh mesh, Source source, TimeScheme scheme, int steps) {
  FaultDiffusionOptions o;
  o.scheme = scheme;
  o.maxStep = kT / steps;
  FaultDiffusion d(std::move(mesh), 1.0, 1.0, o);
  if (source == Source::held || source == Source::heldChange)
    d.addHeldPressure(Point::Zero(), schedule(source), 1e-12);
  else
    d.addRateWell(Point::Zero(), schedule(source), 1e-12);
  d.advance(0.0, kT);
  return d.state();
}

double exact2d(Source source, const Point& x) {
  return source == Source::held || source == Source::heldChange
             ? heldPressure2d(x.x(), 0.0, kT, schedule(source), 1.0)
             : ratePressure2d(x.x(), 0.0, kT, schedule(source), 1.0, 1.0);
}

double order(double coarse, double fine) { return std::log2(coarse / fine); }

}  // namespace

TEST_CASE("flow diffusion in 2D converges to the closed forms at order 2 in h",
          "[flow][diffusion]") {
  const Source source =
      GENERATE(Source::held, Source::heldChange, Source::rate, Source::rateShutIn);
  CAPTURE(static_cast<int>(source));
  // |s| ≥ 0.2 = 2h of the coarsest mesh: the same nodes' region on every mesh.
  const auto keep = [](const Point& x) { return std::abs(x.x()) >= 0.2 - 1e-12; };
  std::vector<test::RelativeError> e;
  for (int n : {80, 160, 320}) {
    const FaultFlowMesh mesh = test::lineMesh(8.0, n);
    e.push_back(test::relativeError(
        mesh, run(mesh, source, TimeScheme::crankNicolson, 500),
        [&](const Point& x) { return exact2d(source, x); }, keep));
  }
  for (std::size_t i = 0; i + 1 < e.size(); ++i) {
    CAPTURE(i, e[i].max, e[i + 1].max, e[i].l2, e[i + 1].l2);
    // P1 with lumped mass on a uniform mesh: consistent to O(h²) away from the kink at the
    // source, which sits on a node. Measured 1.99–2.01; ±0.1 leaves room for round-off and
    // fails any first-order defect (a source off its node, a wrong mass).
    REQUIRE(order(e[i].max, e[i + 1].max) == Approx(2.0).margin(0.1));
    REQUIRE(order(e[i].l2, e[i + 1].l2) == Approx(2.0).margin(0.1));
  }
  // The finest error (measured: held 4.4e-5, rate 2.1e-4 relative max).
  REQUIRE(e.back().max < 5e-4);
}

TEST_CASE("flow diffusion in 2D: backward Euler order 1, Crank–Nicolson order 2 in Δt",
          "[flow][diffusion]") {
  const Source source =
      GENERATE(Source::held, Source::heldChange, Source::rate, Source::rateShutIn);
  CAPTURE(static_cast<int>(source));
  const FaultFlowMesh mesh = test::lineMesh(8.0, 400);  // h = 0.02
  const Eigen::VectorXd reference = run(mesh, source, TimeScheme::crankNicolson, 1280);
  const auto keep = [](const Point& x) { return std::abs(x.x()) >= 0.2 - 1e-12; };
  const auto atNode = [&](const Point& x) { return reference[mesh.nearestNode(x)]; };
  for (TimeScheme scheme : {TimeScheme::backwardEuler, TimeScheme::crankNicolson}) {
    std::vector<test::RelativeError> e;
    for (int steps : {20, 40, 80})
      e.push_back(test::relativeError(mesh, run(mesh, source, scheme, steps), atNode, keep));
    for (std::size_t i = 0; i + 1 < e.size(); ++i) {
      CAPTURE(toString(scheme), i, e[i].max, e[i + 1].max, e[i].l2, e[i + 1].l2);
      if (scheme == TimeScheme::backwardEuler) {
        // Measured 0.99–1.00.
        REQUIRE(order(e[i].max, e[i + 1].max) == Approx(1.0).margin(0.1));
        REQUIRE(order(e[i].l2, e[i + 1].l2) == Approx(1.0).margin(0.1));
      } else {
        // Measured 1.97–2.02, and 2.31 (max) for the first pair of the constant rate, whose
        // √t start at the well is not yet asymptotic at Δt = T/20. Without the damping steps
        // the held case falls to order 1.0 (Δt/8: 1.6e-2 → 2.0e-3) and fails this.
        for (double o : {order(e[i].max, e[i + 1].max), order(e[i].l2, e[i + 1].l2)}) {
          REQUIRE(o >= 1.8);
          REQUIRE(o <= 2.4);
        }
      }
    }
  }
  // The closed form itself at the finest run (space error of h = 0.02 included; measured
  // held 5.5e-5, rate 1.3e-4, shut-in 9.6e-5 relative max).
  const Eigen::VectorXd p = run(mesh, source, TimeScheme::crankNicolson, 80);
  REQUIRE(test::relativeError(
              mesh, p, [&](const Point& x) { return exact2d(source, x); }, keep)
              .max < 5e-4);
}

TEST_CASE("flow diffusion in 3D converges to the E1 form at order 2 in h and in Δt (CN)",
          "[flow][diffusion]") {
  // A square fault [−4, 4]² (E₁(16) ~ 6e-9: the no-flow edges do not matter), S = κ = 1,
  // Q = 1 at the centre node; errors on r ≥ 1.5 (≥ 4.5h on every mesh).
  const auto exact = [](const Point& x) { return ratePressure3d(x.norm(), kT, 1.0, 1.0, 1.0); };
  const auto keep = [](const Point& x) { return x.norm() >= 1.5 - 1e-12; };
  std::vector<test::RelativeError> e;
  for (int n : {12, 24, 48}) {
    const FaultFlowMesh mesh = test::squareMesh(4.0, n);
    e.push_back(test::relativeError(mesh, run(mesh, Source::rate, TimeScheme::crankNicolson, 100),
                                    exact, keep));
  }
  // P1 (the 5-point Laplacian on this mesh) is O(h²) away from the point source (the source's
  // pollution is O(h² ln h) there). Measured max 2.68 then 2.03, L2 2.28 then 2.02: the
  // coarsest mesh (3 cells per √(4αT)) is preasymptotic, so it is only asked ≥ 1.8.
  for (std::size_t i = 0; i + 1 < e.size(); ++i) {
    CAPTURE(i, e[i].max, e[i + 1].max, e[i].l2, e[i + 1].l2);
    REQUIRE(order(e[i].max, e[i + 1].max) >= 1.8);
    REQUIRE(order(e[i].l2, e[i + 1].l2) >= 1.8);
  }
  REQUIRE(order(e[1].max, e[2].max) == Approx(2.0).margin(0.2));
  REQUIRE(order(e[1].l2, e[2].l2) == Approx(2.0).margin(0.2));
  REQUIRE(e.back().max < 0.02);  // measured 1.0e-2 at h = 1/6
  // In Δt at h = 0.25, against the same mesh with Δt/16 (measured BE 0.94–0.97, CN 2.00).
  const FaultFlowMesh mesh = test::squareMesh(4.0, 16);
  const Eigen::VectorXd reference = run(mesh, Source::rate, TimeScheme::crankNicolson, 640);
  const auto atNode = [&](const Point& x) { return reference[mesh.nearestNode(x)]; };
  for (TimeScheme scheme : {TimeScheme::backwardEuler, TimeScheme::crankNicolson}) {
    std::vector<test::RelativeError> et;
    for (int steps : {10, 20, 40})
      et.push_back(test::relativeError(mesh, run(mesh, Source::rate, scheme, steps), atNode, keep));
    const double expected = scheme == TimeScheme::backwardEuler ? 1.0 : 2.0;
    for (std::size_t i = 0; i + 1 < et.size(); ++i) {
      CAPTURE(toString(scheme), i, et[i].max, et[i + 1].max, et[i].l2, et[i + 1].l2);
      REQUIRE(order(et[i].max, et[i + 1].max) == Approx(expected).margin(0.1));
      REQUIRE(order(et[i].l2, et[i + 1].l2) == Approx(expected).margin(0.1));
    }
  }
}

namespace {

// A rotation (axis (1, 2, 3), 0.7 rad) and a shift: the plane z = 0 to an inclined plane.
Point moved(const Point& x) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  return R * x + Point(10.0, -3.0, 2.0);
}

FaultFlowMesh movedMesh(const FaultFlowMesh& flat) {
  std::vector<Point> points;
  for (const Point& p : flat.points()) points.push_back(moved(p));
  std::vector<FaultFlowMesh::Triangle> triangles;
  for (Index e = 0; e < flat.numElements(); ++e)
    triangles.push_back({flat.element(e)[0], flat.element(e)[1], flat.element(e)[2]});
  return FaultFlowMesh(points, triangles);
}

}  // namespace

TEST_CASE("flow diffusion conserves the injected volume with no-flow edges", "[flow][diffusion]") {
  const bool lumped = GENERATE(true, false);
  const TimeScheme scheme = GENERATE(TimeScheme::backwardEuler, TimeScheme::crankNicolson);
  CAPTURE(lumped, toString(scheme));
  const FaultFlowMesh mesh = test::squareMesh(1.0, 6);
  // S per element and κ per node, both varying: conservation does not depend on them.
  Eigen::VectorXd S(mesh.numElements()), kappa(mesh.numNodes());
  for (Index e = 0; e < mesh.numElements(); ++e) S[e] = 1.0 + 0.5 * std::sin(e);
  for (Index i = 0; i < mesh.numNodes(); ++i)
    kappa[i] = 0.2 + mesh.point(i).x() * mesh.point(i).x();
  FaultDiffusionOptions o;
  o.scheme = scheme;
  o.lumpedMass = lumped;
  o.maxStep = 0.05;
  FaultDiffusion d(mesh, FlowCoefficient::perElement(S), FlowCoefficient::perNode(kappa), o);
  // Wells between nodes (their volume shared by weights), one of them producing for a while,
  // changes inside substeps.
  d.addRateWell(Point(0.13, -0.27, 0.0), StepSchedule({0.0, 0.3, 0.55}, {2.0, -0.5, 0.0}), 1e-12);
  d.addRateWell(Point(-0.6, 0.41, 0.0), StepSchedule::constant(1.0, 0.1), 1e-12);
  d.advance(0.0, 0.07);
  d.advance(0.07, 0.4);
  d.advance(0.4, 1.0);
  const double injected = d.injectedVolume(0.0, 1.0);
  REQUIRE(injected == Approx(2.0 * 0.3 - 0.5 * 0.25 + 0.9).epsilon(1e-15));
  // ~20 substeps, each exact but for the round-off of 1ᵀA (~1e-16 of κΔt/h² ~ 1) and of the
  // solve: 1e-13 of the volume is round-off with a margin of ~100.
  REQUIRE(std::abs(d.storedVolume() - injected) <= 1e-13 * injected);
  // A 2D curve likewise (volume per metre out of the plane).
  FaultDiffusion line(test::lineMesh(2.0, 10), 0.5, 3.0, o);
  line.addRateWell(Point(0.33, 0.01, 0.0), StepSchedule({0.0, 0.2}, {1.5, 0.25}), 0.1);
  line.advance(0.0, 0.5);
  REQUIRE(std::abs(line.storedVolume() - (1.5 * 0.2 + 0.25 * 0.3)) <= 1e-13);
}

TEST_CASE("flow diffusion factors once per distinct Δt", "[flow][diffusion]") {
  FaultDiffusion be(test::squareMesh(1.0, 4), 1.0, 1.0);
  be.addRateWell(Point::Zero(), StepSchedule::constant(1.0), 1e-12);
  // Times accumulated as a solver does: the steps' lengths differ in their last bits.
  double t = 0.0;
  for (int i = 0; i < 50; ++i, t += 0.1) be.advance(t, t + 0.1);
  REQUIRE(be.numSubsteps() == 50);
  REQUIRE(be.numFactorisations() == 1);
  be.advance(t, t + 0.05);
  REQUIRE(be.numFactorisations() == 2);
  // Crank–Nicolson with a held pressure: backward Euler for the damping steps after each of
  // its changes, Crank–Nicolson otherwise: two factors for one Δt, however many changes.
  FaultDiffusionOptions o;
  o.scheme = TimeScheme::crankNicolson;
  o.maxStep = 0.1;
  FaultDiffusion cn(test::squareMesh(1.0, 4), 1.0, 1.0, o);
  cn.addHeldPressure(Point(0.5, 0.5, 0.0), StepSchedule({0.0, 2.0, 3.5}, {1.0, 2.0, 0.5}), 1e-12);
  cn.advance(0.0, 5.0);
  REQUIRE(cn.numSubsteps() == 50);
  REQUIRE(cn.numFactorisations() == 2);
}

TEST_CASE("flow diffusion restarts bitwise from its state", "[flow][diffusion]") {
  const TimeScheme scheme = GENERATE(TimeScheme::backwardEuler, TimeScheme::crankNicolson);
  CAPTURE(toString(scheme));
  FaultDiffusionOptions o;
  o.scheme = scheme;
  o.maxStep = 0.15;
  const auto make = [&]() {
    const FaultFlowMesh mesh = test::squareMesh(1.0, 5);
    auto d = std::make_unique<FaultDiffusion>(mesh, 1.0, 0.3, o);
    d->holdNodes(mesh.edgeNodes(), StepSchedule::constant(0.0));
    d->addHeldPressure(Point(0.4, -0.4, 0.0), StepSchedule({0.0, 1.0}, {1.0, 3.0}), 1e-12);
    d->addRateWell(Point(-0.31, 0.22, 0.0), StepSchedule({0.0, 1.5}, {2.0, 0.0}), 1e-12);
    return d;
  };
  auto straight = make();
  straight->advance(0.0, 1.0);
  straight->advance(1.0, 2.0);
  auto first = make();
  first->advance(0.0, 1.0);
  const Eigen::VectorXd saved = first->state();
  auto second = make();
  second->setState(saved);
  second->advance(1.0, 2.0);
  const Eigen::VectorXd& a = straight->state();
  const Eigen::VectorXd& b = second->state();
  REQUIRE(a.size() == b.size());
  REQUIRE(a.cwiseAbs().maxCoeff() > 0.1);  // something happened
  REQUIRE(std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) ==
          0);
}

TEST_CASE("flow diffusion on a junction of three curves", "[flow][diffusion]") {
  // Three arms of 6 m from the origin at 120°, the third listed towards it; h = 0.05.
  std::vector<FaultFlowMesh::Curve> curves(3);
  const int n = 120;
  for (int c = 0; c < 3; ++c) {
    const double angle = 2.0 * 3.14159265358979323846 * c / 3.0 + 0.2;
    const Point dir(std::cos(angle), std::sin(angle), 0.0);
    for (int i = 0; i <= n; ++i) {
      curves[c].id.push_back(i == 0 ? 0 : 1000 * (c + 1) + i);
      curves[c].points.push_back(6.0 * i / n * dir);
    }
  }
  std::reverse(curves[2].id.begin(), curves[2].id.end());
  std::reverse(curves[2].points.begin(), curves[2].points.end());
  const FaultFlowMesh mesh = FaultFlowMesh::fromCurves(curves);
  const Index junction = mesh.curveNodes()[0][0];
  REQUIRE(mesh.curveNodes()[1][0] == junction);
  REQUIRE(mesh.curveNodes()[2][n] == junction);
  FaultDiffusionOptions o;
  o.scheme = TimeScheme::crankNicolson;
  o.maxStep = kT / 200;
  // A well at the junction: each arm takes a third of Q, as the two sides of a straight fault
  // each take half of a rate 2Q/3: p along every arm is the 2D rate form with Q₀ = 2Q/3.
  FaultDiffusion d(mesh, 1.0, 1.0, o);
  d.addRateWell(Point::Zero(), StepSchedule::constant(1.0), 1e-12);
  d.advance(0.0, kT);
  const StepSchedule twoThirds = StepSchedule::constant(2.0 / 3.0);
  for (int c = 0; c < 3; ++c) {
    double worst = 0.0;
    for (int i = 0; i <= n; ++i) {
      const Index node = mesh.curveNodes()[c][i];
      const double s = mesh.point(node).norm();
      if (s < 0.1 - 1e-12) continue;  // 2h
      worst = std::max(worst,
                       std::abs(d.state()[node] - ratePressure2d(s, 0.0, kT, twoThirds, 1.0, 1.0)));
    }
    // The straight line at h = 0.05 has 8.5e-4 of the largest value (first test); 2e-3 here.
    CAPTURE(c);
    REQUIRE(worst <= 2e-3 * ratePressure2d(0.0, 0.0, kT, twoThirds, 1.0, 1.0));
  }
  REQUIRE(std::abs(d.storedVolume() - kT) <= 1e-13);
  // A well on one arm: the volume is kept, and the two other arms see the same pressure.
  FaultDiffusion e(mesh, 1.0, 1.0, o);
  e.addRateWell(curves[0].points[20], StepSchedule::constant(1.0), 1e-12);
  e.advance(0.0, kT);
  REQUIRE(std::abs(e.storedVolume() - kT) <= 1e-13);
  REQUIRE(e.state()[junction] > 0.01);
  for (int i = 1; i <= n; ++i) {
    const double p1 = e.state()[mesh.curveNodes()[1][i]];
    const double p2 = e.state()[mesh.curveNodes()[2][n - i]];
    REQUIRE(std::abs(p1 - p2) <= 1e-12);
  }
}

TEST_CASE("flow diffusion on a 3D fault is invariant under a rigid motion", "[flow][diffusion]") {
  const FaultFlowMesh flat = test::squareMesh(2.0, 8);
  FaultDiffusionOptions o;
  o.scheme = TimeScheme::crankNicolson;
  o.maxStep = 0.02;
  const auto solve = [&](const FaultFlowMesh& mesh, const std::function<Point(Point)>& f) {
    FaultDiffusion d(mesh, 1.0, 0.7, o);
    d.addRateWell(f(Point(0.3, 0.2, 0.0)), StepSchedule({0.0, 0.1}, {1.0, 0.4}), 1e-9);
    d.addHeldPressure(f(Point(-1.0, 1.0, 0.0)), StepSchedule::constant(0.5), 1e-9);
    d.advance(0.0, 0.2);
    return d.state();
  };
  const Eigen::VectorXd p = solve(flat, [](Point x) { return x; });
  const Eigen::VectorXd q = solve(movedMesh(flat), moved);
  // Lengths, areas and dot products of moved edges differ by round-off (~1e-16 relative).
  REQUIRE(p.cwiseAbs().maxCoeff() > 0.1);
  REQUIRE((p - q).cwiseAbs().maxCoeff() <= 1e-12 * p.cwiseAbs().maxCoeff());
}

TEST_CASE("flow diffusion refuses bad input", "[flow][diffusion]") {
  const FaultFlowMesh mesh = test::squareMesh(1.0, 2);
  const SourceLocation where{"constant/pressureDict", 12};
  REQUIRE_THROWS_WITH(FaultDiffusion(mesh, 0.0, 1.0, {}, where),
                      Catch::Contains("constant/pressureDict:12") &&
                          Catch::Contains("storage S [m/Pa] must be a finite number > 0, got 0"));
  Eigen::VectorXd k = Eigen::VectorXd::Ones(mesh.numNodes());
  k[3] = -2.0;
  REQUIRE_THROWS_WITH(FaultDiffusion(mesh, 1.0, FlowCoefficient::perNode(k), {}, where),
                      Catch::Contains("transmissivity") && Catch::Contains(">= 0") &&
                          Catch::Contains("node 3") && Catch::Contains("has -2"));
  FaultDiffusionOptions o;
  o.maxStep = 0.0;
  REQUIRE_THROWS_WITH(FaultDiffusion(mesh, 1.0, 1.0, o), Catch::Contains("substep must be > 0"));
  FaultDiffusion d(mesh, 1.0, 1.0);
  REQUIRE_THROWS_WITH(
      d.addRateWell(Point(0.0, 0.0, 0.5), StepSchedule::constant(1.0), 0.1, where),
      Catch::Contains("constant/pressureDict:12") &&
          Catch::Contains("the well at (0 0 0.5) is 0.5 m from the nearest point") &&
          Catch::Contains("at most 0.1 m"));
  REQUIRE_THROWS_WITH(d.addHeldPressure(Point(3.0, 0.0, 0.0), StepSchedule::constant(1.0), 1.0),
                      Catch::Contains("held pressure at (3 0 0) is 2 m"));
  d.addHeldPressure(Point(0.0, 0.0, 0.0), StepSchedule::constant(1.0), 0.1);
  REQUIRE_THROWS_WITH(d.addHeldPressure(Point(0.1, 0.0, 0.0), StepSchedule::constant(2.0), 0.2),
                      Catch::Contains("held already"));
  REQUIRE_THROWS_WITH(d.holdNodes({99}, StepSchedule::constant(0.0)),
                      Catch::Contains("out of range"));
  REQUIRE_THROWS_WITH(d.setState(Eigen::VectorXd::Zero(3), where),
                      Catch::Contains("expected 25 nodal values, got 3"));
  REQUIRE(timeSchemeNamed("crankNicolson") == TimeScheme::crankNicolson);
  REQUIRE(std::string(toString(TimeScheme::backwardEuler)) == "backwardEuler");
  REQUIRE_THROWS_WITH(timeSchemeNamed("crankNicholson", where),
                      Catch::Contains("unknown time scheme 'crankNicholson'") &&
                          Catch::Contains("valid names are: backwardEuler crankNicolson") &&
                          Catch::Contains("did you mean 'crankNicolson'"));
}
