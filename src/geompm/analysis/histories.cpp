#include "geompm/analysis/histories.hpp"

#include <array>
#include <limits>

#include "geompm/core/tensor.hpp"
#include "geompm/structures/cross_section.hpp"
#include "geompm/structures/deformable_structure.hpp"
#include "geompm/structures/node_selection.hpp"
#include "geompm/structures/rigid_structure.hpp"

namespace geompm {

HistoryRecorder::HistoryRecorder(const Model& model) : histories_(model.spec.output.histories) {
  for (const auto& h : histories_)
    set_bits_.push_back(h.point_set.empty() ? -1 : model.point_set_bit(h.point_set));
}

std::vector<std::string> HistoryRecorder::columns() const {
  std::vector<std::string> c = {"time", "step"};
  for (const auto& h : histories_) c.push_back(h.name);
  return c;
}

double kinetic_energy(const Model& model) {
  const auto& p = model.points;
  double e = 0.0;
  for (Index i = 0; i < p.size(); ++i) e += 0.5 * p.mass[i] * p.velocity[i].squaredNorm();
  return e;
}

double strain_energy(const Model& model) {
  // Stored energy W(eps_e) per unit reference volume, eps_e = 1/2 ln(b_e).
  const auto& p = model.points;
  double e = 0.0;
  for (Index i = 0; i < p.size(); ++i) {
    const Mat3 eps = 0.5 * symmetric_log(p.elastic_left_cauchy_green[i]);
    e += p.initial_volume[i] * model.materials[p.material[i]]->strain_energy(eps);
  }
  return e;
}

namespace {

// A deformable structure's history (docs/theory.md §17.7): the mean over some of its nodes (all
// by default) of their displacement or position, or the mean normal stress over a cross section
// (eq. 17.15).
double deformable_value(const DeformableStructure& body, const spec::History& h) {
  if (h.quantity == "section_stress")
    return section_stress(body, h.section_point, h.section_normal).mean_normal_stress;
  const std::vector<Index> nodes =
      select_nodes(body.mesh(), h.nodes.value_or(spec::StructureNodes{}));
  Vec3 sum = Vec3::Zero();
  for (Index a : nodes)
    sum += h.quantity == "displacement"         ? body.displacement(a)
           : h.quantity == "phase_displacement" ? body.phase_displacement(a)
                                                : body.mesh().nodes()[a];
  return h.quantity == "displacement" || h.quantity == "phase_displacement" ||
                 h.quantity == "position"
             ? sum(h.component) / static_cast<double>(nodes.size())
             : std::numeric_limits<double>::quiet_NaN();
}

// A structure's history (docs/theory.md §17.4): what its drive exerts (reaction, moment) at the
// last converged step, its motion since the start of the analysis or of the phase, where its
// reference point is. Reactions are 0 before the first step.
double structure_value(const Model& model, const spec::History& h, const StepResult* step) {
  if (h.quantity == "contact_force")  // the soil's push on it (docs/theory.md eq. 18.10)
    for (const ContactPair& pair : model.contacts)
      if (pair.name == h.structure) return pair.force(h.component);
  for (const auto& structure : model.structures) {
    if (structure->name() != h.structure) continue;
    const int c = h.component;
    if (h.quantity == "reaction" || h.quantity == "moment") {
      if (!step) return 0.0;
      const auto it = step->structure_forces.find(h.structure);
      if (it == step->structure_forces.end()) return 0.0;
      return (h.quantity == "reaction" ? it->second.force : it->second.moment)(c);
    }
    if (const auto* body = dynamic_cast<const DeformableStructure*>(structure.get()))
      return deformable_value(*body, h);
    const auto* rigid = dynamic_cast<const RigidStructure*>(structure.get());
    if (!rigid) return std::numeric_limits<double>::quiet_NaN();
    if (h.quantity == "displacement") return rigid->displacement()(c);
    if (h.quantity == "rotation") return rigid->rotation()(c);
    if (h.quantity == "phase_displacement") return rigid->phase_displacement()(c);
    if (h.quantity == "phase_rotation") return rigid->phase_rotation()(c);
    if (h.quantity == "position") return rigid->reference_point()(c);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

namespace {

// Sum of w f and of w over point set `set`, w the mass (the volume for a weightless point): a
// mass-weighted mean (volume-weighted for a weightless set).
std::array<double, 2> point_set_sums(const MaterialPoints& p, int set, int component,
                                     const std::vector<Vec3>& field) {
  double sum = 0.0, weight = 0.0;
  for (Index i = 0; i < p.size(); ++i)
    if (p.sets[i] >> set & 1u) {
      const double w = p.mass[i] > 0 ? p.mass[i] : p.volume[i];
      sum += w * field[i](component);
      weight += w;
    }
  return {sum, weight};
}

// The history's value from its sums: a mean (NaN over no point, all of its points left the mesh)
// or an energy.
double from_sums(const spec::History& h, const std::vector<double>& sums, std::size_t k) {
  if (h.quantity == "kinetic_energy" || h.quantity == "strain_energy") return sums[2 * k];
  const double weight = sums[2 * k + 1];
  return weight > 0 ? sums[2 * k] / weight : std::numeric_limits<double>::quiet_NaN();
}

bool reads_points(const spec::History& h) {
  // (A boundary's displacement is what its grid motions prescribed.)
  return h.structure.empty() && ((h.quantity == "displacement" && h.boundary.empty()) ||
                                 h.quantity == "velocity" || h.quantity == "position" ||
                                 h.quantity == "kinetic_energy" || h.quantity == "strain_energy");
}

}  // namespace

std::vector<double> HistoryRecorder::point_sums(const Model& model,
                                                const Communicator& processes) const {
  const MaterialPoints& p = model.points;
  std::vector<double> sums(2 * histories_.size(), 0.0);
  for (std::size_t k = 0; k < histories_.size(); ++k) {
    const spec::History& h = histories_[k];
    if (!reads_points(h)) continue;
    std::array<double, 2> s = {0.0, 0.0};
    if (h.quantity == "kinetic_energy")
      s[0] = kinetic_energy(model);
    else if (h.quantity == "strain_energy")
      s[0] = strain_energy(model);
    else
      s = point_set_sums(p, set_bits_[k], h.component,
                         h.quantity == "displacement" ? p.displacement
                         : h.quantity == "velocity"   ? p.velocity
                                                      : p.position);
    sums[2 * k] = s[0];
    sums[2 * k + 1] = s[1];
  }
  processes.sum(sums);
  return sums;
}

std::vector<double> HistoryRecorder::initial_values(const Model& model,
                                                    const std::vector<double>& sums) const {
  std::vector<double> v = {0.0, 0.0};
  for (std::size_t k = 0; k < histories_.size(); ++k) {
    const auto& h = histories_[k];
    if (!h.structure.empty())
      v.push_back(structure_value(model, h, nullptr));
    else if (reads_points(h))
      v.push_back(from_sums(h, sums, k));
    else
      v.push_back(0.0);
  }
  return v;
}

std::vector<double> HistoryRecorder::values(const Model& model, const GridSystem& grid,
                                            const StepResult& step, const PhaseContext& phase,
                                            double phase_time, double time, int step_number,
                                            double dt, const std::vector<double>& sums) const {
  std::vector<double> v = {time, double(step_number)};
  for (std::size_t k = 0; k < histories_.size(); ++k) {
    const auto& h = histories_[k];
    double value = 0.0;
    if (!h.structure.empty()) {
      value = structure_value(model, h, &step);
    } else if (h.quantity == "reaction") {
      // Sum of the reactions at the constrained unknowns of the boundary or driven set.
      const DofMap& dofs = *step.dofs;
      const int u = dofs.find("displacement");
      auto add = [&](Index active_node) {
        const Index d = dofs.dof(u, active_node, h.component);
        if (dofs.constrained(d)) value += step.reaction(d);
      };
      if (!h.boundary.empty()) {
        for (Index node : model.mesh.node_groups.at(h.boundary))
          if (grid.node_to_active()[node] >= 0) add(grid.node_to_active()[node]);
      } else if (auto it = step.set_reactions.find(set_bits_[k]); it != step.set_reactions.end()) {
        value = it->second(h.component);
      }
    } else if (h.quantity == "displacement" && !h.boundary.empty()) {
      // What the grid motions of the boundary have prescribed so far (docs/theory.md §5.3).
      if (auto it = model.grid_displacement.find(h.boundary); it != model.grid_displacement.end())
        value = it->second(h.component);
    } else if (reads_points(h)) {
      value = from_sums(h, sums, k);
    } else if (h.quantity == "load") {
      for (const auto& load : phase.loads)
        if (load.set == set_bits_[k]) value += phase.load(load, phase_time)(h.component);
    } else if (h.quantity == "newton_iterations") {
      value = step.newton.iterations;
    } else if (h.quantity == "time_step") {
      value = dt;
    } else if (h.quantity == "mesh_smallest_angle" && step.mesh_quality) {
      value = step.mesh_quality->smallest_angle;  // the MPM cells' (docs/theory.md §19.3)
    } else if (h.quantity == "mesh_largest_aspect_ratio" && step.mesh_quality) {
      value = step.mesh_quality->largest_aspect_ratio;
    }
    v.push_back(value);
  }
  return v;
}

}  // namespace geompm
