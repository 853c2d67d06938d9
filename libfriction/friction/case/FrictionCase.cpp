// The case run by frictionSolver: see FrictionCase.hpp.
#include "friction/case/FrictionCase.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <numeric>
#include <ostream>
#include <set>
#include <sstream>

#include <unistd.h>
#include <Eigen/Geometry>

#include "friction/case/RunCase.hpp"
#include "friction/core/Assert.hpp"
#include "friction/core/InputFile.hpp"
#include "friction/core/OutputError.hpp"
#include "friction/core/Parallel.hpp"
#include "friction/core/StopRequest.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/dict/DictionaryWriter.hpp"
#include "friction/fracture/SplitMeshIO.hpp"
#include "friction/output/FaultSeries.hpp"
#include "friction/output/FieldWriter.hpp"
#include "friction/output/TimeFolder.hpp"
#include "friction/time/RemainingTime.hpp"

namespace friction {

namespace fs = std::filesystem;

namespace {

Dictionary readCaseFile(const std::string& caseDir, const std::string& relative) {
  const std::string path = (fs::path(caseDir) / relative).lexically_normal().string();
  // A path that is there but no regular file (a folder, a FIFO) is refused by the reader, which
  // says what it is.
  if (!fs::exists(path)) throw InputError(path, "cannot open: the case needs " + relative);
  return Dictionary::read(path);
}

// system/frictionSolution's elementOrder (1 or 2, default 1).
int elementOrderOf(const Dictionary& solution) {
  return static_cast<int>(solution.getIntOr("elementOrder", 1, {1, 2}));
}

/// The value of a time-folder name, if the whole name is a number ("0.5", "1e-05").
bool timeOfName(const std::string& name, double& t) {
  if (name.empty() || name[0] == '.') return false;
  char* end = nullptr;
  t = std::strtod(name.c_str(), &end);
  return end != name.c_str() && *end == '\0';
}

/// Whether a time folder's name is the time t: as TimeControl::timeName writes t with some
/// number of digits (the run that wrote it may have had another timePrecision), or, for a name
/// typed by hand ("2.0"), within half a unit of the precision-th digit of t.
bool nameReadsAs(const std::string& name, double t, int precision) {
  for (int p = 1; p <= 17; ++p) {
    std::ostringstream s;
    s.precision(p);
    s << t;
    if (s.str() == name) return true;
  }
  double named = 0;
  if (!timeOfName(name, named)) return false;
  const double unit =
      t == 0 ? 0.0 : std::pow(10.0, std::floor(std::log10(std::abs(t))) - precision + 1);
  return std::abs(named - t) <= 0.5 * unit;
}

/// The time folders of a case (folders named as a number), by time.
std::vector<std::pair<double, std::string>> timeFolders(const std::string& caseDir) {
  std::vector<std::pair<double, std::string>> folders;
  for (const auto& e : fs::directory_iterator(caseDir)) {
    double t = 0;
    if (e.is_directory() && timeOfName(e.path().filename().string(), t))
      folders.emplace_back(t, e.path().filename().string());
  }
  std::sort(folders.begin(), folders.end());
  return folders;
}

/// "0.1, 0.2, 0.3" or "0.1, 0.2, ..., 1 (40 folders)".
// γ and γ_n are accepted within [1e-8, 1e8] of their scale-free default E/h: D = 0 does not
// depend on them, but a node's state is read off augmented quantities (N = τ − γβ against ρ;
// σ'_n + γ_n g against 0), and the stop rule weighs β and g by them (D = γβ where a node
// sticks, −γ_n g where faces touch). Far below E/h, γβ and γ_n g fall under the round-off of
// τ and σ'_n: slipping nodes are classed stick, open ones closed (with exit 0), and errors of
// β and g become invisible to the stop rule; far above, γβ and γ_n g swamp the tractions,
// overflow, or the iteration stalls. Measured on cases/pennyCrack (P1, a/8; README.md, "γ's
// range"): wrong states with status converged at gammaNormalRelative 1e-13 and gammaRelative
// 1e-16, a wrong slip with status converged at gammaRelative 1e300, stalls at 1e-14 and 1e16;
// the default's states and columns from 1e-12 to 1e12. The bound keeps at least four decades
// from the first failure on each side.
constexpr double gammaRelativeMin = 1e-8, gammaRelativeMax = 1e8;

/// The refusal of a γ or γ_n (key, as given) outside the accepted range; `scale` is E/h [Pa/m]
/// for an absolute key (0 for a relative one).
std::string gammaRangeMessage(const std::string& key, double value, double scale) {
  const bool normal = key.rfind("gammaNormal", 0) == 0;
  std::ostringstream s;
  s << std::setprecision(6) << "key '" << key << "': " << value;
  if (scale > 0)
    s << " Pa/m is " << value / scale << " x E/h (E/h = " << scale << " Pa/m); accepted from "
      << gammaRelativeMin * scale << " to " << gammaRelativeMax * scale << " Pa/m ("
      << gammaRelativeMin << " to " << gammaRelativeMax << " x E/h)";
  else
    s << " is outside the accepted range [" << gammaRelativeMin << ", " << gammaRelativeMax
      << "] (x E/h)";
  s << ". "
    << (normal ? "gamma_n weighs the opening g against the normal stress (sigma'_n + gamma_n g "
                 "decides whether faces touch)"
               : "gamma weighs the slip increment against the shear traction (tau - gamma "
                 "beta decides whether a node sticks)")
    << "; further from E/h than that, " << (normal ? "gamma_n g" : "gamma beta")
    << " falls below the round-off of the tractions or swamps them, and the states written "
       "would depend on it. The answer does not depend on "
    << (normal ? "gamma_n" : "gamma") << " within the range: use the default";
  return s.str();
}

std::string listNames(const std::vector<std::string>& names) {
  if (names.size() <= 4) return joinWords(names);
  return names[0] + ", " + names[1] + ", ..., " + names.back() + " (" +
         std::to_string(names.size()) + " folders)";
}

}  // namespace

FrictionCase::~FrictionCase() = default;

FrictionCase::FrictionCase(const std::string& caseDir, const GivenFields& given)
    : sinceStart_(), caseDir_(caseDir) {
  if (!fs::exists(caseDir))
    throw InputError(caseDir,
                     "the case folder does not exist (expected a folder with system/, "
                     "constant/ and 0/; see -case)");
  if (!fs::is_directory(caseDir))
    throw InputError(caseDir,
                     "is not a folder (expected a case folder with system/, constant/ "
                     "and 0/; see -case)");
  // 1. Every dictionary is read and checked before any work: a typo costs nothing.
  const Dictionary controlDict = readCaseFile(caseDir, "system/controlDict");
  time_ = std::make_unique<TimeControl>(controlDict);
  faultSeries_ = FaultSeries::read(controlDict);
  controlDict.checkAllRead();

  const std::string splitPath = (fs::path(caseDir) / "constant" / "splitMesh").string();
  if (!fs::exists(splitPath))
    throw InputError(splitPath, "cannot open: run splitFractureNodes on the case first");
  split_ = readSplitMesh(splitPath);
  checkSplitMeshCurrent(caseDir, split_);
  const Dictionary mech = readCaseFile(caseDir, "constant/mechanicalProperties");
  materials_ = std::make_unique<MaterialMap>(MaterialMap::read(mech, split_.mesh));
  mech.checkAllRead();
  if (materials_->uniform() || split_.fractures.empty()) {
    youngScale_ = materials_->maxYoungModulus();
  } else {
    // The cells with a vertex on a fracture (either side's copy): their stiffness sets the
    // size of the tractions a slip makes.
    const Mesh& m = split_.mesh;
    std::vector<char> onFracture(m.points.size(), 0);
    for (const auto& g : split_.fractures) {
      for (Index v : g.plus) onFracture[v] = 1;
      for (Index v : g.minus) onFracture[v] = 1;
    }
    std::vector<Index> touching;
    for (Index c = 0; c < m.numCells(); ++c)
      for (Index v : m.cell(c))
        if (onFracture[v]) {
          touching.push_back(c);
          break;
        }
    youngScale_ = materials_->maxYoungModulus(touching);
  }

  std::vector<int> fractureLabels;
  for (const auto& g : split_.fractures) fractureLabels.push_back(g.label);
  const Dictionary D = readCaseFile(caseDir, "0/D");
  if (D.found("dimensions")) D.values("dimensions");
  if (D.found("internalField")) D.values("internalField");
  bcs_ = std::make_unique<BoundaryConditions>(D, split_.mesh, fractureLabels);
  D.checkAllRead();

  const Dictionary fp = readCaseFile(caseDir, "constant/fractureProperties");
  std::vector<std::string> names;
  for (const auto& g : split_.fractures) names.push_back(g.name);
  for (const std::string& key : fp.keys())
    if (key != "FoamFile" && std::find(names.begin(), names.end(), key) == names.end())
      fp.fail(key, "'" + key + "' is not a fracture of the split mesh" +
                       suggestionText(key, names) + " (fractures: " + joinWords(names) + ")");
  for (const auto& g : split_.fractures) {
    if (!fp.isDict(g.name))
      throw InputError(fp.location(), "no entry for fracture '" + g.name +
                                          "' (expected a sub-dictionary with its 'law')");
    const Dictionary& fd = fp.subDict(g.name);
    // Bilateral is the paper's model (the faces slide but never separate) and the answer of a
    // fracture held shut; unilateral lets the faces open (docs/method.md §4, "Fractures that
    // open").
    const bool unilateral =
        fd.getChoiceOr("contact", {"bilateral", "unilateral"}, "bilateral") == "unilateral";
    fractures_.push_back({g.name, FrictionLaw::New(fd, caseDir, split_.mesh.dim), unilateral});
    opening_ |= unilateral;
    rateState_ |= fractures_.back().law->rateAndState() || fractures_.back().law->imposesSlipRate();
    if (fractures_.back().law->weakening() != Weakening::none) {
      weakening_ = true;
      if (unilateral)
        fd.fail("contact",
                "key 'contact': law slipWeakening is not yet solved with faces that open; use "
                "contact bilateral (the default) on fracture '" +
                    g.name + "'");
    }
  }
  fp.checkAllRead();
  if (rateState_) {
    for (std::size_t f = 0; f < fractures_.size(); ++f)
      if (!fractures_[f].law->rateAndState() && !fractures_[f].law->imposesSlipRate())
        fp.fail(fractures_[f].name,
                "fracture '" + fractures_[f].name + "': law " + fractures_[f].law->name() +
                    " beside law rateState or creep on another fracture: a quasi-dynamic run "
                    "integrates rate-and-state faults and imposed creep only; give every "
                    "fracture law rateState or creep");
    if (opening_)
      throw InputError(fp.location(),
                       "law rateState or creep with contact unilateral: faces that open are "
                       "not yet integrated quasi-dynamically; use contact bilateral");
  }
  if (weakening_ && opening_)
    throw InputError(fp.location(),
                     "law slipWeakening on one fracture and contact unilateral on another: "
                     "friction that weakens is not yet solved with faces that open");

  // Effects: only what the case lists is built (constant/effects is optional).
  const std::string effectsPath = (fs::path(caseDir) / "constant" / "effects").string();
  if (fs::exists(effectsPath)) {
    const Dictionary ed = Dictionary::read(effectsPath);
    for (const std::string& key : ed.keys()) {
      if (key == "FoamFile") continue;
      if (!ed.isDict(key))
        ed.fail(key, "key '" + key + "': expected a sub-dictionary { type ...; } (types: " +
                         joinWords(Effect::names()) + ")");
      const Dictionary& e = ed.subDict(key);
      if (!e.getBoolOr("active", true)) {
        e.markAllRead();  // switched off: its keys are the user's to keep
        skippedEffects_.push_back(key);
        continue;
      }
      effects_.push_back(Effect::New(key, e, names, caseDir, split_.mesh.dim));
      effects_.back()->setMesh(split_.mesh);  // regions named by the effect: checked now
    }
    ed.checkAllRead();
  }
  // Fields the caller gives (the FreeFEM plug-in's pressure): checked, on the split mesh's
  // vertices, and each taken by the effect that asks for it; one that asks and gets none
  // refuses here, and so does the case for a field that no effect takes.
  GivenFields onSplit;
  for (const auto& [key, field] : given) {
    field.check();
    onSplit.emplace(key, field.onSplitMesh(split_));
  }
  std::set<std::string> taken;
  for (const auto& e : effects_)
    for (const std::string& key : e->takeGivenFields(onSplit, split_.mesh)) taken.insert(key);
  for (const auto& [key, field] : given)
    if (!taken.count(key))
      throw InputError(effectsPath, field.caller + " was given " + givenFieldMeaning(key) + " (" +
                                        field.name +
                                        "), and no active effect of the case takes it: add to "
                                        "constant/effects " +
                                        givenFieldTaker(key));

  const Dictionary sol = readCaseFile(caseDir, "system/frictionSolution");
  order_ = elementOrderOf(sol);
  if (sol.found("linearSolver"))
    SparseFactor::requireInBuild(sol.getWord("linearSolver"), sol.location("linearSolver"));
  std::vector<std::string> solvers = SparseFactor::backendNames();
  const bool hasMumps = std::count(solvers.begin(), solvers.end(), "mumps") > 0;
  const bool hasAmg = std::count(solvers.begin(), solvers.end(), "amg") > 0;
  solvers.insert(solvers.begin(), "auto");
  linearSolver_ = sol.getChoiceOr("linearSolver", solvers, "auto");
  // auto: chosen by size in setup() (chooseLinearSolver). Several ranks need a solver they
  // share: mumps (its factor goes out of core by its own estimate), else amg.
  linearSolverAuto_ = linearSolver_ == "auto";
  if (linearSolverAuto_ && parallel::size() > 1) {
    if (hasMumps || hasAmg) {
      linearSolver_ = hasMumps ? "mumps" : "amg";
      linearSolverChoice_ = "Linear solver auto: " + linearSolver_ + " (" +
                            std::to_string(parallel::size()) + " ranks share it)";
    }
  }
  if (sol.found("iterativeAbove") && !linearSolverAuto_)
    throw InputError(sol.location("iterativeAbove"),
                     "key 'iterativeAbove' is the predicted size of a direct factor above which "
                     "'linearSolver auto' takes the iterative solver: it needs 'linearSolver "
                     "auto;' (the default)");
  if (linearSolverAuto_)
    iterativeAbove_ = sol.getScalarOr("iterativeAbove", 0.0, Bounds::positive());
  // The fill-reducing ordering: cholmod's to choose (with auto, where auto takes cholmod); the
  // other solvers have their own, and a case that names one for them is told so rather than
  // ignored.
  ordering_ = orderingNamed(sol.getChoiceOr("ordering", orderingNames(), "auto"));
  if (ordering_ != Ordering::automatic && linearSolver_ != "cholmod" && !linearSolverAuto_)
    throw InputError(sol.location("ordering"),
                     "key 'ordering': linear solver '" + linearSolver_ +
                         "' has its own ordering (simplicialLDLT: AMD, mumps: METIS); 'ordering " +
                         toString(ordering_) +
                         "' needs 'linearSolver cholmod' (or use 'ordering auto')");
  readMumpsMemory(sol);
  // The iterative solver's stopping rule: a relative residual ‖b − A x‖/‖b‖ (with auto, for
  // where auto takes amg).
  if (sol.found("iterativeTolerance") && linearSolver_ != "amg" && !linearSolverAuto_)
    throw InputError(sol.location("iterativeTolerance"),
                     "key 'iterativeTolerance' is where the solves of an iterative linear solver "
                     "stop; linear solver '" +
                         linearSolver_ + "' is direct: it needs 'linearSolver amg'");
  if (linearSolver_ == "amg" || linearSolverAuto_)
    iterativeTolerance_ =
        sol.getScalarOr("iterativeTolerance", 1e-10, Bounds{0.0, 1e-2, true, false});
  // Several ranks share the factorisation (mumps) or the multigrid hierarchy (amg).
  if (parallel::size() > 1 && linearSolver_ != "mumps" && linearSolver_ != "amg")
    throw InputError(sol.found("linearSolver") ? sol.location("linearSolver") : sol.location(),
                     "this run has " + std::to_string(parallel::size()) +
                         " ranks (frictionSolver -parallel) but linear solver '" + linearSolver_ +
                         "' runs on one: set 'linearSolver mumps;'");
  const Dictionary& control = sol.subDict("control");
  // Relative values are checked against their range here, absolute ones in setup() (they need
  // h).
  const auto checkRelative = [&control](const char* key, double value) {
    if (value < gammaRelativeMin || value > gammaRelativeMax)
      control.fail(key, gammaRangeMessage(key, value, 0));
  };
  if (control.alternative({{"gamma"}, {"gammaRelative"}}, 1) == 0) {
    gammaAbsolute_ = true;
    gamma_ = control.getScalar("gamma", Bounds::positive());
    gammaLocation_ = control.location("gamma");
  } else {
    gammaRelative_ = control.getScalarOr("gammaRelative", 1.0, Bounds::positive());
    checkRelative("gammaRelative", gammaRelative_);
  }
  // γ_n: by default γ's own value (both weigh a traction against a jump).
  switch (control.alternative({{"gammaNormal"}, {"gammaNormalRelative"}}, 2)) {
    case 0:
      gammaNGiven_ = GammaNGiven::absolute;
      gammaN_ = control.getScalar("gammaNormal", Bounds::positive());
      gammaNLocation_ = control.location("gammaNormal");
      break;
    case 1:
      gammaNGiven_ = GammaNGiven::relative;
      gammaNRelative_ = control.getScalar("gammaNormalRelative", Bounds::positive());
      checkRelative("gammaNormalRelative", gammaNRelative_);
      break;
    default:
      break;
  }
  zeta_ = control.getScalarOr("zeta", 0.0, Bounds::nonNegative());
  gradient_ = control.getChoiceOr("gradient", {"exact", "frozenRho"}, "exact") == "exact"
                  ? GradientKind::exact
                  : GradientKind::frozenRho;
  warmStart_ = control.getBoolOr("warmStart", false);
  optimizer_ = Optimizer::New(control.subDict("optimizer"));
  timeIntegrator_ = TimeIntegrator::New(sol);
  const SourceLocation integratorAt =
      sol.found("timeIntegration") ? sol.location("timeIntegration") : sol.location();
  if (rateState_ && !timeIntegrator_->takesRateState()) {
    const bool anyRateState = std::any_of(fractures_.begin(), fractures_.end(),
                                          [](const auto& f) { return f.law->rateAndState(); });
    throw InputError(integratorAt, std::string("law ") + (anyRateState ? "rateState" : "creep") +
                                       " (constant/fractureProperties) is integrated in time: set "
                                       "'timeIntegration { type quasiDynamic; }' "
                                       "(timeIntegration is " +
                                       timeIntegrator_->name() + ")");
  }
  if (!rateState_ && timeIntegrator_->takesRateState())
    throw InputError(integratorAt, "timeIntegration " + timeIntegrator_->name() +
                                       " integrates rate-and-state faults: give the fractures "
                                       "law rateState in constant/fractureProperties");
  if (rateState_ && !optimizer_->handlesWeakening())
    control.subDict("optimizer")
        .fail("type",
              "key 'type': timeIntegration quasiDynamic takes the interface operator S from "
              "optimizer semismoothNewton with variant condensed");
  if (weakening_ && !optimizer_->handlesWeakening())
    control.subDict("optimizer")
        .fail("type",
              "key 'type': law slipWeakening (constant/fractureProperties) needs optimizer "
              "semismoothNewton with variant condensed: it alone holds S, which tells a slipping "
              "patch that lost its equilibrium (nucleation) from slow convergence");
  if (opening_ && !optimizer_->handlesOpening())
    control.subDict("optimizer")
        .fail("variant",
              "key 'variant': the krylov variant does not take fractures that open (contact "
              "unilateral in constant/fractureProperties); use variant condensed");
  sol.checkAllRead();
}

// MUMPS's smaller factors (README "Running in parallel"): a block low-rank factor (`lowRank`,
// its dropping tolerance) and an out-of-core one (`outOfCore yes`, in `outOfCoreDir`, the case
// folder by default; `auto`, the default, where MUMPS's in-core estimate exceeds the memory
// available or `outOfCoreAbove`). The other solvers have neither: a case that asks is told so,
// not ignored. The folder is checked here, before any work: a run must not fail on it after
// the assembly.
void FrictionCase::readMumpsMemory(const Dictionary& sol) {
  for (const char* key : {"lowRank", "outOfCore", "outOfCoreDir", "outOfCoreAbove"})
    if (sol.found(key) && linearSolver_ != "mumps")
      throw InputError(sol.location(key), std::string("key '") + key + "': linear solver '" +
                                              linearSolver_ +
                                              "' has no low-rank or out-of-core factor; it needs "
                                              "'linearSolver mumps'");
  if (sol.found("lowRank")) {
    mumpsMemory_.lowRank = sol.getScalar("lowRank", Bounds{0.0, 1.0, true, true});
  }
  if (linearSolver_ != "mumps") return;
  const std::string word = sol.getWordOr("outOfCore", "auto");
  if (word != "auto" && word != "yes" && word != "no" && word != "true" && word != "false" &&
      word != "on" && word != "off")
    sol.fail("outOfCore", "key 'outOfCore': '" + word + "' is none of auto, yes, no");
  const bool automatic = word == "auto";
  const bool outOfCore = automatic || sol.getBool("outOfCore");
  if (sol.found("outOfCoreAbove") && !automatic)
    sol.fail("outOfCoreAbove",
             "key 'outOfCoreAbove' is the in-core estimate above which 'outOfCore auto' goes "
             "out of core: it needs 'outOfCore auto;' (the default)");
  mumpsMemory_.outOfCoreAuto = automatic;
  if (automatic)
    mumpsMemory_.outOfCoreAbove = sol.getScalarOr("outOfCoreAbove", 0.0, Bounds::positive());
  if (!outOfCore) {
    if (sol.found("outOfCoreDir"))
      sol.fail("outOfCoreDir",
               "key 'outOfCoreDir' is the folder of an out-of-core factor: it "
               "needs 'outOfCore yes;' or 'outOfCore auto;'");
    return;
  }
  fs::path dir = caseDir_;
  if (sol.found("outOfCoreDir")) {
    const fs::path given = sol.getFileName("outOfCoreDir");
    dir = given.is_absolute() ? given : fs::path(caseDir_) / given;
  }
  std::error_code ec;
  dir = fs::absolute(dir, ec).lexically_normal();
  const std::string key = sol.found("outOfCoreDir") ? "outOfCoreDir" : "outOfCore";
  // `auto` by default in the case folder: a folder it cannot use (read-only, a path too long
  // for MUMPS) keeps the factor in core, and the settings line says so. Asked for by a key, the
  // folder must do.
  if (automatic && !sol.found("outOfCoreDir")) {
    std::string probe = (dir / "mumpsOutOfCore.XXXXXX").string();
    const bool writable = dir.string().size() <= 200 && ::mkdtemp(probe.data()) != nullptr;
    if (writable) {
      ::rmdir(probe.c_str());
      mumpsMemory_.outOfCoreDir = dir.string();
    } else {
      outOfCoreNote_ =
          ", in core (outOfCore auto: the case folder cannot take an out-of-core "
          "factor; outOfCoreDir names another)";
    }
    return;
  }
  if (!fs::is_directory(dir, ec))
    sol.fail(key, "key '" + key + "': the out-of-core folder '" + dir.string() +
                      "' is not an existing folder");
  // Writable is what matters, and only making a folder tells (access() says yes to root on a
  // read-only mount): a folder of ours, made and removed at once.
  std::string probe = (dir / "mumpsOutOfCore.XXXXXX").string();
  if (!::mkdtemp(probe.data()))
    sol.fail(key, "key '" + key + "': cannot write in the out-of-core folder '" + dir.string() +
                      "' (" + std::strerror(errno) + ")");
  ::rmdir(probe.c_str());
  // MUMPS keeps the folder's name in 255 characters; ours adds "/mumpsOutOfCore.XXXXXX".
  if (dir.string().size() > 200)
    sol.fail(key, "key '" + key +
                      "': the out-of-core folder's path is longer than 200 "
                      "characters, which MUMPS cannot take: give a shorter one");
  mumpsMemory_.outOfCoreDir = dir.string();
}

void FrictionCase::printSettings(std::ostream& log) const {
  const std::string kind = split_.mesh.dim == 3        ? ", 3D"
                           : materials_->planeStress() ? ", plane stress"
                                                       : ", plane strain";
  log << "Case: " << caseDir_ << "\n";
  if (materials_->uniform()) {
    const Material& m = materials_->materials().front();
    log << "Material: E " << m.youngModulus() << " Pa, nu " << m.poissonRatio() << kind << "\n";
  } else {
    log << "Materials: " << materials_->regions().size()
        << (materials_->regions().size() == 1 ? " region" : " regions") << kind
        << "; E for gammaRelative and alphaRelative " << youngScale_
        << (split_.fractures.empty() ? " Pa (the largest E)\n"
                                     : " Pa (the largest E of the cells that touch a fracture)\n");
    for (const MaterialMap::Region& r : materials_->regions()) {
      const Material& m = materials_->materials()[r.material];
      log << "Material " << (r.name.empty() ? "region" + std::to_string(r.number) : r.name)
          << " (region " << r.number << ", " << r.cells
          << (split_.mesh.dim == 3 ? " tetrahedra" : " triangles")
          << (r.entry == "default" ? ", entry default" : "") << "): E " << m.youngModulus()
          << " Pa, nu " << m.poissonRatio() << "\n";
    }
  }
  log << "Elements: P" << order_ << ", linear solver "
      << (linearSolverAuto_ ? "auto" : linearSolver_);
  if (linearSolver_ == "cholmod" || linearSolverAuto_) log << ", ordering " << toString(ordering_);
  if (linearSolver_ == "amg" || linearSolverAuto_)
    log << ", iterativeTolerance " << iterativeTolerance_;
  if (iterativeAbove_ > 0) log << ", iterativeAbove " << iterativeAbove_ << " bytes";
  if (mumpsMemory_.lowRank > 0) log << ", low-rank factor (BLR) at " << mumpsMemory_.lowRank;
  log << outOfCoreNote_;
  if (!mumpsMemory_.outOfCoreDir.empty())
    log << (mumpsMemory_.outOfCoreAuto ? ", out of core if its estimate says so (outOfCore auto)"
                                       : ", out of core")
        << " in " << mumpsMemory_.outOfCoreDir;
  log << "\n";
  if (fractures_.empty()) log << "Fractures: none (a plain elastic solve, no control loop)\n";
  for (const auto& f : fractures_) {
    log << "Fracture " << f.name << ": law " << f.law->name();
    const FrictionField &mu = f.law->mu(), &c = f.law->cohesion();
    if (const auto* rs = dynamic_cast<const RateStateLaw*>(f.law.get())) {
      const RateStateLaw::Fields& F = rs->fields();
      log << ", a " << F.a.describe() << ", b " << F.b.describe() << ", characteristicSlip "
          << F.L.describe() << " m, referenceFriction " << F.f0.describe() << ", referenceSlipRate "
          << F.V0.describe() << " m/s, initialSlipRate " << F.initialV.describe()
          << " m/s, stateEvolution " << (F.aging ? "aging" : "slip");
    } else if (const auto* creep = dynamic_cast<const Creep*>(f.law.get())) {
      log << ", slipRate " << creep->slipRate().describe() << " m/s";
    } else if (f.law->weakening() != Weakening::none)
      log << ", staticCoefficient " << mu.describe() << ", dynamicCoefficient "
          << f.law->dynamicCoefficient().describe() << ", criticalSlip "
          << f.law->criticalSlip().describe() << " m ("
          << (f.law->weakening() == Weakening::linear ? "linear" : "exponential") << ")";
    else if (!mu.isConstant() || mu.value() > 0)
      log << ", frictionCoefficient " << mu.describe();
    if (!c.isConstant())
      log << ", " << f.law->cohesionKey() << " [Pa] " << c.describe();
    else if (c.value() > 0)
      log << ", " << f.law->cohesionKey() << " " << c.value() << " Pa";
    if (opening_) log << ", contact " << (f.unilateral ? "unilateral" : "bilateral");
    log << "\n";
  }
  log << "Control: optimizer " << optimizer_->name() << ", gradient "
      << (gradient_ == GradientKind::exact ? "exact" : "frozenRho") << ", gamma " << gamma_
      << " Pa/m"
      << (gammaAbsolute_ ? "" : " (gammaRelative " + formatNumber(gammaRelative_) + " x E/h)")
      << ", zeta " << zeta_;
  if (opening_)
    log << ", gammaNormal " << gammaN_ << " Pa/m"
        << (gammaNGiven_ == GammaNGiven::relative
                ? " (gammaNormalRelative " + formatNumber(gammaNRelative_) + " x E/h)"
            : gammaNGiven_ == GammaNGiven::sameAsGamma ? " (gamma's)"
                                                       : "");
  if (optimizer_->name() != "semismoothNewton")
    log << ", alpha " << optimizer_->alpha() << " m/Pa"
        << (optimizer_->alphaIsRelative() ? " (alphaRelative x (h/E)^2)" : "");
  log << ", tolerance " << optimizer_->stopRule().tolerance << " ("
      << (optimizer_->stopRule().on == StopRule::On::residual ? "residual" : "step")
      << "), maxIterations " << optimizer_->stopRule().maxIterations << "\n";
  log << "Time integration: " << timeIntegrator_->name()
      << (timeIntegrator_->describe().empty() ? "" : ", " + timeIntegrator_->describe()) << "\n";
  // The effects switched on, and those that cost nothing because they are not.
  std::vector<std::string> off;
  for (const std::string& type : Effect::names()) {
    bool on = false;
    for (const auto& e : effects_) on |= e->type() == type;
    if (!on) off.push_back(type);
  }
  for (const auto& e : effects_)
    log << "Effect " << e->name() << ": " << e->type() << ", " << e->describe() << "\n";
  for (const auto& name : skippedEffects_)
    log << "Effect " << name << ": switched off (active no)\n";
  log << "Not simulated (not in the case): " << (off.empty() ? std::string("-") : joinWords(off))
      << "\n";
  // A load written twice: an in-situ stress and the same traction on a face.
  bool inSitu = false;
  for (const auto& e : effects_) inSitu |= e->givesStressOffset() && e->type() == "initialStress";
  if (inSitu && bcs_)
    for (const std::string& patch : bcs_->tractionsOfInSitu(
             [this](const Point& x) {
               Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
               for (const auto& e : effects_) s += e->initialStress(x);
               return s;
             },
             time_->endTime()))
      log << "Note: patch '" << patch << "' applies the in-situ traction σ⁰·n (initialStress) "
          << "again: the boundary conditions act on the change from the in-situ state, so the "
          << "body carries it twice; to keep the in-situ load alone make the patch 'type free;' "
          << "(or give only the change)\n";
}

void FrictionCase::logPhase(std::ostream& log, const std::string& phase, double seconds) const {
  log << "Setup: " << phase << ": " << formatSeconds(seconds) << " ["
      << formatSeconds(secondsSinceStart()) << "]\n";
}

FactorStatus FrictionCase::setup(std::ostream& log) {
  // Several ranks share the factorisation: they agree (parallel::agree) that each got there,
  // and that each finished what follows it, so that no failure leaves the others waiting in a
  // shared call.
  parallel::agree(
      [&] {
        Stopwatch clock;
        system_ = std::make_unique<FractureSystem>(split_, order_, *materials_);
        system_->setIterativeTolerance(iterativeTolerance_);
        logPhase(log,
                 "finite-element spaces and the fractures' frames (" +
                     std::to_string(system_->unsplitSpace().numDofs()) + " dofs, P" +
                     std::to_string(order_) + ", " + std::to_string(system_->size()) +
                     " fracture control nodes)",
                 clock.seconds());
        // Absolute γ and γ_n against their range around E/h, before the factorisation's work.
        // Where 1e8 E/h overflows, the case's units do (E near 1e300 Pa): the overflow
        // diagnoses of the factorisation and of the step say so, and name the cure.
        if (const double h = meanFractureEdge();
            h > 0 && std::isfinite(gammaRelativeMax * youngScale_ / h)) {
          const double scale = youngScale_ / h;
          const auto checkAbsolute = [scale](const char* key, double value,
                                             const SourceLocation& at) {
            if (!(value >= gammaRelativeMin * scale && value <= gammaRelativeMax * scale))
              throw InputError(at, gammaRangeMessage(key, value, scale));
          };
          if (gammaAbsolute_) checkAbsolute("gamma", gamma_, gammaLocation_);
          if (gammaNGiven_ == GammaNGiven::absolute)
            checkAbsolute("gammaNormal", gammaN_, gammaNLocation_);
        }
        bcs_->fix(system_->dirichlet());
        findFloatingParts();
      },
      exitStatusOf);
  // What the case leaves to its size (Newton's variant auto), before the factorisation, which
  // it decides: from facts of the case alone, alike on every rank and on a restart.
  // The stiffness assembled, then (linearSolver auto) the linear solver chosen for it, then
  // Newton's variant, which depends on the solver (none: no fracture, no control loop).
  const PhaseReport phases = [&](const std::string& phase, double seconds) {
    logPhase(log, phase, seconds);
  };
  parallel::agree(
      [&] {
        system_->assemble(linearSolverAuto_ && parallel::size() == 1 ? "cholmod" : linearSolver_,
                          phases, ordering_, mumpsMemory_);
        if (linearSolverAuto_ && parallel::size() == 1) chooseLinearSolver();
        if (!linearSolverChoice_.empty()) log << linearSolverChoice_ << "\n";
      },
      exitStatusOf);
  if (system_->size() > 0) {
    CaseFacts facts;
    facts.fractureNodes = system_->size();
    facts.dimension = split_.mesh.dim;
    facts.dofs = system_->unsplitSpace().numDofs();
    facts.elementOrder = order_;
    if (linearSolver_ == "amg") facts.iterativeSolver = linearSolver_;
    facts.maxPoissonRatio = materials_->maxPoissonRatio();
    if (opening_)
      facts.needsDenseS = "fractures that open (contact unilateral)";
    else if (weakening_)
      facts.needsDenseS = "law slipWeakening";
    else if (rateState_)
      facts.needsDenseS = "timeIntegration " + timeIntegrator_->name();
    optimizerChoice_ = optimizer_->chooseFor(facts);
  }
  FactorStatus status = system_->factorAssembled(optimizer_->wantsInterfaceOperator());
  // A part that nothing holds, or a direction no patch fixes: K is singular, whatever its
  // pivots say. The backends' pivot checks see it on one rank, but MUMPS on several does not
  // (measured on a free 3D body, cases/pennyCrack with every patch free: INFOG(28) null pivots
  // 5 on one rank, 0 on 2 and 3 ranks, with no negative pivot either, even at CNTL(3) = 1e-2,
  // without the Schur complement, scaling or ScaLAPACK; the run then "converged" on nonsense).
  // The mesh and the patches, the same on every rank, decide alike for every rank count.
  if (status == FactorStatus::ok && canMoveRigidly()) status = FactorStatus::notPositiveDefinite;
  factorStatus_ = status;
  parallel::agree([&] { finishSetup(status, log); }, exitStatusOf);
  return status;
}

// linearSolver auto on one rank: cholmod where its factor fits in memory, else amg, which
// needs none (README "Which linear solver"). The factor's size comes from CHOLMOD's ordering
// and symbolic analysis of the assembled matrix (SparseFactor::predict), whose ordering the
// factorisation then reuses. A restart takes what the run it continues took (recorded in the
// state), so that it writes what an uninterrupted run would, whatever memory is free now.
void FrictionCase::chooseLinearSolver() {
  std::ostringstream why;
  why << std::setprecision(3) << "Linear solver auto: ";
  const std::string recorded = time_->startFromLatest() ? recordedLinearSolver() : "";
  const auto names = SparseFactor::backendNames();
  const bool hasAmg = std::count(names.begin(), names.end(), "amg") > 0;
  if (!recorded.empty()) {
    linearSolver_ = recorded;
    why << recorded << " (as the run this one continues: its newest time folder's state)";
  } else {
    Stopwatch clock;
    FactorAnalysis predicted;
    const bool known = system_->predictFactor(predicted);
    const double limit = iterativeAbove_ > 0 ? iterativeAbove_ : 0.8 * availableMemory();
    const bool fits = !known || predicted.bytes <= limit;
    linearSolver_ = fits || !hasAmg ? "cholmod" : "amg";
    why << linearSolver_ << " (";
    if (!known) {
      why << "the factor's size could not be predicted";
    } else {
      why << "CHOLMOD's factor, predicted by its " << predicted.ordering
          << " ordering and symbolic analysis in " << formatSeconds(clock.seconds()) << ": "
          << predicted.entries << " entries, " << predicted.bytes / 1e9 << " GB, "
          << (fits ? "<= " : "> ") << limit / 1e9 << " GB"
          << (iterativeAbove_ > 0 ? " (iterativeAbove)" : ", 80 % of the memory available");
      if (!fits && !hasAmg) why << "; this build has no amg (FRICTION_HYPRE): factored anyway";
      if (fits) why << "; the factorisation takes this ordering";
    }
    why << ")";
  }
  if (linearSolver_ != "cholmod") system_->useBackend(linearSolver_, mumpsMemory_);
  linearSolverChoice_ = why.str();
}

std::string FrictionCase::recordedLinearSolver() const {
  // The newest complete time folder, as restart() finds it.
  std::string folder;
  for (const auto& [t, name] : timeFolders(caseDir_))
    if (fs::exists(fs::path(caseDir_) / name / "uniform" / "frictionState")) folder = name;
  if (folder.empty()) return "";
  const Dictionary st =
      Dictionary::read((fs::path(caseDir_) / folder / "uniform" / "frictionState").string(),
                       DictionaryLimits::dataFile());
  if (!st.found("linearSolver")) return "";
  const auto names = SparseFactor::backendNames();
  return st.getChoice("linearSolver", names);
}

std::vector<std::string> FrictionCase::freeComponents() const {
  std::vector<std::string> free;
  for (int c = 0; c < split_.mesh.dim; ++c) {
    bool fixes = false;
    for (const auto& p : bcs_->patches())
      fixes |=
          p.type == BoundaryConditions::Type::fixedDisplacement && fixesComponent(p.components, c);
    if (!fixes) free.push_back(std::string(1, "xyz"[c]));
  }
  return free;
}

bool FrictionCase::canMoveRigidly() const {
  for (const FloatingPart& p : floating_)
    if (!p.heldThroughFracture) return true;
  return !freeComponents().empty();
}

void FrictionCase::finishSetup(FactorStatus status, std::ostream& log) {
  const auto& nodes = system_->controlNodes();
  const Eigen::Index n = static_cast<Eigen::Index>(nodes.size());

  // Per control node: ρ = c − μ σ_n from its fracture's law, whose μ and c may vary along the
  // fracture (FrictionField.hpp): evaluated here once, checked node by node, the range logged.
  mu_.resize(n);
  cohesion_.resize(n);
  slipPath_ = Eigen::VectorXd::Zero(n);
  for (std::size_t f = 0; f < fractures_.size(); ++f) {
    std::vector<const ControlNode*> on;
    std::vector<Eigen::Index> index;
    for (Eigen::Index k = 0; k < n; ++k)
      if (nodes[k].fracture == static_cast<int>(f)) on.push_back(&nodes[k]), index.push_back(k);
    const FrictionLaw& law = *fractures_[f].law;
    const Eigen::VectorXd mu = law.mu().evaluate(on), c = law.cohesion().evaluate(on);
    for (std::size_t i = 0; i < index.size(); ++i) {
      mu_[index[i]] = mu[static_cast<Eigen::Index>(i)];
      cohesion_[index[i]] = c[static_cast<Eigen::Index>(i)];
    }
    if (!weakeningSettings_.nodes.empty())
      for (std::size_t i = 0; i < index.size(); ++i)
        weakeningSettings_.cohesion[index[i]] = c[static_cast<Eigen::Index>(i)];
    const auto range = [&](const char* key, const Eigen::VectorXd& v, const char* unit) {
      log << "Fracture " << fractures_[f].name << ": " << key << " from min " << v.minCoeff()
          << " to max " << v.maxCoeff() << unit << " over " << v.size() << " nodes\n";
    };
    if (law.weakening() != Weakening::none) {
      // μ_s ≥ μ_d node by node: friction that strengthens with slip is not this law.
      const Eigen::VectorXd muD = law.dynamicCoefficient().evaluate(on),
                            dc = law.criticalSlip().evaluate(on);
      if (weakeningSettings_.nodes.empty()) {
        weakeningSettings_.nodes.resize(static_cast<std::size_t>(n));
        weakeningSettings_.cohesion = Eigen::VectorXd::Zero(n);
      }
      for (std::size_t i = 0; i < index.size(); ++i) {
        const Eigen::Index j = static_cast<Eigen::Index>(i);
        if (muD[j] > mu[j])
          throw InputError(
              (fs::path(caseDir_) / "constant" / "fractureProperties").string(),
              "fracture '" + fractures_[f].name + "': dynamicCoefficient " + formatNumber(muD[j]) +
                  " above staticCoefficient " + formatNumber(mu[j]) + " at the node at (" +
                  formatNumber(on[i]->position.x()) + ", " + formatNumber(on[i]->position.y()) +
                  (split_.mesh.dim == 3 ? ", " + formatNumber(on[i]->position.z()) : "") + ")" +
                  ": slip-weakening needs mu_d <= mu_s");
        weakeningSettings_.nodes[static_cast<std::size_t>(index[i])] = {law.weakening(), mu[j],
                                                                        muD[j], dc[j]};
      }
    }
    if (!law.mu().isConstant() && !on.empty()) range("frictionCoefficient", mu, "");
    if (!law.cohesion().isConstant() && !on.empty()) range(law.cohesionKey().c_str(), c, " Pa");
  }
  // The rock's shear modulus G at each fracture (the seismic moment's): the mean over the
  // cells that touch it (the material's G when it is uniform).
  shearModulus_.assign(split_.fractures.size(), 0.0);
  for (std::size_t f = 0; f < split_.fractures.size(); ++f) {
    const FractureGeometry& g = split_.fractures[f];
    std::vector<char> on(split_.mesh.points.size(), 0);
    for (Index v : g.plus) on[static_cast<std::size_t>(v)] = 1;
    for (Index v : g.minus) on[static_cast<std::size_t>(v)] = 1;
    double sum = 0;
    long count = 0;
    for (Index c = 0; c < split_.mesh.numCells(); ++c)
      for (Index v : split_.mesh.cell(c))
        if (on[static_cast<std::size_t>(v)]) {
          sum += materials_->ofCell(c).mu();
          ++count;
          break;
        }
    shearModulus_[f] = count > 0 ? sum / static_cast<double>(count) : 0.0;
  }
  // Rate-and-state faults: each node's law, η from the rock's G where c_s is given.
  if (rateState_) {
    rateLaws_.assign(static_cast<std::size_t>(n), RateState{});
    initialSlipRate_ = Eigen::VectorXd::Zero(n);
    psi_ = Eigen::VectorXd::Zero(n);
    slipRate_ = Eigen::VectorXd::Zero(system_->blockSize() * n);
    imposed_ = Eigen::VectorXd::Zero(n);
    imposedRate_ = Eigen::VectorXd::Zero(system_->blockSize() * n);
    for (std::size_t f = 0; f < fractures_.size(); ++f) {
      std::vector<const ControlNode*> on;
      std::vector<Eigen::Index> index;
      for (Eigen::Index k = 0; k < n; ++k)
        if (nodes[k].fracture == static_cast<int>(f)) on.push_back(&nodes[k]), index.push_back(k);
      if (const auto* creep = dynamic_cast<const Creep*>(fractures_[f].law.get())) {
        // The imposed slip rate on each node's tangent basis: the direction projected on it.
        const Eigen::VectorXd rate = creep->slipRate().evaluate(on);
        const int k = system_->blockSize();
        for (std::size_t i = 0; i < index.size(); ++i) {
          const ControlNode& node = *on[i];
          Eigen::Vector3d d = creep->direction();
          d -= d.dot(node.normal) * node.normal;
          if (!(d.norm() > 1e-6))
            throw InputError(
                (fs::path(caseDir_) / "constant" / "fractureProperties").string(),
                "fracture '" + fractures_[f].name + "': law creep's direction is normal to the " +
                    "fracture at the node at (" + formatNumber(node.position.x()) + ", " +
                    formatNumber(node.position.y()) +
                    (system_->dimension() == 3 ? ", " + formatNumber(node.position.z()) : "") +
                    "): it has no component along the fracture to slide in");
          d.normalize();
          imposed_[index[i]] = 1;
          for (int c = 0; c < k; ++c)
            imposedRate_[k * index[i] + c] =
                rate[static_cast<Eigen::Index>(i)] * d.dot(node.tangent[c]);
        }
        log << "Fracture " << fractures_[f].name << ": creep, slip rate imposed along ("
            << formatNumber(creep->direction().x()) << " " << formatNumber(creep->direction().y())
            << (system_->dimension() == 3 ? " " + formatNumber(creep->direction().z()) : "")
            << ")\n";
        continue;
      }
      const auto* law = dynamic_cast<const RateStateLaw*>(fractures_[f].law.get());
      FRICTION_ASSERT(law, "every fracture of a quasi-dynamic case has law rateState or creep");
      const RateStateLaw::Fields& F = law->fields();
      const Eigen::VectorXd a = F.a.evaluate(on), b = F.b.evaluate(on), L = F.L.evaluate(on),
                            f0 = F.f0.evaluate(on), V0 = F.V0.evaluate(on),
                            vi = F.initialV.evaluate(on);
      const double eta =
          F.radiationDamping >= 0 ? F.radiationDamping : shearModulus_[f] / (2 * F.shearWaveSpeed);
      for (std::size_t i = 0; i < index.size(); ++i) {
        const Eigen::Index j = static_cast<Eigen::Index>(i);
        RateState& r = rateLaws_[static_cast<std::size_t>(index[i])];
        r.a = a[j], r.b = b[j], r.L = L[j], r.f0 = f0[j], r.V0 = V0[j], r.eta = eta;
        r.evolution = F.aging ? StateEvolution::aging : StateEvolution::slip;
        initialSlipRate_[index[i]] = vi[j];
      }
      // creepSlipRate: the nodes where it is > 0 creep as law creep's (no state).
      if (!F.creepDirection.isZero()) {
        const Eigen::VectorXd rate = F.creepRate.evaluate(on);
        const int k = system_->blockSize();
        long creeping = 0;
        for (std::size_t i = 0; i < index.size(); ++i) {
          const double v = rate[static_cast<Eigen::Index>(i)];
          if (!(v > 0)) continue;
          const ControlNode& node = *on[i];
          Eigen::Vector3d d = F.creepDirection - F.creepDirection.dot(node.normal) * node.normal;
          if (!(d.norm() > 1e-6))
            throw InputError(
                (fs::path(caseDir_) / "constant" / "fractureProperties").string(),
                "fracture '" + fractures_[f].name + "': creepDirection is normal to the " +
                    "fracture at the node at (" + formatNumber(node.position.x()) + ", " +
                    formatNumber(node.position.y()) +
                    (system_->dimension() == 3 ? ", " + formatNumber(node.position.z()) : "") +
                    "): it has no component along the fracture to creep in");
          d.normalize();
          imposed_[index[i]] = 1;
          for (int c = 0; c < k; ++c) imposedRate_[k * index[i] + c] = v * d.dot(node.tangent[c]);
          ++creeping;
        }
        log << "Fracture " << fractures_[f].name << ": " << creeping << " of " << index.size()
            << " nodes creep (creepSlipRate > 0) along (" << formatNumber(F.creepDirection.x())
            << " " << formatNumber(F.creepDirection.y())
            << (system_->dimension() == 3 ? " " + formatNumber(F.creepDirection.z()) : "") << ")\n";
      }
      log << "Fracture " << fractures_[f].name << ": radiation damping eta " << eta << " Pa s/m"
          << (F.radiationDamping >= 0 ? ""
                                      : " (G/(2 c_s), G " + formatNumber(shearModulus_[f]) + " Pa)")
          << "\n";
    }
    // Measured on SEAS BP3-QD (README): P1's fault tractions kept the earthquake sequence years
    // off the benchmark's at 25 m cells, where P2 at 50 m (as many fault nodes) matched it.
    if (order_ == 1 && std::any_of(fractures_.begin(), fractures_.end(),
                                   [](const auto& f) { return f.law->rateAndState(); }))
      log << "Note: rate-and-state faults on P1 elements: the interevent times converge slowly "
             "with the cell size; elementOrder 2 is far more accurate for the same fault nodes "
             "(README, \"Benchmark: SEAS BP3-QD\")\n";
  }
  if (faultSeries_) {
    if (!rateState_)
      throw InputError((fs::path(caseDir_) / "system" / "controlDict").string(),
                       "faultOutput samples the steps of a quasi-dynamic run (law rateState, "
                       "timeIntegration quasiDynamic); this case has none: remove faultOutput");
    std::vector<std::string> names;
    for (const auto& f : fractures_) names.push_back(f.name);
    const std::size_t f = static_cast<std::size_t>(
        std::find(names.begin(), names.end(), faultSeries_->fracture()) - names.begin());
    faultSeries_->bind(nodes, split_.mesh.dim, system_->blockSize(), names, rateLaws_,
                       system_->splitSpace(), system_->weights(),
                       f < shearModulus_.size() ? shearModulus_[f] : 0.0, imposed_);
  }
  // The cells around each tip and junction end, for the stress the tables give there: those
  // holding a node of the split space at the tip's position (every copy of it; copies share
  // their coordinates exactly, P2 midpoints included).
  tipCells_.assign(nodes.size(), {});
  {
    const LagrangeSpace& space = system_->splitSpace();
    std::map<std::array<double, 3>, std::vector<std::size_t>> tipsAt;
    for (std::size_t k = 0; k < nodes.size(); ++k)
      if (nodes[k].tip) {
        const Point& x = space.point(nodes[k].plus);
        tipsAt[{x.x(), x.y(), x.z()}].push_back(k);
      }
    if (!tipsAt.empty())
      for (Index c = 0; c < space.numCells(); ++c)
        for (const Index node : space.cellNodes(c)) {
          const Point& x = space.point(node);
          const auto it = tipsAt.find({x.x(), x.y(), x.z()});
          if (it == tipsAt.end()) continue;
          for (const std::size_t k : it->second) tipCells_[k].push_back(c);
        }
  }
  // Effects that vary along the fractures (faultPressure's fields) are evaluated at the
  // control nodes once, here, and checked node by node.
  {
    std::vector<std::string> fractureNames;
    for (const auto& g : split_.fractures) fractureNames.push_back(g.name);
    // The fractures given a fluid pressure of their own (the rock's pore pressure leaves them).
    std::vector<char> ownPressure(fractureNames.size(), 0);
    for (std::size_t f = 0; f < fractureNames.size(); ++f)
      for (const auto& e : effects_) ownPressure[f] |= e->givesPressureOn(fractureNames[f]);
    const EffectContext context{split_,     nodes, fractureNames, log, &system_->splitAssembler(),
                                ownPressure};
    for (const auto& e : effects_) {
      e->bind(context);
      hasPressure_ |= e->givesFracturePressure();
    }
  }
  // The initial state that ΔCFS is measured against: the in-situ stress resolved on the
  // fractures and the fluid pressure at startTime (before any effect's state has advanced).
  if (hasPressure_ && n > 0) {
    const double t0 = time_->startTime();
    Eigen::VectorXd sn0 = Eigen::VectorXd::Zero(n),
                    tau0 = Eigen::VectorXd::Zero(system_->blockSize() * n);
    for (const auto& e : effects_) e->addFractureTraction(nodes, t0, sn0, tau0);
    initialSigmaNEffective_ = sn0 + fracturePressure(t0);
    initialTauNorm_.resize(n);
    const int kb = system_->blockSize();
    for (Eigen::Index k = 0; k < n; ++k) initialTauNorm_[k] = blockNorm(tau0.segment(kb * k, kb));
  }
  // γ has units of stress/length; its scale-free default is E over the mean fracture edge
  // length h (docs/method.md §4): then γβ and τ are of the same size for slips of order h·τ/E.
  const double h = meanFractureEdge();
  if (!gammaAbsolute_) gamma_ = h > 0 ? gammaRelative_ * youngScale_ / h : 1.0;
  if (gammaNGiven_ == GammaNGiven::relative)
    gammaN_ = h > 0 ? gammaNRelative_ * youngScale_ / h : 1.0;
  else if (gammaNGiven_ == GammaNGiven::sameAsGamma)
    gammaN_ = gamma_;
  unilateral_.resize(n);
  for (Eigen::Index k = 0; k < n; ++k)
    unilateral_[k] = fractures_[nodes[k].fracture].unilateral ? 1.0 : 0.0;
  // Gradient steps scale like (w/E)², w the length of the smallest lumped weight of Γ (the M
  // of the M-gradient): h for P1, h/3 at the vertices for P2 (Simpson) in 2D.
  if (n > 0) {
    double w = std::numeric_limits<double>::infinity();
    for (Eigen::Index k = 0; k < n; ++k)
      if (system_->freeMask()[k] > 0) w = std::min(w, system_->weights()[k]);
    // 3D: the weight is an area, its root the spacing; and a node is coupled to about six
    // neighbours on a surface against two along a curve, which makes J's Hessian several times
    // larger at the same spacing (on tests/regression/cases/faultInCube the fixed step diverges
    // from (√w/E)²/2 and converges at (√w/E)²/4): a sixth of (√w/E)², so that alphaRelative's
    // defaults keep a margin of about two, as in 2D. P2 in 3D takes a twentieth of that: its
    // tractions come from the consistent mass of Γ (docs/method.md §4), whose small
    // eigenvalues enlarge J's Hessian (measured: the fixed step diverges from alphaRelative
    // 0.2 on faultInCube and 0.5 on the penny crack a/4 with the P1 scale, and converges at
    // 0.1 and 0.3).
    if (split_.mesh.dim == 3) w = std::sqrt(w / (order_ == 2 ? 120 : 6));
    if (std::isfinite(w)) optimizer_->setStepScale(std::pow(w / youngScale_, 2));
  }
  slip_ = Eigen::VectorXd::Zero(system_->blockSize() * n);

  const auto& f = system_->factorization();
  log << "Split mesh: " << split_.mesh.numPoints() << " points, " << split_.mesh.numCells()
      << (split_.mesh.dim == 3 ? " tetrahedra, " : " triangles, ")
      << system_->unsplitSpace().numDofs() << " dofs (P" << order_ << "), " << n
      << " fracture control nodes\n";
  // P1 simplices lock for nearly incompressible material (the discrete divergence-free
  // space is too small): the displacement comes out too small. P2 copes far better.
  if (order_ == 1 && !materials_->planeStress()) {
    if (materials_->uniform()) {
      if (materials_->maxPoissonRatio() > 0.45)
        log << "Warning: nu = " << std::setprecision(12) << materials_->maxPoissonRatio()
            << " with P1 elements: P1 locks for nearly incompressible material (displacements "
               "and slip come out too small); use elementOrder 2\n";
    } else {
      for (const MaterialMap::Region& r : materials_->regions()) {
        const double nu = materials_->materials()[r.material].poissonRatio();
        if (r.cells > 0 && nu > 0.45)
          log << "Warning: nu = " << std::setprecision(12) << nu << " in region "
              << (r.name.empty() ? "region" + std::to_string(r.number) : r.name)
              << " with P1 elements: P1 locks for nearly incompressible material (displacements "
                 "and slip come out too small there); use elementOrder 2\n";
      }
    }
  }
  // A part that only fractures hold factors fine (the unsplit body is whole), but where its
  // fractures cannot carry its load it slides without bound: say so before the run.
  for (const FloatingPart& p : floating_)
    if (p.heldThroughFracture)
      log << "Note: the part of the mesh " << p.describe()
          << " touches no Dirichlet patch: only fracture(s) " << joinWords(p.fractures)
          << " hold it; where they cannot carry its load (frictionless, tension) it slides "
             "without bound"
          << (opening_ ? ", and where they open (contact unilateral) entirely it is free" : "")
          << "\n";
  if (int held = system_->numHeldOnDirichlet())
    log << "Note: " << held
        << " fracture node(s) lie on a Dirichlet patch: their jump is held at zero\n";
  if (int partly = system_->numPartlyHeldOnDirichlet())
    log << "Note: " << partly
        << " fracture node(s) lie on a roller patch: their jump is held along the fixed "
           "direction only\n";
  log << "Assemblies: " << system_->numAssemblies() << " stiffness matri"
      << (system_->numAssemblies() == 1 ? "x" : "ces")
      << (n == 0 ? " (no fracture: no split stiffness, no control loop)" : "") << "\n";
  if (system_->ownCells() > 0)
    log << "Stiffness: each of the " << parallel::size() << " ranks assembled its own cells ("
        << system_->ownCells() << " of " << system_->unsplitSpace().numCells()
        << " on rank 0); the factorisation adds them\n";
  log << "Factorisation: " << toString(status) << " (" << f.backend() << ", "
      << std::setprecision(3) << f.factorSeconds() << " s)\n";
  // An iterative solver: what it set up and what its check solve measured.
  if (!f.analysis().iterativeNote.empty()) log << f.analysis().iterativeNote << "\n";
  if (!f.analysis().problem.empty() && f.iterative())
    log << "Linear solver amg: " << f.analysis().problem << "\n";
  // What the factor costs: at 10⁶ unknowns in 3D it sets the run's time and memory.
  if (const FactorAnalysis& a = f.analysis(); a.entries > 0) {
    std::ostringstream line;
    line << std::setprecision(3) << "Factor: " << a.ordering << " ordering"
         << (a.orderingChoice.empty() ? "" : " (" + a.orderingChoice + ")") << ", " << a.entries
         << " entries (" << a.bytes / 1e9 << " GB of values), " << a.flops << " flops"
         << (f.schurComplement().size() > 0 && f.schurSolves() == 0 ? ", jump unknowns last" : "");
    if (a.numericSeconds > 0) {
      line << "; " << a.analysisSeconds << " s ordering and analysis, " << a.numericSeconds
           << " s numeric";
      if (a.complementSeconds > 0) line << ", " << a.complementSeconds << " s the complement";
    }
    // A distributed factor: how many ranks share it and what it took on each.
    if (a.rankMemoryMax > 0)
      line << "; " << a.ranks << (a.ranks == 1 ? " rank, " : " ranks, ") << a.rankMemoryMax / 1e9
           << " GB on the largest rank, " << a.memoryTotal / 1e9 << " GB in all";
    log << line.str() << "\n";
    // MUMPS's smaller factors: what they kept and wrote (its INFOG(29), INFOG(35), RINFOG(14),
    // RINFOG(16)).
    if (a.lowRank > 0 && a.fullRankEntries > 0) {
      std::ostringstream blr;
      blr << std::setprecision(3) << "Low-rank factor (BLR, dropping tolerance " << a.lowRank
          << "): " << a.entries << " entries of the full-rank " << a.fullRankEntries << " ("
          << 100.0 * a.entries / a.fullRankEntries << " %), " << a.lowRankFlops << " flops of "
          << a.flops << "; its back-substitutions err by about the tolerance (README \"Running in "
          << "parallel\"); MUMPS estimated " << a.estimatedLowRank / 1e9
          << " GB of memory with it, " << a.estimatedInCore / 1e9 << " GB in core full rank\n";
      log << blr.str();
    }
    if (!a.outOfCoreChoice.empty()) log << "Factor: " << a.outOfCoreChoice << "\n";
    if (!a.outOfCoreDir.empty()) {
      std::ostringstream ooc;
      ooc << std::setprecision(3) << "Out-of-core factor: " << a.outOfCoreBytes / 1e9
          << " GB written to " << a.outOfCoreDir
          << " (deleted at the end of the run); MUMPS estimated " << a.estimatedOutOfCore / 1e9
          << " GB of memory out of core, " << a.estimatedInCore / 1e9 << " GB in core\n";
      log << ooc.str();
    }
  }
  // Condensed Newton's S: a by-product of the factorisation, or blocks of solves where the
  // backend cannot deliver it.
  if (status == FactorStatus::ok && f.schurComplement().size() > 0)
    log << "Interface operator: " << f.schurComplement().rows() << " jump unknowns, "
        << (f.schurSolves() == 0
                ? std::string("from the factorisation")
                : std::to_string(f.schurSolves()) + " back-substitutions in blocks (" +
                      (f.schurFallbackReason().empty()
                           ? f.backend() + " cannot deliver it with the factorisation"
                           : f.schurFallbackReason()) +
                      "), " + formatSeconds(f.schurSeconds()))
        << "\n";
  if (!optimizerChoice_.empty()) log << optimizerChoice_ << "\n";
  printSettings(log);
  log << "\n";
}

std::string FloatingPart::describe() const {
  std::ostringstream s;
  s << "around (" << std::setprecision(4) << point.x() << ", " << point.y();
  if (dim == 3) s << ", " << point.z();
  s << "), " << cells
    << (dim == 3 ? (cells == 1 ? " tetrahedron" : " tetrahedra")
                 : (cells == 1 ? " triangle" : " triangles"));
  return s.str();
}

double FrictionCase::meanFractureEdge() const {
  const auto& nodes = system_->controlNodes();
  double sum = 0;
  long count = 0;
  if (split_.mesh.dim == 2) {
    // Consecutive control nodes of a fracture are a mesh edge apart (P1) or half of one (P2).
    for (std::size_t k = 1; k < nodes.size(); ++k)
      if (nodes[k].fracture == nodes[k - 1].fracture) {
        sum += (nodes[k].x - nodes[k - 1].x).norm() * order_;
        ++count;
      }
  } else {
    // Every edge of the fault triangles once.
    for (const auto& g : split_.fractures) {
      std::set<std::pair<Index, Index>> edges;
      for (const auto& t : g.triangles)
        for (int a = 0; a < 3; ++a) edges.insert(std::minmax(t[a], t[(a + 1) % 3]));
      for (const auto& [a, b] : edges) {
        sum += (split_.mesh.points[a] - split_.mesh.points[b]).norm();
        ++count;
      }
    }
  }
  return count > 0 ? sum / count : 0.0;
}

namespace {

/// Union-find over node numbers: the connected parts of a triangle mesh.
struct Parts {
  std::vector<Index> up;
  explicit Parts(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), 0); }
  Index root(Index i) {
    while (up[i] != i) i = up[i] = up[up[i]];
    return i;
  }
  void join(Index a, Index b) { up[root(a)] = root(b); }
};

}  // namespace

