#include "geompm/analysis/point_output.hpp"

#include <fmt/format.h>

#include <utility>

#include "geompm/analysis/output_fields.hpp"
#include "geompm/core/agreement.hpp"
#include "geompm/io/vtk_writer.hpp"

namespace geompm {

namespace {

// "vtk/points_000007.pvtu" -> "points_000007_p2.vtu": process 2's piece, beside the .pvtu.
std::string piece_name(const std::string& name, int rank) {
  return fmt::format("{}_p{}.vtu", std::filesystem::path(name).stem().string(), rank);
}

}  // namespace

PointOutput::PointOutput(const Model& model, std::filesystem::path dir,
                         const Communicator& processes)
    : model_(model), dir_(std::move(dir)), processes_(processes), plastic_(model) {}

PointOutput::Files PointOutput::files(int step_number) const {
  const char* extension = processes_.distributed() ? "pvtu" : "vtu";
  Files files{fmt::format("vtk/points_{:06d}.{}", step_number, extension), ""};
  if (model_.fem) files.gauss = fmt::format("vtk/gauss_points_{:06d}.{}", step_number, extension);
  return files;
}

PointOutput::Files PointOutput::write(int step_number) const {
  const Files written = files(step_number);
  std::vector<std::pair<std::string, FieldSet>> sets;  // what each .pvtu names
  together(processes_, [&] {
    sets.emplace_back(written.points, write_set(written.points, model_.points, plastic_.flags()));
    if (!model_.fem) return;
    // The FEM region's Gauss points (docs/theory.md §19.1), with the points' fields: in a
    // distributed run those of this process's cells.
    const MaterialPoints& gauss = model_.fem->gauss_points();
    sets.emplace_back(written.gauss,
                      processes_.distributed()
                          ? write_set(written.gauss, gauss.subset(model_.fem->own_gauss_points()))
                          : write_set(written.gauss, gauss));
  });
  if (!processes_.distributed()) return written;
  // Once every piece is on disk: a .pvtu never names a piece that is not there.
  together(processes_, [&] {
    if (processes_.rank() != 0) return;
    std::vector<std::string> pieces;
    for (const auto& [name, fields] : sets) {
      pieces.clear();
      for (int rank = 0; rank < processes_.size(); ++rank) pieces.push_back(piece_name(name, rank));
      write_pvtu_points(dir_ / name, pieces, fields);
    }
  });
  return written;
}

FieldSet PointOutput::write_set(const std::string& name, const MaterialPoints& points,
                                const std::vector<Index>& plastic) const {
  FieldSet fields = point_fields(model_, points, plastic);
  const std::filesystem::path file = dir_ / name;
  if (processes_.distributed())
    write_vtu_points(file.parent_path() / piece_name(name, processes_.rank()), points.position,
                     fields);
  else
    write_vtu_points(file, points.position, fields);
  return fields;
}

}  // namespace geompm
