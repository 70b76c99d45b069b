// The model reader's structures (docs/user-guide.md, "structures"): the top-level list (a shape
// or a mesh file, rigid, density, mass or weight, reference point), a phase's drives (per
// component moved or loaded) and a structure's histories; malformed input fails with the file,
// line, key path and what was expected.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>

#include "geompm/io/model_reader.hpp"
#include "model_reader_support.hpp"

namespace geompm {
namespace {

using namespace geompm::testing;

const std::string kStructures = R"m(structures:
  - name: pipe
    shape: {type: pipe, diameter: 0.8, thickness: 0.05, position: [0.5, 56], cell: tri6}
    weight: 6.0
    reference_point: [0.5, 56]
  - name: can
    shape: {type: spudcan, diameter: 1, tip_angle: 150, shoulder: 0.1, position: [0.5, 57]}
    density: 7.8
)m";
const std::string kDrives = R"m(    structures:
      pipe: {displacement: [~, "-0.1*t"], rotation: 0}
      can: {force: [0, "-2*t"], moment: ~}
)m";
const std::string kHistories = R"m(    - {quantity: reaction, structure: pipe, component: y}
    - {quantity: moment, structure: pipe, component: z}
    - {quantity: rotation, structure: can, component: z, name: can_turn}
)m";

// kValidModel with the structures before the phases, the drives in the second phase and the
// histories in the output.
std::string with_structures(const std::string& structures = kStructures,
                            const std::string& drives = kDrives) {
  return apply(kValidModel, {{"phases:\n", structures + "phases:\n"},
                             {"      - {point_set: side, force: [\"0\", \"-10*t\"]}\n",
                              "      - {point_set: side, force: [\"0\", \"-10*t\"]}\n" + drives},
                             {"    - {quantity: kinetic_energy}\n",
                              "    - {quantity: kinetic_energy}\n" + kHistories}});
}

TEST(ModelReaderStructures, ReadsShapesDrivesAndHistories) {
  const spec::Model model = read_model_from_string(with_structures(), "model.yaml");
  ASSERT_EQ(model.structures.size(), 2u);
  const spec::Structure& pipe = model.structures[0];
  EXPECT_EQ(pipe.name, "pipe");
  ASSERT_TRUE(pipe.shape);
  EXPECT_EQ(pipe.shape->kind, "pipe");
  EXPECT_EQ(pipe.shape->dimensions.at("thickness"), 0.05);
  EXPECT_EQ(pipe.shape->position, Vec3(0.5, 56, 0));
  EXPECT_EQ(pipe.shape->cell, CellType::Tri6);
  EXPECT_EQ(pipe.weight, 6.0);
  EXPECT_FALSE(pipe.density);
  EXPECT_TRUE(pipe.rigid);
  EXPECT_EQ(pipe.reference_point, Vec3(0.5, 56, 0));
  EXPECT_EQ(model.structures[1].shape->dimensions.at("tip_angle"), 150.0);
  EXPECT_EQ(model.structures[1].density, 7.8);

  ASSERT_EQ(model.phases[1].structure_drives.size(), 2u);
  const spec::StructureDrive& push = model.phases[1].structure_drives[0];
  EXPECT_EQ(push.structure, "pipe");
  EXPECT_FALSE(push.velocity);
  EXPECT_EQ(push.motion[0], "");
  EXPECT_EQ(push.motion[1], "-0.1*t");
  EXPECT_EQ(push.motion[5], "0");  // the rotation about z
  const spec::StructureDrive& load = model.phases[1].structure_drives[1];
  EXPECT_EQ(load.load[1], "-2*t");
  EXPECT_EQ(load.load[5], "");  // a free moment: none
  EXPECT_TRUE(model.phases[0].structure_drives.empty());

  const auto& h = model.output.histories;
  ASSERT_GE(h.size(), 6u);
  EXPECT_EQ(h[3].name, "reaction_pipe_y");
  EXPECT_EQ(h[3].structure, "pipe");
  EXPECT_EQ(h[4].name, "moment_pipe_z");
  EXPECT_EQ(h[4].component, 2);
  EXPECT_EQ(h[5].name, "can_turn");
}