void FrictionCase::findFloatingParts() {
  // Parts of the split mesh (a fracture separates its two sides; a tip joins them) and of
  // the unsplit mesh (through origin); a part is held when a node of it lies on a Dirichlet
  // patch.
  const Mesh& m = split_.mesh;
  const std::size_t np = m.points.size();
  Parts split(np), whole(np);
  for (Index t = 0; t < m.numCells(); ++t)
    for (int a = 1, n = m.verticesPerCell(); a < n; ++a) {
      const auto tri = m.cell(t);
      split.join(tri[0], tri[a]);
      whole.join(split_.origin.empty() ? tri[0] : split_.origin[tri[0]],
                 split_.origin.empty() ? tri[a] : split_.origin[tri[a]]);
    }
  std::vector<char> fixedLabel;
  for (const auto& p : bcs_->patches())
    if (p.type == BoundaryConditions::Type::fixedDisplacement) {
      if (p.label >= static_cast<int>(fixedLabel.size())) fixedLabel.resize(p.label + 1, 0);
      fixedLabel[p.label] = 1;
    }
  std::vector<char> held(np, 0), wholeHeld(np, 0);
  for (Index e = 0; e < m.numFacets(); ++e) {
    const int l = m.facetLabel[e];
    if (l < 0 || l >= static_cast<int>(fixedLabel.size()) || !fixedLabel[l]) continue;
    for (Index v : m.facet(e)) {
      held[split.root(v)] = 1;
      wholeHeld[whole.root(split_.origin.empty() ? v : split_.origin[v])] = 1;
    }
  }
  struct Sum {
    int cells = 0;
    Point centre = Point::Zero();
    double measure = 0;
  };
  const auto vertexSum = [&m](Index c) {
    Point x = Point::Zero();
    for (Index v : m.cell(c)) x += m.points[v];
    return x;
  };
  const int nv = m.verticesPerCell();
  std::map<Index, Sum> sums;
  Point lo = Point::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& x : m.points) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  diameter_ = m.points.empty() ? 0.0 : (hi - lo).norm();
  for (Index t = 0; t < m.numCells(); ++t) {
    const Index r = split.root(m.cellVertex(t, 0));
    if (held[r]) continue;
    Sum& s = sums[r];
    const double a = std::abs(m.signedMeasure(t));
    ++s.cells;
    s.centre += a * vertexSum(t) / nv;
    s.measure += a;
  }
  floating_.clear();
  std::map<Index, std::size_t> index;
  for (auto& [r, s] : sums) {
    FloatingPart p;
    p.dim = m.dim;
    p.cells = s.cells;
    const Point centre = s.measure > 0 ? Point(s.centre / s.measure) : Point::Zero();
    double best = std::numeric_limits<double>::infinity();
    for (Index t = 0; t < m.numCells(); ++t) {
      if (split.root(m.cellVertex(t, 0)) != r) continue;
      const Point c = vertexSum(t) / nv;
      if ((c - centre).norm() < best) best = (c - centre).norm(), p.point = c;
    }
    p.heldThroughFracture = wholeHeld[whole.root(split_.origin.empty() ? r : split_.origin[r])];
    index[r] = floating_.size();
    floating_.push_back(p);
  }
  for (const auto& g : split_.fractures)
    for (const auto* side : {&g.plus, &g.minus})
      for (Index v : *side) {
        const auto it = index.find(split.root(v));
        if (it == index.end()) continue;
        auto& names = floating_[it->second].fractures;
        if (std::find(names.begin(), names.end(), "'" + g.name + "'") == names.end())
          names.push_back("'" + g.name + "'");
      }
}

