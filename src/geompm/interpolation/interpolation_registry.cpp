// The interpolations by name: one line each.
#include <stdexcept>

#include "geompm/interpolation/dual_domain.hpp"
#include "geompm/interpolation/gimp.hpp"
#include "geompm/interpolation/standard.hpp"

namespace geompm {
namespace {

struct Entry {
  GridInterpolation kind;
  const char* name;
  std::unique_ptr<Interpolation> (*make)(const Mesh& mesh, Kinematics kinematics);
};

const Entry registry[] = {
    {GridInterpolation::Standard, "standard",
     [](const Mesh&, Kinematics) -> std::unique_ptr<Interpolation> {
       return std::make_unique<StandardInterpolation>();
     }},
    {GridInterpolation::DualDomain, "ddmp",
     [](const Mesh&, Kinematics) -> std::unique_ptr<Interpolation> {
       return std::make_unique<DualDomainInterpolation>();
     }},
    {GridInterpolation::Gimp, "gimp",
     [](const Mesh& mesh, Kinematics kinematics) -> std::unique_ptr<Interpolation> {
       return std::make_unique<Gimp>(mesh, kinematics);
     }},
};

const Entry& entry(GridInterpolation kind) {
  for (const Entry& e : registry)
    if (e.kind == kind) return e;
  throw std::invalid_argument("unknown interpolation");
}

}  // namespace

std::unique_ptr<Interpolation> make_interpolation(GridInterpolation kind, const Mesh& mesh,
                                                  Kinematics kinematics) {
  return entry(kind).make(mesh, kinematics);
}

const char* interpolation_name(GridInterpolation kind) { return entry(kind).name; }

}  // namespace geompm
