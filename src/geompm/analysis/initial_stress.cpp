#include "geompm/analysis/initial_stress.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "geompm/core/error.hpp"
#include "geompm/core/expression.hpp"

namespace geompm {
namespace {

// The body is also among the K0 procedure's bodies: two initial stresses for one body.
void check_not_in_k0_procedure(const spec::Model& spec, const spec::Body& body) {
  if (spec.phases.empty() || !spec.phases.front().k0_procedure) return;
  const auto& listed = spec.phases.front().k0_procedure->bodies;
  if (!listed.empty() && std::find(listed.begin(), listed.end(), body.name) == listed.end()) return;
  throw InputError(body.initial_stress->source,
                   fmt::format("the body '{}' is also set by the K0 procedure of the first phase "
                               "({}, line {}): give it one initial stress (list the other "
                               "bodies in k0_procedure.bodies, or remove initial_stress)",
                               body.name, spec.phases.front().k0_procedure->source.key_path,
                               spec.phases.front().k0_procedure->source.line));
}

}  // namespace

void apply_initial_stresses(Model& model) {
  const spec::Model& spec = model.spec;
  const int dim = model.mesh.dim();
  MaterialPoints& points = model.points;
  for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
    const spec::Body& body = spec.bodies[b];
    if (!body.initial_stress) continue;
    check_not_in_k0_procedure(spec, body);
    const SourceLocation& where = body.initial_stress->source;
    std::array<Expression, 6> component;
    static const char* names[6] = {"xx", "yy", "zz", "xy", "yz", "xz"};
    for (int k = 0; k < 6; ++k)
      component[k] = Expression(body.initial_stress->components[k],
                                fmt::format("{}.{}", where.describe(), names[k]));
    // (xx, yy, zz, xy, yz, xz) into the symmetric tensor.
    constexpr int row[6] = {0, 1, 2, 0, 1, 0}, col[6] = {0, 1, 2, 1, 2, 2};
    for (Index p = 0; p < points.size(); ++p) {
      if (points.body[p] != static_cast<Index>(b)) continue;
      const Vec3& x = points.position[p];
      Mat3 sigma = Mat3::Zero();
      for (int k = 0; k < 6; ++k)
        sigma(row[k], col[k]) = sigma(col[k], row[k]) = component[k](x.x(), x.y(), x.z(), 0.0);
      // F = I at the start: tau = sigma; the elastic strain that gives it (theory eq. 10.3).
      const Index m = points.material[p];
      const Material& law = *model.materials[m];
      const std::string& material = spec.materials[m].name;
      const std::optional<Mat3> strain = law.elastic_strain_for_stress(sigma, points.internal[p]);
      if (!strain)
        throw InputError(where, fmt::format("the material model '{}' of material '{}' cannot "
                                            "start from a given stress",
                                            law.model_name(), material));
      // Admissible as in the K0 procedure: the material's update at that strain gives the same
      // stress back; a stress outside the yield surface would be returned to it.
      StressUpdate check;
      law.update(*strain, points.internal[p], check);
      const double scale = std::max(sigma.norm(), 1e-12 * law.reference_modulus());
      if ((check.kirchhoff - sigma).norm() > 1e-9 * scale)
        throw InputError(
            where,
            fmt::format("the initial stress of the point at {} of body '{}' lies outside the "
                        "yield surface of '{}' (material '{}'): sxx = {:g}, syy = {:g}, szz = "
                        "{:g}, sxy = {:g}; the material would return it to {:g}, {:g}, {:g}, {:g}",
                        dim == 3 ? fmt::format("[{:g}, {:g}, {:g}]", x.x(), x.y(), x.z())
                                 : fmt::format("[{:g}, {:g}]", x.x(), x.y()),
                        body.name, law.model_name(), material, sigma(0, 0), sigma(1, 1),
                        sigma(2, 2), sigma(0, 1), check.kirchhoff(0, 0), check.kirchhoff(1, 1),
                        check.kirchhoff(2, 2), check.kirchhoff(0, 1)));
      points.stress[p] = sigma;
      points.elastic_left_cauchy_green[p] = symmetric_exp(2.0 * *strain);
    }
  }
}

}  // namespace geompm