std::string FrictionCase::continuation() const {
  std::string how = "continue with startFrom latestTime: from time " +
                    time_->timeName(lastWritten_) + ", the last one written";
  if (lastTime_ > lastWritten_)
    how += " (the steps after it, up to time " + time_->timeName(lastTime_) +
           ", were not written and are computed again)";
  return how;
}

std::string FrictionCase::factorFailureDiagnosis() const {
  const SparseFactor& f = system_->factorization();
  std::ostringstream s;
  s << std::setprecision(4) << "the stiffness matrix could not be factored ("
    << toString(factorStatus_) << "): ";
  // 0. The backend said why (mumps: memory, the out-of-core folder).
  if (factorStatus_ == FactorStatus::failed && !f.analysis().problem.empty()) {
    s << f.backend() << ": " << f.analysis().problem;
    return s.str();
  }
  // 1. Scaling: entries beyond double precision (the case's units).
  if (!std::isfinite(f.maxAbsEntry()) || f.maxAbsEntry() > 1e250) {
    s << "its entries overflow double precision (largest |K_ij| " << f.maxAbsEntry()
      << ", Young's modulus E = " << materials_->maxYoungModulus()
      << " Pa); express the case in units that keep E and the stresses well below 1e300 "
         "(e.g. MPa or GPa for rock)";
    return s.str();
  }
  // 2. Parts that nothing holds: rigid-body motion.
  std::vector<const FloatingPart*> loose;
  for (const FloatingPart& p : floating_)
    if (!p.heldThroughFracture) loose.push_back(&p);
  if (!loose.empty()) {
    s << loose.size() << " part" << (loose.size() == 1 ? "" : "s") << " of the mesh "
      << (loose.size() == 1 ? "touches" : "touch")
      << " no Dirichlet patch and can move as a rigid body:";
    for (const FloatingPart* p : loose) s << " the part " << p->describe() << ";";
    s << " fix a patch of each (0/D, type fixedDisplacement)";
    return s.str();
  }
  // 3. Held, but by rollers that leave a direction free.
  const Mesh& m = split_.mesh;
  const std::vector<std::string> free = freeComponents();
  std::vector<std::string> fixed;
  for (int c = 0; c < m.dim; ++c)
    if (std::find(free.begin(), free.end(), std::string(1, "xyz"[c])) == free.end())
      fixed.push_back(std::string(1, "xyz"[c]));
  if (!free.empty()) {
    s << "every part touches a Dirichlet patch, but they fix only the " << joinWords(fixed)
      << " component" << (fixed.size() == 1 ? "" : "s") << ": the body can slide along "
      << joinWords(free) << "; fix that component somewhere (0/D, components)";
    return s.str();
  }
  // 4. Conditioning: the worst-shaped cell (longest edge over its smallest height), nearly
  // incompressible material.
  double worst = 0;
  Point where = Point::Zero();
  for (Index t = 0; t < m.numCells(); ++t) {
    const auto cell = m.cell(t);
    const int nv = m.verticesPerCell();
    double aspect = 0;
    const double measure = std::abs(m.signedMeasure(t));
    if (m.dim == 2) {
      double longest = 0;
      for (int a = 0; a < 3; ++a)
        longest =
            std::max(longest, (m.points[cell[a]] - m.points[cell[(a + 1) % 3]]).squaredNorm());
      aspect = measure > 0 ? longest / (2 * measure) : std::numeric_limits<double>::infinity();
    } else {
      // Smallest height 3V / (largest face area).
      double longest = 0, face = 0;
      for (int a = 0; a < nv; ++a)
        for (int b = a + 1; b < nv; ++b)
          longest = std::max(longest, (m.points[cell[a]] - m.points[cell[b]]).norm());
      for (int skip = 0; skip < nv; ++skip) {
        Point v[3];
        for (int a = 0, j = 0; a < nv; ++a)
          if (a != skip) v[j++] = m.points[cell[a]];
        face = std::max(face, 0.5 * (v[1] - v[0]).cross(v[2] - v[0]).norm());
      }
      aspect =
          measure > 0 ? longest * face / (3 * measure) : std::numeric_limits<double>::infinity();
    }
    if (aspect > worst) {
      worst = aspect;
      where = Point::Zero();
      for (Index v : cell) where += m.points[v];
      where /= nv;
    }
  }
  s << "every part is held, so the matrix is singular to working precision through its "
       "conditioning (smallest pivot ratio "
    << f.minPivotRatio() << ", tolerance " << f.pivotTolerance() << "): the worst "
    << (m.dim == 3 ? "tetrahedron" : "triangle") << ", at (" << where.x() << ", " << where.y();
  if (m.dim == 3) s << ", " << where.z();
  s << "), has aspect ratio (longest edge / height) " << worst << ", nu = " << std::setprecision(12)
    << materials_->maxPoissonRatio() << "; remesh without slivers (aspect ratio below ~1e6)"
    << (materials_->maxPoissonRatio() > 0.49 ? " and keep nu below 0.5 by a margin" : "");
  return s.str();
}

