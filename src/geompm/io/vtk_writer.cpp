// VTK XML UnstructuredGrid (.vtu) files in the "appended raw" binary layout: the XML header
// describes every array by (type, name, components, offset), and all array bytes follow in one
// <AppendedData encoding="raw"> block, each array preceded by its byte count as a UInt64. This is
// the layout ParaView itself writes: compact, exact (no decimal round trip) and fast to read.
#include "geompm/io/vtk_writer.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <type_traits>

#include "geompm/core/error.hpp"
#include "geompm/io/vtk_writer_xml.hpp"

namespace geompm {

namespace {

/// The bytes of the <AppendedData> block. Every block starts with its size in bytes (the
/// file's header_type, UInt64); a DataArray refers to a block by the offset of that size word.
class AppendedData {
 public:
  /// Starts a block of `bytes` bytes and returns its offset for the DataArray's `offset`.
  std::size_t begin_block(std::size_t bytes) {
    const std::size_t offset = data_.size();
    data_.reserve(data_.size() + sizeof(std::uint64_t) + bytes);
    put(static_cast<std::uint64_t>(bytes));
    return offset;
  }

  /// Appends one value in little-endian byte order (the file says byte_order="LittleEndian").
  template <class T>
  void put(T value) {
    static_assert(std::is_arithmetic_v<T>);
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(bytes, bytes + sizeof(T));
    data_.append(bytes, sizeof(T));
  }

  const std::string& bytes() const { return data_; }

 private:
  std::string data_;
};

/// VTK cell type numbers (vtkCellType.h). geompm's node orders follow Gmsh, which for these
/// cells is also VTK's order (Tri6: corners, then mid-sides 0-1, 1-2, 2-0), so no renumbering.
std::uint8_t vtk_cell_type(CellType type) {
  switch (type) {
    case CellType::Tri3:
      return 5;  // VTK_TRIANGLE
    case CellType::Tri6:
      return 22;  // VTK_QUADRATIC_TRIANGLE
    case CellType::Quad4:
      return 9;  // VTK_QUAD
    case CellType::Tet4:
      return 10;  // VTK_TETRA
    case CellType::Hex8:
      return 12;  // VTK_HEXAHEDRON
    case CellType::Pyramid5:
      return 14;  // VTK_PYRAMID
  }
  throw std::invalid_argument("vtk_cell_type: unknown cell type");
}

constexpr std::uint8_t kVtkVertex = 1;

/// Builds one .vtu file: the XML sections of a single <Piece> and the appended bytes.
class VtuBuilder {
 public:
  VtuBuilder(std::size_t num_points, std::size_t num_cells)
      : num_points_(num_points), num_cells_(num_cells) {}

  void set_points(const std::vector<Vec3>& positions) {
    const std::size_t offset = data_.begin_block(positions.size() * 3 * sizeof(double));
    for (const Vec3& p : positions) put_vec3(p);
    points_xml_ = data_array_tag("Float64", "Points", 3, offset);
  }

  /// Cells given as a flat connectivity with `nodes_per_cell` entries each, all of one type.
  void set_cells(const std::vector<Index>& connectivity, int nodes_per_cell,
                 std::uint8_t cell_type) {
    set_cells(
        connectivity,
        [&](std::size_t c) { return (c + 1) * static_cast<std::size_t>(nodes_per_cell); },
        [&](std::size_t) { return cell_type; });
  }

  /// Cells of a flat connectivity: cell c ends at end_of(c) and has the VTK type type_of(c).
  template <class EndOf, class TypeOf>
  void set_cells(const std::vector<Index>& connectivity, EndOf&& end_of, TypeOf&& type_of) {
    const std::size_t count = num_cells_;
    // Int64 connectivity and offsets: VTK's own choice, and safe beyond 2^31 entries.
    std::size_t offset = data_.begin_block(connectivity.size() * sizeof(std::int64_t));
    for (Index node : connectivity) data_.put(static_cast<std::int64_t>(node));
    cells_xml_ = data_array_tag("Int64", "connectivity", 1, offset);

    // VTK's offsets are the end of each cell in the connectivity (no leading zero).
    offset = data_.begin_block(count * sizeof(std::int64_t));
    for (std::size_t c = 0; c < count; ++c) data_.put(static_cast<std::int64_t>(end_of(c)));
    cells_xml_ += data_array_tag("Int64", "offsets", 1, offset);

    offset = data_.begin_block(count * sizeof(std::uint8_t));
    for (std::size_t c = 0; c < count; ++c) data_.put(type_of(c));
    cells_xml_ += data_array_tag("UInt8", "types", 1, offset);
  }

