// The contact of a phase's rigid footings with the soil in one step (docs/theory.md §13): a
// penalty force law at the top of each candidate point's domain (eq. 13.6), the points held in
// contact through the step's iterations (ContactHold, eqs. 13.8-13.9), the force each footing
// exerts on the soil and, once the step is accepted, the footings' new positions and stick anchors.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "geompm/boundary/contact_hold.hpp"
#include "geompm/boundary/rigid_footing.hpp"
#include "geompm/physics/point_forces.hpp"

namespace geompm {

/// What the footings' contact needs of the model.
struct FootingContactInputs {
  std::vector<RigidFooting>* footings = nullptr;
  /// Per footing and body index: 1 if the footing acts on the body's points.
  std::vector<std::vector<char>> acts_on_body;
  /// Per point: its material's reference modulus (the penalty's scale, eq. 13.7).
  std::vector<double> modulus;
  double t0 = 0.0, t1 = 0.0;  // the step, in phase time
};

class FootingContact final : public PointForces {
 public:
  FootingContact(const GridSystem& grid, const MaterialPoints& points, const DofMap& dofs,
                 FootingContactInputs inputs);
  void iterate_accepted() override { hold(false); }
  void restart() override { hold(true); }
  /// The force each footing exerts on the soil, and the points touching it with their anchors.
  void report(const Vector& du, Reactions& reactions) override;
  /// The footings move to the step's end and keep the touching points' anchors.
  void commit() override;
  /// Footing k's displacement since the phase start at the end of the step.
  const Vec3& displacement(std::size_t k) const { return step_.displacement[k]; }

 private:
  // The rigid footings of a step: each footing's displacement and pose at the end of the step,
  // the points that may touch it with what the contact law needs of them, and, after
  // convergence, the points touching it with the anchors they used.
  struct Step {
    std::vector<Vec3> displacement;
    std::vector<FootingPose> pose;
    std::vector<std::vector<std::pair<Index, FootingContactPoint>>> points;
    std::vector<std::vector<int>> slot;  // per footing and point: its entry in `points`, or -1
    std::vector<std::unordered_map<Index, Vec3>> touching;  // point id -> anchor, per footing
    /// Per footing and candidate: pressed against the base at the contact law's last evaluation.
    std::vector<std::vector<char>> pressed;
    std::vector<ContactHold> hold;  // per footing: the candidates held in contact (eqs. 13.8-9)
  };
  struct Prepared {
    std::vector<char> acts;
    std::vector<Vec3> offset;
    Step step;
  };
  static Prepared prepare(const GridSystem& grid, const MaterialPoints& points,
                          const FootingContactInputs& inputs);
  FootingContact(const GridSystem& grid, const MaterialPoints& points, const DofMap& dofs,
                 std::vector<RigidFooting>& footings, Prepared prepared);
  /// After an accepted iterate (restart false) or before a new solve of the step (true).
  void hold(bool restart);
  void law(Index p, const Vec3& u, Vec3& force, Mat3& stiffness);

  std::vector<RigidFooting>& footings_;
  Step step_;
};

/// Per point: from the point to the top of its domain, carried by its deformation (eq. 13.1).
std::vector<Vec3> domain_top_offsets(const MaterialPoints& points, int dim);

}  // namespace geompm
