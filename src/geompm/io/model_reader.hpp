// Reads a model file (YAML; JSON is valid YAML) into a spec::Model, checking every key: unknown
// keys, wrong types, missing required keys, out-of-range values, names that refer to nothing,
// non-finite numbers. The first problem is thrown as an InputError naming the file, the key path
// and the line.
#pragma once

#include <string>

#include "geompm/spec/model_spec.hpp"

namespace geompm {

spec::Model read_model(const std::string& path);

/// The same from text (for tests); `file_name` is used in messages and to resolve relative paths.
spec::Model read_model_from_string(const std::string& text, const std::string& file_name);

}  // namespace geompm
