#include "geompm/materials/isotropic_elastic.hpp"

#include "geompm/materials/linear_elastic.hpp"
#include "geompm/materials/neo_hookean.hpp"
#include "geompm/materials/parameters.hpp"

namespace geompm {

IsotropicElastic::IsotropicElastic(double E, double nu, double density)
    : E_(E), nu_(nu), density_(density), lambda_(lame_lambda(E, nu)), mu_(shear_modulus(E, nu)) {}

template <class Law>
std::unique_ptr<Material> IsotropicElastic::create_from(const char* model, const ParameterMap& p) {
  ParameterReader r(model, p, {"E", "nu", "density"});
  return std::make_unique<Law>(ParameterReader::positive("E", r.required("E")),
                               ParameterReader::poisson_ratio("nu", r.required("nu")),
                               ParameterReader::non_negative("density", r.optional("density", 0)));
}

std::unique_ptr<Material> LinearElastic::create(const ParameterMap& p) {
  return create_from<LinearElastic>("linear_elastic", p);
}

std::unique_ptr<Material> NeoHookean::create(const ParameterMap& p) {
  return create_from<NeoHookean>("neo_hookean", p);
}

}  // namespace geompm
