#include "geompm/structures/shapes.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "geompm/mesh/gmsh_import.hpp"
#include "geompm/mesh/gmsh_session.hpp"

namespace geompm {

namespace {

constexpr double pi = std::numbers::pi;

// A dimension of the shape: given and positive (or zero where `zero_allowed`), else `fallback`.
double dimension(const spec::StructureShape& s, const char* key,
                 std::optional<double> fallback = std::nullopt, bool zero_allowed = false) {
  const auto it = s.dimensions.find(key);
  if (it == s.dimensions.end()) {
    if (fallback) return *fallback;
    throw std::invalid_argument(fmt::format("a {} needs its '{}'", s.kind, key));
  }
  const double v = it->second;
  if (!(zero_allowed ? v >= 0 : v > 0) || !std::isfinite(v))
    throw std::invalid_argument(fmt::format("{} of the {}: expected a number {} 0, found {}", key,
                                            s.kind, zero_allowed ? ">=" : ">", v));
  return v;
}

// An included angle in degrees, in (0, 180]: 180 is flat.
double angle(const spec::StructureShape& s, const char* key, std::optional<double> fallback) {
  const double degrees = dimension(s, key, fallback);
  if (degrees > 180.0)
    throw std::invalid_argument(fmt::format(
        "{} of the {}: expected an included angle in degrees, up to 180 (flat), found {}", key,
        s.kind, degrees));
  return degrees * pi / 180.0;
}

// The height of a cone of the included angle over the radius r (0 when flat).
double cone_height(double r, double included) {
  return included >= pi ? 0.0 : r / std::tan(0.5 * included);
}

// Appends x unless it repeats the last point (a zero shoulder, a flat top).
void append(std::vector<Vec3>& points, double x, double y) {
  const Vec3 p(x, y, 0.0);
  if (points.empty() || (points.back() - p).norm() > 1e-12 * (1.0 + p.norm())) points.push_back(p);
}

std::vector<Vec3> spudcan_profile(const spec::StructureShape& s) {
  const double R = 0.5 * dimension(s, "diameter");
  const double tip = cone_height(R, angle(s, "tip_angle", std::nullopt));
  const double shoulder = dimension(s, "shoulder", 0.0, true);
  const double r = 0.5 * dimension(s, "shaft_diameter", 0.0, true);
  const double shaft = dimension(s, "shaft_length", 0.0, true);
  if (r >= R)
    throw std::invalid_argument(
        fmt::format("shaft_diameter of the spudcan: expected less than its diameter {}, found {}",
                    2 * R, 2 * r));
  if (shaft > 0 && r == 0)
    throw std::invalid_argument("a spudcan with a shaft_length needs its shaft_diameter");
  const double top = tip + shoulder + cone_height(R - r, angle(s, "top_angle", 180.0));
  if (!(top > 0))
    throw std::invalid_argument(
        "the spudcan has no height: give a tip_angle below 180, a shoulder or a top_angle below "
        "180");
  std::vector<Vec3> p;
  append(p, 0.0, 0.0);
  append(p, R, tip);
  append(p, R, tip + shoulder);
  append(p, r, top);
  append(p, r, top + shaft);
  append(p, 0.0, top + shaft);
  return p;
}

std::vector<Vec3> cone_profile(const spec::StructureShape& s) {
  const double R = 0.5 * dimension(s, "diameter");
  const double apex = angle(s, "apex_angle", 60.0);
  if (apex >= pi) throw std::invalid_argument("apex_angle of the cone: expected below 180");
  const double h = cone_height(R, apex), shaft = dimension(s, "shaft_length");
  return {Vec3(0, 0, 0), Vec3(R, h, 0), Vec3(R, h + shaft, 0), Vec3(0, h + shaft, 0)};
}

std::vector<Vec3> plate_profile(const spec::StructureShape& s) {
  const double w = 0.5 * dimension(s, "width"), L = dimension(s, "length");
  const double tip = dimension(s, "tip", 0.0, true);
  if (tip >= L)
    throw std::invalid_argument(
        fmt::format("tip of the plate: expected less than its length {}, found {}", L, tip));
  std::vector<Vec3> p;
  append(p, 0.0, 0.0);
  append(p, w, 0.0);
  if (tip > 0) p.back().y() = tip;
  append(p, w, L);
  append(p, 0.0, L);
  return p;
}

std::vector<Vec3> footing_profile(const spec::StructureShape& s) {
  const double B = 0.5 * dimension(s, "width"), H = dimension(s, "height");
  return {Vec3(0, 0, 0), Vec3(B, 0, 0), Vec3(B, H, 0), Vec3(0, H, 0)};
}

// The cell size: given, or a twentieth of the shape's largest dimension but at most half its
// smallest (a pipe's wall two cells thick, a shoulder split).
double cell_size(const spec::StructureShape& s) {
  if (s.cell_size > 0) return s.cell_size;
  double smallest = 0.0, largest = 0.0;
  for (const auto& [key, value] : s.dimensions)
    if (value > 0 && !key.ends_with("angle")) {
      if (smallest == 0 || value < smallest) smallest = value;
      largest = std::max(largest, value);
    }
  return std::min(largest / 20, smallest / 2);
}

// --- 2D: the geo kernel, counter-clockwise loops (cells counter-clockwise, normal +z) ---------

int polygon_loop(const std::vector<Vec3>& polygon, double h) {
  namespace geo = gmsh::model::geo;
  std::vector<int> points, lines;
  for (const Vec3& x : polygon) points.push_back(geo::addPoint(x.x(), x.y(), 0, h));
  for (std::size_t k = 0; k < points.size(); ++k)
    lines.push_back(geo::addLine(points[k], points[(k + 1) % points.size()]));
  return geo::addCurveLoop(lines);
}

// The full section of a profile in plane strain: the profile, then its mirror image back down.
std::vector<Vec3> full_section(const std::vector<Vec3>& profile) {
  std::vector<Vec3> polygon = profile;
  for (std::size_t k = profile.size(); k-- > 0;)
    if (profile[k].x() > 0) polygon.emplace_back(-profile[k].x(), profile[k].y(), 0.0);
  return polygon;
}

// A circle of radius r about c as counter-clockwise quarter arcs from its bottom point, and
// their end points; `half`: only the right half (bottom to top), for an axisymmetric
// half-section.
struct Arcs {
  std::vector<int> arcs, points;
};

/// A pipe's or T-bar's outer radius and wall thickness (0: solid).
std::pair<double, double> circle_radii(const spec::StructureShape& s) {
  const double R = 0.5 * dimension(s, "diameter");
  const double t = s.kind == "pipe" ? dimension(s, "thickness", 0.0, true) : 0.0;
  if (t >= R)
    throw std::invalid_argument(fmt::format(
        "thickness of the pipe: expected less than its radius {} (0: solid), found {}", R, t));
  return {R, t};
}

Arcs circle_arcs(const Vec3& c, double r, double h, bool half) {
  namespace geo = gmsh::model::geo;
  const int centre = geo::addPoint(c.x(), c.y(), 0, h);
  const int quarters = half ? 2 : 4;
  Arcs a;
  for (int k = 0; k < (half ? 3 : 4); ++k) {
    const double phi = -0.5 * pi + 0.5 * pi * k;
    a.points.push_back(geo::addPoint(c.x() + r * std::cos(phi), c.y() + r * std::sin(phi), 0, h));
  }
  for (int k = 0; k < quarters; ++k)
    a.arcs.push_back(geo::addCircleArc(a.points[k], centre, a.points[(k + 1) % a.points.size()]));
  return a;
}

void circle_section(const spec::StructureShape& s, bool axisymmetric, double h) {
  namespace geo = gmsh::model::geo;
  const auto [R, t] = circle_radii(s);
  const Vec3& c = s.position;
  const Arcs outer = circle_arcs(c, R, h, axisymmetric);
  if (!axisymmetric) {
    std::vector<int> loops = {geo::addCurveLoop(outer.arcs)};
    if (t > 0) loops.push_back(geo::addCurveLoop(circle_arcs(c, R - t, h, false).arcs));
    geo::addPlaneSurface(loops);
    return;
  }
  // The half-section (a sphere's, or a spherical shell's): the outer arcs up, then down the
  // axis, through the inner arcs (clockwise) of a shell.
  std::vector<int> curves = outer.arcs;
  const int top = outer.points.back(), bottom = outer.points.front();
  if (t > 0) {
    const Arcs inner = circle_arcs(c, R - t, h, true);
    curves.push_back(geo::addLine(top, inner.points.back()));
    for (auto it = inner.arcs.rbegin(); it != inner.arcs.rend(); ++it) curves.push_back(-*it);
    curves.push_back(geo::addLine(inner.points.front(), bottom));
  } else {
    curves.push_back(geo::addLine(top, bottom));
  }
  geo::addPlaneSurface({geo::addCurveLoop(curves)});
}

void mesh_2d(const spec::StructureShape& s, Kinematics kinematics, double h) {
  namespace geo = gmsh::model::geo;
  const bool axisymmetric = kinematics == Kinematics::Axisymmetric;
  if (s.kind == "pipe" || s.kind == "tbar") {
    circle_section(s, axisymmetric, h);
  } else {
    std::vector<Vec3> polygon = shape_profile(s);
    if (!axisymmetric) polygon = full_section(polygon);
    for (Vec3& x : polygon) x += s.position;
    geo::addPlaneSurface({polygon_loop(polygon, h)});
  }
  geo::synchronize();
  const CellType type = s.cell.value_or(CellType::Tri3);
  if (type == CellType::Quad4) {
    // As mesh/gmsh_generate.cpp: Frontal-Delaunay triangles recombined into quadrangles only.
    gmsh::option::setNumber("Mesh.Algorithm", 6);
    gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 3);
    gmsh::option::setNumber("Mesh.RecombineAll", 1);
  }
  gmsh::model::mesh::generate(2);
  if (type == CellType::Tri6) {
    // Straight-sided: the surface's facets are the straight segments contact sees.
    gmsh::option::setNumber("Mesh.SecondOrderLinear", 1);
    gmsh::model::mesh::setOrder(2);
  }
}

// --- 3D: the OpenCASCADE kernel -----------------------------------------------------------------

// The profile (x, y) as a face in the x-z plane, placed at p.
int profile_face(const std::vector<Vec3>& profile, const Vec3& p) {
  namespace occ = gmsh::model::occ;
  std::vector<int> points, lines;
  for (const Vec3& x : profile)
    points.push_back(occ::addPoint(p.x() + x.x(), p.y(), p.z() + x.y()));
  for (std::size_t k = 0; k < points.size(); ++k)
    lines.push_back(occ::addLine(points[k], points[(k + 1) % points.size()]));
  return occ::addPlaneSurface({occ::addCurveLoop(lines)});
}

void mesh_3d(const spec::StructureShape& s, double h) {
  namespace occ = gmsh::model::occ;
  const Vec3& p = s.position;
  gmsh::vectorpair out;
  if (s.kind == "pipe" || s.kind == "tbar") {
    // A horizontal cylinder along y, centred at p.
    const auto [R, t] = circle_radii(s);
    const double L = dimension(s, "length");
    const int outer = occ::addCylinder(p.x(), p.y() - 0.5 * L, p.z(), 0, L, 0, R);
    if (t > 0) {
      const int inner = occ::addCylinder(p.x(), p.y() - 0.5 * L, p.z(), 0, L, 0, R - t);
      std::vector<gmsh::vectorpair> map;
      occ::cut({{3, outer}}, {{3, inner}}, out, map);
    }
  } else if (s.kind == "footing") {
    const double B = dimension(s, "width"), H = dimension(s, "height");
    const double b = dimension(s, "breadth", B);
    occ::addBox(p.x() - 0.5 * B, p.y() - 0.5 * b, p.z(), B, b, H);
  } else if (s.kind == "plate") {
    // The plate's section (with its tip) extruded along y over its breadth.
    const double b = dimension(s, "breadth");
    const int face = profile_face(full_section(shape_profile(s)), p - Vec3(0, 0.5 * b, 0));
    occ::extrude({{2, face}}, 0, b, 0, out);
  } else {
    // A body of revolution about the vertical axis through p.
    const int face = profile_face(shape_profile(s), p);
    occ::revolve({{2, face}}, p.x(), p.y(), p.z(), 0, 0, 1, 2 * pi, out);
  }
  occ::synchronize();
  gmsh::option::setNumber("Mesh.CharacteristicLengthMax", h);
  gmsh::option::setNumber("Mesh.CharacteristicLengthMin", 0.2 * h);
  gmsh::model::mesh::generate(3);
}

// The shape in units of its cell size h, anchored at the origin. Gmsh meshes this one: its
// floating-point decisions (the frontal mesher's, its geometric tolerance) then see the same
// numbers whatever the model's length unit and wherever the shape stands, so the mesh only scales
// with the unit (a footing 2.5 m wide was meshed with 130 nodes, the same 2500 mm wide with 129,
// and the two models' loads differed by 5e-5).
// The dimensions as given checked (messages in the model's units) before the shape is meshed in
// units of its cell size.
void check_dimensions(const spec::StructureShape& s, bool three_d) {
  if (s.kind == "pipe" || s.kind == "tbar") {
    (void)circle_radii(s);
    if (three_d) (void)dimension(s, "length");
    return;
  }
  (void)shape_profile(s);
  if (three_d && s.kind == "footing") (void)dimension(s, "breadth", 1.0);
  if (three_d && s.kind == "plate") (void)dimension(s, "breadth");
}

spec::StructureShape unit_shape(const spec::StructureShape& s, double h) {
  spec::StructureShape unit = s;
  for (auto& [key, value] : unit.dimensions)
    if (!key.ends_with("angle")) value /= h;
  unit.position = Vec3::Zero();
  unit.cell_size = 1.0;
  return unit;
}

}  // namespace

