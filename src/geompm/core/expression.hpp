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
  /// The same, with where it was given ("model.yaml:23: phases[1].loads[0] force[1]"), named
  /// by the error a non-finite value throws.
  Expression(const std::string& text, std::string where);
  Expression(const Expression& other);
  Expression& operator=(const Expression& other);
  ~Expression();

  /// The value; throws NonFiniteValue (naming the expression, where it was given and the
  /// arguments) if it is NaN or infinite: no such value may pass silently into a run.
  double operator()(double x, double y, double z, double t) const;
  /// The value at time t alone. A non-finite one is thrown as met by every process of a
  /// distributed run (core/agreement.hpp): each evaluates the phase's functions of time at the
  /// same t.
  double at_time(double t) const;
  const std::string& text() const { return text_; }
  bool is_constant_zero() const { return text_ == "0"; }

 private:
  struct Impl;
  std::string text_, where_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace geompm
