#include "geompm/contact/level_set_contact.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "geompm/core/byte_archive.hpp"
#include "geompm/core/error.hpp"
#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"

namespace geompm {

namespace {

// The shape values of mesh cell c at its reference coordinates xi (its nodes' entries).
void cell_shape(const Mesh& mesh, Index c, const Vec3& xi, double* N) {
  dispatch_cell_type(mesh.type_of(c), [&](auto e) {
    using E = decltype(e);
    const auto values = E::shape(xi.template head<E::dim>());
    for (int a = 0; a < E::nodes; ++a) N[a] = values(a);
  });
}

// Gaps below a millionth of a cell count as closed (contact_equations).
constexpr double kClosed = 1e-6;

double cell_size(const Mesh& mesh, Index cell) {
  return std::pow(cell_measure(mesh, cell, false), 1.0 / mesh.dim());
}

// Pieces of the surface that share one set of multipliers.
struct PieceGroup {
  std::vector<Index> pieces;
  Index cell = -1;  // the background cell of its first pieces
  int cells = 1;    // how many cells' groups it holds
  Vec3 normal = Vec3::Zero(), centre = Vec3::Zero();
  double measure = 0.0, h = 0.0;
};

// Merges each group of fewer than `min_cells` cells with its nearest neighbours facing the same
// way (centres at most three cells apart), in the surface's order: deterministic from step to
// step while the surface and the grid do not change.
void merge_small_groups(std::vector<PieceGroup>& groups, int min_cells) {
  for (std::size_t g = 0; g < groups.size(); ++g) {
    PieceGroup& into = groups[g];
    while (!into.pieces.empty() && into.cells < min_cells) {
      std::size_t best = groups.size();
      double nearest = 3.0 * into.h;
      for (std::size_t j = 0; j < groups.size(); ++j) {
        const PieceGroup& other = groups[j];
        if (j == g || other.pieces.empty() || other.normal.dot(into.normal) < 0.7071) continue;
        const double d = (other.centre - into.centre).norm();
        if (d < nearest) nearest = d, best = j;
      }
      if (best == groups.size()) break;
      PieceGroup& other = groups[best];
      into.pieces.insert(into.pieces.end(), other.pieces.begin(), other.pieces.end());
      into.centre = (into.measure * into.centre + other.measure * other.centre) /
                    (into.measure + other.measure);
      into.measure += other.measure;
      into.cells += other.cells;
      into.h = std::max(into.h, other.h);
      other.pieces.clear();
    }
  }
}

}  // namespace

LevelSetContact::LevelSetContact(const GridSystem& grid, const MaterialPoints& points,
                                 const PointLocator& locator, const Structure& structure,
                                 ContactPair& pair, double modulus, DofMap& dofs)
    : grid_(grid),
      points_(points),
      locator_(locator),
      structure_(structure),
      level_set_(grid, points, pair.bodies),
      dofs_(dofs),
      pair_(pair),
      dim_(grid.dim()),
      modulus_(modulus) {
  tangents_ = pair.law.tangential == TangentialContact::Smooth ? 0 : dim_ - 1;
  // Segments about a cell long: the cell where a facet's centre lies, or the structure's own
  // facet where it lies outside the mesh (it cannot touch the soil there).
  all_ = contact_segments(structure.mesh(), [&](const Vec3& x) {
    return cell_size_at(locator, x, std::numeric_limits<double>::infinity());
  });
  if (pair_.multipliers.size() != all_.size()) {
    pair_.multipliers.assign(all_.size(), {0.0, 0.0, 0.0});
    pair_.pressure.assign(all_.size(), 0.0);
    pair_.shear.assign(all_.size(), 0.0);
    pair_.state.assign(all_.size(), ContactState::Open);
    pair_.in_grid.assign(all_.size(), 0);
    pair_.penetration.assign(all_.size(), 0.0);
    pair_.piece_facet.clear();
    pair_.piece_measure.clear();
    for (const ContactSegment& piece : all_) {
      pair_.piece_facet.push_back(piece.facet);
      pair_.piece_measure.push_back(piece.measure);
    }
  }
  fill_.assign(grid.mesh().num_cells(), 0.0);
  active_of_cell_.assign(grid.mesh().num_cells(), -1);
  for (std::size_t c = 0; c < grid.active_cells().size(); ++c) {
    fill_[grid.active_cells()[c]] = grid.cell_fill()[c];
    active_of_cell_[grid.active_cells()[c]] = static_cast<Index>(c);
  }
  for (const Material* material : grid.materials()) {
    int su = -1;
    for (int k = 0; material && k < material->internal_variable_count(); ++k)
      if (std::string(material->internal_variable_name(k)) == "su") su = k;
    su_index_.push_back(su);
  }
  if (pair_.law.alpha > 0.0) find_cell_strengths();
  for (const std::vector<Index>& group : group_pieces()) {
    Kinematics k;
    if (build_kinematics(group, k)) segments_.push_back(std::move(k));
  }
  field_ = dofs.add_field("contact:" + structure.name(), FieldKind::Other,
                          static_cast<Index>(segments_.size()), 1 + tangents_);
  state_.assign(segments_.size(), ContactState::Open);
}

std::vector<std::vector<Index>> LevelSetContact::group_pieces() const {
  // First one group per background cell and direction (normals within 45 degrees of the group's
  // first), then groups merged with their nearest neighbour facing the same way until each spans
  // about two cells (eq. 18.1): a multiplier constant over one cell lets the soil's nodal
  // displacement along the surface zigzag under it, and the multipliers oscillate from cell to
  // cell, opening and closing at every iteration; over two cells each multiplier holds the whole
  // trace of at least one grid node (the macro-element condition of inf-sup stability).
  std::vector<PieceGroup> groups;
  Index hint = -1;
  for (std::size_t s = 0; s < all_.size(); ++s) {
    Vec3 centre = Vec3::Zero();
    for (const ContactGaussPoint& q : all_[s].points) centre += q.weight * q.x;
    centre /= all_[s].measure;
    // The cell on the soil's side of the piece (a piece on a cell face belongs to the cell its
    // normal points into, so that the pieces of one face are one group).
    const auto at = locator_.locate(centre, hint);
    if (!at) continue;
    const double h = cell_size(grid_.mesh(), at->cell);
    const auto where = locator_.locate(centre + 1e-3 * h * all_[s].normal, at->cell);
    if (!where) continue;
    refuse_fem_cell(at->cell, centre);
    refuse_fem_cell(where->cell, centre);
    hint = where->cell;
    std::size_t g = 0;
    while (g < groups.size() &&
           (groups[g].cell != where->cell || groups[g].normal.dot(all_[s].normal) < 0.7071))
      ++g;
    if (g == groups.size()) groups.push_back({{}, where->cell, 1, all_[s].normal});
    groups[g].pieces.push_back(static_cast<Index>(s));
    groups[g].centre += all_[s].measure * centre;
    groups[g].measure += all_[s].measure;
    groups[g].h = std::max(groups[g].h, h);
  }
  for (PieceGroup& g : groups) g.centre /= g.measure;
  merge_small_groups(groups, dim_ == 3 ? 4 : 2);
  std::vector<std::vector<Index>> out;
  for (PieceGroup& g : groups)
    if (!g.pieces.empty()) out.push_back(std::move(g.pieces));
  return out;
}

void LevelSetContact::find_cell_strengths() {
  const Index n_active = static_cast<Index>(grid_.active_cells().size());
  std::vector<double> sum(n_active, 0.0), volume(n_active, 0.0);
  for (Index ci = 0; ci < n_active; ++ci)
    for (Index p = grid_.cell_point_begin(ci); p < grid_.cell_point_end(ci); ++p) {
      const int su = su_index_[points_.material[p]];
      if (su < 0 || (!pair_.bodies.empty() && !pair_.bodies[points_.body[p]])) continue;
      sum[ci] += points_.volume[p] * points_.internal[p][su];
      volume[ci] += points_.volume[p];
    }
  // A cell's points are on the process that owns it; the contact may read any cell.
  grid_.communicator().sum(sum);
  grid_.communicator().sum(volume);
  strength_.assign(n_active, 0.0);
  for (Index ci = 0; ci < n_active; ++ci)
    if (volume[ci] > 0.0) strength_[ci] = sum[ci] / volume[ci];
}

double LevelSetContact::cell_strength(Index cell) const {
  const Index ci = active_of_cell_[cell];
  return ci < 0 ? 0.0 : strength_[ci];
}

void LevelSetContact::refuse_fem_cell(Index cell, const Vec3& x) const {
  // Contact acts on the soil's material points: their level set gives the gap and their cells
  // the soil's displacement and strength. An FEM cell has no points (docs/theory.md §19): a
  // structure reaching one would pass through it or push its nodes without the soil's strength.
  if (!grid_.fem_cell(cell)) return;
  throw RunError(fmt::format(
      "the contact surface of structure '{}' reaches FEM cell {} at [{:g}, {:g}, {:g}]: contact "
      "acts on the material points of MPM cells only; make the cells around the structure and "
      "along its path MPM cells (regions)",
      structure_.name(), cell, x.x(), x.y(), x.z()));
}

std::optional<Location> LevelSetContact::soil_cell(const Vec3& x, const Vec3& normal, double h,
                                                   Index cell) const {
  // The soil's displacement at a contact point is read in the first cell along the normal, into
  // the soil, that its points fill: in a cell the soil has left, the nodes away from it are held
  // by the empty-cell stiffness alone, and a contact read there would push them, not the soil.
  // The first cell at least half filled within two cells' length, else the fullest one there.
  std::optional<Location> fullest;
  double most = 0.0;
  for (int k = 0; k <= 16; ++k) {
    const Vec3 y = x + (0.125 * k * h) * normal;
    const auto at = locator_.locate(y, cell);
    if (!at) break;
    cell = at->cell;
    refuse_fem_cell(cell, x);
    const double fill = fill_[at->cell];
    if (fill >= fill_threshold_) return at;
    if (fill > most) most = fill, fullest = at;
  }
  return fullest;
}

bool LevelSetContact::build_kinematics(const std::vector<Index>& pieces, Kinematics& k) const {
  // Eq. 18.3: p = sum_q w_q [d_q + n_q . (u_s(x_q) - sum_a N_a(x_q) u_a)] / A, the same with a
  // tangent for the slip; d_q = phi / max(|grad phi|, 1 / (2 h)) the level set's depth (eq. 18.2).
  const Mesh& mesh = grid_.mesh();
  const int u = dofs_.find("displacement");
  std::vector<std::pair<Index, std::array<double, 3>>> terms;
  std::vector<DofWeight> weights;
  double N[27];
  Index hint = -1;
  double h = 0.0;
  for (Index piece : pieces) k.measure += all_[piece].measure;
  for (Index piece : pieces) {
    const ContactSegment& segment = all_[piece];
    for (int c = 0; c < 3; ++c)
      k.start[c] += segment.measure / k.measure * pair_.multipliers[piece][c];
    // Tracked: the piece touched at the end of the last step. An open piece is measured by the
    // level set again: its gap tracked along the structure's normal n would close only at the
    // rate n . du, slower than the soil's surface approaches where that surface is not normal to
    // n (a cone's face, a pipe's flank: contact found late by 1 / cos of the angle between them).
    const bool tracked = pair_.in_grid[piece] && pair_.state[piece] != ContactState::Open;
    for (const ContactGaussPoint& q : segment.points) {
      auto where = locator_.locate(q.x, hint);
      if (!where) return false;
      hint = where->cell;
      const double here = cell_size(mesh, where->cell);
      const auto soil_side = soil_cell(q.x, segment.normal, here, where->cell);
      if (!soil_side) return false;
      const auto nodes = mesh.cell_nodes(soil_side->cell);
      for (Index node : nodes)
        if (grid_.node_to_active()[node] < 0) return false;  // outside the step's grid
      h = std::max(h, here);
      // A piece that touched at the end of the last step starts where it was then (eq. 18.2):
      // the level set, smeared over a cell, would place the soil's surface up to a fraction of a
      // cell away, and a piece at the edge of the contact would open and close by that much.
      const double w = q.weight / k.measure;
      if (tracked) {
        k.p0 += w * pair_.penetration[piece];
      } else {
        const double phi = level_set_.value(where->cell, where->xi);
        const Vec3 gradient = level_set_.gradient(where->cell, where->xi);
        const double depth = phi / std::max(gradient.norm(), 0.5 / here);
        // Open, or new: the smeared level set may bring it to the surface, not past it. A piece
        // at the edge of the contact would otherwise close from step to step by a fraction of a
        // cell, and a structure that starts embedded (the soil seeded around it) would push the
        // soil out by that much in its first step.
        k.p0 += w * std::min(depth, 0.0);
      }
      const auto along = [&](const Vec3& c) {
        return std::array<double, 3>{w * segment.normal.dot(c), w * segment.tangents[0].dot(c),
                                     w * segment.tangents[1].dot(c)};
      };
      cell_shape(mesh, soil_side->cell, soil_side->xi, N);
      if (pair_.law.alpha > 0.0) k.strength += w * cell_strength(soil_side->cell);
      for (std::size_t a = 0; a < nodes.size(); ++a)
        for (int i = 0; i < dim_; ++i)
          terms.push_back(
              {dofs_.dof(u, grid_.node_to_active()[nodes[a]], i), along(-N[a] * Vec3::Unit(i))});
      structure_.displacement_weights(dofs_, q.x, segment.structure_cell, weights);
      for (const DofWeight& dw : weights) terms.push_back({dw.dof, along(dw.coefficient)});
    }
  }
  std::sort(terms.begin(), terms.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [dof, c] : terms) {
    if (!k.dofs.empty() && k.dofs.back() == dof) {
      k.dp.back() += c[0];
      k.ds.back()[0] += c[1];
      k.ds.back()[1] += c[2];
      continue;
    }
    k.dofs.push_back(dof);
    k.dp.push_back(c[0]);
    k.ds.push_back({c[1], c[2]});
  }
  k.pieces = pieces;
  k.scale = pair_.scale_factor * modulus_ / h;  // c = E / h (eq. 18.8)
  k.cell = h;
  return true;
}

double LevelSetContact::multiplier(const Vector& du, std::size_t k, int component) const {
  // The unknowns are the multipliers' changes over the step (eq. 18.9).
  return segments_[k].start[component] + du(dofs_.dof(field_, static_cast<Index>(k), component));
}

void LevelSetContact::declare_couplings(SparsityBuilder& pattern) const {
  std::vector<Index> block;
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    for (int c = 0; c <= tangents_; ++c) block.push_back(dofs_.dof(field_, Index(k), c));
    const std::size_t own = block.size();
    for (Index dof : segments_[k].dofs) {
      block.resize(own);
      block.push_back(dof);
      pattern.couple_unknowns(block);
    }
    block.clear();
  }
}