TEST(ModelReaderStructures, ReadsAMeshFileRelativeToTheModel) {
  const std::string structures = R"m(structures:
  - {name: pile, mesh: ../../examples/footing_gmsh/footing.msh, mass: 2}
)m";
  const std::string text = with_structures(structures, "");
  // Only the history of 'pipe' refers to a structure the list lacks: drop them.
  const std::string without = apply(text, {{kHistories, ""}});
  const std::string file = std::string(GEOMPM_SOURCE_DIR) + "/tests/unit/model.yaml";
  const spec::Model model = read_model_from_string(without, file);
  ASSERT_EQ(model.structures.size(), 1u);
  EXPECT_TRUE(model.structures[0].mesh_file.ends_with("examples/footing_gmsh/footing.msh"));
  EXPECT_EQ(model.structures[0].mass, 2.0);
}

struct Bad {
  std::string name;
  std::string structures, drives;  // replacing kStructures, kDrives
  std::string line_marker, key_path, explanation;
};

void PrintTo(const Bad& c, std::ostream* os) { *os << c.name; }

class ModelReaderStructuresMalformed : public ::testing::TestWithParam<Bad> {};

TEST_P(ModelReaderStructuresMalformed, NamesFileLineKeyPathAndProblem) {
  const Bad& c = GetParam();
  const std::string text = with_structures(c.structures.empty() ? kStructures : c.structures,
                                           c.drives.empty() ? kDrives : c.drives);
  std::string message;
  try {
    read_model_from_string(text, "model.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    message = e.what();
  }
  const std::string where =
      fmt::format("model.yaml:{}: {}: ", line_of(text, c.line_marker), c.key_path);
  EXPECT_EQ(message.rfind(where, 0), 0u) << "expected '" << where << "'\n  message: " << message;
  EXPECT_NE(message.find(c.explanation), std::string::npos)
      << "expected '" << c.explanation << "' in\n  " << message;
}

const std::string kOne =
    "structures:\n  - name: pipe\n    shape: {type: pipe, diameter: 0.8, position: [0.5, 56]}\n";
const std::string kPipeDrive = "    structures:\n      pipe: {displacement: [0, 0]}\n";

const std::vector<Bad> kBad = {
    {"rigid_false", kOne + "    density: 1\n    rigid: false\n", kPipeDrive, "rigid: false",
     "structures[0].rigid", "give deformable: {material: <a materials entry>}"},
    {"deformable_of_no_material", kOne + "    deformable: {material: steel}\n", kPipeDrive,
     "deformable:", "structures[0].deformable.material", "no material named 'steel'"},
    {"deformable_and_rigid", kOne + "    deformable: {material: soil}\n    rigid: true\n",
     kPipeDrive, "rigid: true", "structures[0].rigid", "either rigid or deformable"},
    {"deformable_reference_point",
     kOne + "    deformable: {material: soil}\n    reference_point: [0, 0]\n", kPipeDrive,
     "reference_point", "structures[0].reference_point", "no rigid-body motion"},
    {"deformable_turned", kOne + "    deformable: {material: soil}\n",
     "    structures:\n      pipe: {nodes: top, rotation: 0}\n", "pipe: {nodes",
     "phases[1].structures.pipe.rotation", "no rigid-body rotation"},
    {"deformable_drive_without_nodes", kOne + "    deformable: {material: soil}\n",
     "    structures:\n      pipe: {displacement: [0, 0]}\n", "pipe: {disp",
     "phases[1].structures.pipe.nodes", "missing required key"},
    {"deformable_box_upside_down", kOne + "    deformable: {material: soil}\n",
     "    structures:\n      pipe: {nodes: {min: [0, 1], max: [1, 0]}, displacement: [0, 0]}\n",
     "pipe: {nodes", "phases[1].structures.pipe.nodes.max", "expected max >= min"},
    {"no_mass", kOne, kPipeDrive, "- name: pipe", "structures[0]",
     "expected one of the keys density, mass, weight"},
    {"two_masses", kOne + "    density: 1\n    mass: 2\n", kPipeDrive, "mass: 2",
     "structures[0].mass", "give only one of density, mass, weight"},
    {"unknown_shape",
     "structures:\n  - name: pipe\n    shape: {type: pile, diameter: 1, position: [0, 0]}\n    "
     "mass: 1\n",
     kPipeDrive, "shape: {", "structures[0].shape.type", "did you mean 'pipe'"},
    {"dimension_of_another_shape",
     "structures:\n  - name: pipe\n    shape: {type: pipe, diameter: 1, tip_angle: 30, position: "
     "[0, 0]}\n    mass: 1\n",
     kPipeDrive, "shape: {", "structures[0].shape.tip_angle", "its dimensions are: diameter"},
    {"missing_dimension",
     "structures:\n  - name: pipe\n    shape: {type: spudcan, diameter: 1, position: [0, 0]}\n  "
     "  mass: 1\n",
     kPipeDrive, "shape: {", "structures[0].shape.tip_angle", "missing required key"},
    {"angle_above_180",
     "structures:\n  - name: pipe\n    shape: {type: spudcan, diameter: 1, tip_angle: 200, "
     "position: [0, 0]}\n    mass: 1\n",
     kPipeDrive, "shape: {", "structures[0].shape.tip_angle", "at most 180"},
    {"missing_mesh_file", "structures:\n  - {name: pipe, mesh: nowhere.msh, mass: 1}\n", kPipeDrive,
     "- {name: pipe", "structures[0].mesh", "not found"},
    {"shape_and_mesh", "structures:\n  - {name: pipe, mesh: a.msh, shape: {type: pipe}, mass: 1}\n",
     kPipeDrive, "- {name: pipe", "structures[0].mesh", "give only one of shape, mesh"},
    {"drive_of_no_structure", kOne + "    mass: 1\n",
     "    structures:\n      pipes: {displacement: [0, 0]}\n",
     "pipes:", "phases[1].structures.pipes", "did you mean 'pipe'"},
    {"moved_and_loaded", kOne + "    mass: 1\n",
     "    structures:\n      pipe: {displacement: [0, ~], force: [1, 0]}\n", "pipe: {disp",
     "phases[1].structures.pipe", "both prescribed and loaded"},
    {"mixed_kinds", kOne + "    mass: 1\n",
     "    structures:\n      pipe: {displacement: [0, ~], angular_velocity: 0}\n", "pipe: {disp",
     "phases[1].structures.pipe", "displacement with rotation"},
    {"drive_too_short", kOne + "    mass: 1\n", "    structures:\n      pipe: {velocity: [1]}\n",
     "pipe: {vel", "phases[1].structures.pipe.velocity", "expected a list of 2 components"},
    {"alpha_above_one", kOne + "    mass: 1\n    contact: {tangential: adhesion, alpha: 1.5}\n",
     kPipeDrive, "contact: {", "structures[0].contact.alpha", "expected 0 < alpha <= 1"},
    {"adhesion_and_alpha",
     kOne + "    mass: 1\n    contact: {tangential: adhesion, adhesion: 5, alpha: 0.5}\n",
     kPipeDrive, "contact: {", "structures[0].contact.alpha", "either 'adhesion'"},
    {"adhesion_of_nothing", kOne + "    mass: 1\n    contact: {tangential: adhesion}\n", kPipeDrive,
     "contact: {", "structures[0].contact", "needs 'adhesion' (a stress) or 'alpha'"},
    {"alpha_with_friction",
     kOne + "    mass: 1\n    contact: {tangential: friction, friction: 0.3, alpha: 0.5}\n",
     kPipeDrive, "contact: {", "structures[0].contact.alpha", "belongs to tangential: adhesion"},
};

INSTANTIATE_TEST_SUITE_P(Cases, ModelReaderStructuresMalformed, ::testing::ValuesIn(kBad),
                         [](const auto& info) { return info.param.name; });

TEST(ModelReaderStructures, HistoriesOfStructuresNeedAKnownOneAndAnAxisOfRotation) {
  const std::string unknown =
      apply(with_structures(),
            {{"structure: can, component: z, name", "structure: cab, component: z, name"}});
  EXPECT_THROW(read_model_from_string(unknown, "model.yaml"), InputError);
  const std::string about_y = apply(with_structures(), {{"{quantity: moment, structure: pipe, "
                                                         "component: z}",
                                                         "{quantity: moment, structure: pipe, "
                                                         "component: y}"}});
  try {
    read_model_from_string(about_y, "model.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a moment is about z"), std::string::npos) << e.what();
  }
}

