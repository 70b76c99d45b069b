// A scalar expression of x, y, z and t given in a model file ("0.1*sin(pi*x/50)"), evaluated
// with muparser. Used for initial fields, prescribed motions and loads as functions of time.
#pragma once

#include <memory>
#include <string>

namespace geompm {

class Expression {
 public:
  Expression();  // the constant 0
  /// Parses `text`; throws std::invalid_argument with muparser's message if it is not a valid
  /// expression of x, y, z, t (constants pi and e are defined).
  explicit Expression(const std::string& text);
  Expression(const Expression& other);
  Expression& operator=(const Expression& other);
  ~Expression();

  double operator()(double x, double y, double z, double t) const;
  double at_time(double t) const { return (*this)(0.0, 0.0, 0.0, t); }
  const std::string& text() const { return text_; }
  bool is_constant_zero() const { return text_ == "0"; }

 private:
  struct Impl;
  std::string text_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace geompm
