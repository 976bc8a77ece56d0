#include "shockgas/core/expression.hpp"

#include <muParser.h>

#include <cmath>
#include <numbers>

#include "shockgas/core/error.hpp"

namespace shockgas {

struct Expression::Impl {
  mu::Parser parser;
  mutable double x = 0;
};

namespace {
void setup(Expression::Impl& impl, const std::string& text, const std::string& key) {
  try {
    impl.parser.DefineVar("x", &impl.x);
    impl.parser.DefineConst("pi", std::numbers::pi);
    impl.parser.DefineConst("e", std::numbers::e);
    impl.parser.SetExpr(text);
    impl.parser.Eval();  // parse now, so errors surface before any run
  } catch (const mu::Parser::exception_type& e) {
    throw InputError(key, "\"" + text + "\"",
                     "an expression in x (muParser syntax; constants pi, e): " + e.GetMsg());
  }
}
}  // namespace

Expression::Expression(const std::string& text, const std::string& key)
    : text_(text), key_(key), impl_(std::make_unique<Impl>()) {
  setup(*impl_, text_, key_);
}

Expression::Expression(const Expression& other)
    : text_(other.text_), key_(other.key_), impl_(std::make_unique<Impl>()) {
  setup(*impl_, text_, key_);
}

Expression::~Expression() = default;

double Expression::operator()(double x) const {
  impl_->x = x;
  return impl_->parser.Eval();
}

void Expression::require_finite_on(double a, double b, int n) const {
  for (int i = 0; i < n; ++i) {
    const double x = a + (b - a) * i / (n - 1);
    const double y = (*this)(x);
    if (!std::isfinite(y))
      throw InputError(key_, "\"" + text_ + "\"",
                       "an expression finite on [" + to_text(a) + ", " + to_text(b) + "] (it is " +
                           to_text(y) + " at x = " + to_text(x) + ")");
  }
}

}  // namespace shockgas
