#include "geompm/mesh/cell_geometry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "geompm/core/error.hpp"

namespace geompm {

namespace {

/// Runs f.template operator()<T>() for the type of cell c, so the bodies below are written once
/// with compile-time sizes.
template <class F>
decltype(auto) with_cell_type(const Mesh& mesh, Index c, F&& f) {
  return dispatch_cell_type(mesh.type_of(c), [&](auto element) -> decltype(auto) {
    return f.template operator()<cell_type_of<decltype(element)>>();
  });
}

template <CellType T>
double reference_measure() {
  double sum = 0.0;
  for (int q = 0; q < Element<T>::quadrature_size(); ++q) sum += Element<T>::quadrature_weight(q);
  return sum;
}

std::string describe_cell_nodes(const Mesh& mesh, Index c) {
  std::string out;
  for (Index n : mesh.cell_nodes(c)) {
    if (!out.empty()) out += " ";
    if (n < 0 || n >= mesh.num_nodes()) {
      out += fmt::format("[node {} out of range]", n);
      continue;
    }
    const Vec3& x = mesh.nodes[n];
    out += mesh.dim() == 2 ? fmt::format("({:g}, {:g})", x[0], x[1])
                           : fmt::format("({:g}, {:g}, {:g})", x[0], x[1], x[2]);
  }
  return out;
}

}  // namespace

Vec3 map_to_physical(const Mesh& mesh, Index c, const Vec3& xi) {
  return with_cell_type(mesh, c, [&]<CellType T>() {
    constexpr int dim = Element<T>::dim;
    Vec3 x = Vec3::Zero();
    x.head<dim>() = map_to_physical<T>(cell_node_coordinates<T>(mesh, c), xi.head<dim>());
    return x;
  });
}

std::optional<Vec3> map_to_reference(const Mesh& mesh, Index c, const Vec3& x) {
  return with_cell_type(mesh, c, [&]<CellType T>() -> std::optional<Vec3> {
    constexpr int dim = Element<T>::dim;
    const auto xi = map_to_reference<T>(cell_node_coordinates<T>(mesh, c), x.head<dim>());
    if (!xi) return std::nullopt;
    Vec3 out = Vec3::Zero();
    out.head<dim>() = *xi;
    return out;
  });
}

bool cell_contains(const Mesh& mesh, Index c, const Vec3& x, Vec3& xi) {
  return with_cell_type(mesh, c, [&]<CellType T>() {
    constexpr int dim = Element<T>::dim;
    typename Element<T>::Local local;
    if (!cell_contains<T>(cell_node_coordinates<T>(mesh, c), x.head<dim>(), local)) return false;
    xi.setZero();
    xi.head<dim>() = local;
    return true;
  });
}

// The element rules integrate det J exactly (it has degree <= 2 for every type, also for a
// curved Tri6 and a trilinear Hex8; for a Pyramid5 it is biquadratic in the collapsed
// coordinates, docs/theory.md eq. 19.9) and, for the radial measure, x det J too (degree 4 for a
// curved Tri6, biquadratic for Quad4), so no higher-order rule is needed.
double cell_measure(const Mesh& mesh, Index c, bool radial) {
  return with_cell_type(mesh, c, [&]<CellType T>() {
    const NodeCoordinates<T> nodes = cell_node_coordinates<T>(mesh, c);
    double sum = 0.0;
    for (int q = 0; q < Element<T>::quadrature_size(); ++q) {
      const auto xi = Element<T>::quadrature_point(q);
      double integrand = jacobian<T>(nodes, xi).determinant();
      if (radial) integrand *= map_to_physical<T>(nodes, xi)[0];
      sum += Element<T>::quadrature_weight(q) * integrand;
    }
    return sum;
  });
}

double cell_min_relative_jacobian(const Mesh& mesh, Index c) {
  return with_cell_type(mesh, c, [&]<CellType T>() {
    const NodeCoordinates<T> nodes = cell_node_coordinates<T>(mesh, c);
    double smallest = std::numeric_limits<double>::infinity();
    double mean = 0.0;  // mean det J = measure / reference measure
    for (int q = 0; q < Element<T>::quadrature_size(); ++q) {
      const double det = jacobian<T>(nodes, Element<T>::quadrature_point(q)).determinant();
      smallest = std::min(smallest, det);
      mean += Element<T>::quadrature_weight(q) * det;
    }
    for (int a = 0; a < Element<T>::nodes; ++a)
      smallest = std::min(smallest, jacobian<T>(nodes, Element<T>::node(a)).determinant());
    mean = std::abs(mean) / reference_measure<T>();
    // |mean| keeps a wholly inverted cell negative; a cell of zero size is degenerate.
    if (!(mean > 0.0) || !std::isfinite(smallest)) return 0.0;
    return smallest / mean;
  });
}

void validate_mesh(const Mesh& mesh, const std::string& source) {
  const SourceLocation where{source, "", 0};
  const int per_cell = mesh.nodes_per_cell();
  if (mesh.nodes.empty() || mesh.connectivity.empty())
    throw InputError(where, fmt::format("the mesh is empty ({} nodes, {} cells); expected at "
                                        "least one {} cell",
                                        mesh.nodes.size(), mesh.connectivity.size() / per_cell,
                                        to_string(mesh.cell_type)));
  if (mesh.mixed() && (mesh.cell_offsets.size() != mesh.cell_types.size() + 1 ||
                       mesh.cell_offsets.back() != static_cast<Index>(mesh.connectivity.size())))
    throw InputError(where, fmt::format("the mixed mesh's {} cell offsets do not span its {} "
                                        "connectivity entries; expected one per cell and one more",
                                        mesh.cell_offsets.size(), mesh.connectivity.size()));
  for (CellType t : mesh.types_present())
    if (cell_dimension(t) != mesh.dim())
      throw InputError(where, fmt::format("the mesh mixes {}D and {}D cells ({} and {}); expected "
                                          "cells of one dimension",
                                          mesh.dim(), cell_dimension(t), to_string(mesh.cell_type),
                                          to_string(t)));
  if (!mesh.mixed() && mesh.connectivity.size() % per_cell != 0)
    throw InputError(where,
                     fmt::format("the connectivity has {} entries; expected a multiple "
                                 "of {} ({} nodes per cell)",
                                 mesh.connectivity.size(), per_cell, to_string(mesh.cell_type)));
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const Vec3& x = mesh.nodes[n];
    if (!x.allFinite())
      throw InputError(where, fmt::format("node {} has a non-finite coordinate ({}, {}, {}); "
                                          "expected finite numbers",
                                          n, x[0], x[1], x[2]));
    if (mesh.dim() == 2 && x[2] != 0.0)
      throw InputError(where, fmt::format("node {} has z = {:g}; expected z = 0 in a 2D mesh "
                                          "(x horizontal, y up)",
                                          n, x[2]));
  }
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (Index n : mesh.cell_nodes(c))
      if (n < 0 || n >= mesh.num_nodes())
        throw InputError(where, fmt::format("cell {} refers to node {}; expected a node index "
                                            "in 0..{}",
                                            c, n, mesh.num_nodes() - 1));
  // Below this a cell is numerically flat: its Jacobian cannot be inverted reliably.
  constexpr double degenerate = 1e-10;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const double relative = cell_min_relative_jacobian(mesh, c);
    if (!(relative > degenerate))
      throw InputError(
          where, fmt::format("cell {} ({}) is inverted or degenerate: nodes {}; smallest "
                             "det(dx/dxi) relative to its mean is {:.3g}; expected a positive "
                             "Jacobian throughout the cell (nodes in Gmsh order, {})",
                             c, to_string(mesh.type_of(c)), describe_cell_nodes(mesh, c), relative,
                             mesh.dim() == 2 ? "counter-clockwise" : "positively oriented"));
  }
  for (const auto& [name, cells] : mesh.cell_groups)
    for (Index c : cells)
      if (c < 0 || c >= mesh.num_cells())
        throw InputError(where, fmt::format("cell group '{}' holds cell {}; expected a cell "
                                            "index in 0..{}",
                                            name, c, mesh.num_cells() - 1));
  for (const auto& [name, ids] : mesh.node_groups)
    for (Index n : ids)
      if (n < 0 || n >= mesh.num_nodes())
        throw InputError(where, fmt::format("node group '{}' holds node {}; expected a node "
                                            "index in 0..{}",
                                            name, n, mesh.num_nodes() - 1));
}

std::pair<Vec3, Vec3> cell_bounding_box(const Mesh& mesh, Index c) {
  return with_cell_type(mesh, c, [&]<CellType T>() {
    constexpr int dim = Element<T>::dim;
    const auto [lower, upper] = cell_bounding_box<T>(cell_node_coordinates<T>(mesh, c));
    std::pair<Vec3, Vec3> box{Vec3::Zero(), Vec3::Zero()};
    box.first.head<dim>() = lower;
    box.second.head<dim>() = upper;
    return box;
  });
}

}  // namespace geompm
