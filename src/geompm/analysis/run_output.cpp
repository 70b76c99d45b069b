#include "geompm/analysis/run_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "geompm/analysis/output_fields.hpp"
#include "geompm/core/error.hpp"
#include "geompm/io/plot.hpp"
#include "geompm/structures/deformable_structure.hpp"

namespace geompm {

namespace {

const std::vector<std::string> newton_columns = {"step",
                                                 "time",
                                                 "dt",
                                                 "iteration",
                                                 "relative_residual",
                                                 "relative_correction",
                                                 "converged",
                                                 "largest_residual_node",
                                                 "largest_residual_unknown",
                                                 "tangent_error",
                                                 "plastic_points",
                                                 "plastic_changes",
                                                 "largest_correction_node",
                                                 "largest_correction_unknown",
                                                 "step_length"};

}  // namespace

OutputWriter::Positions OutputWriter::read_positions(ByteReader& saved,
                                                     const std::filesystem::path& dir,
                                                     bool boundary) {
  Positions at;
  saved.get(at.history);
  saved.get(at.newton);
  saved.get(at.points);
  saved.get(at.grid);
  if (boundary) saved.get(at.boundary);
  saved.get(at.last_values);
  saved.get(at.structures);
  saved.expect_end();
  // Both files are checked before either is cut back, so a refused resume changes nothing.
  HistoryWriter::check_resumable(dir / "history.csv", at.history);
  HistoryWriter::check_resumable(dir / "newton.csv", at.newton);
  return at;
}

OutputWriter::OutputWriter(Model& model, const std::filesystem::path& dir)
    : OutputWriter(model, dir, std::optional<Positions>()) {}

OutputWriter::OutputWriter(Model& model, const std::filesystem::path& dir, ByteReader& saved)
    : OutputWriter(
          model, dir,
          std::optional<Positions>(read_positions(saved, dir, writes_boundary(model.spec)))) {}

// One constructor for both: a resumed run opens the same files in the same order, each cut back
// to its length at the checkpoint.
OutputWriter::OutputWriter(Model& model, const std::filesystem::path& dir,
                           std::optional<Positions> resume)
    : model_(model),
      dir_((std::filesystem::create_directories(dir / "vtk"), dir)),
      points_series_(dir / "points.pvd"),
      grid_series_(dir / "grid.pvd"),
      gauss_series_(dir / "gauss_points.pvd"),
      boundary_series_(dir / "boundary.pvd"),
      boundary_(writes_boundary(model.spec)),
      recorder_(model),
      columns_(recorder_.columns()),
      history_(resume ? HistoryWriter(dir / "history.csv", columns_, resume->history)
                      : HistoryWriter(dir / "history.csv", columns_)),
      newton_(resume ? HistoryWriter(dir / "newton.csv", newton_columns, resume->newton)
                     : HistoryWriter(dir / "newton.csv", newton_columns)) {
  for (const auto& structure : model.structures)
    structure_series_.emplace_back(dir / ("structure_" + structure->name() + ".pvd"));
  if (!resume) return;
  points_series_.restore(std::move(resume->points));
  grid_series_.restore(std::move(resume->grid));
  if (resume->structures.size() != structure_series_.size())
    throw InputError(fmt::format("checkpoint: {} structures' series saved, the model has {}",
                                 resume->structures.size(), structure_series_.size()));
  for (std::size_t k = 0; k < structure_series_.size(); ++k)
    structure_series_[k].restore(std::move(resume->structures[k]));
  if (boundary_) boundary_series_.restore(std::move(resume->boundary));
  last_values_ = std::move(resume->last_values);
}

void OutputWriter::save(ByteWriter& out) const {
  out.put(static_cast<std::uintmax_t>(history_.size()));
  out.put(static_cast<std::uintmax_t>(newton_.size()));
  out.put(points_series_.entries());
  out.put(grid_series_.entries());
  // Only with the boundary series, so that a model without one keeps its checkpoint's layout.
  if (boundary_) out.put(boundary_series_.entries());
  out.put(last_values_);
  std::vector<std::vector<std::pair<double, std::string>>> structures;
  for (const PvdSeries& series : structure_series_) structures.push_back(series.entries());
  out.put(structures);
}

// One row per iteration, with where the residual is largest (mesh node; 0, 1, 2 = force in x, y,
// z, 3 = pressure equation), with `newton.tangent_check`, the tangent's error along the
// correction that follows (0 when the check is off or no correction followed), and the points
// returned plastically with how many switched between elastic and plastic since the iterate
// before (-1 at an attempt's first iterate), and the unknown the correction that led to the
// iterate moved most (node -1 at an attempt's first iterate), and the fraction of that correction
// kept (1 for the full Newton correction, less where backtracking or the energy line search
// shortened it; 0 at an attempt's first iterate).
void OutputWriter::newton_log(int step_number, double time, double dt, const StepResult& step) {
  const NewtonResult& newton = step.newton;
  for (std::size_t k = 0; k < newton.residuals.size(); ++k) {
    const UnknownAt at = k < step.largest_residual.size() ? step.largest_residual[k] : UnknownAt{};
    const UnknownAt moved = k > 0 && k - 1 < step.largest_correction.size()
                                ? step.largest_correction[k - 1]
                                : UnknownAt{};
    newton_.append(
        {double(step_number), time, dt, double(k), newton.residuals[k],
         k > 0 && k - 1 < newton.corrections.size() ? newton.corrections[k - 1] : 0.0,
         newton.converged ? 1.0 : 0.0, double(at.node), double(at.unknown),
         k < newton.tangent_errors.size() ? newton.tangent_errors[k] : 0.0,
         k < newton.active.size() ? double(newton.active[k].size) : -1.0,
         k < newton.active.size() ? double(newton.active[k].changed) : -1.0, double(moved.node),
         double(moved.unknown),
         k > 0 && k - 1 < newton.step_lengths.size() ? newton.step_lengths[k - 1] : 0.0});
  }
}

void OutputWriter::initial(const std::vector<double>& point_sums) {
  // vtk: {every: 0} writes no ParaView file at all
  if (model_.spec.output.vtk_every > 0) write_structures(0.0, 0);
  append_history(recorder_.initial_values(model_, point_sums));
}

void OutputWriter::list_points(double time, const std::string& points, const std::string& gauss) {
  points_series_.add(time, points);
  if (!gauss.empty()) gauss_series_.add(time, gauss);
}

bool OutputWriter::lists_points(const std::string& points) const {
  const auto& written = points_series_.entries();
  return !written.empty() && written.back().second == points;
}

void OutputWriter::step(GridSystem& grid, const StepResult& step, const PhaseContext& phase,
                        double phase_time, double time, int step_number, double dt, bool vtk,
                        const std::vector<double>& point_sums) {
  append_history(
      recorder_.values(model_, grid, step, phase, phase_time, time, step_number, dt, point_sums));
  if (!vtk) return;
  write_structures(time, step_number);
  if (model_.spec.output.vtk_grid) {
    FieldSet nodes, cells;
    grid_fields(model_, grid, step, nodes, cells);
    const std::string name = fmt::format("vtk/grid_{:06d}.vtu", step_number);
    write_vtu_mesh(dir_ / name, model_.mesh, model_.mesh.nodes, nodes, cells);
    grid_series_.add(time, name);
  }
  if (boundary_) write_boundary(step, time, step_number);
}

// The bodies' boundary at the step's end (StepResult::boundary): segments or triangles with their
// outward normals and the cells they were found in.
void OutputWriter::write_boundary(const StepResult& step, double time, int step_number) {
  std::vector<Vec3> vertices;
  FieldSet cells;
  auto& normal = cells.vectors.emplace_back("normal", std::vector<Vec3>{}).second;
  auto& cell = cells.integers.emplace_back("cell", std::vector<Index>{}).second;
  const int per_facet = model_.mesh.dim() == 3 ? 3 : 2;
  for (const SurfaceFacet& facet : step.boundary) {
    for (int k = 0; k < facet.vertices; ++k) vertices.push_back(facet.x[k]);
    normal.push_back(facet.normal);
    cell.push_back(facet.cell);
  }
  const std::string name = fmt::format("vtk/boundary_{:06d}.vtp", step_number);
  write_vtp_facets(dir_ / name, vertices, per_facet, cells);
  boundary_series_.add(time, name);
}

std::vector<std::filesystem::path> OutputWriter::plots() {
  std::vector<std::filesystem::path> written;
  for (const auto& p : model_.spec.output.plots) {
    PlotRequest request;
    request.csv = history_.path();
    request.x = p.x;
    request.y = p.y;
    request.x_scale = p.x_scale;
    request.y_scale = p.y_scale;
    request.title = p.title.empty() ? model_.spec.title : p.title;
    request.x_label = p.x_label;
    request.y_label = p.y_label;
    for (const spec::PlotReference& r : p.references)
      request.references.push_back({r.lo, r.hi, r.label});
    plot_history(request, dir_ / p.file);
    written.push_back(dir_ / p.file);
  }
  return written;
}

void OutputWriter::append_history(const std::vector<double>& values) {
  // An infinity never reaches the results: the run stops with the step before it. (NaN is the
  // value of a quantity that has none, the mean of a point set whose points all left the mesh.)
  for (std::size_t k = 0; k < values.size() && k < columns_.size(); ++k)
    if (std::isinf(values[k]))
      throw RunError(fmt::format(
          "the history column '{}' would be {} at time {:g}: the model's values lie outside "
          "what the arithmetic can follow (check the magnitudes of its parameters and loads); "
          "history.csv holds every step before it",
          columns_[k], values[k], values.empty() ? 0.0 : values[0]));
  history_.append(values);
  // As the CSV has them (10 significant digits), so that summary.json agrees with history.csv.
  last_values_.clear();
  // strtod, not stod: a subnormal value is a value, not an error.
  for (const double v : values)
    last_values_.push_back(std::strtod(fmt::format("{:.10g}", v).c_str(), nullptr));
}

// Each structure's mesh where it is, with its displacement since the start of the analysis.
void OutputWriter::write_structures(double time, int step_number) {
  for (std::size_t k = 0; k < model_.structures.size(); ++k) {
    const Structure& structure = *model_.structures[k];
    const std::vector<Vec3>& x = structure.mesh().nodes();
    FieldSet nodes, cells;
    std::vector<Vec3> displacement(x.size());
    for (std::size_t a = 0; a < x.size(); ++a)
      displacement[a] = x[a] - structure.initial_nodes()[a];
    nodes.vectors.emplace_back("displacement", std::move(displacement));
    // Its contact with the soil (docs/theory.md §18) on its surface's nodes.
    std::vector<std::array<Index, 4>> facet_nodes;
    std::vector<int> facet_count;
    for (const Facet& facet : structure.mesh().surface()) {
      facet_nodes.push_back(facet.nodes);
      facet_count.push_back(facet.num_nodes);
    }
    std::vector<double> pressure, shear;
    std::vector<Index> state;
    model_.contacts[k].nodal_fields(facet_nodes, facet_count, static_cast<Index>(x.size()),
                                    pressure, shear, state);
    nodes.scalars.emplace_back("contact_pressure", std::move(pressure));
    nodes.scalars.emplace_back("contact_shear", std::move(shear));
    nodes.integers.emplace_back("contact_state", std::move(state));
    if (const auto* body = dynamic_cast<const DeformableStructure*>(&structure)) {
      // A deformable structure's stress: each cell's mean over its Gauss points (§17.7).
      std::vector<Mat3> stress = body->cell_stress();
      std::vector<double> mean(stress.size());
      for (std::size_t c = 0; c < stress.size(); ++c) mean[c] = stress[c].trace() / 3.0;
      cells.tensors.emplace_back("stress", std::move(stress));
      cells.scalars.emplace_back("mean_stress", std::move(mean));
    }
    const std::string name =
        fmt::format("vtk/structure_{}_{:06d}.vtu", structure.name(), step_number);
    write_vtu_mesh(dir_ / name, structure.mesh().mesh(), x, nodes, cells);
    structure_series_[k].add(time, name);
  }
}

}  // namespace geompm
