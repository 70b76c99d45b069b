// VTK XML PolyData (.vtp) of line segments or triangles, in ASCII: the soil's boundary as the
// zero level set of its points (boundary.pvd). A boundary has few facets next to the points and
// the grid, so plain text (doubles written to round trip) costs little and needs no appended
// block.
#include <fmt/format.h>

#include <stdexcept>

#include "geompm/io/vtk_writer.hpp"
#include "geompm/io/vtk_writer_xml.hpp"

namespace geompm {

void write_vtp_facets(const std::filesystem::path& file, const std::vector<Vec3>& vertices,
                      int per_facet, const FieldSet& cell_fields) {
  if (per_facet != 2 && per_facet != 3)
    throw std::invalid_argument("write_vtp_facets: a facet has 2 or 3 vertices");
  const std::size_t n_facets = vertices.size() / per_facet;
  const char* kind = per_facet == 2 ? "Lines" : "Polys";
  std::string xml = fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <PolyData>\n"
      "    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"{}\" "
      "NumberOfStrips=\"0\" NumberOfPolys=\"{}\">\n"
      "      <Points>\n"
      "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
      vertices.size(), per_facet == 2 ? n_facets : 0, per_facet == 3 ? n_facets : 0);
  for (const Vec3& x : vertices) xml += fmt::format("{} {} {}\n", x.x(), x.y(), x.z());
  xml += "        </DataArray>\n      </Points>\n      <CellData>\n";
  for (const auto& [name, values] : cell_fields.vectors) {
    xml += fmt::format(
        "        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"3\" "
        "format=\"ascii\">\n",
        vtk_xml::escape(name));
    for (const Vec3& v : values) xml += fmt::format("{} {} {}\n", v.x(), v.y(), v.z());
    xml += "        </DataArray>\n";
  }
  for (const auto& [name, values] : cell_fields.scalars) {
    xml += fmt::format("        <DataArray type=\"Float64\" Name=\"{}\" format=\"ascii\">\n",
                       vtk_xml::escape(name));
    for (const double v : values) xml += fmt::format("{}\n", v);
    xml += "        </DataArray>\n";
  }
  for (const auto& [name, values] : cell_fields.integers) {
    xml += fmt::format("        <DataArray type=\"Int64\" Name=\"{}\" format=\"ascii\">\n",
                       vtk_xml::escape(name));
    for (const Index v : values) xml += fmt::format("{}\n", v);
    xml += "        </DataArray>\n";
  }
  xml += fmt::format(
      "      </CellData>\n      <{}>\n"
      "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n",
      kind);
  for (std::size_t k = 0; k < vertices.size(); ++k) xml += fmt::format("{}\n", k);
  xml +=
      "        </DataArray>\n"
      "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t f = 1; f <= n_facets; ++f) xml += fmt::format("{}\n", f * per_facet);
  xml += fmt::format("        </DataArray>\n      </{}>\n    </Piece>\n  </PolyData>\n</VTKFile>\n",
                     kind);
  write_file_atomically(file, xml);
}

}  // namespace geompm
