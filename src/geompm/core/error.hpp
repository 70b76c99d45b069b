// Errors that reach the user. Every message says where (file, key path, line) and what was
// expected, so that a bad model is fixed without reading source code.
#pragma once

#include <stdexcept>
#include <string>

namespace geompm {

/// Where a value of the model came from: file, key path ("phases[1].gravity") and line (0 when
/// the format gave none).
struct SourceLocation {
  std::string file;
  std::string key_path;
  int line = 0;

  std::string describe() const;  // "model.yaml:12: phases[1].gravity"
};

/// "model.yaml:23: phases[1].loads[0] (its y component)": a component (0, 1, 2) of a vector
/// given at `where`, for messages about one of its values.
std::string component_place(const SourceLocation& where, int component);

/// Bad input: a model file, a mesh file or a command-line argument. Exit code 2.
class InputError : public std::runtime_error {
 public:
  InputError(const SourceLocation& where, const std::string& what);
  explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

/// A run that cannot go on (time step below its minimum, a point left the mesh under the "stop"
/// policy). Finished work has been written before it is thrown. Exit code 3.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An expression of the model file that gives NaN or infinity where it is evaluated (its message
/// names the expression, where it was given and the arguments). Met in a run, it stops the run
/// (exit code 3); where it is evaluated while the model is built, the builder makes it an
/// InputError.
class NonFiniteValue : public RunError {
 public:
  using RunError::RunError;
};

/// A material parameter that is missing or out of range; the model reader turns it into an
/// InputError with the key path of the material.
class ParameterError : public std::runtime_error {
 public:
  ParameterError(std::string key, const std::string& what)
      : std::runtime_error(what), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

}  // namespace geompm
