// The contact of a structure with the soil in one step (seed §3.7, after Andreykiv et al. 2011;
// docs/theory.md §18): the structure's surface is embedded in the background grid, and a segment
// of it penetrates the soil where the soil's density-based level set is positive there. Within
// the step the penetration and the slip of each segment are linear in the step's unknowns: the
// structure's motion at its Gauss points against the grid's displacement there. Each segment has
// Lagrange multipliers, unknowns of the step (field "contact:<structure>"), and the contact
// conditions are semi-smooth equations in them (contact/contact_law.hpp), solved by the same
// Newton iterations as the rest: no penalty to choose, and the scale c = E / h that makes the
// multipliers lengths changes the iterations, not the result.
#pragma once

#include <optional>
#include <vector>

#include "geompm/contact/contact_pair.hpp"
#include "geompm/contact/contact_surface.hpp"
#include "geompm/levelset/level_set.hpp"
#include "geompm/physics/contribution.hpp"
#include "geompm/structures/structure.hpp"

namespace geompm {

class LevelSetContact final : public Contribution {
 public:
  /// Adds the pair's multipliers to `dofs` (after the structure's and the grid's fields).
  /// `modulus`: the soil's Young's modulus for the scale c = modulus / h.
  LevelSetContact(const GridSystem& grid, const MaterialPoints& points, const PointLocator& locator,
                  const Structure& structure, ContactPair& pair, double modulus, DofMap& dofs);
  const char* name() const override { return "contact"; }

  void declare_couplings(SparsityBuilder& pattern) const override;
  bool add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) override;
  /// The contact force on the structure into reactions.contacts. Collective in a distributed
  /// run: process 0 evaluates the contact (a term of no point), and every process takes its
  /// segments' states, which the next step's tracking reads.
  void report(const Vector& du, Reactions& reactions) override;
  /// The pair keeps the converged multipliers, pressures, shears and states.
  void commit() override;

  /// The number of segments in the step's grid (those with multipliers).
  Index active_segments() const { return static_cast<Index>(segments_.size()); }

 private:
  /// A group of pieces of the surface over about two background cells, facing one way, with one
  /// set of multipliers (eq. 18.1): its mean penetration and slip, p = p0 + sum dp_j du_j and s_t =
  /// sum ds_tj du_j, over the unknowns j of the structure and of the grid nodes around its Gauss
  /// points (eq. 18.3), and its multipliers at the start of the step.
  struct Kinematics {
    std::vector<Index> pieces;                      // in contact_segments' numbering
    double measure = 0.0, scale = 0.0, cell = 0.0;  // A, c, h
    double p0 = 0.0;
    double strength = 0.0;  // with adhesion alpha: the soil's mean s_u where it is read
    std::array<double, 3> start = {0.0, 0.0, 0.0};
    std::vector<Index> dofs;
    std::vector<double> dp;
    std::vector<std::array<double, 2>> ds;
  };
  /// The pieces grouped by the background cell their centre lies in and by the way they face,
  /// merged to span two cells (four in 3D); pieces outside the step's grid are left out.
  std::vector<std::vector<Index>> group_pieces() const;
  bool build_kinematics(const std::vector<Index>& pieces, Kinematics& k) const;
  double multiplier(const Vector& du, std::size_t k, int component) const;
  /// Segment k's mean penetration p at the increment du (eq. 18.3).
  double penetration(const Vector& du, std::size_t k) const;
  /// A segment's tangential equations with their derivatives with respect to (p, s_0, s_1, l_n,
  /// l_t0, l_t1): the vector law where the shear is bounded in 3D, else each tangent's own `e`.
  TangentialPair tangential_rows(const ContactLaw& law, double scale, double p,
                                 const double slip[2], double l_n, const double l_t[2],
                                 const ContactEquations e[2]) const;
  /// Throws RunError if mesh cell `cell`, which the surface at x reaches, is an FEM cell.
  void refuse_fem_cell(Index cell, const Vec3& x) const;
  std::optional<Location> soil_cell(const Vec3& x, const Vec3& normal, double h, Index cell) const;
  /// With adhesion: per active cell, the mean s_u of the touched bodies' points in it (0 if none
  /// carries one), over every process's points.
  void find_cell_strengths();
  /// The mean s_u of the touched bodies' points in a mesh cell (0 if none carries one).
  double cell_strength(Index cell) const;
  std::vector<double> fill_;  // per mesh cell: the fraction its points cover (0 outside the grid)
  std::vector<double> strength_;       // per active cell (find_cell_strengths)
  std::vector<Index> active_of_cell_;  // per mesh cell: its index among the active cells, or -1
  std::vector<int> su_index_;          // per material: its internal variable "su", or -1
  static constexpr double fill_threshold_ = 0.5;  // a cell at least half filled holds its nodes

  const GridSystem& grid_;
  const MaterialPoints& points_;
  const PointLocator& locator_;
  const Structure& structure_;
  const LevelSet level_set_;
  const DofMap& dofs_;
  ContactPair& pair_;
  int dim_ = 2;
  int tangents_ = 0;  // tangential multipliers per segment: 0 (smooth), 1 (2D), 2 (3D)
  double modulus_ = 0.0;
  std::vector<ContactSegment> all_;   // the structure's surface in pieces about a cell long
  std::vector<Kinematics> segments_;  // groups of pieces in the step's grid, with multipliers
  int field_ = -1;
  // At the last evaluation, per segment with multipliers: the law's state.
  std::vector<ContactState> state_;
  std::vector<std::array<double, 3>> converged_;  // multipliers at the last report()
  std::vector<double> converged_penetration_;     // and penetrations
};

}  // namespace geompm
