"""A distributed run writes the points' ParaView files in pieces (docs/user-guide.md, "Running on
several processes"): each process its own points' .vtu, process 0 the .pvtu that names them, which
points.pvd lists. Read back (point_files.py: each piece with meshio, the .pvtu's structure
checked), the pieces of every step written hold every point exactly once, with the serial run's
values: to `TOLERANCE` of each field's largest magnitude (the round-off between the serial and the
distributed direct solver, as in test_rank_counts.py), the integers (id, body, material and the
`plastic` flag, which follows each point across the processes) exactly. A run that stops between
two ParaView steps writes its last state in pieces too.

Environment: GEOMPM_BINARY (the geompm executable), GEOMPM_MPIRUN (mpirun).
"""
import os
import shutil
import tempfile
import unittest

import numpy as np

from point_files import read_points, series
from runs import ROOT, run

TOLERANCE = 1e-6


class ParallelOutput(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="geompm_mpi_output_")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def run_on(self, model, processes, expect=0):
        output = os.path.join(self.dir, f"np{processes}")
        done = run(model, output, processes)
        self.assertEqual(done.returncode, expect, f"{model} on {processes}: {done.stderr}")
        return output

    def assert_same_points(self, serial_file, pieces_file):
        """The .pvtu's pieces hold the serial .vtu's points; returns (fields, piece per point)."""
        self.assertTrue(serial_file.endswith(".vtu"), serial_file)
        self.assertTrue(pieces_file.endswith(".pvtu"), pieces_file)
        expected, _ = read_points(serial_file)
        got, piece = read_points(pieces_file)
        label = os.path.basename(pieces_file)
        np.testing.assert_array_equal(got["id"], expected["id"], f"{label}: the points' ids")
        self.assertEqual(sorted(got), sorted(expected), f"{label}: the fields")
        for name in expected:
            a, b = expected[name], got[name]
            if np.issubdtype(a.dtype, np.integer):
                np.testing.assert_array_equal(b, a, f"{label}: {name}")
            else:
                scale = np.abs(a).max() or 1.0
                worst = np.abs(a - b).max()
                self.assertLessEqual(worst, TOLERANCE * scale,
                                     f"{label}: {name} differs by {worst:.3g} (scale {scale:.3g})")
        return got, piece

    def assert_series_in_pieces(self, model, processes, expect=0, names=("points.pvd",)):
        """Every file of the serial run's series (points.pvd), at the same times, in pieces."""
        serial = self.run_on(model, 1, expect)
        output = self.run_on(model, processes, expect)
        pieces = []
        for name in names:
            pieces += self.assert_same_series(serial, output, name, processes)
        return pieces

    def assert_same_series(self, serial, output, name, processes):
        expected, written = series(serial, name), series(output, name)
        self.assertEqual([t for t, _ in written], [t for t, _ in expected], f"{name}'s times")
        pieces = []
        for (_, a), (_, b) in zip(expected, written):
            # The pieces are named by the process that wrote them, beside the .pvtu.
            for rank in range(processes):
                stem = os.path.splitext(b)[0]
                self.assertTrue(os.path.isfile(os.path.join(output, f"{stem}_p{rank}.vtu")))
            pieces.append(self.assert_same_points(os.path.join(serial, a), os.path.join(output, b)))
        return pieces

    def test_the_pieces_hold_every_point_once_with_the_serial_values(self):
        # The Mohr-Coulomb footing: its points flow plastically under the footing, which the RCB
        # cuts through, and they cross between the processes' cells as it sinks.
        for processes in (2, 3):
            pieces = self.assert_series_in_pieces(
                "mohr_coulomb_footing/mohr_coulomb_footing.yaml", processes)
            (first, first_piece), (last, last_piece) = pieces[0], pieces[-1]
            self.assertEqual(len(np.unique(last_piece)), processes, "a piece per process")
            self.assertGreater((first_piece != last_piece).sum(), 0, "points changed process")
            self.assertGreater(last["plastic"].sum(), 0, "plastic points at the end")

    def test_the_fem_regions_gauss_points_in_pieces(self):
        # The coupled strip footing on 3 processes: the FEM region's cells are shared out by
        # their Gauss points, and each process writes those of its cells (gauss_points.pvd).
        pieces = self.assert_series_in_pieces("coupling/strip_footing_coupled.yaml", 3,
                                              names=("points.pvd", "gauss_points.pvd"))
        self.assertGreater(len(np.unique(pieces[-1][1])), 1, "Gauss points on several processes")

    def test_a_stopped_run_writes_its_last_state_in_pieces(self):
        # The oedometer's top pulled up out of the mesh: its points leave the mesh at the 7th step
        # (lost_points: stop), and the run stops with the 6th, which ParaView output every 4th
        # step did not write: the last state is written then, in pieces.
        with open(os.path.join(ROOT, "examples", "oedometer", "oedometer.yaml")) as f:
            text = f.read().replace('"-0.1*t"', '"0.5*t"').replace("every: 5", "every: 4")
        model = os.path.join(self.dir, "pulled.yaml")
        with open(model, "w") as f:
            f.write(text)
        self.assert_series_in_pieces(model, 2, expect=3)
        written = series(os.path.join(self.dir, "np2"), "points.pvd")
        self.assertEqual(written[-1], (0.6, "vtk/points_000006.pvtu"))


if __name__ == "__main__":
    unittest.main()
