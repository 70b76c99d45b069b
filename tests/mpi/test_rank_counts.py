"""Distributed runs give the serial run's results (docs/architecture.md, "Distributed runs").

Each example in the distributed subset is run on one process (no mpirun: the serial code, UMFPACK)
and under mpirun on 2 and 3 processes (MUMPS on the distributed matrix); every history column must
agree with the serial one to `TOLERANCE` of the column's largest magnitude, which is what the
Newton tolerances of these examples (1e-9 and tighter on the residual) leave of the difference in
round-off between the two direct solvers and the order of the sums. A checkpoint written by a run
on 2 processes, killed half-way through its next checkpoint, resumes on 1, 2 and 3 processes to
the same history (on 1 and 3 for a model with an FEM region), and the checkpoints of 2 and 3
processes hold the serial one's sections and points.

Environment: GEOMPM_BINARY (the geompm executable), GEOMPM_MPIRUN (mpirun).
"""
import os
import shutil
import tempfile
import unittest

import checkpoint_file
from runs import ROOT, history, run

TOLERANCE = 1e-6

EXAMPLES = [
    "column/column.yaml",  # GIMP, quasi-static, elastic, 2D
    "column/column_3d.yaml",  # standard MPM, 3D hexahedra
    "column/column_large_deformation.yaml",  # points cross cells and the parts' boundaries
    "earth_pressure/rankine_active.yaml",  # Mohr-Coulomb, K0 procedure, grid motion
    "vibrating_bar/vibrating_bar.yaml",  # dynamic (Newmark), points cross cells
    "oedometer/oedometer.yaml",  # prescribed point motion and its reaction
    "mohr_coulomb_footing/mohr_coulomb_footing.yaml",  # a plastic footing driven through its points
    "strip_footing/strip_footing.yaml",  # mixed p-u, Tresca, incremental pressure, fitted start
    "thick_cylinder/thick_cylinder.yaml",  # mixed p-u, axisymmetric, a limit pressure
    "structures/contact_patch.yaml",  # a rigid plate in contact: its unknowns on process 0
    "structures/contact_friction.yaml",  # contact with friction: stick and slip
    "structures/strip_footing_rough.yaml",  # a rough rigid footing on mixed p-u clay
    "structures/deformable_pile.yaml",  # a deformable structure in contact
    # FEM regions (seed §3.4): their Gauss points worked on by the owners of their cells, the
    # relaxed mesh moved alike on every process; quad4 cells, and quad4 over tri3 with the mixed
    # p-u MPM region; a deformable pile in contact, axisymmetric.
    "coupling/strip_footing_coupled.yaml",
    "coupling/strip_footing_coupled_mixed.yaml",
    "coupling/pile_coupled.yaml",
]