double LevelSetContact::penetration(const Vector& du, std::size_t k) const {
  const Kinematics& s = segments_[k];
  double p = s.p0;
  for (std::size_t j = 0; j < s.dofs.size(); ++j) p += s.dp[j] * du(s.dofs[j]);
  return p;
}

TangentialPair LevelSetContact::tangential_rows(const ContactLaw& law, double scale, double p,
                                                const double slip[2], double l_n,
                                                const double l_t[2],
                                                const ContactEquations e[2]) const {
  const bool bounded = law.tangential == TangentialContact::Adhesion ||
                       law.tangential == TangentialContact::Friction;
  if (tangents_ == 2 && bounded && e[0].state != ContactState::Open)
    return tangential_pair(law, scale, p, slip, l_n, l_t);
  TangentialPair rows;  // each tangent's own equation, in the pair's layout
  for (int t = 0; t < tangents_; ++t) {
    rows.residual[t] = e[t].tangential;
    rows.d[t][0] = e[t].tangential_d[0];
    rows.d[t][1 + t] = e[t].tangential_d[1];
    rows.d[t][3] = e[t].tangential_d[2];
    rows.d[t][4 + t] = e[t].tangential_d[3];
  }
  rows.state = e[0].state;
  return rows;
}

bool LevelSetContact::add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) {
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    const Kinematics& s = segments_[k];
    double p = s.p0, slip[2] = {0.0, 0.0};
    for (std::size_t j = 0; j < s.dofs.size(); ++j) {
      const double v = du(s.dofs[j]);
      p += s.dp[j] * v;
      slip[0] += s.ds[j][0] * v;
      slip[1] += s.ds[j][1] * v;
    }
    const double l_n = multiplier(du, k, 0);
    const Index n_dof = dofs_.dof(field_, Index(k), 0);
    const double cA = s.scale * s.measure;
    // The normal equation, then the tangential ones (eq. 18.4-18.7): in 3D each tangent on its
    // own where that is the same law (smooth, rough), the shear as a vector where it is bounded
    // (adhesion, friction: eq. 18.7a).
    ContactEquations e[2];
    double l_t[2] = {0.0, 0.0};
    ContactLaw law = pair_.law;
    if (law.alpha > 0.0) law.adhesion = law.alpha * s.strength;  // alpha s_u (eq. 18.6)
    for (int t = 0; t < std::max(tangents_, 1); ++t) {
      if (t < tangents_) l_t[t] = multiplier(du, k, 1 + t);
      e[t] = contact_equations(law, s.scale, p, slip[t], l_n, l_t[t], kClosed * s.cell);
    }
    const TangentialPair rows = tangential_rows(law, s.scale, p, slip, l_n, l_t, e);
    state_[k] = rows.state;
    forces.internal(n_dof) += cA * e[0].normal;
    for (std::size_t j = 0; j < s.dofs.size(); ++j)
      forces.internal(s.dofs[j]) +=
          cA * (l_n * s.dp[j] + l_t[0] * s.ds[j][0] + l_t[1] * s.ds[j][1]);
    for (int t = 0; t < tangents_; ++t)
      forces.internal(dofs_.dof(field_, Index(k), 1 + t)) += cA * rows.residual[t];
    if (!tangent) continue;
    const auto put = [&](Index row, Index col, double v) {
      if (v != 0.0) add_to_tangent(*tangent, dofs_, row, col, v);
    };
    for (std::size_t j = 0; j < s.dofs.size(); ++j) {
      put(s.dofs[j], n_dof, cA * s.dp[j]);
      put(n_dof, s.dofs[j], cA * e[0].normal_d[0] * s.dp[j]);
    }
    put(n_dof, n_dof, cA * e[0].normal_d[2]);
    // Row t: derivatives with respect to (p, s_0, s_1, l_n, l_t0, l_t1).
    for (int t = 0; t < tangents_; ++t) {
      const Index t_dof = dofs_.dof(field_, Index(k), 1 + t);
      const double* d = rows.d[t];
      for (std::size_t j = 0; j < s.dofs.size(); ++j) {
        put(s.dofs[j], t_dof, cA * s.ds[j][t]);
        put(t_dof, s.dofs[j], cA * (d[0] * s.dp[j] + d[1] * s.ds[j][0] + d[2] * s.ds[j][1]));
      }
      put(t_dof, n_dof, cA * d[3]);
      for (int u = 0; u < tangents_; ++u)
        put(t_dof, dofs_.dof(field_, Index(k), 1 + u), cA * d[4 + u]);
    }
  }
  return true;
}