  void set_point_data(const FieldSet& fields, const char* what) {
    point_data_xml_ = add_fields(fields, num_points_, what);
  }

  void set_cell_data(const FieldSet& fields) {
    cell_data_xml_ = add_fields(fields, num_cells_, "cell");
  }

  std::string str() const {
    std::string out = fmt::format(
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt64\">\n"
        "  <UnstructuredGrid>\n"
        "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n"
        "      <PointData>\n{}      </PointData>\n"
        "      <CellData>\n{}      </CellData>\n"
        "      <Points>\n{}      </Points>\n"
        "      <Cells>\n{}      </Cells>\n"
        "    </Piece>\n"
        "  </UnstructuredGrid>\n"
        "  <AppendedData encoding=\"raw\">\n   _",
        num_points_, num_cells_, point_data_xml_, cell_data_xml_, points_xml_, cells_xml_);
    out += data_.bytes();
    // The newline after the bytes is part of the format as VTK writes it; readers such as
    // meshio find the end of the data by it.
    out += "\n  </AppendedData>\n</VTKFile>\n";
    return out;
  }

 private:
  static std::string data_array_tag(const char* type, const std::string& name, int components,
                                    std::size_t offset, const std::string& extra = "") {
    return fmt::format(
        "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\"{} "
        "format=\"appended\" offset=\"{}\"/>\n",
        type, vtk_xml::escape(name), components, extra, offset);
  }

  void put_vec3(const Vec3& v) {
    data_.put(v.x());
    data_.put(v.y());
    data_.put(v.z());
  }

  /// A field with a number of values other than the number of points/cells would shift every
  /// later array in the reader's view, so it is refused, naming the field.
  template <class T>
  static void check_size(const std::string& name, const std::vector<T>& values,
                         std::size_t expected, const char* what) {
    if (values.size() != expected)
      throw std::invalid_argument(
          fmt::format("vtu field '{}' has {} values, expected {} (one per {})", name, values.size(),
                      expected, what));
  }

  std::string add_fields(const FieldSet& fields, std::size_t count, const char* what) {
    std::string xml;
    for (const auto& [name, values] : fields.scalars) {
      check_size(name, values, count, what);
      const std::size_t offset = data_.begin_block(values.size() * sizeof(double));
      for (double v : values) data_.put(v);
      xml += data_array_tag("Float64", name, 1, offset);
    }
    for (const auto& [name, values] : fields.vectors) {
      check_size(name, values, count, what);
      const std::size_t offset = data_.begin_block(values.size() * 3 * sizeof(double));
      for (const Vec3& v : values) put_vec3(v);
      xml += data_array_tag("Float64", name, 3, offset);
    }
    for (const auto& [name, values] : fields.tensors) {
      check_size(name, values, count, what);
      const std::size_t offset = data_.begin_block(values.size() * 6 * sizeof(double));
      // ParaView's symmetric-tensor order. Of a non-symmetric tensor the symmetric part is
      // written, which leaves a symmetric one (stress) exactly as it is.
      for (const Mat3& t : values) {
        data_.put(t(0, 0));
        data_.put(t(1, 1));
        data_.put(t(2, 2));
        data_.put(0.5 * (t(0, 1) + t(1, 0)));
        data_.put(0.5 * (t(1, 2) + t(2, 1)));
        data_.put(0.5 * (t(0, 2) + t(2, 0)));
      }
      xml += data_array_tag("Float64", name, 6, offset, vtk_xml::symmetric_tensor_components);
    }
    for (const auto& [name, values] : fields.integers) {
      check_size(name, values, count, what);
      const std::size_t offset = data_.begin_block(values.size() * sizeof(std::int32_t));
      for (Index v : values) data_.put(static_cast<std::int32_t>(v));
      xml += data_array_tag("Int32", name, 1, offset);
    }
    return xml;
  }

