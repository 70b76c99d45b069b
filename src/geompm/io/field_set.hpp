// Named arrays of values attached to the points or nodes or cells of an output file.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "geompm/core/types.hpp"

namespace geompm {

struct FieldSet {
  std::vector<std::pair<std::string, std::vector<double>>> scalars;
  std::vector<std::pair<std::string, std::vector<Vec3>>> vectors;  // 3 components
  std::vector<std::pair<std::string, std::vector<Mat3>>> tensors;  // symmetric: written as 6
  std::vector<std::pair<std::string, std::vector<Index>>> integers;
};

}  // namespace geompm
