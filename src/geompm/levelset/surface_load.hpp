// A distributed load on the soil's boundary (seed §3.5; docs/theory.md §16.3): a pressure or a
// traction integrated over the zero level set of the step (levelset/zero_level_set.hpp),
//   f_ext,a = int_Gamma N_a t dA,   t = -p n (a pressure p, positive into the body) or t given,
// with each facet's Gauss points and the shape functions of the cell it lies in. A pressure that
// follows the surface acts on the facets as the step's displacement moves them (their area
// vectors, and in axisymmetry their radii, at x = X + u), and adds its load stiffness
// -d f_ext / d du to the tangent (eq. 16.6); otherwise the load is fixed over the step, on the
// facets of its start.
#pragma once

#include <functional>
#include <vector>

#include "geompm/levelset/zero_level_set.hpp"
#include "geompm/physics/contribution.hpp"

namespace geompm {

class SurfaceLoad final : public Contribution {
 public:
  enum class Kind { Pressure, Traction };
  /// `value(x)`: the pressure (in x(0)) or traction at the start-of-step place x of a Gauss point,
  /// per unit area (per radian and unit length in axisymmetry, as loads are there). `follower`:
  /// a pressure that follows the surface (a traction is always fixed).
  SurfaceLoad(const GridSystem& grid, const DofMap& dofs, std::vector<SurfaceFacet> facets,
              Kind kind, bool follower, const std::function<Vec3(const Vec3&)>& value);
  const char* name() const override { return "surface load"; }
  /// A following pressure couples the nodes of each facet's cell.
  void declare_couplings(SparsityBuilder& pattern) const override;
  bool add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) override;

  const std::vector<SurfaceFacet>& facets() const { return facets_; }
  bool follower() const { return follower_; }
  /// f_ext at du per unknown (its stiffness -d f_ext / d du too, if `tangent`).
  Vector force(const Vector& du, SparseMatrix* tangent = nullptr) const;
  /// The sum of the load's nodal forces at du: the resultant on the body.
  Vec3 resultant(const Vector& du) const;

 private:
  /// What a facet needs at every evaluation: its cell's active nodes, the shape functions at its
  /// vertices and Gauss points, and the load at each Gauss point.
  struct Loaded {
    std::vector<Index> nodes;
    Eigen::MatrixXd N_vertex, N_point;  // (vertices or points) x nodes of the cell
    std::vector<FacetPoint> points;
    std::vector<Vec3> value;  // pressure (in x) or traction per Gauss point
  };
  void add_facet(std::size_t f, const Vector& du, Vector& f_ext, SparseMatrix* tangent) const;

  const GridSystem& grid_;
  const DofMap& dofs_;
  std::vector<SurfaceFacet> facets_;
  std::vector<Loaded> loaded_;
  Kind kind_;
  bool follower_;
  int u_;
};

}  // namespace geompm