Eigen::VectorXd FrictionCase::loadVector(double t) const {
  const LagrangeSpace& space = system_->splitSpace();
  Eigen::VectorXd F = bcs_->neumannLoad(space, t);
  for (const auto& e : effects_) e->addLoad(system_->splitAssembler(), t, F);
  return F;
}

std::string FrictionCase::loadFields(double t, const Eigen::VectorXd& pressure) const {
  // A patch counts where it loads at all: a value other than zero at some time of its table.
  const auto loads = [](const TimeFunction& f) {
    if (!f.isConstant()) return true;
    const std::vector<double> v = f(0);
    return std::any_of(v.begin(), v.end(), [](double x) { return x != 0; });
  };
  const auto magnitude = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x * x;
    return std::sqrt(s);
  };
  bool displacement = false, traction = false;
  double maxU = 0, maxT = 0;
  for (const auto& p : bcs_->patches()) {
    if (p.type == BoundaryConditions::Type::free || !loads(p.value)) continue;
    const double m = magnitude(p.value(t));
    if (p.type == BoundaryConditions::Type::fixedDisplacement) {
      displacement = true;
      maxU = std::max(maxU, m);
    } else {
      traction = true;
      maxT = std::max(maxT, m);
    }
  }
  std::ostringstream s;
  s << std::setprecision(4);
  if (displacement) s << "  loadDisplacement " << maxU << " m";
  if (traction) s << "  loadTraction " << maxT << " Pa";
  if (hasPressure_ && pressure.size() > 0) {
    // Mean over the fracture surface (the nodes' lumped weights), held nodes included.
    const Eigen::VectorXd& w = system_->weights();
    const double area = w.sum();
    s << "  meanPressure " << (area > 0 ? w.dot(pressure) / area : pressure.mean()) << " Pa";
  }
  return s.str();
}

Eigen::VectorXd FrictionCase::fracturePressure(double t) const {
  std::vector<std::string> names;
  for (const auto& g : split_.fractures) names.push_back(g.name);
  Eigen::VectorXd p = Eigen::VectorXd::Zero(system_->size());
  for (const auto& e : effects_) e->addFracturePressure(system_->controlNodes(), names, t, p);
  return p;
}

