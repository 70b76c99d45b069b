// A parallel unstructured grid (.pvtu): the XML file that names the pieces of one data set, each
// a .vtu of its own written by one process of a distributed run, and describes the arrays every
// piece holds, so that ParaView reads them as one. It holds no data itself.
#include <fmt/format.h>

#include "geompm/io/vtk_writer.hpp"
#include "geompm/io/vtk_writer_xml.hpp"

namespace geompm {

namespace {

std::string array_tag(const char* type, const std::string& name, int components,
                      const char* extra = "") {
  return fmt::format("      <PDataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\"{}/>\n",
                     type, vtk_xml::escape(name), components, extra);
}

}  // namespace

void write_pvtu_points(const std::filesystem::path& file, const std::vector<std::string>& pieces,
                       const FieldSet& fields) {
  // The arrays as write_vtu_points writes them: each kind its type, components and order.
  std::string point_data;
  for (const auto& [name, values] : fields.scalars) point_data += array_tag("Float64", name, 1);
  for (const auto& [name, values] : fields.vectors) point_data += array_tag("Float64", name, 3);
  for (const auto& [name, values] : fields.tensors)
    point_data += array_tag("Float64", name, 6, vtk_xml::symmetric_tensor_components);
  for (const auto& [name, values] : fields.integers) point_data += array_tag("Int32", name, 1);
  std::string xml = fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <PUnstructuredGrid GhostLevel=\"0\">\n"
      "    <PPointData>\n{}    </PPointData>\n"
      "    <PCellData>\n    </PCellData>\n"
      "    <PPoints>\n{}    </PPoints>\n"
      "    <PCells>\n{}{}{}    </PCells>\n",
      point_data, array_tag("Float64", "Points", 3), array_tag("Int64", "connectivity", 1),
      array_tag("Int64", "offsets", 1), array_tag("UInt8", "types", 1));
  for (const std::string& piece : pieces)
    xml += fmt::format("    <Piece Source=\"{}\"/>\n", vtk_xml::escape(piece));
  xml += "  </PUnstructuredGrid>\n</VTKFile>\n";
  write_file_atomically(file, xml);
}

}  // namespace geompm
