// The registry of material models by name. Adding a material: one file, one line below.
#include <fmt/format.h>

#include <functional>
#include <utility>

#include "geompm/core/error.hpp"
#include "geompm/materials/linear_elastic.hpp"
#include "geompm/materials/material.hpp"
#include "geompm/materials/mohr_coulomb.hpp"
#include "geompm/materials/neo_hookean.hpp"
#include "geompm/materials/tresca.hpp"

namespace geompm {

namespace {

using Creator = std::function<std::unique_ptr<Material>(const ParameterMap&)>;

const std::vector<std::pair<std::string, Creator>>& registry() {
  static const std::vector<std::pair<std::string, Creator>> entries = {
      {"linear_elastic", &LinearElastic::create}, {"hencky", &LinearElastic::create},
      {"neo_hookean", &NeoHookean::create},       {"tresca", &Tresca::create},
      {"mohr_coulomb", &MohrCoulomb::create},
  };
  return entries;
}

}  // namespace

std::vector<std::string> material_models() {
  std::vector<std::string> names;
  for (const auto& [name, creator] : registry()) names.push_back(name);
  return names;
}

std::unique_ptr<Material> create_material(const std::string& model, const ParameterMap& p) {
  for (const auto& [name, creator] : registry())
    if (name == model) return creator(p);
  throw ParameterError("model", fmt::format("unknown material model '{}'; known models: {}", model,
                                            fmt::join(material_models(), ", ")));
}

}  // namespace geompm