void FrictionCase::prepareOutput(bool overwrite, std::ostream& log,
                                 const std::string& overwriteHint) {
  outputPrepared_ = true;
  overwriteHint_ = overwriteHint;
  std::vector<std::string> earlier;
  for (const auto& [t, name] : timeFolders(caseDir_))
    if (t > time_->startTime()) earlier.push_back(name);
  if (overwrite) {
    // Only what the solver wrote is removed: every folder is checked before any is (on every
    // rank, which all see the same folders, so that all refuse together).
    for (const std::string& name : earlier) {
      const std::string foreign =
          TimeFolder::notWrittenBySolver((fs::path(caseDir_) / name).string());
      if (!foreign.empty())
        throw InputError((fs::path(caseDir_) / name).string(),
                         "not removed by " + overwriteHint_ +
                             ": this folder under a time's name was not written by "
                             "frictionSolver (" +
                             foreign +
                             "), and what the solver did not write is never removed; move it "
                             "out of the case, then run again");
    }
    // Several ranks: rank 0 alone touches the files (the others wait at a barrier in main).
    if (!parallel::isMaster()) return;
    for (const std::string& name : earlier) {
      // Out of sight first (one rename), then removed: a run killed in between leaves a
      // hidden leftover that the next run removes, never a time folder half removed, which
      // would look like a folder the solver did not write.
      std::error_code ec;
      const fs::path doomed = fs::path(caseDir_) / ("." + name + ".old");
      fs::remove_all(doomed, ec);
      if (!ec) fs::rename(fs::path(caseDir_) / name, doomed, ec);
      if (!ec) fs::remove_all(doomed, ec);
      if (ec)
        throw OutputError((fs::path(caseDir_) / name).string(),
                          "-overwrite cannot remove this time folder (" + ec.message() + ")");
    }
    trimOutputs([](const std::string&) { return false; }, true, log);
    log << "-overwrite: removed the earlier run's outputs ("
        << (earlier.empty() ? std::string("no time folder") : "time folders " + listNames(earlier))
        << ", VTK files, postProcessing/convergence.dat)\n";
    return;
  }
  if (earlier.empty() || time_->startFromLatest()) return;
  throw InputError(caseDir_,
                   "time folders of an earlier run exist after startTime " +
                       formatNumber(time_->startTime()) + ": " + listNames(earlier) +
                       "; frictionSolver does not overwrite them. Either continue that run with "
                       "'startFrom latestTime;' in system/controlDict, or start again with '" +
                       overwriteHint_ +
                       "', which first removes them, VTK/ and "
                       "postProcessing/convergence.dat");
}

void FrictionCase::trimOutputs(const std::function<bool(const std::string&)>& keep, bool fresh,
                               std::ostream& log, double limit) {
  if (!parallel::isMaster()) return;  // rank 0 writes every output file
  TimeFolder::removeLeftovers(caseDir_);
  std::vector<std::string> fractureNames;
  for (const auto& g : split_.fractures) fractureNames.push_back(g.name);
  // The VTK files carry the case folder's name. A case continued in a copy under another name
  // (cp -r a b) has its earlier times' files named after 'a': a restart goes on under that
  // name, so that ParaView's series (one .pvd) stays whole.
  std::string seriesName;
  {
    const VtkSeries own(caseDir_);
    std::error_code ec;
    std::vector<std::string> others;
    if (!fs::exists(own.pvdPath(), ec))
      for (const auto& e : fs::directory_iterator(fs::path(caseDir_) / "VTK", ec))
        if (e.path().extension() == ".pvd" && e.is_regular_file(ec))
          others.push_back(e.path().stem().string());
    std::sort(others.begin(), others.end());
    if (!fresh && others.size() == 1) {
      seriesName = others[0];
      log << "VTK: the earlier times are in VTK/" << seriesName << ".pvd, named after the folder '"
          << seriesName << "' this case was run in (this one is '" << own.caseName()
          << "'): the series goes on under that name, so ParaView shows one series\n";
    } else if (!others.empty()) {
      std::vector<std::string> files;
      for (const std::string& o : others) files.push_back("VTK/" + o + ".pvd");
      log << "Note: VTK/ holds " << joinWords(files) << " of a folder of another name, left as "
          << (others.size() == 1 ? "it is" : "they are") << "; this run's series is VTK/"
          << own.caseName() << ".pvd\n";
    }
  }
  auto vtk = std::make_unique<VtkSeries>(caseDir_, seriesName,
                                         time_->vtkBinary() ? VtkFormat::binary : VtkFormat::ascii);
  vtk->resume(keep, fractureNames, time_->writePrecision());
  if (time_->writeVTK()) vtk_ = std::move(vtk);

  const fs::path post = fs::path(caseDir_) / "postProcessing";
  std::error_code ec;
  fs::create_directories(post, ec);
  if (ec || !fs::is_directory(post))
    throw OutputError(post.string(),
                      "cannot create the folder" +
                          (ec ? " (" + ec.message() + ")" : std::string(": a file has its name")));
  removeTemporaryFiles(post.string());
  // The history of the steps up to the restart time, as the run that wrote them left it:
  // its lines start with the time's name (which reads back as that time).
  const std::string path = (post / "convergence.dat").string();
  std::string text = "# time iteration J relResidual stepNorm\n";
  if (!fresh) {
    std::istringstream in;
    if (fs::exists(path)) {
      InputFileRole role;  // a FIFO put in its place must not block the restart
      role.what = "the convergence history frictionSolver writes";
      in.str(readInputFile(path, role));
    }
    std::string kept;
    for (std::string line; std::getline(in, line);) {
      const std::string first = line.substr(0, line.find(' '));
      if (line.empty() || line[0] == '#' || keep(first)) kept += line + "\n";
    }
    if (!kept.empty()) text = kept;
  }
  writeTextAtomic(path, text);
  history_ = std::make_unique<AppendFile>(path, false);

  // Per fracture, the rupture's history (history_<name>.dat): trimmed by the same rule.
  fractureHistories_.clear();
  for (const auto& g : split_.fractures) {
    const std::string file = (post / ("history_" + g.name + ".dat")).string();
    std::string kept;
    if (!fresh && fs::exists(file)) {
      InputFileRole role;  // a FIFO put in its place must not block the restart
      role.what = "the fracture history frictionSolver writes";
      std::istringstream in(readInputFile(file, role));
      for (std::string line; std::getline(in, line);) {
        const std::string first = line.substr(0, line.find(' '));
        if (!line.empty() && line[0] != '#' && keep(first)) kept += line + "\n";
      }
    }
    writeTextAtomic(file, historyHeader() + kept);
    fractureHistories_.push_back(std::make_unique<AppendFile>(file, false));
  }
  // The fault outputs of a quasi-dynamic run (faultOutput): rows up to the restart's time.
  if (faultSeries_) faultSeries_->open(caseDir_, fresh, limit);
}

std::string FrictionCase::historyHeader() const {
  return split_.mesh.dim == 3
             ? "# time slippingArea maxSlip moment magnitude\n"
               "# per step: slippingArea [m2] of the nodes in state slip, maxSlip [m] the largest "
               "|slip|, moment M0 = G * integral of |slip| dA [N m], magnitude Mw = (2/3) "
               "(log10 M0 - 9.1) (nan while M0 = 0)\n"
             : "# time slippingLength maxSlip moment\n"
               "# per step: slippingLength [m] of the nodes in state slip, maxSlip [m] the "
               "largest |slip|, moment M0 = G * integral of |slip| ds [N m per m out of the "
               "plane]\n";
}

std::string FrictionCase::historyLine(std::size_t f, double t) const {
  const auto& nodes = system_->controlNodes();
  const int kb = system_->blockSize();
  double slipping = 0, maxSlip = 0, moment = 0;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    if (nodes[k].fracture != static_cast<int>(f)) continue;
    const double w = system_->weights()[static_cast<Eigen::Index>(k)];
    const double slip = blockNorm(slip_.segment(kb * static_cast<Eigen::Index>(k), kb));
    if (nodeState(static_cast<Eigen::Index>(k)) == "slip") slipping += w;
    maxSlip = std::max(maxSlip, slip);
    moment += shearModulus_[f] * slip * w;
  }
  std::ostringstream line;
  line.precision(time_->writePrecision());
  line << time_->timeName(t) << " " << slipping << " " << maxSlip << " " << moment;
  if (split_.mesh.dim == 3) {
    // Hanks & Kanamori (1979): Mw = (2/3)(log10 M0 − 9.1), M0 in N m.
    if (moment > 0)
      line << " " << 2.0 / 3.0 * (std::log10(moment) - 9.1);
    else
      line << " nan";
  }
  line << "\n";
  return line.str();
}

long FrictionCase::restart(std::ostream& log) {
  // The newest time folder that is complete: it has a state file (a folder appears only
  // whole, TimeFolder.hpp; a half-written one is still named .<time>.partial).
  const auto folders = timeFolders(caseDir_);
  std::string folder;
  double folderTime = time_->startTime();
  for (const auto& [t, name] : folders)
    if (fs::exists(fs::path(caseDir_) / name / "uniform" / "frictionState")) {
      folder = name;
      folderTime = std::max(folderTime, t);
    }
  // The run writes after that time: a folder there that the solver did not write (a user's,
  // under a time's name) would be replaced. Nothing of the user's is removed: refused.
  std::vector<std::string> foreign, why;
  for (const auto& [t, name] : folders)
    if (t > folderTime) {
      const std::string reason =
          TimeFolder::notWrittenBySolver((fs::path(caseDir_) / name).string());
      if (reason.empty()) continue;
      foreign.push_back(name);
      why.push_back(name + ": " + reason);
    }
  if (!foreign.empty())
    throw InputError(
        (fs::path(caseDir_) / foreign[0]).string(),
        "startFrom latestTime: time folder" + std::string(foreign.size() > 1 ? "s " : " ") +
            listNames(foreign) + " after " +
            (folder.empty() ? "startTime " + formatNumber(time_->startTime())
                            : "the newest complete time folder " + folder) +
            (foreign.size() > 1 ? " were" : " was") + " not written by frictionSolver (" +
            joinWords(why) + "); the run would write its times over " +
            (foreign.size() > 1 ? "them" : "it") +
            ", and what the solver did not write is never removed or replaced: move " +
            (foreign.size() > 1 ? "them" : "it") + " out of the case, then run again");
  if (folder.empty()) {
    log << "startFrom latestTime: no complete time folder yet, starting at startTime\n";
    trimOutputs([](const std::string&) { return false; }, true, log);
    return 1;
  }
  const std::string statePath =
      (fs::path(caseDir_) / folder / "uniform" / "frictionState").string();
  const Dictionary st = Dictionary::read(statePath, DictionaryLimits::dataFile());
  // k values per fracture node (k = 1 in 2D), node-major as writeTimeFolder() writes them.
  const std::vector<double> slip = st.getScalarList("slip");
  const std::vector<double> beta = st.getScalarList("lastIncrement");
  const int k = system_->blockSize();
  const Eigen::Index expected = k * system_->size();
  if (static_cast<Eigen::Index>(slip.size()) != expected || beta.size() != slip.size())
    st.fail("slip", "key 'slip': " + std::to_string(slip.size()) + " values, expected " +
                        (k == 1 ? std::string("one") : std::to_string(k)) +
                        " per "
                        "fracture node (" +
                        std::to_string(expected) +
                        "): the mesh or element "
                        "order changed since this folder was written");
  const long step = st.getInt("step", Bounds::nonNegative());
  const double t0 = st.getScalar("time");
  std::vector<double> opening;
  if (!opening_ && st.found("opening"))
    st.fail("opening",
            "key 'opening': this folder was written by a run whose fractures could open "
            "(contact unilateral), and none may now: restore contact unilateral in "
            "constant/fractureProperties, or start again (" +
                overwriteHint_ + ")");
  if (opening_) {
    if (!st.found("opening"))
      throw InputError(st.location(),
                       "no key 'opening': this folder was written by a run whose fractures "
                       "could not open (contact unilateral in constant/fractureProperties "
                       "changed since)");
    opening = st.getScalarList("opening");
    if (static_cast<Eigen::Index>(opening.size()) != system_->size())
      st.fail("opening", "key 'opening': " + std::to_string(opening.size()) +
                             " values, expected one per fracture node (" +
                             std::to_string(system_->size()) + ")");
  }
  // Rate-and-state faults: ψ and the last slip rates; the integrator's state.
  std::vector<double> psi, rates;
  if (rateState_) {
    if (!st.found("psi"))
      throw InputError(st.location(),
                       "no key 'psi': this folder was written by a run without rate-and-state "
                       "faults; start again (" +
                           overwriteHint_ + ")");
    psi = st.getScalarList("psi");
    rates = st.getScalarList("slipRate");
    if (static_cast<Eigen::Index>(psi.size()) != system_->size() ||
        static_cast<Eigen::Index>(rates.size()) != system_->blockSize() * system_->size())
      st.fail("psi", "key 'psi': " + std::to_string(psi.size()) +
                         " values, expected one per fracture node (" +
                         std::to_string(system_->size()) + ")");
  } else if (st.found("psi")) {
    st.fail("psi",
            "key 'psi': this folder was written by a run with rate-and-state faults (law "
            "rateState), and none are now; start again (" +
                overwriteHint_ + ")");
  }
  if (timeIntegrator_->hasState()) {
    if (!st.isDict("integrator"))
      throw InputError(st.location(),
                       "no 'integrator' state: this folder was written by a run "
                       "with another timeIntegration; start again (" +
                           overwriteHint_ + ")");
    timeIntegrator_->readState(st.subDict("integrator"));
    if (faultSeries_ && st.isDict("faultOutput"))
      faultSeries_->readState(st.subDict("faultOutput"));
  } else if (st.found("integrator")) {
    st.fail("integrator",
            "'integrator': this folder was written by a run with timeIntegration "
            "quasiDynamic; restore it, or start again (" +
                overwriteHint_ + ")");
  }
  // The laws' state: the slip path of friction that weakens.
  std::vector<double> path;
  if (!weakening_ && st.found("slipPath"))
    st.fail("slipPath",
            "key 'slipPath': this folder was written by a run whose friction weakened with slip "
            "(law slipWeakening), and none does now: restore the law in "
            "constant/fractureProperties, or start again (" +
                overwriteHint_ + ")");
  if (weakening_) {
    if (!st.found("slipPath"))
      throw InputError(st.location(),
                       "no key 'slipPath': this folder was written by a run without friction "
                       "that weakens (law slipWeakening in constant/fractureProperties changed "
                       "since); start again (" +
                           overwriteHint_ + ")");
    path = st.getScalarList("slipPath");
    if (static_cast<Eigen::Index>(path.size()) != system_->size())
      st.fail("slipPath", "key 'slipPath': " + std::to_string(path.size()) +
                              " values, expected one per fracture node (" +
                              std::to_string(system_->size()) + ")");
  }
  // The effects' states (faultPressure's computed diffusion), as writeTimeFolder() wrote them.
  const Dictionary* effectStates = st.findDict("effects");
  for (const auto& e : effects_) {
    if (!e->hasState()) continue;
    if (!effectStates || !effectStates->isDict(e->name()))
      throw InputError(st.location(),
                       "no state of effect '" + e->name() + "' (effects/" + e->name() +
                           "): this folder was written by a run without it; start again "
                           "(frictionSolver -overwrite)");
    e->readState(effectStates->subDict(e->name()), t0);
  }
  if (st.found("linearSolver")) (void)st.getWord("linearSolver");  // setup() took it
  // The evaluation of the step that wrote the folder, for a first step that reuses it.
  std::optional<Evaluation> restore;
  if (const Dictionary* e = st.findDict("restore")) {
    const std::vector<double> s0 = e->getScalarList("slip"), b0 = e->getScalarList("control");
    const Eigen::Index controls = expected + static_cast<Eigen::Index>(opening.size());
    if (static_cast<Eigen::Index>(s0.size()) != expected)
      e->fail("slip", "key 'slip': " + std::to_string(s0.size()) + " values, expected " +
                          std::to_string(expected));
    if (static_cast<Eigen::Index>(b0.size()) != controls)
      e->fail("control", "key 'control': " + std::to_string(b0.size()) + " values, expected " +
                             std::to_string(controls));
    restore = Evaluation{};
    restore->time = e->getScalar("time");
    restore->slip = Eigen::Map<const Eigen::VectorXd>(s0.data(), expected);
    restore->beta = Eigen::Map<const Eigen::VectorXd>(b0.data(), controls);
    // Friction that weakens: its slip path at the step's start and Newton's patch stiffness
    // (without them, a folder of a run whose law did not weaken, the first step is solved).
    if (weakening_ && e->found("slipPath")) {
      const std::vector<double> p0 = e->getScalarList("slipPath");
      if (static_cast<Eigen::Index>(p0.size()) != system_->size())
        e->fail("slipPath", "key 'slipPath': " + std::to_string(p0.size()) + " values, expected " +
                                std::to_string(system_->size()));
      restore->path = Eigen::Map<const Eigen::VectorXd>(p0.data(), system_->size());
      if (e->found("tangentStiffness"))
        restore->tangentStiffness = e->getScalar("tangentStiffness");
      restore->stiffnessComponents = e->getIntOr("stiffnessComponents", 0);
    } else if (weakening_) {
      restore.reset();
    }
    e->markAllRead();
  }
  st.checkAllRead();
  // The folder's name must be the time its state records (to the digits of the name): a
  // folder copied or renamed to a later name would restart an earlier state there, compute
  // the times in between again and write over their folders.
  if (!nameReadsAs(folder, t0, time_->timePrecision()))
    throw InputError(statePath,
                     "startFrom latestTime: this state is of time " + formatNumber(t0) + " (step " +
                         std::to_string(step) + "), not of its folder's time " + folder +
                         ": the folder was copied or renamed, and a restart from it would "
                         "compute again the times after " +
                         formatNumber(t0) + " and write over their folders. Remove the folder " +
                         folder + " or move it out of the case, then run again");
  slip_ = Eigen::Map<const Eigen::VectorXd>(slip.data(), expected);
  lastBeta_.resize(expected + static_cast<Eigen::Index>(opening.size()));
  lastBeta_.head(expected) = Eigen::Map<const Eigen::VectorXd>(beta.data(), expected);
  for (std::size_t i = 0; i < opening.size(); ++i)
    lastBeta_[expected + static_cast<Eigen::Index>(i)] = opening[i];
  if (weakening_) slipPath_ = Eigen::Map<const Eigen::VectorXd>(path.data(), system_->size());
  restore_ = std::move(restore);
  restartedFromFolder_ = true;
  if (rateState_) {
    psi_ = Eigen::Map<const Eigen::VectorXd>(psi.data(), system_->size());
    slipRate_ =
        Eigen::Map<const Eigen::VectorXd>(rates.data(), static_cast<Eigen::Index>(rates.size()));
    psiKnown_ = true;
  }
  lastTime_ = t0;

  // What a killed run wrote after t0 goes: every time after it has a name that reads back
  // above both t0 and the value of t0's own name (names are distinct, TimeControl.hpp).
  double named = t0;
  timeOfName(folder, named);
  const double limit = std::max(t0, named);
  const long first = time_->continueAfter(t0, step);
  log << "Restarting from time " << folder << " (step " << step << ")";
  if (first > time_->numSteps()) {
    // Nothing to do, and nothing is touched: the outputs stay as they are.
    log << ": nothing is left to compute: endTime " << formatNumber(time_->endTime())
        << " (system/controlDict) is at or before the saved time " << folder
        << "; raise endTime to continue. Nothing written\n\n";
    return first;
  }
  log << ", next time " << time_->timeName(time_->time(first)) << " (step " << first << " of "
      << time_->numSteps() << ")\n\n";
  trimOutputs(
      [limit](const std::string& name) {
        double t = 0;
        return timeOfName(name, t) && t <= limit;
      },
      false, log, limit);
  return first;
}

