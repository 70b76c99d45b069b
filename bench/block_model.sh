# The block of bench/step_case.cpp as a model file, for the distributed runs' benches
# (bench/mpi_scaling.sh, bench/mpi_memory.sh; sourced): 10 m (2D square or 3D cube), the body all
# but the top layer of cells, rollers on the sides, fixed base; `steps` quasi-static steps of
# ramped gravity, the linear solver `solver`.
#
#   model DIM CELLS FILE      (with $steps and $solver set)
#
# Sourcing it also makes the work folder $work (removed at exit) and sets the environment of the
# runs: one OpenMP thread per process, waiting passively, mpirun allowed as root.
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMP_WAIT_POLICY=passive OMP_NUM_THREADS=1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

model() {  # dim cells file
  local dim=$1 n=$2 file=$3 top
  top=$(/usr/bin/python3 -c "print(10 - 10 / $n)")
  if [[ $dim == 2 ]]; then
    cat >"$file" <<YAML
title: MPI scaling block 2D
analysis: {kinematics: plane_strain}
mesh: {generate: {cell: quad4, origin: [0, 0], x: {length: 10, cells: $n}, y: {length: 10, cells: $n}}}
materials: {soil: {model: linear_elastic, E: 1.0e5, nu: 0.3, density: 2}}
bodies: {block: {material: soil, region: {box: {min: [0, 0], max: [10, $top]}}, points_per_cell: 4}}
YAML
  else
    cat >"$file" <<YAML
title: MPI scaling block 3D
analysis: {kinematics: 3d}
mesh: {generate: {cell: hex8, origin: [0, 0, 0], x: {length: 10, cells: $n}, y: {length: 10, cells: $n}, z: {length: 10, cells: $n}}}
materials: {soil: {model: linear_elastic, E: 1.0e5, nu: 0.3, density: 2}}
bodies: {block: {material: soil, region: {box: {min: [0, 0, 0], max: [10, 10, $top]}}, points_per_cell: 8}}
YAML
  fi
  local down="[0, -10]" sides="[left, right]"
  [[ $dim == 3 ]] && down="[0, 0, -10]" && sides="[left, right, front, back]"
  cat >>"$file" <<YAML
phases:
  - name: gravity
    duration: $steps
    time_step: 1
    dynamics: quasi_static
    gravity: {acceleration: $down, ramp: true}
    fixities:
YAML
  for side in ${sides//[\[\],]/ }; do echo "      - {boundary: $side, fix: normal}" >>"$file"; done
  cat >>"$file" <<YAML
      - {boundary: bottom, fix: all}
output: {vtk: {every: 0}, checkpoint: {every_steps: 0, every_minutes: 0}}
numerics: {linear_solver: $solver}
YAML
}

