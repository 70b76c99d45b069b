#include "geompm/physics/point_forces.hpp"

namespace geompm {

PointForces::PointForces(const char* name, const GridSystem& grid, const MaterialPoints& points,
                         std::vector<char> acts, PointForceLaw law)
    : grid_(grid), points_(points), acts_(std::move(acts)), name_(name), law_(std::move(law)) {}

}  // namespace geompm