std::string FrictionCase::prepareSolver() { return optimizer_->prepare(*system_, opening_); }

StepLoads FrictionCase::loadsAt(double t) {
  FractureSystem& sys = *system_;
  bcs_->setValues(sys.dirichlet(), t);
  // Effects with a state of their own (the fault's computed diffusion) advance to the step's
  // time first: the loads and pressures below are those of that time.
  for (const auto& e : effects_) e->advance(t);
  return {loadVector(t), sys.dirichlet().values(), fracturePressure(t)};
}

void FrictionCase::keepSolution(const StepLoads& loads) {
  // No slip increment; the openings stay.
  last_.beta.head(system_->blockSize() * system_->size()).setZero();
  pressure_ = loads.pressure;
}

void FrictionCase::withStepProblem(const StepLoads& loads, double t,
                                   const Eigen::VectorXd& startSlip,
                                   const Eigen::VectorXd& startPath,
                                   const std::function<void(ControlProblem&)>& use) {
  FractureSystem& sys = *system_;
  const Eigen::Index n = sys.size(), perNode = sys.blockSize();
  sys.setStep(loads.load, startSlip);
  if (n > 0) {
    Eigen::VectorXd sn0 = Eigen::VectorXd::Zero(n), tau0 = Eigen::VectorXd::Zero(perNode * n);
    for (const auto& e : effects_) e->addFractureTraction(sys.controlNodes(), t, sn0, tau0);
    sys.setTractionOffset(sn0, tau0);
  }
  // ρ = c − μ(σ_n + p): the pressure lowers the cohesion term node by node.
  const Eigen::VectorXd cohesion = cohesion_ - mu_.cwiseProduct(loads.pressure);
  OpeningSettings openings{unilateral_, loads.pressure, gammaN_};
  // Friction that weakens: μ(δ_n + |β|) from the slip path at the step's start.
  if (weakening_) {
    weakeningSettings_.pathStart = startPath;
    weakeningSettings_.pressure = loads.pressure;
  }
  ControlProblem problem(sys, mu_, cohesion, gamma_, zeta_, gradient_,
                         opening_ ? &openings : nullptr,
                         weakening_ ? &weakeningSettings_ : nullptr);
  use(problem);
}

void FrictionCase::solveStep(const StepLoads& loads, double t, StepResult& r) {
  const Eigen::Index n = system_->size(), perNode = system_->blockSize();
  const Eigen::Index controlSize = opening_ ? perNode * n + n : perNode * n;
  withStepProblem(loads, t, slip_, slipPath_, [&](ControlProblem& problem) {
    Eigen::VectorXd beta = warmStart_ ? lastBeta_ : Eigen::VectorXd::Zero(controlSize);
    if (n > 0)
      r.report = optimizer_->minimize(problem, beta);
    else
      r.report.status = OptimizerStatus::converged;  // no fracture: nothing to iterate on
    // The accepted β once more, so that displacement and tractions on disk belong to it (a
    // line search may have evaluated a rejected trial last). judgeStep() judges this state,
    // not the optimizer's last evaluation.
    last_ = problem.evaluate(beta);
    r.relResidual = problem.relativeResidual(last_);
    evaluated_ = Evaluation{t,
                            slip_,
                            beta,
                            weakening_ ? slipPath_ : Eigen::VectorXd(),
                            r.report.tangentStiffness,
                            r.report.stiffnessComponents};
  });
  pressure_ = loads.pressure;
}

bool FrictionCase::restoreStep(const StepLoads& loads, StepResult& r) {
  if (!restore_) return false;
  const Evaluation e = std::move(*restore_);
  restore_.reset();
  const long solves0 = system_->factorization().numSolves();
  withStepProblem(loads, e.time, e.slip, e.path, [&](ControlProblem& problem) {
    last_ = problem.evaluate(e.beta);
    r.relResidual = problem.relativeResidual(last_);
  });
  r.report.status = OptimizerStatus::converged;  // recorded only for a converged step
  r.report.tangentStiffness = e.tangentStiffness;
  r.report.stiffnessComponents = e.stiffnessComponents;
  r.equilibrium = system_->equilibriumResidual();
  pressure_ = loads.pressure;
  evaluated_ = e;
  restoreSolves_ = system_->factorization().numSolves() - solves0;
  return true;
}

const InterfaceOperator& FrictionCase::faultOperator() {
  const InterfaceOperator* S = optimizer_->heldOperator();
  FRICTION_ASSERT(S, "the condensed Newton holds S once prepareSolver() ran");
  return *S;
}

void FrictionCase::tractionsAt(const StepLoads& loads, double t, Eigen::VectorXd& tau,
                               Eigen::VectorXd& sigmaN) {
  FractureSystem& sys = *system_;
  const Eigen::Index n = sys.size(), perNode = sys.blockSize();
  sys.setStep(loads.load, slip_);
  Eigen::VectorXd sn0 = Eigen::VectorXd::Zero(n), tau0 = Eigen::VectorXd::Zero(perNode * n);
  for (const auto& e : effects_) e->addFractureTraction(sys.controlNodes(), t, sn0, tau0);
  sys.setTractionOffset(sn0, tau0);
  sys.primal(Eigen::VectorXd::Zero(perNode * n), tau, sigmaN);
  // The surface stations at this time (the integrator asks for t_A, then t_B).
  if (faultSeries_ && faultSeries_->hasSurfaceStations() && parallel::isMaster()) {
    surfaceAt_[0] = surfaceAt_[1];
    surfaceAt_[1] = {t, faultSeries_->surfaceOperator() * sys.lastSplitDisplacement()};
  }
}

bool FrictionCase::wantsRateSamples() const {
  return faultSeries_ != nullptr && parallel::isMaster();
}

void FrictionCase::rateSample(const RateSample& sample) {
  if (!faultSeries_) return;
  if (!faultSeries_->hasSurfaceStations()) {
    faultSeries_->sample(sample);
    return;
  }
  // The surface stations between the solves at the interval's ends t_A, t_B (the last two
  // tractionsAt): u = u_A + θ (u_B − u_A) + G (s − s_A), v = (u_B − u_A)/(t_B − t_A) + G V.
  RateSample withSurface = sample;
  withSurface.surface = [&](Eigen::VectorXd& u, Eigen::VectorXd& v) {
    const SurfaceAt &A = surfaceAt_[0], &B = surfaceAt_[1];
    const double span = B.time - A.time;
    const double theta = span > 0 ? (sample.time - A.time) / span : 1.0;
    const Eigen::VectorXd mask = system_->componentMask();
    u = A.u + theta * (B.u - A.u) + surfaceResponse_ * (*sample.slip - slip_).cwiseProduct(mask);
    v = surfaceResponse_ * sample.rate->cwiseProduct(mask);
    if (span > 0) v += (B.u - A.u) / span;
  };
  faultSeries_->sample(withSurface);
}

void FrictionCase::buildSurfaceResponse(std::ostream& log) {
  // G = W ∂u/∂β under no load at all (no load vector, Dirichlet values 0, no slip), so that
  // G is the same bits whatever the time it is formed at (a restarted run's), once per run; by
  // the adjoint, one back-substitution per station component (collective).
  if (!faultSeries_ || !faultSeries_->hasSurfaceStations()) return;
  Stopwatch clock;
  const Eigen::SparseMatrix<double>& W = faultSeries_->surfaceOperator();
  surfaceResponse_ = system_->displacementResponse(W);
  log << "Setup: the surface stations' response to the slip (" << W.rows() / split_.mesh.dim
      << " stations, " << W.rows() << " back-substitutions, once per run): " << clock.seconds()
      << " s\n";
}

RateStateFault FrictionCase::rateStateFault() {
  RateStateFault f;
  f.k = system_->blockSize();
  f.laws = &rateLaws_;
  f.slip = &slip_;
  f.psi = &psi_;
  f.componentMask = system_->componentMask();
  f.imposed = &imposed_;
  f.imposedRate = &imposedRate_;
  const auto& nodes = system_->controlNodes();
  f.positions.resize(3, static_cast<Eigen::Index>(nodes.size()));
  for (std::size_t i = 0; i < nodes.size(); ++i)
    f.positions.col(static_cast<Eigen::Index>(i)) = nodes[i].position;
  return f;
}

void FrictionCase::initialiseRateState() {
  // ψ₀ so that each node slides at its initialSlipRate under the stresses of the start.
  const double t = lastTime_;
  const StepLoads loads = loadsAt(t);
  Eigen::VectorXd tau, sigmaN;
  tractionsAt(loads, t, tau, sigmaN);
  const FractureSystem& sys = *system_;
  const int k = sys.blockSize();
  const Eigen::VectorXd mask = sys.componentMask();
  for (Eigen::Index i = 0; i < sys.size(); ++i) {
    Block phi(k);
    for (int c = 0; c < k; ++c) phi[c] = -tau[k * i + c] * mask[k * i + c];
    if (blockNorm(phi) == 0 && mask.segment(k * i, k).isZero()) continue;  // held: no slip
    if (imposed_[i] != 0) continue;                                        // creep: no state
    RateState law = rateLaws_[static_cast<std::size_t>(i)];
    law.sigmaBar = -(sigmaN[i] + loads.pressure[i]);
    const std::optional<double> psi =
        law.sigmaBar > 0 ? law.stateFor(initialSlipRate_[i], blockNorm(phi)) : std::nullopt;
    if (!psi) {
      const Point& x = sys.controlNodes()[static_cast<std::size_t>(i)].position;
      std::ostringstream m;
      m << std::setprecision(4) << "law rateState: at the node at (" << x.x() << ", " << x.y();
      if (sys.dimension() == 3) m << ", " << x.z();
      m << ") of fracture '"
        << fractures_[sys.controlNodes()[static_cast<std::size_t>(i)].fracture].name
        << "' no state gives initialSlipRate " << initialSlipRate_[i]
        << " m/s under the initial shear " << blockNorm(phi) << " Pa and normal compression "
        << law.sigmaBar << " Pa (it needs compression, and a shear above eta x initialSlipRate = "
        << law.eta * initialSlipRate_[i] << " Pa)";
      throw InputError((fs::path(caseDir_) / "constant" / "fractureProperties").string(), m.str());
    }
    psi_[i] = *psi;
  }
  psiKnown_ = true;
}

void FrictionCase::finishRateStep(const StepLoads& loads, double t, const Eigen::VectorXd& slip,
                                  const Eigen::VectorXd& V, StepResult& r) {
  FractureSystem& sys = *system_;
  const Eigen::Index n = sys.size(), k = sys.blockSize();
  // One solve of the body with the new slip: its tractions are the outputs' and the check of
  // the ones S gave the integration.
  sys.setStep(loads.load, slip_);
  Eigen::VectorXd sn0 = Eigen::VectorXd::Zero(n), tau0 = Eigen::VectorXd::Zero(k * n);
  for (const auto& e : effects_) e->addFractureTraction(sys.controlNodes(), t, sn0, tau0);
  sys.setTractionOffset(sn0, tau0);
  const Eigen::VectorXd beta = slip - slip_;
  Eigen::VectorXd tau, sigmaN;
  sys.primal(beta.cwiseProduct(sys.componentMask()), tau, sigmaN);
  // The friction the law gives at (V, ψ) as a coefficient of the compression, so that the
  // node states read as the complementarity reads them; D is the balance's residual
  // τ + (σ̄ f(V, ψ) + η|V|) V̂ (0 where the law holds).
  Eigen::VectorXd muEff = Eigen::VectorXd::Zero(n), D = Eigen::VectorXd::Zero(k * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    RateState law = rateLaws_[static_cast<std::size_t>(i)];
    law.sigmaBar = -(sigmaN[i] + loads.pressure[i]);
    const Block v = V.segment(k * i, k);
    const double speed = blockNorm(v);
    if (imposed_[i] != 0 || law.sigmaBar <= 0 || speed == 0) continue;  // creep: no balance
    const double strength = law.sigmaBar * law.friction(speed, psi_[i]) + law.eta * speed;
    muEff[i] = strength / law.sigmaBar;
    for (Eigen::Index c = 0; c < k; ++c) D[k * i + c] = tau[k * i + c] + strength * v[c] / speed;
  }
  ControlProblem problem(sys, muEff, -muEff.cwiseProduct(loads.pressure), gamma_, 0.0, gradient_);
  last_ = problem.stateFrom(beta.cwiseProduct(problem.componentMask()), tau, sigmaN);
  last_.D = D.cwiseProduct(problem.componentMask());
  last_.J = 0.5 * problem.dot(last_.D, last_.D);
  r.relResidual = problem.relativeResidual(last_);
  slipRate_ = V;
  pressure_ = loads.pressure;
}

