// GIMP: weights averaged over each point's domain (docs/theory.md §9), on a rectilinear grid.
#pragma once

#include "geompm/interpolation/interpolation.hpp"
#include "geompm/mesh/rectilinear_grid.hpp"

namespace geompm {

class Gimp final : public Interpolation {
 public:
  /// Throws std::invalid_argument if `mesh` is not a rectilinear grid.
  Gimp(const Mesh& mesh, Kinematics kinematics);
  const char* name() const override { return "gimp"; }
  bool wide() const override { return true; }
  void before_activation(const MaterialPoints& points, std::vector<char>& occupied,
                         WideStencils& out) const override;
  void after_activation(const MaterialPoints& points, const StencilInputs& in,
                        WideStencils& out) const override;

 private:
  RectilinearGrid grid_;
  Kinematics kinematics_;
  int dim_;
};

}  // namespace geompm
