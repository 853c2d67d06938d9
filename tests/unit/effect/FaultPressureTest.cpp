// faultPressure (FaultPressure.hpp): p_f = p₀(x) + Δp(t) at the control nodes of the listed
// fractures only, the initial state in the friction fields' forms (a hydrostatic depth
// gradient, points), the change in time interpolated from its table; wrong fracture names and
// bad fields are InputErrors naming the key.
#include <catch2/catch.hpp>
#include <sstream>
#include <string>

#include "friction/core/InputError.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/effect/Effect.hpp"
#include "friction/fracture/FractureSystem.hpp"
#include "friction/fracture/SplitMesh.hpp"

using namespace friction;

namespace {

const std::vector<std::string> kFractures = {"fault", "other"};

std::unique_ptr<Effect> effect(const std::string& text, int dim) {
  const Dictionary d = Dictionary::parse(text, "constant/effects");
  auto e = Effect::New("fluid", d, kFractures, ".", dim);
  d.checkAllRead();
  return e;
}

std::string errorOf(const std::string& text, int dim) {
  try {
    effect(text, dim);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

/// Nodes at depths 0, 100, 1000 m on 'fault' (z down in 3D) and one on 'other'.
std::vector<ControlNode> nodes3d() {
  std::vector<ControlNode> n(4);
  const double z[] = {0, -100, -1000, -500};
  for (int i = 0; i < 4; ++i) {
    n[i].position = Point(10.0 * i, 0, z[i]);
    n[i].fracture = i < 3 ? 0 : 1;
  }
  return n;
}

Eigen::VectorXd pressureAt(Effect& e, const std::vector<ControlNode>& nodes, double t,
                           std::ostream& log) {
  const SplitMesh split;
  e.bind(EffectContext{split, nodes, kFractures, log});
  Eigen::VectorXd p = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nodes.size()));
  e.addFracturePressure(nodes, kFractures, t, p);
  return p;
}

}  // namespace

TEST_CASE("faultPressure: hydrostatic initial state plus a change in time, on its fracture only",
          "[effect][faultPressure]") {
  // ρ_f g = 1000 · 9.81 Pa/m: p₀ = 1e5 + 9810·depth; Δp ramps 0 → 2e6 Pa over t in [0, 10].
  const auto e = effect(
      "type faultPressure; fracture fault; initial { type depth; value 1e5; gradient -9810; } "
      "change table ((0 0) (10 2e6));",
      3);
  CHECK(e->givesFracturePressure());
  const auto nodes = nodes3d();
  std::ostringstream log;
  const Eigen::VectorXd p = pressureAt(*e, nodes, 5.0, log);
  CHECK(p[0] == Approx(1e5 + 1e6).epsilon(1e-15));
  CHECK(p[1] == Approx(1e5 + 981e3 + 1e6).epsilon(1e-15));
  CHECK(p[2] == Approx(1e5 + 9.81e6 + 1e6).epsilon(1e-15));
  CHECK(p[3] == 0);  // 'other' is not listed
  CHECK(log.str().find("Fracture fault: initial pressure (fluid) from min 100000 to max") == 0);
}

TEST_CASE("faultPressure: every fracture by default, a constant initial state",
          "[effect][faultPressure]") {
  const auto e = effect("type faultPressure; initial 3e6;", 3);
  std::ostringstream log;
  const Eigen::VectorXd p = pressureAt(*e, nodes3d(), 0.0, log);
  for (Eigen::Index i = 0; i < p.size(); ++i) CHECK(p[i] == 3e6);
  CHECK(log.str().empty());  // a constant has no range to report
}

TEST_CASE("faultPressure: bad keys are InputErrors naming them", "[effect][faultPressure]") {
  CHECK(errorOf("type faultPressure; fracture faul;", 3)
            .find("key 'fracture': 'faul' is not a fracture of the case") != std::string::npos);
  CHECK(errorOf("type faultPressure; fractures (fault nope);", 3)
            .find("key 'fractures': 'nope' is not a fracture of the case") != std::string::npos);
  CHECK(errorOf("type faultPressure; fractures ();", 3).find("key 'fractures': an empty list") !=
        std::string::npos);
  CHECK(errorOf("type faultPressure; fracture fault; fractures (fault);", 3) != "(no InputError)");
  CHECK(errorOf("type faultPressure; initial { type arclength; table ((0 1) (1 2)); }", 3)
            .find("arclength") != std::string::npos);
}