class RankCounts(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="geompm_mpi_")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def assert_same_history(self, reference, other, label):
        columns, expected = history(reference)
        other_columns, got = history(other)
        self.assertEqual(columns, other_columns, label)
        self.assertEqual(len(expected), len(got), f"{label}: number of rows")
        for k, name in enumerate(columns):
            if name in ("newton_iterations", "time_step"):
                continue  # the same to the iteration is not asked of another solver's round-off
            scale = max(abs(row[k]) for row in expected) or 1.0
            worst = max(abs(a[k] - b[k]) for a, b in zip(expected, got))
            self.assertLessEqual(worst, TOLERANCE * scale,
                                 f"{label}: column {name} differs by {worst:.3g} (scale {scale:.3g})")

    def test_history_does_not_depend_on_the_process_count(self):
        for model in EXAMPLES:
            self.assert_same_on_two_and_three(model, model)

    def variant(self, example, change, name="variant.yaml"):
        """The example's model with its text changed by `change`, written to the work directory."""
        with open(os.path.join(ROOT, "examples", example)) as f:
            text = change(f.read())
        model = os.path.join(self.dir, name)
        with open(model, "w") as f:
            f.write(text)
        return model

    def assert_same_on_two_and_three(self, model, label):
        """`model`'s history on 2 and 3 processes is its serial one; returns the serial output."""
        serial = os.path.join(self.dir, "serial")
        done = run(model, serial, 1)
        self.assertEqual(done.returncode, 0, f"{label}: {done.stderr}")
        for processes in (2, 3):
            output = os.path.join(self.dir, f"np{processes}")
            done = run(model, output, processes)
            self.assertEqual(done.returncode, 0, f"{label} on {processes}: {done.stderr}")
            self.assert_same_history(serial, output, f"{label} on {processes} processes")
            self.assertTrue(os.path.isfile(os.path.join(output, "summary.json")))
        return serial

    def assert_changes_history(self, example, changed, label):
        """The change acts: `changed` (a serial output) is not the example's own history."""
        plain = os.path.join(self.dir, "plain")
        self.assertEqual(run(example, plain, 1).returncode, 0)
        with self.assertRaises(AssertionError):
            self.assert_same_history(plain, changed, label)

    def test_surface_load_across_the_parts(self):
        # The strip surcharge's following pressure on the points' zero level set, over 14 of the
        # ground's 20 m, so that the loaded surface crosses the parts (RCB cuts the ground along
        # x): each process's points fill the nodes of its own cells only, and a level set not
        # summed over the processes would load a false boundary at the cut (measured 0.29 of the
        # base reaction on 2 processes, 0.5 on 3).
        model = self.variant("surface_load/strip_surcharge.yaml",
                             lambda text: text.replace("where: {x: [0, 2]}", "where: {x: [0, 14]}"))
        self.assert_same_on_two_and_three(model, "the wide surcharge")

    def test_ddmp(self):
        # DDMP's node-averaged gradients (theory eq. 8.1) are sums over the points around a node:
        # the large-deformation column, whose points cross cells and the parts' boundaries, and
        # the thick cylinder (mixed p-u), each with `interpolation: ddmp`.
        for example in ("column/column_large_deformation.yaml", "thick_cylinder/thick_cylinder.yaml"):
            model = self.variant(example, lambda text: text + "numerics: {interpolation: ddmp}\n")
            serial = self.assert_same_on_two_and_three(model, f"{example} with DDMP")
            self.assert_changes_history(example, serial, f"{example}: DDMP against standard")

    def test_contact_with_adhesion(self):
        # The rough footing with adhesion (shear at most 0.5 s_u): each contact segment reads the
        # mean s_u of the points in the cell under it, summed over the processes (without, process
        # 0, which assembles the contact, reads the cells of its own points only: the run stopped
        # after 35 of 68 steps). The steps are halved and the iteration limit raised to the
        # default (15) so that no step comes near a cut-back: with the example's 0.025 and 10, the
        # steps took 7-10 iterations and a one-iteration difference of round-off between the
        # processes' sums decided whether a step was cut back (a CI machine's 3-process run took
        # 50 steps against the serial run's 68); here at most 10 of 15 are taken.
        example = "structures/strip_footing_rough.yaml"

        def short_steps(text):
            text = text.replace("initial: 0.025, min: 0.0001, max: 0.025",
                                "initial: 0.0125, min: 0.0001, max: 0.0125")
            return text.replace("max_iterations: 10", "max_iterations: 15")

        model = self.variant(example, lambda text: short_steps(text).replace(
            "contact: {tangential: rough}", "contact: {tangential: adhesion, alpha: 0.5}"))
        serial = self.assert_same_on_two_and_three(model, "the footing with adhesion")
        rough = self.variant(example, short_steps, name="rough.yaml")
        self.assert_changes_history(rough, serial, "adhesion against rough")

    def test_mixed_cell_types(self):
        # A band of tri3 cells in the quad4 meshes (a region's cell type): the large-deformation
        # column, whose points cross from one type to the other and between the parts, and the
        # thick cylinder (mixed p-u, axisymmetric), whose parts' cuts fall in both types.
        bands = {
            "column/column_large_deformation.yaml":
                "regions: {middle: {kind: mpm, cell: tri3, region: {box: {min: [0, 10], "
                "max: [1, 30]}}}}\n",
            "thick_cylinder/thick_cylinder.yaml":
                "regions: {inner: {kind: mpm, cell: tri3, region: {box: {min: [1, 0], "
                "max: [1.5, 0.1]}}}}\n",
        }
        for example, band in bands.items():
            model = self.variant(example, lambda text: text + band)
            self.assert_same_on_two_and_three(model, f"{example} with tri3 cells")

    def test_sparse_node_springs_and_ghost_penalty(self):
        # The thick cylinder's outer face moves into empty cells: its edge cells get the ghost
        # penalty's faces and its barely reached nodes the sparse-node springs (the fill limit
        # raised so that there are some), terms of no point that every process builds alike from
        # the cells' summed fill and largest modulus, and process 0 assembles.
        example = "thick_cylinder/thick_cylinder.yaml"
        model = self.variant(example, lambda text: text + (
            "numerics: {sparse_node_stiffness: 0.01, sparse_node_fill: 0.5, ghost_penalty: 0.05, "
            "ghost_penalty_fill: 0.9}\n"))
        serial = self.assert_same_on_two_and_three(model, "the cylinder with the terms")
        self.assert_changes_history(example, serial, "with the terms against without")

    def test_iterative_solvers_on_two_processes(self):
        # BoomerAMG and GAMG on the distributed matrix (nodal blocks, padded at constrained
        # components) reach the serial direct solver's history within the Newton tolerances.
        for model in ("earth_pressure/rankine_active.yaml", "column/column_3d.yaml"):
            serial = os.path.join(self.dir, "serial")
            done = run(model, serial, 1)
            self.assertEqual(done.returncode, 0, f"{model} serial: {done.stderr}")
            for solver in ("petsc_hypre", "petsc_gamg"):
                output = os.path.join(self.dir, solver)
                done = run(model, output, 2, "--linear-solver", solver)
                self.assertEqual(done.returncode, 0, f"{model} with {solver}: {done.stderr}")
                self.assert_same_history(serial, output, f"{model} with {solver} on 2 processes")

    def test_checkpoint_of_two_processes_resumes_on_one_two_and_three(self):
        self.assert_resumes_on_one_and_three("earth_pressure/rankine_active.yaml", (1, 2, 3))

    def test_checkpoints_of_two_and_three_processes_are_laid_out_as_the_serial_one(self):
        # Process 0 writes the file while every process's points reach it a window of ids at a
        # time (points/streamed_points.hpp): the sections of the serial file, in its order, the
        # same run state, and the same points (by id; the distributed files in id order) with the
        # same integers and the serial values to the round-off of the solvers (the bytes of the
        # same points are the serial ones exactly: tests/mpi/test_streamed_checkpoint.cpp).
        # The oedometer: its serial store leaves id order (points cross cells), and it has a
        # prescribed motion.
        model = "oedometer/oedometer.yaml"
        files = {}
        for processes in (1, 2, 3):
            output = os.path.join(self.dir, f"np{processes}")
            done = run(model, output, processes, "--checkpoint-every", "1000")
            self.assertEqual(done.returncode, 0, done.stderr)
            files[processes] = checkpoint_file.sections(os.path.join(output, "checkpoint.bin"))
        serial = files[1]
        serial_points = checkpoint_file.point_arrays(serial["points"])
        ids = serial_points["id"]
        self.assertNotEqual(ids, sorted(ids), "the serial store should have left id order")
        by_id = sorted(range(len(ids)), key=lambda k: ids[k])
        for processes in (2, 3):
            label = f"{processes} processes"
            self.assertEqual(list(files[processes]), list(serial), label)
            self.assertEqual(files[processes]["run"], serial["run"], label)
            self.assertEqual(len(files[processes]["points"]), len(serial["points"]), label)
            points = checkpoint_file.point_arrays(files[processes]["points"])
            for name, values in points.items():
                expected = [serial_points[name][k] for k in by_id]
                if name in ("id", "body", "material", "sets", "cell"):
                    self.assertEqual(values, expected, f"{label}: {name}")
                    continue
                scale = max(max(abs(x) for x in v) for v in expected) or 1.0
                worst = max(max(abs(x - y) for x, y in zip(a, b)) for a, b in zip(values, expected))
                self.assertLessEqual(worst, TOLERANCE * scale, f"{label}: {name}")

    def assert_resumes_on_one_and_three(self, model, counts=(1, 3)):
        """A checkpoint of `model` on 2 processes resumes on each of `counts` processes to the
        run's history."""
        whole = os.path.join(self.dir, "whole")
        done = run(model, whole, 2)
        self.assertEqual(done.returncode, 0, done.stderr)
        for processes in counts:
            output = os.path.join(self.dir, f"resumed{processes}")
            # Killed half-way through its third checkpoint: it resumes from the second.
            killed = run(model, output, 2, "--checkpoint-every", "5",
                         env={"GEOMPM_TEST_KILL_IN_CHECKPOINT": "3"})
            self.assertNotEqual(killed.returncode, 0)
            resumed = run(model, output, processes, "--resume", "--checkpoint-every", "5")
            self.assertEqual(resumed.returncode, 0, resumed.stderr)
            self.assert_same_history(whole, output, f"resumed on {processes} processes")

    def test_fem_region_checkpoint_resumes_on_one_and_three(self):
        # The coupled pile's checkpoint holds its Gauss points' states, which each process keeps
        # for its own cells only: streamed to process 0 as it writes (without, the run resumed
        # on 3 processes from a checkpoint of 2 took its stale Gauss points: the head force 15 %
        # off).
        self.assert_resumes_on_one_and_three("coupling/pile_coupled.yaml")

    def test_a_motion_the_points_cannot_follow_stops_the_run(self):
        # The oedometer's block squeezed by twice its height (as the serial test,
        # tests/examples/test_run_policies.cpp): the driven points' mean displacement, summed over
        # the processes (analysis/motion_check.hpp), falls far short, and every process stops
        # with the serial run's verdict, said once. The example itself (EXAMPLES) passes it.
        model = self.variant("oedometer/oedometer.yaml", lambda text: text.replace(
            'displacement: [~, "-0.1*t"]', 'displacement: [~, "-2*t"]'))
        for processes in (1, 2, 3):
            done = run(model, os.path.join(self.dir, f"squeezed{processes}"), processes)
            self.assertEqual(done.returncode, 3, done.stderr)
            self.assertEqual(done.stderr.count("the points did not follow the displacement "
                                               "prescribed to them"), 1, done.stderr)
            self.assertIn("phases[0].prescribed_motion[0] (top): the point set moved", done.stderr)
            self.assertIn("of the -2 prescribed", done.stderr)

    def test_a_feature_not_distributed_is_refused(self):
        model = self.variant("column/column.yaml", lambda text: text.replace(
            "    dynamics: quasi_static\n",
            "    dynamics: quasi_static\n    newton: {tangent_check: 1.0e-6}\n"))
        done = run(model, os.path.join(self.dir, "refused"), 2)
        self.assertEqual(done.returncode, 2, done.stderr)
        self.assertIn("the tangent check (newton.tangent_check)", done.stderr)
        self.assertIn("variant.yaml", done.stderr)
        self.assertEqual(done.stderr.count("does not handle yet"), 1, done.stderr)


if __name__ == "__main__":
    unittest.main()
