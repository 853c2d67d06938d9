// Friction laws and their selection table.
#include "friction/law/FrictionLaw.hpp"

#include "friction/dict/Dictionary.hpp"

namespace friction {

namespace {

struct LawEntry {
  const char* name;
  std::unique_ptr<FrictionLaw> (*make)(const Dictionary&);
};

// The one table of friction laws: adding one is one line here.
const LawEntry lawTable[] = {
    {"frictionless",
     [](const Dictionary&) -> std::unique_ptr<FrictionLaw> {
       return std::make_unique<Frictionless>();
     }},
    {"tresca",
     [](const Dictionary& d) -> std::unique_ptr<FrictionLaw> {
       return std::make_unique<Tresca>(d.getScalar("threshold", Bounds::positive()));
     }},
    {"coulomb",
     [](const Dictionary& d) -> std::unique_ptr<FrictionLaw> {
       return std::make_unique<Coulomb>(d.getScalar("frictionCoefficient", Bounds::nonNegative()));
     }},
    {"coulombCohesion",
     [](const Dictionary& d) -> std::unique_ptr<FrictionLaw> {
       return std::make_unique<CoulombCohesion>(
           d.getScalar("frictionCoefficient", Bounds::nonNegative()),
           d.getScalar("cohesion", Bounds::nonNegative()));
     }},
};

}  // namespace

std::vector<std::string> FrictionLaw::names() {
  std::vector<std::string> n;
  for (const auto& e : lawTable) n.push_back(e.name);
  return n;
}

std::unique_ptr<FrictionLaw> FrictionLaw::New(const Dictionary& dict) {
  const std::string type = dict.getChoice("law", names());
  for (const auto& e : lawTable)
    if (type == e.name) return e.make(dict);
  return nullptr;  // unreachable: getChoice validated the name
}

}  // namespace friction
