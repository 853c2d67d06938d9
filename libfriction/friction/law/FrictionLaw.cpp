// Friction laws and their selection table.
#include "friction/law/FrictionLaw.hpp"

#include "friction/dict/Dictionary.hpp"

namespace friction {

namespace {

/// What a law's keys are read with: the fracture's dictionary, the case folder, the dimension.
struct LawInput {
  const Dictionary& d;
  const std::string& caseDir;
  int dim;
  FrictionField field(const std::string& key, Bounds bounds) const {
    return FrictionField::read(d, key, bounds, caseDir, dim);
  }
};

struct LawEntry {
  const char* name;
  std::unique_ptr<FrictionLaw> (*make)(const LawInput&);
};

// The one table of friction laws: adding one is one line here.
const LawEntry lawTable[] = {
    {"frictionless",
     [](const LawInput&) -> std::unique_ptr<FrictionLaw> {
       return std::make_unique<Frictionless>();
     }},
    {"tresca",
     [](const LawInput& in) -> std::unique_ptr<FrictionLaw> {
       return std::make_unique<Tresca>(in.field("threshold", Bounds::positive()));
     }},
    {"coulomb",
     [](const LawInput& in) -> std::unique_ptr<FrictionLaw> {
       return std::make_unique<Coulomb>(in.field("frictionCoefficient", Bounds::nonNegative()));
     }},
    {"coulombCohesion",
     [](const LawInput& in) -> std::unique_ptr<FrictionLaw> {
       return std::make_unique<CoulombCohesion>(
           in.field("frictionCoefficient", Bounds::nonNegative()),
           in.field("cohesion", Bounds::nonNegative()));
     }},
};

}  // namespace

std::vector<std::string> FrictionLaw::names() {
  std::vector<std::string> n;
  for (const auto& e : lawTable) n.push_back(e.name);
  return n;
}

std::unique_ptr<FrictionLaw> FrictionLaw::New(const Dictionary& dict, const std::string& caseDir,
                                              int dim) {
  const std::string type = dict.getChoice("law", names());
  for (const auto& e : lawTable)
    if (type == e.name) return e.make(LawInput{dict, caseDir, dim});
  return nullptr;  // unreachable: getChoice validated the name
}

}  // namespace friction
