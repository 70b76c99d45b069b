// Writes tests/unit/mesh/data/mixed_box.msh, the 3D mixed mesh of the tests (gmsh_test.cpp,
// analysis/test_mixed_meshes_3d.cpp): the box [0, 2] x [0, 1] x [0, 1] that Gmsh meshes with
// hexahedra left of x = 1 (a transfinite, recombined volume, 2 cells per edge), tetrahedra right
// of it, and the pyramids its 3D mesher puts on the quadrangles of x = 1 between them. Regions
// "hexahedra" and "tetrahedra"; boundaries "left", "right" (x), "front", "back" (y), "bottom",
// "top" (z).
//
// The file is shipped rather than made in the tests: Gmsh 4.8.4 (Debian 12) reads out of bounds
// when it moves the pyramids' apexes (RelocateVerticesOfPyramids, seen with valgrind), which
// aborted the test programs that called it; this program ran clean under valgrind. Build and run:
//   g++ -std=c++20 tests/tools/mixed_box_msh.cpp -lgmsh -o /tmp/mixed_box_msh
//   /tmp/mixed_box_msh tests/unit/mesh/data/mixed_box.msh
#include <gmsh.h>

#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace {

void named_group(int dim, const std::vector<int>& tags, const std::string& name) {
  gmsh::model::setPhysicalName(dim, gmsh::model::addPhysicalGroup(dim, tags), name);
}

void build_mixed_box(int hex_cells, double tet_size) {
  namespace occ = gmsh::model::occ;
  gmsh::model::add("mixed_box");
  const int hexahedra = occ::addBox(0, 0, 0, 1, 1, 1), tetrahedra = occ::addBox(1, 0, 0, 1, 1, 1);
  std::vector<std::pair<int, int>> fragments;
  std::vector<std::vector<std::pair<int, int>>> children;
  occ::fragment({{3, hexahedra}}, {{3, tetrahedra}}, fragments, children);
  occ::synchronize();
  std::vector<std::pair<int, int>> faces;
  gmsh::model::getBoundary({{3, hexahedra}}, faces, false, false, false);
  for (const auto& [dim, signed_tag] : faces) {
    const int face = std::abs(signed_tag);
    std::vector<std::pair<int, int>> curves;
    gmsh::model::getBoundary({{2, face}}, curves, false, false, false);
    for (const auto& [curve_dim, curve] : curves)
      gmsh::model::mesh::setTransfiniteCurve(std::abs(curve), hex_cells + 1);
    gmsh::model::mesh::setTransfiniteSurface(face);
    gmsh::model::mesh::setRecombine(2, face);
  }
  gmsh::model::mesh::setTransfiniteVolume(hexahedra);
  named_group(3, {hexahedra}, "hexahedra");
  named_group(3, {tetrahedra}, "tetrahedra");
  // The outer faces by the side of the box they lie on (OCC pads its bounding boxes).
  std::vector<std::pair<int, int>> surfaces;
  gmsh::model::getEntities(surfaces, 2);
  const char* names[3][2] = {{"left", "right"}, {"front", "back"}, {"bottom", "top"}};
  const double ends[3][2] = {{0.0, 2.0}, {0.0, 1.0}, {0.0, 1.0}};
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      std::vector<int> on_side;
      for (const auto& [dim, tag] : surfaces) {
        double box[6];
        gmsh::model::getBoundingBox(2, tag, box[0], box[1], box[2], box[3], box[4], box[5]);
        if (std::abs(box[axis] - ends[axis][side]) < 1e-6 &&
            std::abs(box[axis + 3] - ends[axis][side]) < 1e-6)
          on_side.push_back(tag);
      }
      named_group(2, on_side, names[axis][side]);
    }
  gmsh::option::setNumber("Mesh.MeshSizeMax", tet_size);
  gmsh::model::mesh::generate(3);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: mixed_box_msh OUTPUT.msh\n";
    return 2;
  }
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  build_mixed_box(2, 0.5);
  gmsh::write(argv[1]);
  gmsh::finalize();
  return 0;
}