std::vector<StepResult> FrictionCase::run(std::ostream& log) {
  std::vector<StepResult> results;
  FractureSystem& sys = *system_;
  // k tangential components per control node (SlipResponse.hpp): β, τ and the slip are k·n.
  const Eigen::Index n = sys.size(), perNode = sys.blockSize();
  // The control: β (k·n), then with openings g (n).
  const Eigen::Index controlSize = opening_ ? perNode * n + n : perNode * n;
  lastBeta_ = Eigen::VectorXd::Zero(controlSize);
  lastTime_ = time_->startTime();
  // Rank 0 prepares the outputs (postProcessing/ may be a file, the folder read-only): every
  // rank learns whether it could before the first shared solve (parallel::agree).
  long first = 1;
  parallel::agree(
      [&] {
        if (!outputPrepared_) prepareOutput(false, log);
        if (time_->startFromLatest())
          first = restart(log);
        else
          trimOutputs([](const std::string&) { return false; }, true, log);
      },
      exitStatusOf);
  lastWritten_ = lastTime_;  // the start (startTime, or the time a restart read)
  if (!time_->precisionNote().empty()) log << time_->precisionNote() << "\n\n";
  if (time_->steps() != TimeControl::Steps::uniform) log << "Time: " << time_->describe() << "\n\n";
  const std::string controlDict = (fs::path(caseDir_) / "system" / "controlDict").string();
  auto controlStamp = fs::last_write_time(controlDict);
  bool controlDictGone = false;
  const auto start = std::chrono::steady_clock::now();
  const StopHandlerScope stopHandlers;  // for the time loop only

  // What the optimizer forms once per run, formed here and not inside the first step, so that
  // the log says what it is and what it costs (a P2 3D fault: seconds the first step would
  // otherwise take without a word). Its back-substitutions are shown on the first step's line
  // apart from the step's own, as before.
  long prepareSolves = 0;
  if (n > 0 && first <= time_->numSteps()) {
    Stopwatch clock;
    const long solves0 = sys.factorization().numSolves();
    std::string built;
    try {
      built = timeIntegrator_->prepare(*this);
      if (rateState_ && !psiKnown_) initialiseRateState();
      buildSurfaceResponse(log);
    } catch (const StopNow& s) {
      if (parallel::size() > 1) {
        log << "\nStopped while forming the interface operator (" << s.what()
            << " twice: nothing computed)" << std::endl;
        parallel::abort(5);
      }
      stoppedEarly_ = std::string(stopRequested() == SIGINT ? "SIGINT" : "SIGTERM") + ", then " +
                      s.what() + ": stopped while forming the interface operator, nothing computed";
      log << "\nStopped before the first step (" << stoppedEarly_ << ")\n";
      return results;
    }
    prepareSolves = sys.factorization().numSolves() - solves0;
    if (!built.empty()) {
      logPhase(
          log,
          built + (prepareSolves > 0 ? ", " + std::to_string(prepareSolves) + " back-substitutions"
                                     : std::string()),
          clock.seconds());
      log << "\n";
    }
  }
  if (restartedFromFolder_ && first <= time_->numSteps()) timeIntegrator_->restarted(*this);
  RemainingTime remaining;

  for (long k = first; k <= time_->numSteps(); ++k) {
    Stopwatch stepClock;
    StepResult r;
    r.time = time_->time(k);
    const long solves0 = sys.factorization().numSolves();
    try {
      timeIntegrator_->advance(*this, r, results.empty() ? nullptr : &results.back());
    } catch (const StopNow& s) {
      // A second signal: the step is abandoned; nothing of it is written. With several ranks
      // the others may be inside a shared solve that would wait for this one forever: stop
      // them all (exit status 5, as a serial run's).
      if (parallel::size() > 1) {
        log << "\nStopped during the step to time " << time_->timeName(r.time) << " (" << s.what()
            << " twice: abandoned, not written)" << std::endl;
        parallel::abort(5);
      }
      stoppedEarly_ = std::string(stopRequested() == SIGINT ? "SIGINT" : "SIGTERM") + ", then " +
                      s.what() + ": the step to time " + time_->timeName(r.time) +
                      " was abandoned and not written";
      log << "\nStopped during the step to time " << time_->timeName(r.time) << " ("
          << stoppedEarly_ << ")\n";
      break;
    }
    const Eigen::VectorXd& pressure = pressure_;
    lastTime_ = r.time;

    // The step's own solves: operators built once per run (Newton's condensed S) are counted
    // apart, so that a restarted run, which builds them again, writes the same numbers.
    r.backSubstitutions =
        sys.factorization().numSolves() - solves0 - r.report.setupSolves - restoreSolves_;
    restoreSolves_ = 0;  // a restart's remaking of its state is not the step's work
    // The solves of prepare() above, on the first step that iterates (as when they were spent
    // inside it).
    if (prepareSolves > 0 && !r.reused && n > 0) {
      r.report.setupSolves += prepareSolves;
      prepareSolves = 0;
    }
    if (!r.reused) r.equilibrium = sys.equilibriumResidual();  // a reused step has its own
    r.J = last_.J;
    r.lastStepNorm = r.report.history.empty() ? 0 : std::max(0.0, r.report.history.back().stepNorm);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double effective = last_.sigmaN[i] + pressure[i];
      // Open faces (contact unilateral) carry no friction: σ'_n = 0 there up to round-off.
      const bool open = !last_.contact.empty() && !last_.contact[i];
      if (sys.freeMask()[i] > 0 && effective < 0 && !open)
        r.maxExcessST = std::max(
            r.maxExcessST,
            (blockNorm(last_.tau.segment(perNode * i, perNode)) - std::max(last_.rho[i], 0.0)) /
                -effective);
    }
    if (!r.reused) judgeStep(r);
    if (!r.reused) sanityNotes(log);
    if (r.nonFinite) {
      // Nothing non-finite reaches the disk, and later steps would start from it: stop here.
      log << "Time = " << time_->timeName(r.time) << "  iterations " << r.report.iterations << "  "
          << toString(r.report.status) << "  [" << r.report.note << "]  (not written)\n"
          << "\nStopped at time " << time_->timeName(r.time)
          << ": its results are not finite, later steps would start from them\n";
      results.push_back(std::move(r));
      break;
    }
    slip_ += last_.beta.head(perNode * n);
    // The laws' state: the slip path δ grows by the length of each step's increment.
    if (weakening_)
      for (Eigen::Index i = 0; i < n; ++i)
        slipPath_[i] += blockNorm(last_.beta.segment(perNode * i, perNode));
    lastBeta_ = last_.beta;
    // The step line's trailer (README.md, "frictionSolver"): the largest slip and opening.
    double maxSlip = 0, maxOpening = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (sys.freeMask()[i] == 0) continue;
      maxSlip = std::max(maxSlip, blockNorm(slip_.segment(perNode * i, perNode)));
      if (opening_) maxOpening = std::max(maxOpening, last_.beta[perNode * n + i]);
    }
    // The time as its folder name: it identifies the step when a restart trims the history.
    std::ostringstream lines;
    lines.precision(8);
    for (const auto& h : r.report.history)
      lines << time_->timeName(r.time) << " " << h.iteration << " " << h.J << " " << h.relResidual
            << " " << std::max(h.stepNorm, 0.0) << "\n";

    // Stop requests: the user edited stopAt in controlDict, or sent SIGINT/SIGTERM.
    std::error_code stampError;
    const auto stamp = fs::last_write_time(controlDict, stampError);
    if (stampError) {
      // Removed or unreadable while running: the run keeps the settings it read at start.
      if (!controlDictGone)
        log << "Warning: " << controlDict << " cannot be read any more (" << stampError.message()
            << "): the run goes on with the settings read at start\n";
      controlDictGone = true;
    } else if (stamp != controlStamp) {
      controlDictGone = false;
      controlStamp = stamp;
      try {
        if (time_->rereadStopAt(controlDict)) log << "controlDict changed: stopAt re-read\n";
      } catch (const InputError& e) {
        log << "controlDict changed but cannot be read (" << e.what() << "): ignored\n";
      }
    }
    // Every rank takes rank 0's stopAt and the first signal any rank received, so that they
    // all stop, or go on, together.
    int shared[2] = {static_cast<int>(time_->stopAt()), parallel::maxOverRanks(stopRequested())};
    parallel::broadcast(shared, 2);
    const auto stopAt = static_cast<TimeControl::StopAt>(shared[0]);
    const int signal = shared[1];
    const bool signalled = signal != 0;
    const bool stopNow = signalled || stopAt == TimeControl::StopAt::writeNow ||
                         stopAt == TimeControl::StopAt::noWriteNow ||
                         (stopAt == TimeControl::StopAt::nextWrite && time_->writes(k));
    const bool write = time_->writes(k) || signalled || stopAt == TimeControl::StopAt::writeNow;
    // Rank 0 writes (the history, the time folder); every rank learns whether it could before
    // the next shared solve, so that a full disk stops them all (exit 6) instead of leaving the
    // others waiting for rank 0 in it.
    const bool writeFolder = write && stopAt != TimeControl::StopAt::noWriteNow;
    parallel::agree(
        [&] {
          if (history_) history_->append(lines.str());  // rank 0's only
          for (std::size_t f = 0; f < fractureHistories_.size(); ++f)
            fractureHistories_[f]->append(historyLine(f, r.time));
          if (faultSeries_) faultSeries_->flush();
          if (!writeFolder) return;
          try {
            writeTimeFolder(r, last_.beta, k);
          } catch (const OutputError&) {
            throw;
          } catch (const InputError& e) {
            // The case was read fine: a write that fails is the disk's or the system's doing.
            throw OutputError(e.location(), e.message());
          }
        },
        exitStatusOf);
    r.written = writeFolder;
    if (writeFolder) lastWritten_ = r.time;
    log << "Time = " << time_->timeName(r.time)
        << (r.reused ? "  loads unchanged: previous solution reused" : "") << "  iterations "
        << r.report.iterations << "  backSubstitutions " << r.backSubstitutions
        << (r.report.setupSolves
                ? " (+" + std::to_string(r.report.setupSolves) + " building S, once per run)"
                : "")
        << std::setprecision(4) << "  J " << r.J << "  |D|/|Sigma| " << r.relResidual
        << "  maxExcessST " << r.maxExcessST << "  |dBeta| " << r.lastStepNorm << "  "
        << toString(r.report.status)
        << (!r.reused && n > 0 && r.report.iterations == 0 ? " (stuck at the trial state)" : "")
        << (r.report.note.empty() ? "" : "  [" + r.report.note + "]");
    if (opening_) {
      // Fractures that open: how many nodes are in each state (all fractures together).
      std::map<std::string, long> count;
      for (Eigen::Index i = 0; i < n; ++i) ++count[nodeState(i)];
      log << "  nodes stick " << count["stick"] << " slip " << count["slip"] << " open "
          << count["open"] << " tip " << count["tip"];
      if (count["junction"] > 0) log << " junction " << count["junction"];
    }
    log << (r.written ? "  (written)" : "");
    // Progress: step k of n, the time loop's elapsed time, the estimated remaining (on the
    // step's own line, so a log gets no extra lines). The estimate is the recent steps' pace
    // (RemainingTime.hpp), said once two steps are known.
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    remaining.add(stepClock.seconds());
    const long left = time_->numSteps() - k;
    log << "  [step " << k << "/" << time_->numSteps() << ", " << std::setprecision(3) << elapsed
        << " s";
    if (left == 0 || remaining.ready()) log << ", ~" << remaining.estimate(left) << " s left";
    log << "]";
    // Appended after the fields above (scripts and tests read those by position): the largest
    // accumulated slip, the largest opening, the loads' scale, and the wall clock since the
    // run started.
    std::ostringstream trailer;
    trailer << std::setprecision(4) << "  maxSlip " << maxSlip << " m";
    if (opening_) trailer << "  maxOpening " << maxOpening << " m";
    // Friction that weakens: the slipping patch's relative tangent stiffness (≤ 0: unstable).
    if (r.maxSlipRate >= 0)
      trailer << "  maxSlipRate " << r.maxSlipRate << " m/s  peakSlipRate " << r.peakSlipRate
              << " m/s";
    if (weakening_ && !std::isnan(r.report.tangentStiffness))
      trailer << "  patchStiffness " << r.report.tangentStiffness;
    log << trailer.str() << loadFields(r.time, pressure) << "  ["
        << formatSeconds(secondsSinceStart()) << "]\n";
    log.flush();
    const bool nucleated = r.report.status == OptimizerStatus::nucleation;
    // A quasi-dynamic step whose integration stopped: later steps would start from a state
    // that is not the one of their time.
    const bool integrationStopped = rateState_ && r.report.status != OptimizerStatus::converged &&
                                    r.report.status != OptimizerStatus::inaccurate;
    results.push_back(std::move(r));
    if (integrationStopped) {
      log << "\nStopped at time " << time_->timeName(time_->time(k))
          << ": the time integration did not reach it (see the step's note)\n";
      break;
    }
    if (nucleated) {
      // Past the loss of equilibrium the slip is dynamic: a quasi-static step has no answer.
      log << "\nStopped at time " << time_->timeName(time_->time(k))
          << ": the quasi-static equilibrium is lost (nucleation; see the step's note); the "
             "slip that follows is an instability the quasi-static stepping does not follow\n";
      break;
    }
    if (stopNow && k < time_->numSteps()) {
      stoppedEarly_ = signalled ? std::string(signal == SIGINT ? "SIGINT" : "SIGTERM")
                                : "stopAt in system/controlDict";
      log << "\nStopped at time " << time_->timeName(time_->time(k)) << " (" << stoppedEarly_ << ")"
          << (results.back().written ? ", this time written" : "") << "\n";
      break;
    }
  }
  // What the integration cost, where the integrator counts it (quasiDynamic: steps and
  // right-hand sides, the time on the fault alone).
  if (const std::string work = timeIntegrator_->summary(); !work.empty())
    log << "\nTime integration: " << work << "\n";
  return results;
}

void FrictionCase::sanityNotes(std::ostream& log) {
  // Once per run each: answers that are most likely a case typed wrong (a pressure above
  // every confining stress, a gradient of the wrong sign), said before the step's line.
  const FractureSystem& sys = *system_;
  const auto& nodes = sys.controlNodes();
  for (std::size_t f = 0; f < split_.fractures.size(); ++f) {
    if (allOpenNoted_.size() <= f) allOpenNoted_.resize(split_.fractures.size(), 0);
    if (allOpenNoted_[f]) continue;
    long inner = 0, open = 0;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (nodes[k].fracture != static_cast<int>(f) || nodes[k].tip) continue;
      ++inner;
      if (nodeState(static_cast<Eigen::Index>(k)) == "open") ++open;
    }
    if (inner > 0 && open == inner) {
      allOpenNoted_[f] = 1;
      log << "Note: every node of fracture " << split_.fractures[f].name
          << " is open (sigma'_n = sigma_n + p >= 0 everywhere on it): the fluid pressure "
             "exceeds the confinement on the whole fracture, or the stresses pull it apart; "
             "check the pressure and the stresses' signs and units\n";
    }
  }
  if (largeDisplacementNoted_ || diameter_ <= 0) return;
  const Eigen::VectorXd u = sys.lastSplitDisplacement();
  const LagrangeSpace& space = sys.splitSpace();
  double largest = 0;
  for (Index i = 0; i < space.numNodes(); ++i) {
    double norm2 = 0;
    for (int c = 0; c < sys.dimension(); ++c) norm2 += std::pow(u[space.dof(i, c)], 2);
    largest = std::max(largest, std::sqrt(norm2));
  }
  if (largest > diameter_) {
    largeDisplacementNoted_ = true;
    log << std::setprecision(3) << "Note: the displacement reaches " << largest
        << " m, more than the body's size (" << diameter_
        << " m): check the loads' signs and units (e.g. a stress gradient of the wrong sign, "
           "a pressure in the wrong unit)\n";
  }
}

void FrictionCase::judgeStep(StepResult& r) const {
  const FractureSystem& sys = *system_;
  const auto addNote = [&r](const std::string& note) {
    r.report.note += (r.report.note.empty() ? "" : "; ") + note;
  };
  // 1. Non-finite results (finite input that overflows, e.g. E = 1e300 Pa): diverged.
  std::vector<std::string> bad;
  if (!sys.lastSplitDisplacement().allFinite()) bad.push_back("displacement");
  if (!last_.tau.allFinite() || !last_.sigmaN.allFinite()) bad.push_back("tractions");
  if (!last_.beta.allFinite() || !(slip_ + last_.beta.head(slip_.size())).allFinite())
    bad.push_back("slip");
  if (!last_.D.allFinite() || !std::isfinite(r.J) || !std::isfinite(r.relResidual) ||
      !std::isfinite(r.maxExcessST))
    bad.push_back("residual or J");
  if (!bad.empty()) {
    r.nonFinite = true;
    r.report.status = OptimizerStatus::diverged;
    std::ostringstream s;
    s << "non-finite " << joinWords(bad)
      << ": the numbers overflow double precision (E = " << materials_->maxYoungModulus()
      << " Pa; J = ½‖D‖² squares the stresses); express the case "
      << "in units that keep E and the stresses well below 1e150 (e.g. MPa or GPa)";
    addNote(s.str());
    return;
  }
  // 2. The status written is the status of this state: the optimizer judged its own last
  // evaluation, which for Newton's condensed variant is the dense model, not this solve.
  const StopRule& rule = optimizer_->stopRule();
  const double balanceTolerance = timeIntegrator_->balanceTolerance(rule.tolerance);
  if (r.report.status == OptimizerStatus::converged && rule.on == StopRule::On::residual &&
      r.relResidual > balanceTolerance && !timeIntegrator_->balanceNote().empty()) {
    r.report.status = OptimizerStatus::inaccurate;
    std::ostringstream s;
    s << std::setprecision(3) << "the state written has |D|/|Sigma| " << r.relResidual << " > "
      << balanceTolerance << ": " << timeIntegrator_->balanceNote();
    addNote(s.str());
  } else if (r.report.status == OptimizerStatus::converged && rule.on == StopRule::On::residual &&
             r.relResidual > balanceTolerance && sys.factorization().iterative()) {
    // The solves' own residual bounds what the state written can reach.
    r.report.status = OptimizerStatus::inaccurate;
    std::ostringstream s;
    s << std::setprecision(3) << "the iteration reached |D|/|Sigma| "
      << (r.report.history.empty() ? 0.0 : r.report.history.back().relResidual)
      << " but the state written has " << r.relResidual << " > tolerance " << rule.tolerance
      << ": linear solver amg solves only to iterativeTolerance " << iterativeTolerance_
      << " (its check solve's forward error "
      << sys.factorization().analysis().iterativeForwardError
      << "); tighten iterativeTolerance, or loosen the tolerance";
    addNote(s.str());
  } else if (r.report.status == OptimizerStatus::converged && rule.on == StopRule::On::residual &&
             r.relResidual > balanceTolerance) {
    r.report.status = OptimizerStatus::inaccurate;
    std::ostringstream s;
    s << std::setprecision(3) << "the iteration reached |D|/|Sigma| "
      << (r.report.history.empty() ? 0.0 : r.report.history.back().relResidual)
      << " but the state written has " << r.relResidual << " > tolerance " << rule.tolerance
      << ": round-off of an ill-conditioned system (nu = " << std::setprecision(12)
      << materials_->maxPoissonRatio() << std::setprecision(3) << ", smallest pivot ratio "
      << sys.factorization().minPivotRatio()
      << "); loosen the tolerance, "
      // A P2 run is told nothing about elementOrder 2.
      << (order_ == 1 ? "use elementOrder 2, " : "") << "or remesh without slivers";
    addNote(s.str());
  }
  // 2a. An iterative linear solver whose solves stopped short of their tolerance in this step:
  // what was solved with them is not as accurate as the stop rule says.
  if (sys.factorization().iterative()) {
    const long unconverged = sys.factorization().currentAnalysis().iterativeUnconverged;
    if (unconverged > iterativeUnconvergedSeen_ && r.report.status == OptimizerStatus::converged) {
      r.report.status = OptimizerStatus::inaccurate;
      addNote(std::to_string(unconverged - iterativeUnconvergedSeen_) +
              " solve(s) of linear solver amg stopped at the iteration limit short of "
              "iterativeTolerance: loosen it, or use a direct linear solver");
    }
    iterativeUnconvergedSeen_ = unconverged;
  }
  // 2b. Friction that weakens: a converged state whose slipping patch has no positive tangent
  // stiffness is an unstable equilibrium, and an iteration that found none while weakening
  // nodes slip has lost the quasi-static path; either way an instability nucleates, and the
  // step says so rather than "converged" (or a bare "maxIterations").
  if (weakening_) {
    const OptimizerStatus st = r.report.status;
    const bool unstable = st == OptimizerStatus::converged && !(r.report.tangentStiffness > 0) &&
                          r.report.stiffnessComponents > 0;
    const bool lost = (st == OptimizerStatus::maxIterations || st == OptimizerStatus::stalled ||
                       st == OptimizerStatus::diverged) &&
                      !patchOfWeakeningSlip().empty();
    if (unstable || lost) {
      r.report.status = OptimizerStatus::nucleation;
      std::ostringstream s;
      s << std::setprecision(3) << "nucleation at time " << time_->timeName(r.time) << ": "
        << (unstable
                ? "the slipping patch's tangent stiffness is " +
                      formatNumber(r.report.tangentStiffness) + " (relative; <= 0: slip runs away)"
                : std::string("no equilibrium near the previous step's (") + toString(st) + ")")
        << "; slipping " << patchOfWeakeningSlip()
        << "; the slip written is the iteration's last, not an equilibrium";
      addNote(s.str());
    }
  }
  // 3. A slip larger than the body: nothing holds part of it.
  double maxSlip = 0;
  const Eigen::Index k = sys.blockSize();
  for (Eigen::Index i = 0; i < sys.size(); ++i)
    if (sys.freeMask()[i] > 0)
      maxSlip =
          std::max(maxSlip, blockNorm(slip_.segment(k * i, k) + last_.beta.segment(k * i, k)));
  // Openings: a part pushed off by the pressure on a fracture that opens (open faces hold it
  // neither way: no friction, no compression) flies off along the normal too.
  double maxOpening = 0;
  if (opening_)
    for (Eigen::Index i = 0; i < sys.size(); ++i)
      if (sys.freeMask()[i] > 0) maxOpening = std::max(maxOpening, last_.beta[k * sys.size() + i]);
  const bool flies = diameter_ > 0 && maxOpening > diameter_;
  if (diameter_ > 0 && (maxSlip > diameter_ || flies)) {
    std::ostringstream s;
    s << std::setprecision(3) << "slip up to " << maxSlip << " m"
      << (flies ? ", opening up to " : "");
    if (flies) s << maxOpening << " m";
    s << ", larger than the body (" << diameter_ << " m): ";
    std::vector<std::string> parts;
    for (const FloatingPart& p : floating_)
      if (p.heldThroughFracture)
        parts.push_back("the part " + p.describe() + " touches no Dirichlet patch and only " +
                        joinWords(p.fractures) + " hold" + (p.fractures.size() == 1 ? "s" : "") +
                        " it");
    if (parts.empty())
      s << "the fractures cannot carry the load (check the loads and the friction law)";
    else
      for (std::size_t i = 0; i < parts.size(); ++i) s << (i ? "; " : "") << parts[i];
    if (!parts.empty())
      s << (flies ? ": fix a patch of it (0/D) or keep its fracture closed (contact bilateral; "
                    "open faces carry no friction)"
                  : ": fix a patch of it (0/D) or give its fracture friction");
    addNote(s.str());
  }
  // 4. Fractures that open: a part held only by fractures whose faces all separate has
  // nothing left to hold it, and its opening is a rigid-body motion. Where the opening has not
  // run off beyond the body (3. says so then), Newton finds the normal rows singular and
  // stops without converging: say why.
  if (!opening_ || flies || r.report.status == OptimizerStatus::converged) return;
  std::vector<std::string> parts;
  for (const FloatingPart& p : floating_) {
    if (!p.heldThroughFracture) continue;
    bool opens = false;
    for (const auto& f : fractures_)
      if (f.unilateral && std::find(p.fractures.begin(), p.fractures.end(),
                                    "'" + f.name + "'") != p.fractures.end())  // quoted names
        opens = true;
    if (opens)
      parts.push_back("the part " + p.describe() + " touches no Dirichlet patch and only " +
                      joinWords(p.fractures) + " hold" + (p.fractures.size() == 1 ? "s" : "") +
                      " it");
  }
  if (parts.empty()) return;
  std::ostringstream s;
  for (std::size_t i = 0; i < parts.size(); ++i) s << (i ? "; " : "") << parts[i];
  s << ", and contact unilateral lets the faces separate: where they all open nothing holds "
       "the part (a rigid-body motion); fix a patch of it (0/D), or make the fracture "
       "bilateral";
  addNote(s.str());
}

