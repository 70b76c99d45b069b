// ParaView output: binary VTK XML unstructured grids (.vtu, appended raw data, UInt64 headers)
// for the material points (as vertices) and for the background mesh, the .pvtu that makes the
// points' pieces of a distributed run one data set, and a .pvd collection per series that lists
// every file with its time. Every file is written to a temporary name and
// renamed, so a file on disk is always complete, also when a run stops.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "geompm/io/field_set.hpp"
#include "geompm/mesh/mesh.hpp"

namespace geompm {

/// Writes points (positions) as VTK_VERTEX cells with point data `fields`.
void write_vtu_points(const std::filesystem::path& file, const std::vector<Vec3>& positions,
                      const FieldSet& fields);

/// Writes the .pvtu that makes the pieces (`pieces`, .vtu files of write_vtu_points, relative to
/// the .pvtu's folder) one data set: each piece holds the arrays of `fields` (their values are
/// not read, any piece's will do).
void write_pvtu_points(const std::filesystem::path& file, const std::vector<std::string>& pieces,
                       const FieldSet& fields);

/// Writes the mesh (node positions `nodes`, which may differ from mesh.nodes) with node data and
/// cell data. Tri6 is written as VTK_QUADRATIC_TRIANGLE.
void write_vtu_mesh(const std::filesystem::path& file, const Mesh& mesh,
                    const std::vector<Vec3>& nodes, const FieldSet& node_fields,
                    const FieldSet& cell_fields);

/// Writes facets - line segments (per_facet 2) or triangles (3), `vertices` facet after facet - as
/// VTK PolyData (.vtp, ASCII) with cell data `cell_fields` (vtp_writer.cpp).
void write_vtp_facets(const std::filesystem::path& file, const std::vector<Vec3>& vertices,
                      int per_facet, const FieldSet& cell_fields);

/// A time series: each add() records (time, file relative to the .pvd) and rewrites the .pvd.
class PvdSeries {
 public:
  explicit PvdSeries(std::filesystem::path pvd_file);
  void add(double time, const std::string& relative_file);
  const std::filesystem::path& path() const { return pvd_file_; }

  /// The (time, file) entries so far, as a checkpoint saves them.
  const std::vector<std::pair<double, std::string>>& entries() const { return entries_; }
  /// A resumed run's series: the entries at the checkpoint, written out at once (if any).
  void restore(std::vector<std::pair<double, std::string>> entries);

 private:
  void write() const;
  std::filesystem::path pvd_file_;
  std::vector<std::pair<double, std::string>> entries_;
};

/// Writes `content` to `file` through a temporary file and a rename (never a partial file).
void write_file_atomically(const std::filesystem::path& file, const std::string& content);

}  // namespace geompm
