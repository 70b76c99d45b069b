#include "geompm/core/expression.hpp"

#include <fmt/format.h>
#include <muParser.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include "geompm/core/agreement.hpp"
#include "geompm/core/error.hpp"

namespace geompm {

// muparser binds variables by address, so each Expression owns its parser and variables.
// Evaluation mutates those variables: an Expression is not shared between threads.
struct Expression::Impl {
  mu::Parser parser;
  double x = 0, y = 0, z = 0, t = 0;

  explicit Impl(const std::string& text) {
    parser.DefineVar("x", &x);
    parser.DefineVar("y", &y);
    parser.DefineVar("z", &z);
    parser.DefineVar("t", &t);
    parser.DefineConst("pi", M_PI);
    parser.DefineConst("e", M_E);
    parser.SetExpr(text);
    parser.Eval();  // compiles now, so a bad expression fails while the model is read
    for (const auto& [name, address] : parser.GetUsedVar()) used += name;
  }
  std::string used;  // the variables it uses, "xt" (for messages)
};

Expression::Expression() : Expression("0") {}

Expression::Expression(const std::string& text) : text_(text) {
  try {
    impl_ = std::make_unique<Impl>(text);
  } catch (const mu::Parser::exception_type& e) {
    throw std::invalid_argument("invalid expression '" + text + "': " + e.GetMsg());
  }
}

Expression::Expression(const std::string& text, std::string where) : Expression(text) {
  where_ = std::move(where);
}

Expression::Expression(const Expression& other) : Expression(other.text_) { where_ = other.where_; }

Expression& Expression::operator=(const Expression& other) {
  if (this != &other) {
    text_ = other.text_;
    where_ = other.where_;
    impl_ = std::make_unique<Impl>(other.text_);
  }
  return *this;
}

Expression::~Expression() = default;

double Expression::operator()(double x, double y, double z, double t) const {
  impl_->x = x;
  impl_->y = y;
  impl_->z = z;
  impl_->t = t;
  const double value = impl_->parser.Eval();
  if (!std::isfinite(value)) {
    std::string at;
    const std::pair<char, double> arguments[] = {{'x', x}, {'y', y}, {'z', z}, {'t', t}};
    for (const auto& [name, v] : arguments)
      if (impl_->used.find(name) != std::string::npos)
        at += fmt::format("{}{} = {:g}", at.empty() ? " at " : ", ", name, v);
    throw NonFiniteValue(fmt::format(
        "{}{}the expression '{}' is {}{}; expected a finite number (a division by zero, the log "
        "of 0, the root of a negative number?)",
        where_, where_.empty() ? "" : ": ", text_,
        std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf"), at));
  }
  return value;
}

double Expression::at_time(double t) const {
  try {
    return (*this)(0.0, 0.0, 0.0, t);
  } catch (const NonFiniteValue& e) {
    throw Shared<NonFiniteValue>(e.what());
  }
}

}  // namespace geompm
