// Model file key `initial_stress` of a body: the Cauchy stress its points start from, given
// directly (docs/user-guide.md, "initial_stress"), as an alternative to the K0 procedure.
#include <fmt/format.h>

#include "geompm/io/model_reader_sections.hpp"

namespace geompm::model_reader {

spec::InitialStress read_initial_stress(const yaml::Node& node, const Context& context) {
  const bool three_d = context.dimension == 3;
  // Plane strain and axisymmetry have the out-of-plane (hoop) normal stress szz but no shear
  // with z.
  const yaml::Map section = three_d ? node.map({"sxx", "syy", "szz", "sxy", "syz", "sxz"})
                                    : node.map({"sxx", "syy", "szz", "sxy"});
  const std::vector<std::string> variables =
      three_d ? std::vector<std::string>{"x", "y", "z"} : std::vector<std::string>{"x", "y"};
  const char* keys[] = {"sxx", "syy", "szz", "sxy", "syz", "sxz"};
  spec::InitialStress stress;
  stress.source = node.where();
  bool any = false;
  for (int k = 0; k < (three_d ? 6 : 4); ++k)
    if (auto value = section.find(keys[k])) {
      stress.components[k] = read_expression(*value, variables);
      any = true;
    }
  if (!any)
    node.fail(fmt::format(
        "expected the Cauchy stress components (tension positive) as numbers or expressions of {}, "
        "such as {{sxx: -66, syy: -66, szz: -66}}; allowed: {}",
        three_d ? "x, y, z" : "x, y",
        three_d ? "sxx, syy, szz, sxy, syz, sxz" : "sxx, syy, szz, sxy"));
  return stress;
}

}  // namespace geompm::model_reader
