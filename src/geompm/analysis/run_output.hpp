// What a run writes as it goes, into its output directory: the history (history.csv), every
// Newton iteration (newton.csv), the ParaView series of the points and the grid (points.pvd,
// grid.pvd, structure_<name>.pvd per structure, vtk/*.vtu; the points' files themselves are
// point_output.hpp's), with surface loads the boundary's (boundary.pvd, vtk/*.vtp) and, at the
// end, the plots. Process 0 of a distributed run holds it. Everything is flushed step by step, so a
// run that stops keeps every finished step; a resumed run goes on with the files as they were at
// its checkpoint (save() / the resuming constructor).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geompm/analysis/histories.hpp"
#include "geompm/analysis/model.hpp"
#include "geompm/analysis/phase_context.hpp"
#include "geompm/analysis/step.hpp"
#include "geompm/core/byte_archive.hpp"
#include "geompm/io/history_writer.hpp"
#include "geompm/io/vtk_writer.hpp"

namespace geompm {

class OutputWriter {
 public:
  /// A new run: creates the output files (and vtk/), writing the CSV headers.
  OutputWriter(Model& model, const std::filesystem::path& dir);
  /// A resumed run: the files cut back to what they held when save() wrote `saved`.
  OutputWriter(Model& model, const std::filesystem::path& dir, ByteReader& saved);

  /// Where the files are (their lengths, the series' entries, the last history row), for a
  /// checkpoint.
  void save(ByteWriter& out) const;

  /// Every Newton attempt, converged or cut back: one row per iteration in newton.csv.
  void newton_log(int step_number, double time, double dt, const StepResult& step);
  /// The initial state (step 0): the structures' ParaView files and the history's first row,
  /// whose points' part is `point_sums` (HistoryRecorder::point_sums, of every process).
  void initial(const std::vector<double>& point_sums);
  /// A converged step: its history row (`point_sums` as for initial) and, if `vtk`, its ParaView
  /// files but the points'.
  void step(GridSystem& grid, const StepResult& step, const PhaseContext& phase, double phase_time,
            double time, int step_number, double dt, bool vtk,
            const std::vector<double>& point_sums);
  /// The points' files of a step (PointOutput::Files: the points', the Gauss points' or empty),
  /// written: they join the series.
  void list_points(double time, const std::string& points, const std::string& gauss);
  /// Whether the points' series ends with `points` (the last step's file was written).
  bool lists_points(const std::string& points) const;
  /// Each structure's ParaView file of a step (with vtk output).
  void write_structures(double time, int step_number);
  /// Draws the plots the model asks for; returns the files written.
  std::vector<std::filesystem::path> plots();

  const std::filesystem::path& history_file() const { return history_.path(); }
  /// history.csv's columns and its last row as written (the values it reads back as).
  const std::vector<std::string>& columns() const { return columns_; }
  const std::vector<double>& last_values() const { return last_values_; }

 private:
  struct Positions {
    std::uintmax_t history = 0, newton = 0;  // bytes of history.csv and newton.csv
    std::vector<std::pair<double, std::string>> points, grid;  // the series' entries
    std::vector<std::pair<double, std::string>> boundary;      // with writes_boundary only
    std::vector<std::vector<std::pair<double, std::string>>> structures;  // one per structure
    std::vector<double> last_values;
  };
  static Positions read_positions(ByteReader& saved, const std::filesystem::path& dir,
                                  bool boundary);
  OutputWriter(Model& model, const std::filesystem::path& dir, std::optional<Positions> resume);
  void append_history(const std::vector<double>& values);
  void write_boundary(const StepResult& step, double time, int step_number);

  Model& model_;
  std::filesystem::path dir_;
  PvdSeries points_series_, grid_series_, gauss_series_, boundary_series_;  // gauss: FEM region
  bool boundary_;                            // writes_boundary(model.spec)
  std::vector<PvdSeries> structure_series_;  // structure_<name>.pvd, one per structure
  HistoryRecorder recorder_;
  std::vector<std::string> columns_;
  HistoryWriter history_;
  HistoryWriter newton_;
  std::vector<double> last_values_;
};

}  // namespace geompm
