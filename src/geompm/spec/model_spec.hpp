// The model as read from a model file, before anything is built: plain data, validated by the
// reader (types, ranges, names that refer to each other). analysis/ builds the simulation from
// it. Each part keeps where it came from (SourceLocation) so that errors found later, while the
// mesh is built or points are seeded, still name the file, key path and line.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "geompm/core/error.hpp"
#include "geompm/core/types.hpp"
#include "geompm/mesh/cell_kind.hpp"
#include "geompm/mesh/structured_mesh.hpp"

namespace geompm::spec {

struct Mesh {
  std::optional<StructuredMeshSpec> generate;  // either generate ...
  std::string file;                            // ... or a Gmsh .msh file (absolute path)
  SourceLocation source;
};

/// How the stress of a material's points enters equilibrium: from the displacements alone; from
/// the displacements with each point's volume change replaced by its cell's mean (F-bar,
/// docs/theory.md §12), so that a dilatant or nearly isochoric plastic flow need only keep one
/// volume per cell; or with its mean stress replaced by an independent pressure field (mixed
/// p-u, docs/theory.md §11) so that nearly incompressible (undrained) soil does not lock.
enum class Formulation { Displacement, FBar, Mixed };

struct Material {
  std::string name;
  std::string model;                         // registered name, e.g. "linear_elastic"
  std::map<std::string, double> parameters;  // E, nu, density, ...
  /// As given; none: numerics.formulation, or the one that suits the model
  /// (analysis/material_formulation.hpp).
  std::optional<Formulation> formulation;
  SourceLocation source;
};

/// A part of space: selects cells of a mesh region, or points by position.
struct Region {
  enum class Kind { All, Group, Box, Polygon, Circle };
  Kind kind = Kind::All;
  std::string group;        // Group: a region (cell group) of the mesh
  Vec3 min = Vec3::Zero();  // Box
  Vec3 max = Vec3::Zero();
  std::vector<Vec3> polygon;   // Polygon (2D), counter-clockwise or clockwise
  Vec3 center = Vec3::Zero();  // Circle (2D) or sphere (3D)
  double radius = 0.0;
  SourceLocation source;
};

/// A region of the background mesh of one kind (docs/user-guide.md, "regions"): the cells of a
/// cell group, or those whose centroid lies in a geometric region, are MPM, FEM or buffer cells.
/// Cells no region names are MPM cells.
struct MeshRegion {
  std::string name;
  CellKind kind = CellKind::Mpm;
  Region region;  // All when only a distance from a structure is given
  /// Optionally, of those cells the ones whose centroid lies within (or beyond) `distance` of a
  /// structure as the model file places it (inside it counts as distance 0).
  struct Near {
    std::string structure;
    double distance = 0.0;
    bool beyond = false;
    SourceLocation source;
  };
  std::optional<Near> near;
  /// Of a generated mesh: the cell type of the region's rectangles (tri3 in a quad4 mesh or quad4
  /// in a tri3 one), e.g. a quad4 MPM region over a tri3 FEM region (seed §3.4); none: the
  /// generator's.
  std::optional<CellType> cell;
  SourceLocation cell_source;
  SourceLocation source;
};

/// A layer of a body layered by depth: the body's points at or above `bottom` (and below the
/// layer above) take `material`. The last layer has no bottom: it reaches down to the body's.
struct Layer {
  std::string material;
  std::optional<double> bottom;  // elevation (y in 2D, z in 3D) of the layer's base
  SourceLocation source;
};

/// A body's initial Cauchy stress given directly (tension positive; docs/user-guide.md,
/// "initial_stress"), each component an expression of x, y (, z): xx, yy, zz, xy, yz, xz.
struct InitialStress {
  std::array<std::string, 6> components = {"0", "0", "0", "0", "0", "0"};
  SourceLocation source;
};

struct Body {
  std::string name;
  std::string material;       // one material, or ...
  std::vector<Layer> layers;  // ... layers by elevation, top down (then `material` is empty)
  Region region;
  int points_per_cell = 4;  // 0: each cell's type's default (an imported mesh, not given)
  std::array<std::string, 3> initial_velocity = {"0", "0", "0"};  // expressions of x, y, z
  std::optional<InitialStress> initial_stress;  // none: zero, or the K0 procedure's
  SourceLocation source;
  SourceLocation points_per_cell_source;  // where the count was given (the body if defaulted)
};

/// Named set of material points (e.g. the head of a pile), for prescribed motion, loads and
/// histories. Selected by region among the points of `body` (all bodies if empty).
struct PointSet {
  std::string name;
  std::string body;
  Region region;
  SourceLocation source;
};

/// Named set of grid nodes: the mesh nodes in a box (min <= max; a side of zero length selects
/// the nodes on a line or plane, e.g. the base of a footing). Added to the mesh's boundaries, so
/// fixities, grid motions and reaction histories refer to it by name like a boundary.
struct NodeSet {
  std::string name;
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Zero();
  SourceLocation source;
};

/// Fixity of grid nodes: on a named boundary of the mesh, or on a plane x_axis = value.
struct Fixity {
  std::string boundary;  // empty when a plane is given
  int plane_axis = -1;   // 0, 1, 2
  double plane_value = 0.0;
  bool normal_only = false;  // "normal": only the component normal to the boundary
  std::array<bool, 3> components = {false, false, false};  // when not normal_only
  SourceLocation source;
};

/// Prescribed motion of a point set: each component an expression of t, or empty = free.
struct PrescribedMotion {
  std::string point_set;
  bool velocity = false;  // false: the expressions give the displacement since phase start
  std::array<std::string, 3> components;  // "" = free
  SourceLocation source;
};

/// Prescribed motion of grid nodes (docs/theory.md §5.3): the nodes of a boundary, node set or
/// plane are moved by the given displacement (or velocity) per component, an expression of t or
/// empty = free. A smooth footing drives only the vertical component, a rough one every one.
struct GridMotion {
  std::string boundary;  // a boundary or node set; empty when a plane is given
  int plane_axis = -1;
  double plane_value = 0.0;
  bool velocity = false;  // false: the expressions give the displacement since phase start
  std::array<std::string, 3> components;  // "" = free
  SourceLocation source;
};

/// A force on a point set (load control), shared among its points in proportion to mass.
struct PointSetLoad {
  std::string point_set;
  std::array<std::string, 3> components = {"0", "0", "0"};  // expressions of t (phase time)
  SourceLocation source;
};

/// A built-in structure shape (docs/user-guide.md, "structures"), meshed when the model is built:
/// its kind, its dimensions by name, where it is placed and how finely it is meshed.
struct StructureShape {
  std::string kind;                          // pipe | tbar | spudcan | plate | cone | footing
  std::map<std::string, double> dimensions;  // diameter, thickness, length, tip_angle, ...
  Vec3 position = Vec3::Zero();  // its anchor: the tip (spudcan, plate, cone), the centre of the
                                 // base (footing) or of the circle (pipe, tbar)
  double cell_size = 0.0;        // about this size; 0: largest dimension / 20, at most smallest / 2
  std::optional<CellType> cell;  // tri3, tri6, quad4 (2D), tet4 (3D); default tri3 / tet4
  SourceLocation source;
};

/// A structure in the soil (docs/theory.md §17): a finite-element mesh of its own, from a shape
/// or a Gmsh file, rigid (one rigid-body motion); its mass from exactly one of density, mass or
/// weight (per unit thickness in plane strain, per radian in axisymmetry).
/// The contact of a structure with the soil (docs/theory.md §18): the tangential law and the
/// bodies whose points it touches.
struct Contact {
  bool enabled = true;                // `contact: none`: the structure touches nothing
  std::string tangential = "smooth";  // smooth | rough | adhesion | friction
  double adhesion = 0.0;              // adhesion: the largest shear stress, or ...
  double alpha = 0.0;                 // ... alpha times the soil's s_u at the contact
  double friction = 0.0;              // friction: Coulomb's mu ...
  std::optional<double> cap;          // ... and, optionally, the largest shear stress
  std::vector<std::string> bodies;    // empty: every body
  SourceLocation source;
};

/// Some nodes of a deformable structure's mesh (a drive's or a history's): all of them, those at
/// its top or bottom (largest or smallest y in 2D, z in 3D) or left or right (x), a physical group
/// of its Gmsh mesh, or those in a box.
struct StructureNodes {
  enum class Kind { All, Top, Bottom, Left, Right, Group, Box };
  Kind kind = Kind::All;
  std::string group;                            // Group
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();  // Box
  SourceLocation source;
};

struct Structure {
  std::string name;
  Contact contact;  // every structure touches the soil; smooth unless said otherwise
  std::optional<StructureShape> shape;  // either a built-in shape ...
  std::string mesh_file;                // ... or a Gmsh .msh file (absolute path)
  bool rigid = true;
  /// A deformable structure (docs/theory.md §17.7): the name of the materials entry its Gauss
  /// points follow (its density the material's unless density, mass or weight is given).
  std::string material;
  std::optional<double> density, mass, weight;
  std::optional<Vec3> reference_point;  // of its rotation; default: the centroid
  SourceLocation source;
};

/// How a phase drives a structure, per component of its rigid-body motion: translations of the
/// reference point (0, 1, 2: x, y, z) and rotations about it (3, 4, 5: about x, y, z; in 2D
/// only 5). A component with a motion is prescribed (its displacement since the phase start or
/// its velocity); the others are free, loaded by the given force or moment (and self-weight).
/// A deformable structure is driven on sets of its nodes (`nodes`; translations only, the force
/// the set's total), several per phase.
struct StructureDrive {
  std::string structure;
  std::optional<StructureNodes> nodes;  // deformable structures only
  bool velocity = false;                // motion components are velocities (angular velocities)
  std::array<std::string, 6> motion;    // expressions of t; "" = free
  std::array<std::string, 6> load;      // force, moment: expressions of t; "" = none
  SourceLocation source;
};

/// A distributed load on the soil's boundary, the zero level set of its points' density
/// (docs/theory.md §16): a pressure (normal, positive into the body) or a traction, expressions
/// of x, y (, z) and the phase time t, on the part of the boundary inside `where` (a box, each
/// axis optional) of the bodies named (all if empty).
struct SurfaceLoad {
  bool pressure = true;  // pressure: components[0]; traction: a vector
  std::array<std::string, 3> components = {"0", "0", "0"};
  bool following = false;  // a pressure that turns and stretches with the surface in a step
  std::array<std::optional<std::array<double, 2>>, 3> where;  // [low, high] per axis
  std::vector<std::string> bodies;
  SourceLocation source;
};

struct Gravity {
  Vec3 acceleration = Vec3::Zero();
  bool ramp = false;  // ramp linearly from 0 over the phase (quasi-static load steps)
};

/// The K0 procedure (docs/theory.md §10): the analysis starts from geostatic stresses in the
/// points of `bodies`, sigma_v = weight of the soil above (with the first phase's gravity) and
/// sigma_h = K0 sigma_v, for level ground in horizontal layers. Only in the first phase.
struct K0Procedure {
  std::map<std::string, double> k0;  // per material; a material absent takes its default
  std::vector<std::string> bodies;   // empty: every body
  SourceLocation source;
};

struct TimeStepping {
  double initial = 0.0;
  double min = 0.0;
  double max = 0.0;
  double growth = 1.5;        // largest factor after a converged step
  double cutback = 0.5;       // factor after a failed step
  int target_iterations = 8;  // Newton iterations a step should take (fewer: grow; more: shrink)
};

struct Newton {
  int max_iterations = 15;
  double residual_tolerance = 1e-8;      // relative to the force scale
  double displacement_tolerance = 1e-8;  // relative to the step's displacement increment
  // Halvings of a correction whose residual grew (0: none); -1, the default: none in a step's
  // first attempt, up to 6 in a second one from zero if the first does not converge
  // (analysis/step.cpp, docs/theory.md §4.4).
  int line_search = -1;
  bool last_resort_backtracking() const { return line_search < 0; }
  // The energy line search's tolerance on dx . R relative to its start (docs/theory.md §4.4;
  // 0: off).
  double energy_line_search = 0.0;
  double tangent_check = 0.0;  // finite-difference step of the tangent check (0: off)
  // Newton's first iterate: a zero increment, or the last converged step's increment scaled to
  // this step's length (linear extrapolation of the path).
  bool extrapolate = false;
  // With the extrapolated start: the iterations after which it goes on only while converging
  // superlinearly (docs/theory.md §4.5); 0: half of max_iterations; max_iterations or more: it may
  // use them all.
  int extrapolated_patience = 0;
};

/// The `damped` preset: Bossak's scheme damping the highest frequencies to a spectral radius of
/// (1 + alpha_m) / (1 - alpha_m) = 0.82 (docs/theory.md §4.7); a mode of 20 steps a period loses
/// about 0.5 % of its amplitude a period.
inline constexpr double damped_alpha_m = -0.1;

struct Dynamics {
  bool quasi_static = true;
  double beta = 0.25;  // Newmark; trapezoidal rule by default (no numerical damping)
  double gamma = 0.5;
  double alpha_m = 0.0;  // Bossak's weight of the old acceleration (docs/theory.md §4.7)
};

struct Phase {
  std::string name;
  double duration = 1.0;
  TimeStepping time_step;
  Dynamics dynamics;
  Newton newton;
  std::optional<Gravity> gravity;
  std::optional<K0Procedure> k0_procedure;
  std::vector<Fixity> fixities;
  std::vector<PrescribedMotion> motions;
  std::vector<GridMotion> grid_motions;
  std::vector<PointSetLoad> loads;
  std::vector<StructureDrive> structure_drives;  // structures not listed: free
  std::vector<SurfaceLoad> surface_loads;
  SourceLocation source;
};

/// One column of the history CSV.
struct History {
  std::string name;       // column name; defaults to quantity[_target][_component]
  std::string quantity;   // reaction | displacement | velocity | position | kinetic_energy |
                          // strain_energy | newton_iterations | time_step | load
  std::string boundary;   // reaction on a boundary or node set; displacement of its grid motion
  std::string point_set;  // reaction, displacement, velocity, position, load of a point set
  std::string structure;  // reaction, moment, displacement, rotation, position of a structure
  int component = -1;     // 0, 1, 2; -1 for scalars
  /// A deformable structure's displacement, phase_displacement, position: the mean of these
  /// nodes (default all).
  std::optional<StructureNodes> nodes;
  /// section_stress of a deformable structure: the mean normal stress n . sigma n over its cross
  /// section by the line (2D) or plane (3D) through `section_point` normal to `section_normal`.
  Vec3 section_point = Vec3::Zero(), section_normal = Vec3::Zero();
  SourceLocation source;
};

/// A horizontal line (lo == hi) or band (lo < hi) of a plot, in the plotted (scaled) y units.
struct PlotReference {
  double lo = 0, hi = 0;
  std::string label;
};

struct Plot {
  std::string file;                     // PNG, relative to the output directory
  std::string x;                        // history column
  std::vector<std::string> y;           // history columns
  double x_scale = 1.0, y_scale = 1.0;  // e.g. -1 to plot settlement downward as positive
  std::string title;
  std::string x_label, y_label;  // quantity and unit; default: the columns with their scale
  std::vector<PlotReference> references;
  SourceLocation source;
};

/// When `geompm run` saves the state of the run to checkpoint.bin (and at the end of each
/// phase); both 0: never. Defaults: a killed run loses at most 100 steps or 10 minutes of work,
/// and a checkpoint costs little next to 100 steps (docs/user-guide.md, "Checkpoints").
struct Checkpoint {
  int every_steps = 100;      // converged steps between checkpoints (0: not by steps)
  double every_minutes = 10;  // wall-clock minutes between checkpoints (0: not by time)
};

struct Output {
  int vtk_every = 1;     // write ParaView files every n converged steps (0 = never)
  bool vtk_grid = true;  // also write the grid with nodal fields
  std::vector<History> histories;
  std::vector<Plot> plots;
  Checkpoint checkpoint;
};

enum class LostPointPolicy { Stop, Remove };

/// How a point sees the grid: standard MPM shape functions of its cell, the dual domain
/// material point method (DDMP, seed §3.6; docs/theory.md §8) with smoothed gradients, or GIMP
/// weights averaged over the point's domain (docs/theory.md §9; rectilinear grids only).
enum class Interpolation { Standard, DualDomain, Gimp };

/// The most steps a phase may need at its largest time step (docs/user-guide.md, phases).
inline constexpr double max_steps_per_phase = 1e8;

/// The most columns output.history may have (docs/user-guide.md, output).
inline constexpr std::size_t max_history_columns = 10000;

/// The most numerics.buffer_layers may be (docs/user-guide.md, numerics).
inline constexpr int max_buffer_layers = 100;

struct Numerics {
  Interpolation interpolation = Interpolation::Standard;
  /// The formulation of the materials that give none; none: each material the one that suits it
  /// (analysis/material_formulation.hpp).
  std::optional<Formulation> formulation;
  SourceLocation interpolation_source;  // where it was given, for errors found with the mesh
  double empty_cell_stiffness = 1e-4;   // relative to the softest carried Young's modulus
  double sparse_node_stiffness = 0.0;   // relative to the same modulus (eq. 6.2)
  double sparse_node_fill = 0.05;       // support fill below which a node gets that spring
  double ghost_penalty = 0.0;           // gamma of the edge cells' face penalty (eq. 6.3)
  double ghost_penalty_fill = 0.5;      // fill up to which an edge cell carries it
  int buffer_layers = 1;                // layers of empty cells kept active around the body
  LostPointPolicy lost_points = LostPointPolicy::Stop;
  std::string linear_solver = "umfpack";
  std::string petsc_options;  // for experts: PETSc's own options (linear_solver.hpp)
  Index direct_limit = -1;    // auto: the direct solver below this many unknowns (-1: by dimension)
  bool mixed_volume_average = false;  // mixed_volume: cell_average (F-bar) or per_point
  /// mixed_material_pressure: field (theory §14) or own; none: each mixed material the one that
  /// suits it (analysis/material_formulation.hpp).
  std::optional<bool> mixed_field_pressure;
  bool mixed_incremental_pressure = false;     // mixed_pressure_equation: incremental or total
  SourceLocation incremental_pressure_source;  // where it was given
  double pressure_stabilisation_floor = 0.0;   // share of the exact projection (theory eq. 11.10)
  bool fitted_pressure_start = false;          // mixed_pressure_start: fitted (eq. 11.11) or points
};

struct Model {
  std::string file;       // the model file, as given
  std::string directory;  // its directory, for relative paths
  std::string title;
  Kinematics kinematics = Kinematics::PlaneStrain;
  Mesh mesh;
  std::vector<MeshRegion> regions;  // kinds of the mesh's cells (none: every cell MPM)
  std::vector<Material> materials;
  std::vector<Body> bodies;
  std::vector<PointSet> point_sets;
  std::vector<NodeSet> node_sets;
  std::vector<Structure> structures;
  std::vector<Phase> phases;
  Output output;
  Numerics numerics;
};

}  // namespace geompm::spec
