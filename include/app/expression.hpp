// Expressions in x, y, z and t for scene values (muparser syntax: sin, cos, exp, min, max,
// _pi, _e, ^, ...). A number is a constant expression.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

namespace num::app {

struct ExpressionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class Expression {
  public:
    /// A constant (the default is 0); implicit so that a number can stand for an expression.
    Expression(double value = 0.0) : constant_(value) {}
    /// Parses `text`; throws ExpressionError with the parser's message and position.
    static Expression parse(const std::string& text);

    double operator()(double x, double y, double z, double t) const;
    bool isConstant() const { return impl_ == nullptr; }
    /// Depends on t (false for constants).
    bool dependsOnTime() const;
    /// The variables the expression uses, of "xyzt" in that order ("" for constants).
    std::string variables() const;
    /// The source text ("" for constants).
    const std::string& text() const;

  private:
    struct Impl;
    double constant_ = 0.0;
    std::shared_ptr<Impl> impl_;
};

}  // namespace num::app
