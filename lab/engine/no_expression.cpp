// shockgas::Expression for the lab's WebAssembly build, which has no expression
// parser (muParser is not built for it): every expression is refused with a
// message. The lab's scenes give v0 and rho0 as compiled functions
// (lab_scenes.cpp), so nothing in the lab parses one; the native build links
// shockgas/core/expression.cpp instead.
#include "shockgas/core/error.hpp"
#include "shockgas/core/expression.hpp"

namespace shockgas {

struct Expression::Impl {};

Expression::Expression(const std::string& text, const std::string& key) : text_(text), key_(key) {
  throw InputError(key, "\"" + text + "\"", "a scene of the lab (this build has no expression parser)");
}

Expression::Expression(const Expression& other) : Expression(other.text_, other.key_) {}

Expression::~Expression() = default;

double Expression::operator()(double) const { return 0; }

void Expression::require_finite_on(double, double, int) const {}

}  // namespace shockgas