std::vector<Vec3> shape_profile(const spec::StructureShape& s) {
  if (s.kind == "spudcan") return spudcan_profile(s);
  if (s.kind == "cone") return cone_profile(s);
  if (s.kind == "plate") return plate_profile(s);
  if (s.kind == "footing") return footing_profile(s);
  throw std::invalid_argument(fmt::format("the {} has no profile", s.kind));
}

Mesh shape_mesh(const spec::StructureShape& s, Kinematics kinematics) {
  const bool axisymmetric = kinematics == Kinematics::Axisymmetric;
  const bool three_d = kinematics == Kinematics::ThreeD;
  if (axisymmetric && s.kind == "tbar")
    throw std::invalid_argument(
        "a T-bar is no body of revolution: use it in plane strain or 3D (in axisymmetry a pipe "
        "is a sphere)");
  if (axisymmetric && s.position.x() != 0)
    throw std::invalid_argument(fmt::format(
        "in an axisymmetric model a structure is a body of revolution about the axis: its "
        "position's x must be 0, found {}",
        s.position.x()));
  const CellType type = s.cell.value_or(three_d ? CellType::Tet4 : CellType::Tri3);
  if (three_d != (type == CellType::Tet4))
    throw std::invalid_argument(fmt::format("a built-in shape in a {} model is meshed with {}",
                                            to_string(kinematics),
                                            three_d ? "tet4" : "tri3, tri6 or quad4"));
  check_dimensions(s, three_d);
  const double h = cell_size(s);
  const spec::StructureShape unit = unit_shape(s, h);
  GmshSession session;
  try {
    gmsh::model::add(s.kind);
    if (three_d)
      mesh_3d(unit, 1.0);
    else
      mesh_2d(unit, kinematics, 1.0);
    Mesh mesh = mesh_from_gmsh_model(fmt::format("the {} shape", s.kind), three_d ? 3 : 2);
    for (Vec3& x : mesh.nodes) x = h * x + s.position;
    return mesh;
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("meshing the {}: {}", s.kind, e.what()));
  } catch (...) {
    throw std::runtime_error(
        fmt::format("Gmsh failed to mesh the {}: {}", s.kind, current_exception_message()));
  }
}

}  // namespace geompm
