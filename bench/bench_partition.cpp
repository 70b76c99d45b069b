// The cut of the background mesh between the processes of a distributed run (docs/performance.md
// note 23; mesh/partition.hpp): geompm's recursive coordinate bisection of the cells' centroids
// (RCB), weighted by the points in each cell, against PT-Scotch (Chevalier & Pellegrini 2008)
// through PETSc's MatPartitioning on the graph of the cells that share a node, each cell
// weighing its points + 1 and, second, 16 x its points + 1. Per case and number of parts: the
// cut (mesh nodes that cells of more than one part share: the nodes whose sums cross
// processes), the point balance (the largest part's points over the mean), the parts that are
// not in one piece, and the time to cut (median of 5). One markdown table on the standard output.
//
//   build/bench/bench_partition                    the 2D and 3D blocks of step_case.hpp, and
//                                                  the examples named below
//   GEOMPM_BENCH_PARTS=2,3,4,8,16 ...              numbers of parts
#include <fmt/format.h>
#include <petscmat.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" {
#include <scotch/scotch.h>  // for its random generator's reset
}

#include "geompm/io/model_reader.hpp"
#include "geompm/mesh/partition.hpp"
#include "step_case.hpp"

namespace {

using geompm::Index;
using geompm::Model;

void check(PetscErrorCode code) {
  if (code != 0) throw std::runtime_error("PETSc: a MatPartitioning call failed");
}

// PT-Scotch on the graph of the cells that share a node, each cell weighing `weights`.
std::vector<int> pt_scotch(const geompm::CompressedRows& graph, const std::vector<Index>& weights,
                           int parts) {
  const auto n = static_cast<PetscInt>(weights.size());
  PetscInt *start = nullptr, *columns = nullptr, *vertex_weights = nullptr;  // PETSc takes them
  check(PetscMalloc1(n + 1, &start));
  check(PetscMalloc1(static_cast<PetscInt>(graph.entries.size()), &columns));
  check(PetscMalloc1(n, &vertex_weights));
  std::copy(graph.start.begin(), graph.start.end(), start);
  std::copy(graph.entries.begin(), graph.entries.end(), columns);
  std::copy(weights.begin(), weights.end(), vertex_weights);
  Mat adjacency;
  MatPartitioning partitioning;
  IS part;
  check(MatCreateMPIAdj(PETSC_COMM_SELF, n, n, start, columns, nullptr, &adjacency));
  check(MatPartitioningCreate(PETSC_COMM_SELF, &partitioning));
  check(MatPartitioningSetAdjacency(partitioning, adjacency));
  check(MatPartitioningSetType(partitioning, MATPARTITIONINGPTSCOTCH));
  check(MatPartitioningSetNParts(partitioning, parts));
  check(MatPartitioningSetVertexWeights(partitioning, vertex_weights));
  // Scotch's generator starts from a fixed seed in a process and runs on from one cut to the
  // next: reset, the same graph gets the same cut each time.
  SCOTCH_randomReset();
  check(MatPartitioningApply(partitioning, &part));
  const PetscInt* values = nullptr;
  check(ISGetIndices(part, &values));
  std::vector<int> result(values, values + n);
  check(ISRestoreIndices(part, &values));
  ISDestroy(&part);
  MatPartitioningDestroy(&partitioning);
  MatDestroy(&adjacency);
  return result;
}

struct Quality {
  Index shared_nodes = 0;
  double balance = 0;   // largest part's points / mean
  int split_parts = 0;  // parts in more than one piece
  double seconds = 0;
};

Quality measure(const Model& model, const std::vector<int>& part, int parts) {
  Quality q;
  const std::vector<int> owner = geompm::node_owners(model.mesh, part);
  std::vector<char> shared(model.mesh.num_nodes(), 0);
  for (Index c = 0; c < model.mesh.num_cells(); ++c)
    for (Index node : model.mesh.cell_nodes(c))
      if (part[c] != owner[node]) shared[node] = 1;
  q.shared_nodes = static_cast<Index>(std::count(shared.begin(), shared.end(), 1));
  std::vector<double> points(parts, 0.0);
  for (Index c : model.points.cell) points[part[c]] += 1.0;
  const double mean = double(model.points.size()) / parts;
  q.balance = *std::max_element(points.begin(), points.end()) / mean;
  // Pieces of each part: cells joined by a shared node, flooded part by part.
  std::vector<char> seen(part.size(), 0);
  std::vector<int> pieces(parts, 0);
  for (std::size_t start = 0; start < part.size(); ++start) {
    if (seen[start]) continue;
    ++pieces[part[start]];
    std::vector<Index> stack{static_cast<Index>(start)};
    seen[start] = 1;
    while (!stack.empty()) {
      const Index c = stack.back();
      stack.pop_back();
      for (Index nb : model.topology.cell_neighbours.row(c))
        if (!seen[nb] && part[nb] == part[c]) {
          seen[nb] = 1;
          stack.push_back(nb);
        }
    }
  }
  for (int p : pieces) q.split_parts += p > 1;
  return q;
}

Quality timed(const Model& model, int parts, const std::function<std::vector<int>()>& cut) {
  std::vector<double> seconds;
  std::vector<int> part;
  for (int r = 0; r < 5; ++r) {
    const auto start = std::chrono::steady_clock::now();
    part = cut();
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  Quality q = measure(model, part, parts);
  q.seconds = seconds[2];
  return q;
}

void report(const std::string& name, const Model& model, const std::vector<int>& counts) {
  std::vector<double> points(model.mesh.num_cells(), 0.0);
  for (Index c : model.points.cell) points[c] += 1.0;
  const auto scotch_weights = [&](Index per_point) {
    std::vector<Index> weight(points.size());
    for (std::size_t c = 0; c < points.size(); ++c)
      weight[c] = per_point * static_cast<Index>(points[c]) + 1;
    return weight;
  };
  const std::vector<Index> plain = scotch_weights(1), scaled = scotch_weights(16);
  const auto& graph = model.topology.cell_neighbours;
  for (const int parts : counts) {
    const Quality a =
        timed(model, parts, [&] { return geompm::partition_cells(model.mesh, points, parts); });
    const Quality b = timed(model, parts, [&] { return pt_scotch(graph, plain, parts); });
    const Quality c = timed(model, parts, [&] { return pt_scotch(graph, scaled, parts); });
    fmt::print(
        "| {} | {} | {} / {} / {} | {:.3f} / {:.3f} / {:.3f} | {} / {} / {} | "
        "{:.4f} / {:.4f} / {:.4f} |\n",
        name, parts, a.shared_nodes, b.shared_nodes, c.shared_nodes, a.balance, b.balance,
        c.balance, a.split_parts, b.split_parts, c.split_parts, a.seconds, b.seconds, c.seconds);
  }
}

std::vector<int> counts_from_environment() {
  const char* text = std::getenv("GEOMPM_BENCH_PARTS");
  std::stringstream in(text ? text : "2,3,4,8,16");
  std::vector<int> counts;
  for (std::string item; std::getline(in, item, ',');) counts.push_back(std::stoi(item));
  return counts;
}

}  // namespace

int main(int argc, char** argv) {
  using geompm::bench::Formulation;
  check(PetscInitialize(&argc, &argv, nullptr, nullptr));
  const std::vector<int> counts = counts_from_environment();
  fmt::print(
      "| model | parts | shared nodes: RCB / PT-Scotch (p+1) / (16p+1) | point balance "
      "(largest / mean) | parts not in one piece | seconds to cut |\n"
      "|---|---|---|---|---|---|\n");
  report("2D block, 300 × 300 cells", *geompm::build_model(geompm::bench::block_under_gravity(300)),
         counts);
  report(
      "3D block, 24³ cells",
      *geompm::build_model(geompm::bench::block_under_gravity(24, Formulation::Displacement, true)),
      counts);
  // Graded meshes and bodies that fill part of them, as the examples have them.
  for (const char* example :
       {"strip_footing/strip_footing.yaml", "mohr_coulomb_footing/mohr_coulomb_footing.yaml",
        "structures/cone_penetration.yaml", "slope/mohr_coulomb_slope.yaml",
        "footing_gmsh/footing_gmsh.yaml", "structures/pipe_embedment.yaml",
        "structures/contact_friction_3d.yaml"})
    report(
        fmt::format("examples/{}", example),
        *geompm::build_model(geompm::read_model(std::string(GEOMPM_EXAMPLES_DIR) + "/" + example)),
        counts);
  PetscFinalize();
}
