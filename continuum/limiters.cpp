// Names of the slope limiters as the scene spells them (key continuum.limiter).
#include "shockgas/continuum/limiters.hpp"

#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

Limiter limiter_from_name(const std::string& name) {
  if (name == "minmod") return Limiter::minmod;
  if (name == "vanleer") return Limiter::vanleer;
  if (name == "mc") return Limiter::mc;
  throw InputError("continuum.limiter", to_text(name), "\"minmod\", \"vanleer\" or \"mc\"");
}

std::string limiter_name(Limiter limiter) {
  switch (limiter) {
    case Limiter::minmod:
      return "minmod";
    case Limiter::vanleer:
      return "vanleer";
    case Limiter::mc:
      break;
  }
  return "mc";
}

}  // namespace shockgas::continuum