void LevelSetContact::report(const Vector& du, Reactions& reactions) {
  if (const Communicator& processes = grid_.communicator(); processes.distributed()) {
    std::vector<int> states;
    for (const ContactState state : state_) states.push_back(static_cast<int>(state));
    ByteWriter mine;
    if (processes.rank() == 0) mine.put(states);
    const std::string process0 = processes.all_gather(mine.take()).front();
    ByteReader in(process0, "contact states of process 0");
    in.get(states);
    for (std::size_t k = 0; k < state_.size(); ++k)
      state_[k] = static_cast<ContactState>(states[k]);
  }
  // The soil pushes the structure out along -n and against its slip along -t (eq. 18.10).
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  converged_.assign(segments_.size(), {0.0, 0.0, 0.0});
  converged_penetration_.assign(segments_.size(), 0.0);
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    const Kinematics& s = segments_[k];
    for (int c = 0; c <= tangents_; ++c) converged_[k][c] = multiplier(du, k, c);
    converged_penetration_[k] = penetration(du, k);
    for (Index piece : s.pieces) {
      const ContactSegment& segment = all_[piece];
      Vec3 traction = -s.scale * converged_[k][0] * segment.normal;
      for (int t = 0; t < tangents_; ++t)
        traction -= s.scale * converged_[k][1 + t] * segment.tangents[t];
      for (const ContactGaussPoint& q : segment.points) {
        force += q.weight * traction;
        moment += q.x.cross(q.weight * traction);
      }
    }
  }
  pair_.force = force;
  pair_.moment = moment;
  reactions.contacts[pair_.name] = force;
}

