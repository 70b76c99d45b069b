// The material points' ParaView files (docs/user-guide.md, "Output"): vtk/points_<step>.vtu with
// the point fields (output_fields.hpp) and, with an FEM region, its Gauss points'
// vtk/gauss_points_<step>.vtu. A distributed run writes each in pieces (docs/user-guide.md,
// "Running on several processes"): every process its own points' vtk/points_<step>_p<rank>.vtu,
// and process 0 the vtk/points_<step>.pvtu that names the pieces, which the series (points.pvd)
// lists; the points stay where they are. Every process holds one of these.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "geompm/analysis/model.hpp"
#include "geompm/analysis/plastic_points.hpp"
#include "geompm/core/communicator.hpp"
#include "geompm/io/field_set.hpp"

namespace geompm {

class PointOutput {
 public:
  /// For the points the model holds now (their plastic strains as the next step's start).
  PointOutput(const Model& model, std::filesystem::path dir, const Communicator& processes);

  /// After every converged step: which points flowed plastically in it. Collective.
  void after_step() { plastic_.update(model_, processes_); }

  /// The files the series list for a step, relative to the output directory: the points' and
  /// the Gauss points' (empty without an FEM region).
  struct Files {
    std::string points, gauss;
  };
  Files files(int step_number) const;

  /// Writes the step's files. Collective: an error on any process (a full disk) stops every
  /// process with it (core/agreement.hpp).
  Files write(int step_number) const;

 private:
  /// Writes one set of points as file `name` (relative), or in a distributed run this process's
  /// piece of it; returns the fields written.
  FieldSet write_set(const std::string& name, const MaterialPoints& points,
                     const std::vector<Index>& plastic = {}) const;

  const Model& model_;
  std::filesystem::path dir_;
  const Communicator& processes_;
  PlasticPoints plastic_;
};

}  // namespace geompm