  std::size_t num_points_, num_cells_;
  AppendedData data_;
  std::string point_data_xml_, cell_data_xml_, points_xml_, cells_xml_;
};

}  // namespace

void write_vtu_points(const std::filesystem::path& file, const std::vector<Vec3>& positions,
                      const FieldSet& fields) {
  const std::size_t n = positions.size();
  VtuBuilder vtu(n, n);
  vtu.set_points(positions);
  // One VTK_VERTEX per point: ParaView needs cells to draw anything, and vertices let the
  // points be shown as glyphs or as "Point Gaussian" without a filter.
  std::vector<Index> connectivity(n);
  for (std::size_t i = 0; i < n; ++i) connectivity[i] = static_cast<Index>(i);
  vtu.set_cells(connectivity, 1, kVtkVertex);
  vtu.set_point_data(fields, "point");
  write_file_atomically(file, vtu.str());
}

void write_vtu_mesh(const std::filesystem::path& file, const Mesh& mesh,
                    const std::vector<Vec3>& nodes, const FieldSet& node_fields,
                    const FieldSet& cell_fields) {
  const int per_cell = mesh.nodes_per_cell();
  if (!mesh.mixed() && mesh.connectivity.size() % static_cast<std::size_t>(per_cell) != 0)
    throw std::invalid_argument(fmt::format(
        "write_vtu_mesh: {} connectivity entries are not a whole number of {} cells ({} nodes)",
        mesh.connectivity.size(), to_string(mesh.cell_type), per_cell));
  // `nodes` may be a deformed copy of mesh.nodes; it must still hold every node a cell uses.
  for (Index node : mesh.connectivity)
    if (node < 0 || static_cast<std::size_t>(node) >= nodes.size())
      throw std::invalid_argument(
          fmt::format("write_vtu_mesh: a cell uses node {}, but {} node positions were given", node,
                      nodes.size()));

  VtuBuilder vtu(nodes.size(), static_cast<std::size_t>(mesh.num_cells()));
  vtu.set_points(nodes);
  // Each cell its own VTK type and end: a mixed mesh is written as it is.
  vtu.set_cells(
      mesh.connectivity,
      [&](std::size_t c) {
        return static_cast<std::size_t>(mesh.cell_nodes(static_cast<Index>(c)).data() -
                                        mesh.connectivity.data()) +
               mesh.cell_nodes(static_cast<Index>(c)).size();
      },
      [&](std::size_t c) { return vtk_cell_type(mesh.type_of(static_cast<Index>(c))); });
  vtu.set_point_data(node_fields, "node");
  vtu.set_cell_data(cell_fields);
  write_file_atomically(file, vtu.str());
}

void write_file_atomically(const std::filesystem::path& file, const std::string& content) {
  namespace fs = std::filesystem;
  const fs::path directory = file.parent_path();
  if (!directory.empty()) fs::create_directories(directory);

  // The temporary lives in the same directory, so that the rename stays on one file system and
  // is atomic: a reader (ParaView refreshing, a stopped run) sees the old file or the new one,
  // never half of one. Process id and a counter keep concurrent writers apart.
  static std::atomic<unsigned long> counter{0};
  const fs::path temporary =
      directory / fmt::format(".{}.tmp-{}-{}", file.filename().string(),
                              static_cast<long>(::getpid()), counter.fetch_add(1));
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    if (!out) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw RunError("cannot write " + file.string() + " (through " + temporary.string() + ")");
    }
  }
  std::error_code error;
  fs::rename(temporary, file, error);
  if (error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw RunError("cannot rename " + temporary.string() + " to " + file.string() + ": " +
                   error.message());
  }
}

}  // namespace geompm
