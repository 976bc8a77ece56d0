#pragma once
// A function of x given as text ("0.5 + sin(2*pi*x)"), evaluated by muParser.
// The one place muParser is used.
#include <memory>
#include <string>

namespace shockgas {

class Expression {
 public:
  // key names the scene key for error messages; throws InputError if the
  // text does not parse.
  Expression(const std::string& text, const std::string& key);
  ~Expression();
  Expression(const Expression& other);
  Expression& operator=(const Expression&) = delete;

  double operator()(double x) const;
  const std::string& text() const { return text_; }

  // Throws InputError unless the expression is finite at n points of [a, b].
  void require_finite_on(double a, double b, int n = 1001) const;

  struct Impl;  // the parser state (muParser is not const-callable)

 private:
  std::string text_, key_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace shockgas