std::string FrictionCase::patchOfWeakeningSlip() const {
  const FractureSystem& sys = *system_;
  const auto& nodes = sys.controlNodes();
  const int dim = sys.dimension();
  std::vector<std::string> parts;
  for (std::size_t f = 0; f < fractures_.size(); ++f) {
    if (fractures_[f].law->weakening() == Weakening::none) continue;
    long count = 0;
    double size = 0, sMin = 0, sMax = 0;
    Point centre = Point::Zero(), low = Point::Zero(), high = Point::Zero();
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (nodes[k].fracture != static_cast<int>(f) ||
          nodeState(static_cast<Eigen::Index>(k)) != "slip")
        continue;
      const double w = sys.weights()[static_cast<Eigen::Index>(k)];
      const Point& x = nodes[k].position;
      if (count == 0) sMin = sMax = nodes[k].arclength, low = high = x;
      sMin = std::min(sMin, nodes[k].arclength);
      sMax = std::max(sMax, nodes[k].arclength);
      low = low.cwiseMin(x);
      high = high.cwiseMax(x);
      centre += w * x;
      size += w;
      ++count;
    }
    if (count == 0) continue;
    centre /= size;
    std::ostringstream s;
    s << std::setprecision(4) << "on '" << fractures_[f].name << "' " << count << " nodes, ";
    if (dim == 2)
      s << "s from " << sMin << " to " << sMax << " m (length " << size << " m), centre ("
        << centre.x() << ", " << centre.y() << ")";
    else
      s << "area " << size << " m2 around (" << centre.x() << ", " << centre.y() << ", "
        << centre.z() << "), extent (" << high.x() - low.x() << ", " << high.y() - low.y() << ", "
        << high.z() - low.z() << ") m";
    parts.push_back(s.str());
  }
  return joinWords(parts);
}

std::string FrictionCase::nodeState(Eigen::Index k) const {
  const FractureSystem& sys = *system_;
  // Held at a junction where the fracture ends on another: no jump, like a tip.
  if (sys.controlNodes()[k].tip) return sys.controlNodes()[k].junction ? "junction" : "tip";
  // Nodes on Dirichlet patches have their jump held at zero: they stick.
  if (sys.freeMask()[k] == 0) return "stick";
  // Faces apart (contact unilateral): open, whatever the tangential law says (τ = 0 there).
  if (!last_.contact.empty() && !last_.contact[k]) return "open";
  // The law's bound ρ ≤ 0 frees a node; it is open only where σ'_n ≥ 0 — compressed
  // (frictionless, μ_f = 0) it slides freely.
  const double effective = last_.sigmaN[k] + (pressure_.size() ? pressure_[k] : 0.0);
  const SlipState law = last_.node[k].state;
  return law == SlipState::open ? (effective >= 0 ? "open" : "slip") : toString(law);
}

bool FrictionCase::hasStressOffset() const {
  for (const auto& e : effects_)
    if (e->givesStressOffset()) return true;
  return false;
}

Eigen::Matrix3d FrictionCase::stressOffset(Index cell, const Point& x, double t) const {
  // 2D: the in-plane block and σ_zz (Effect.hpp).
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  for (const auto& e : effects_) s += e->stressOffset(cell, x, t);
  return s;
}

Eigen::Matrix3d FrictionCase::tipStress(std::size_t k, const Eigen::VectorXd& u, double t) const {
  const std::vector<Index>& cells = tipCells_[k];
  FRICTION_ASSERT(!cells.empty(), "a tip lies in some cell");
  const ElasticityAssembler& assembler = system_->splitAssembler();
  const Point& x = system_->controlNodes()[k].position;
  const bool offset = hasStressOffset();
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  for (const Index c : cells) {
    sum += assembler.stress(u, c, x);
    if (offset) sum += stressOffset(c, x, t);
  }
  return sum / static_cast<double>(cells.size());
}

std::vector<FractureRow> FrictionCase::fractureRows(std::size_t f) const {
  FRICTION_ASSERT(f < split_.fractures.size(), "a fracture of the case");
  return fractureRows(f, lastBeta_, nullptr);
}

std::vector<FractureRow> FrictionCase::fractureRows(std::size_t f, const Eigen::VectorXd& beta,
                                                    std::map<Index, Index>* rowOfNode) const {
  const FractureSystem& sys = *system_;
  const auto& nodes = sys.controlNodes();
  // k tangential components per node (k = d − 1), node-major in last_.tau, last_.D, slip_, beta.
  const int kb = sys.blockSize();
  // The split displacement for the stress at tips (that of the last primal solve, which the
  // time folder's D holds too); zero before any solve.
  Eigen::VectorXd u;
  std::vector<FractureRow> rows;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    if (nodes[k].fracture != static_cast<int>(f)) continue;
    const bool tip = nodes[k].tip;
    const Eigen::Index at = kb * static_cast<Eigen::Index>(k);
    FractureRow row;
    row.s = nodes[k].arclength;
    row.position = nodes[k].position;
    row.normal = nodes[k].normal;
    row.tangent = nodes[k].tangent;
    // At a tip (single node, or a junction end) the two sides are not told apart and no
    // traction is recovered; the row gives the body's stress there resolved on the node's
    // frame, τ_c = t_c·σ n_Γ and σ_n = n_Γ·σ n_Γ (SignConventions.hpp), the quantity the other
    // rows recover. The law is not imposed there (no unknown): its residual is 0.
    Eigen::Vector2d tipTau = Eigen::Vector2d::Zero();
    double sn = 0;
    if (tip) {
      if (u.size() == 0)
        u = sys.lastUnsplitSolution().size() > 0
                ? sys.lastSplitDisplacement()
                : Eigen::VectorXd::Zero(sys.splitSpace().numDofs());
      const Eigen::Vector3d traction = tipStress(k, u, lastTime_) * nodes[k].normal;
      sn = traction.dot(nodes[k].normal);
      for (int c = 0; c < kb; ++c) tipTau[c] = traction.dot(nodes[k].tangent[c]);
    } else {
      sn = last_.sigmaN[k];
    }
    for (int c = 0; c < kb; ++c) {
      row.slip[c] = slip_[at + c];
      row.slipIncrement[c] = beta[at + c];
      row.tau[c] = tip ? tipTau[c] : last_.tau[at + c];
      row.residual[c] = tip ? 0.0 : last_.D[at + c];
    }
    row.sigmaN = sn;
    // Slip tendency |τ| / −σ'_n on the effective normal stress σ'_n = σ_n + p (p = 0 without
    // fracturePressure); |τ| of k = 1 is |τ₁| exactly (blockNorm).
    const double effective = sn + (pressure_.size() ? pressure_[k] : 0.0);
    const double tauNorm = tip ? blockNorm(tipTau.head(kb)) : blockNorm(last_.tau.segment(at, kb));
    row.state = nodeState(static_cast<Eigen::Index>(k));
    // Open faces (σ'_n = 0 up to round-off) have no slip tendency: 0, not round-off over
    // round-off. Bilateral nodes are open only where σ'_n ≥ 0, where ST is 0 already.
    row.ST = row.state == "open" ? 0.0 : effective < 0 ? tauNorm / -effective : 0.0;
    if (opening_) {
      row.hasOpening = true;
      row.opening = beta[kb * static_cast<Eigen::Index>(nodes.size()) + k];
    }
    if (hasPressure_) {
      // The fluid's pressure and the effective normal stress σ'_n = σ_n + p: the stress the
      // friction law and ST use.
      row.hasPressure = true;
      row.pressure = pressure_.size() ? pressure_[k] : 0.0;
      row.sigmaNEffective = effective;
      // ΔCFS = Δ|τ| + μ_f Δσ'_n against the initial state (setup()): positive towards failure.
      const Eigen::Index i = static_cast<Eigen::Index>(k);
      row.deltaCFS =
          (tauNorm - initialTauNorm_[i]) + mu_[i] * (effective - initialSigmaNEffective_[i]);
    }
    if (rateState_) {
      row.hasRateState = true;
      row.slipRate = blockNorm(slipRate_.segment(kb * static_cast<Eigen::Index>(k), kb));
      row.psi = psi_[static_cast<Eigen::Index>(k)];
    }
    if (weakening_) {
      row.hasWeakening = true;
      row.slipPath = slipPath_[static_cast<Eigen::Index>(k)];
      const WeakeningNode& w = weakeningSettings_.nodes[k];
      row.frictionCoefficient =
          w.form == Weakening::none ? mu_[static_cast<Eigen::Index>(k)] : w.mu(row.slipPath);
    }
    if (rowOfNode) (*rowOfNode)[static_cast<Index>(k)] = static_cast<Index>(rows.size());
    rows.push_back(row);
  }
  return rows;
}

int FrictionCase::elementOrder(const std::string& caseDir) {
  return elementOrderOf(readCaseFile(caseDir, "system/frictionSolution"));
}

const std::vector<std::string>& FrictionCase::intersectionNotes3D(std::size_t f) {
  if (intersectionNotes_.empty()) {
    const std::vector<IntersectionCurve> curves =
        intersectionCurves(split_, system_->unsplitSpace().mesh());
    for (std::size_t g = 0; g < split_.fractures.size(); ++g)
      intersectionNotes_.push_back(intersectionNotes(split_, curves, g));
  }
  return intersectionNotes_.at(f);
}

void FrictionCase::writeTimeFolder(const StepResult& r, const Eigen::VectorXd& beta, long step) {
  if (!parallel::isMaster()) return;  // rank 0 writes every output file
  const int precision = time_->writePrecision();
  TimeFolder folder(caseDir_, time_->timeName(r.time));
  const FractureSystem& sys = *system_;
  const LagrangeSpace& space = sys.splitSpace();
  const int dim = sys.dimension();

  // Displacement at the split-mesh points (P2: the vertices, which come first).
  const Eigen::VectorXd u = sys.lastSplitDisplacement();
  std::vector<Point> points(split_.mesh.points.size(), Point::Zero());
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int c = 0; c < dim; ++c) points[i][c] = u[space.dof(static_cast<Index>(i), c)];
  writeDisplacementField(folder.file("D"), points, precision);

  std::ostringstream status;
  status << "status " << toString(r.report.status) << " iterations " << r.report.iterations
         << " backSubstitutions " << r.backSubstitutions << " J " << r.J << " relResidual "
         << r.relResidual << " maxExcessST " << r.maxExcessST << " equilibrium " << r.equilibrium;
  std::vector<VtkSeries::Fracture> vtkFractures;
  for (std::size_t f = 0; f < split_.fractures.size(); ++f) {
    VtkSeries::Fracture out{split_.fractures[f].name, {}};
    std::map<Index, Index> rowOf;  // control node -> its row
    out.rows = fractureRows(f, beta, &rowOf);
    writeFractureTable(folder.file("fractures/" + split_.fractures[f].name + ".dat"), out.rows,
                       status.str(), precision, dim,
                       dim == 2 ? junctionNotes(split_, f) : intersectionNotes3D(f));
    if (dim != 3) {
      vtkFractures.push_back(std::move(out));
      continue;
    }
    // 3D: the fault triangles as row indices for the .vtp (FractureSystem::triangleNodes). A
    // node whose row is in another fracture's table (joined: the first-listed one's) is
    // appended to this .vtp's rows, not to its table.
    out.nodesPerTriangle = space.degree() == 2 ? 6 : 3;
    std::map<int, std::pair<std::vector<FractureRow>, std::map<Index, Index>>> others;
    const auto row = [&](Index k) {
      const auto it = rowOf.find(k);
      if (it != rowOf.end()) return it->second;
      const int o = sys.controlNodes()[static_cast<std::size_t>(k)].fracture;
      auto found = others.find(o);
      if (found == others.end()) {
        found =
            others.emplace(o, std::make_pair(std::vector<FractureRow>{}, std::map<Index, Index>{}))
                .first;
        found->second.first =
            fractureRows(static_cast<std::size_t>(o), beta, &found->second.second);
      }
      out.rows.push_back(found->second.first.at(found->second.second.at(k)));
      return rowOf[k] = static_cast<Index>(out.rows.size()) - 1;
    };
    for (const auto& t : sys.triangleNodes(f)) {
      std::array<Index, 6> tri{};
      for (int j = 0; j < out.nodesPerTriangle; ++j) tri[j] = row(t[j]);
      out.triangles.push_back(tri);
    }
    // Per row, what the node does where the fault meets others (intersectionCodes, by the
    // fracture's nodes; P2 mid-edge nodes on the curves by FractureSystem).
    if (!intersectionNotes3D(f).empty()) {
      const std::vector<int> codes = intersectionCodes(split_, f);
      out.intersection.assign(out.rows.size(), 0);
      for (std::size_t i = 0; i < codes.size(); ++i)
        out.intersection[rowOf.at(sys.vertexControl(f)[i])] = codes[i];
      for (const auto& [k, at] : rowOf)
        if (sys.edgeIntersectionCode(k) != 0) out.intersection[at] = sys.edgeIntersectionCode(k);
    }
    vtkFractures.push_back(std::move(out));
  }
  DictionaryWriter st("dictionary", "solverStatus");
  st.entryWord("status", toString(r.report.status));
  st.entry("iterations", r.report.iterations);
  st.entry("backSubstitutions", r.backSubstitutions);
  st.entry("J", r.J);
  st.entry("relResidual", r.relResidual);
  st.entry("maxExcessST", r.maxExcessST);
  st.entry("equilibriumResidual", r.equilibrium);
  // Friction that weakens: the slipping patch's relative tangent stiffness (OptimizerReport;
  // "none" where no weakening node slips), which falls to 0 at the loss of equilibrium.
  if (weakening_) {
    if (std::isfinite(r.report.tangentStiffness))
      st.entry("patchStiffness", r.report.tangentStiffness);
    else
      st.entryWord("patchStiffness", "none");
  }
  st.writeAtomic(folder.file("solverStatus"));

  // What a restart needs, at full precision (the tables above use writePrecision). 'slip' and
  // 'lastIncrement' hold k values per fracture node, node-major (k = 1 in 2D): node i's
  // components on t₁ … t_k at k·i … k·i + k − 1, as restart() reads them.
  DictionaryWriter state("dictionary", "frictionState", "restart state of frictionSolver");
  state.entry("time", r.time);
  state.entry("step", static_cast<long>(step));
  state.entry("slip", std::vector<double>(slip_.data(), slip_.data() + slip_.size()));
  state.entry("lastIncrement", std::vector<double>(beta.data(), beta.data() + slip_.size()));
  // With fractures that open: the opening g per node [m] (0 where a fracture may not open).
  if (opening_)
    state.entry("opening",
                std::vector<double>(beta.data() + slip_.size(), beta.data() + beta.size()));
  // Rate-and-state faults: the state ψ per node and the integrator's own state.
  if (rateState_) {
    state.entry("psi", std::vector<double>(psi_.data(), psi_.data() + psi_.size()));
    state.entry("slipRate",
                std::vector<double>(slipRate_.data(), slipRate_.data() + slipRate_.size()));
  }
  if (timeIntegrator_->hasState()) {
    state.beginDict("integrator");
    timeIntegrator_->writeState(state);
    state.endDict();
  }
  // The fault outputs' sampling: the times of their last rows.
  if (faultSeries_) {
    state.beginDict("faultOutput");
    faultSeries_->writeState(state);
    state.endDict();
  }
  // Friction that weakens: the laws' state, the slip path δ per fracture node [m].
  if (weakening_)
    state.entry("slipPath",
                std::vector<double>(slipPath_.data(), slipPath_.data() + slipPath_.size()));
  // Effects with a state (faultPressure's computed diffusion), one sub-dictionary each.
  if (std::any_of(effects_.begin(), effects_.end(), [](const auto& e) { return e->hasState(); })) {
    state.beginDict("effects");
    for (const auto& e : effects_) {
      if (!e->hasState()) continue;
      state.beginDict(e->name());
      e->writeState(state);
      state.endDict();
    }
    state.endDict();
  }
  // The evaluation the tables above come from (quasiStatic, a converged step): a restart
  // makes it again bit for bit if its first step has this step's loads (restoreStep).
  if (evaluated_ && !rateState_ && r.report.status == OptimizerStatus::converged) {
    const auto list = [](const Eigen::VectorXd& v) {
      return std::vector<double>(v.data(), v.data() + v.size());
    };
    state.beginDict("restore");
    state.entry("time", evaluated_->time);
    state.entry("slip", list(evaluated_->slip));
    state.entry("control", list(evaluated_->beta));
    if (weakening_) {
      state.entry("slipPath", list(evaluated_->path));
      if (std::isfinite(evaluated_->tangentStiffness))
        state.entry("tangentStiffness", evaluated_->tangentStiffness);
      state.entry("stiffnessComponents", evaluated_->stiffnessComponents);
    }
    state.endDict();
  }
  // linearSolver auto: what it chose, which a restart takes again (chooseLinearSolver).
  if (linearSolverAuto_) state.entryWord("linearSolver", linearSolver_);
  state.writeAtomic(folder.file("uniform/frictionState"));

  // The VTK files first: the rename of the time folder commits the time. A run killed before
  // it restarts from the time before, which drops this time's VTK files and .pvd entry.
  if (time_->writeVTK()) {
    if (!vtk_)
      vtk_ = std::make_unique<VtkSeries>(caseDir_, "",
                                         time_->vtkBinary() ? VtkFormat::binary : VtkFormat::ascii);
    // The total stress: C:ε(u) plus what the effects add (initialStress's σ⁰, porePressure's
    // −α_B Δp_b I); nothing to add without them.
    std::function<Eigen::Matrix3d(Index, const Point&)> offset;
    if (hasStressOffset())
      offset = [this, t = r.time](Index cell, const Point& x) { return stressOffset(cell, x, t); };
    vtk_->write(r.time, time_->timeName(r.time), sys.splitSpace(), sys.splitAssembler(), u,
                vtkFractures, precision, offset);
  }
  if (history_) history_->sync();
  for (const auto& h : fractureHistories_) h->sync();
  if (faultSeries_) faultSeries_->sync();
  folder.commit();
}

}  // namespace friction