TEST(ModelReaderStructures, RefuseWhatAxisymmetryCannotDo) {
  const std::string axi =
      apply(with_structures(kOne + "    mass: 1\n",
                            "    structures:\n      pipe: {displacement: [0, ~], rotation: 0}\n"),
            {{"kinematics: plane_strain", "kinematics: axisymmetric"}, {kHistories, ""}});
  try {
    read_model_from_string(axi, "model.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    // The pipe off the axis is found first.
    EXPECT_NE(std::string(e.what()).find("its position's x must be 0"), std::string::npos)
        << e.what();
  }
}

// 3D: six components, rotations and moments as lists of three; a 3D plate needs its breadth.
TEST(ModelReaderStructures, ReadsThreeDimensionalDrives) {
  const std::string model = R"m(analysis: {kinematics: 3d}
mesh:
  generate: {cell: hex8, x: {length: 1, cells: 1}, y: {length: 1, cells: 1}, z: {length: 1, cells: 1}}
materials:
  soil: {model: linear_elastic, E: 1000, nu: 0.3, density: 1}
bodies:
  ground: {material: soil, region: all}
structures:
  - name: pile
    shape: {type: plate, width: 0.1, length: 2, tip: 0.1, breadth: 0.5, position: [0.5, 0.5, 2]}
    mass: 1
phases:
  - name: drive
    time_step: 0.1
    structures:
      pile: {displacement: [0, 0, "-t"], rotation: [0, ~, "0.1*t"], moment: [~, 1, ~]}
)m";
  const spec::Model m = read_model_from_string(model, "m.yaml");
  const spec::StructureDrive& d = m.phases[0].structure_drives.at(0);
  EXPECT_EQ(d.motion[2], "-t");
  EXPECT_EQ(d.motion[3], "0");
  EXPECT_EQ(d.motion[4], "");
  EXPECT_EQ(d.motion[5], "0.1*t");
  EXPECT_EQ(d.load[4], "1");
  EXPECT_EQ(m.structures[0].shape->dimensions.at("breadth"), 0.5);
  std::string no_breadth = model;
  no_breadth.erase(no_breadth.find(" breadth: 0.5,"), 14);
  try {
    read_model_from_string(no_breadth, "m.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("structures[0].shape.breadth: missing required key"),
              std::string::npos)
        << e.what();
  }
}

// The example of docs/user-guide.md, "structures", after the model's first sections, reads.
TEST(ModelReaderStructures, ReadsTheExampleOfTheUserGuide) {
  std::ifstream guide(std::string(GEOMPM_SOURCE_DIR) + "/docs/user-guide.md");
  const std::string text((std::istreambuf_iterator<char>(guide)), std::istreambuf_iterator<char>());
  const std::size_t heading = text.find("### structures");
  ASSERT_NE(heading, std::string::npos);
  const std::size_t begin = text.find("```yaml\n", heading) + 8;
  const std::size_t end = text.find("```", begin);
  const spec::Model m = read_model_from_string(
      kHeader + kMesh + kMaterials + kBodies + text.substr(begin, end - begin), "guide.yaml");
  ASSERT_EQ(m.structures.size(), 1u);
  EXPECT_EQ(m.structures[0].weight, 6.0);
  EXPECT_EQ(m.phases[0].structure_drives[0].motion[1], "-0.4*t");
  EXPECT_EQ(m.output.histories[0].name, "reaction_pipe_y");
}

}  // namespace
}  // namespace geompm
