#include "geompm/core/types.hpp"

namespace geompm {

const char* to_string(Kinematics k) {
  switch (k) {
    case Kinematics::PlaneStrain:
      return "plane_strain";
    case Kinematics::Axisymmetric:
      return "axisymmetric";
    case Kinematics::ThreeD:
      return "3d";
  }
  return "?";
}

}  // namespace geompm