void LevelSetContact::commit() {
  // Each piece keeps its group's multipliers, the start of the next step's.
  std::fill(pair_.in_grid.begin(), pair_.in_grid.end(), 0);
  std::fill(pair_.penetration.begin(), pair_.penetration.end(), 0.0);
  for (auto& m : pair_.multipliers) m = {0.0, 0.0, 0.0};
  std::fill(pair_.pressure.begin(), pair_.pressure.end(), 0.0);
  std::fill(pair_.shear.begin(), pair_.shear.end(), 0.0);
  std::fill(pair_.state.begin(), pair_.state.end(), ContactState::Open);
  for (std::size_t k = 0; k < segments_.size() && k < converged_.size(); ++k) {
    const Kinematics& s = segments_[k];
    const double shear = s.scale * std::hypot(converged_[k][1], converged_[k][2]);
    for (Index piece : s.pieces) {
      pair_.in_grid[piece] = 1;
      pair_.multipliers[piece] = converged_[k];
      pair_.penetration[piece] = converged_penetration_[k];
      pair_.pressure[piece] = s.scale * converged_[k][0];
      pair_.shear[piece] = tangents_ == 1 && converged_[k][1] < 0.0 ? -shear : shear;
      pair_.state[piece] = state_[k];
    }
  }
}

}  // namespace geompm
