// The restitution law registry (restitution_laws.hpp): the built-in law, then any
// a program adds.
#include "shockgas/particles/restitution_laws.hpp"

#include "shockgas/core/error.hpp"

namespace shockgas::particles {

namespace {

// r(g) = particles.r: the engine's own constant rule.
RestitutionLawInfo constant_law() {
  return {kConstantRestitution, "r(g) = particles.r for every g >= delta",
          [](const ParticleParams&) { return RestitutionLaw{}; }};
}

std::vector<RestitutionLawInfo>& registry() {
  static std::vector<RestitutionLawInfo> laws = {constant_law()};
  return laws;
}

}  // namespace

void register_restitution_law(RestitutionLawInfo info) {
  require(!info.name.empty(), "particles.restitution_law", info.name, "a law with a name");
  require(static_cast<bool>(info.make), "particles.restitution_law", info.name, "a law with a make function");
  for (const auto& law : registry())
    require(law.name != info.name, "particles.restitution_law", info.name, "a name not yet registered");
  registry().push_back(std::move(info));
}

const std::vector<RestitutionLawInfo>& registered_restitution_laws() { return registry(); }

std::vector<std::string> restitution_law_names() {
  std::vector<std::string> names;
  for (const auto& law : registry()) names.push_back(law.name);
  return names;
}

const RestitutionLawInfo& restitution_law_info(const std::string& name) {
  for (const auto& law : registry())
    if (law.name == name) return law;
  throw InputError("particles.restitution_law", to_text(name),
                   "one of " + choices_text(restitution_law_names()));
}

RestitutionLaw restitution_law(const ParticleParams& p) {
  RestitutionLaw law = restitution_law_info(p.restitution_law).make(p);
  if (!law) return law;
  return [law = std::move(law), name = p.restitution_law](double g) {
    const double r = law(g);
    if (!(r > 0.0 && r <= 1.0))
      throw RunError("particles.restitution_law = " + to_text(name) + " gives r(" + to_text(g) +
                     ") = " + to_text(r) + ", outside (0, 1]");
    return r;
  };
}

}  // namespace shockgas::particles
