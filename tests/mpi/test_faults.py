"""A distributed run that meets an error ends every process with the serial run's exit code and
one message, never a hang (core/agreement.hpp): an output directory process 0 cannot use, a
history file on a full disk (written by process 0 only), a checkpoint on a full disk (written by
process 0 as the others stream their points to it), a fault in the step's work on process 1
only (shared in the step's reduction: the run stops as a serial run stops, summary.json written),
a fault on process 1 outside any shared point (the last resort: every process is stopped), and a
model error met by every process while reading the model (said once).

Environment: GEOMPM_BINARY (the geompm executable), GEOMPM_MPIRUN (mpirun).
"""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("GEOMPM_BINARY", os.path.join(ROOT, "build", "geompm"))
MPIRUN = os.environ.get("GEOMPM_MPIRUN", "mpirun")
# A hang is a failure: the column runs in a few seconds on 2 or 3 processes.
TIMEOUT = 120

# The elastic column under its weight (26 cells cut between the processes), with its history.
with open(os.path.join(ROOT, "examples", "column", "column.yaml")) as f:
    COLUMN = f.read()

# An elastic block of 40 x 40 cells, 4 points a cell, one step under gravity.
BLOCK = """title: block
analysis: {kinematics: plane_strain}
mesh: {generate: {cell: quad4, origin: [0, 0], x: {length: 10, cells: 40}, y: {length: 10, cells: 40}}}
materials: {soil: {model: linear_elastic, E: 1.0e5, nu: 0.3, density: 2}}
bodies: {block: {material: soil, region: {box: {min: [0, 0], max: [10, 10]}}, points_per_cell: 4}}
phases:
  - name: gravity
    duration: 1
    time_step: 1
    dynamics: quasi_static
    gravity: {acceleration: [0, -10]}
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: bottom, fix: all}
output: {vtk: {every: 0}}
"""


class Faults(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="geompm_mpi_faults_")
        self.model = os.path.join(self.dir, "column.yaml")
        with open(self.model, "w") as f:
            f.write(COLUMN)

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def run_on(self, processes, output, env=None, model=None):
        command = [MPIRUN, "--oversubscribe", "-np", str(processes), BINARY, "run",
                   model or self.model, "-o", output, "--quiet"]
        environment = dict(os.environ, OMP_NUM_THREADS="1")
        environment.update(env or {})
        return subprocess.run(command, capture_output=True, text=True, env=environment,
                              timeout=TIMEOUT, cwd=self.dir)

    def assert_said_once(self, done, text):
        self.assertEqual(done.stderr.count(text), 1, f"'{text}' once in:\n{done.stderr}")

    def test_unusable_output_directory(self):
        with open(os.path.join(self.dir, "notes.txt"), "w") as f:
            f.write("not a directory\n")
        done = self.run_on(2, "notes.txt/out")
        self.assertEqual(done.returncode, 2, done.stderr)
        self.assert_said_once(done, "cannot use it as the output directory")
        self.assertNotIn("internal error", done.stderr)

    def test_history_on_a_full_disk(self):
        if not os.path.exists("/dev/full"):
            self.skipTest("no /dev/full")
        output = os.path.join(self.dir, "out")
        os.makedirs(output)
        os.symlink("/dev/full", os.path.join(output, "history.csv"))
        done = self.run_on(2, output)
        self.assertEqual(done.returncode, 3, done.stderr)
        self.assert_said_once(done, "No space left on device")
        self.assertIn("history.csv", done.stderr)

    def test_checkpoint_on_a_full_disk(self):
        # A block of 6400 points (a checkpoint of 3.3 MB) under a file size limit of 1 MiB (SIGXFSZ
        # ignored: the write fails with EFBIG as on a full disk): process 0's write fails in the
        # middle of the points section, which the other processes are streaming to it
        # (points/streamed_points.hpp); they finish the section, then all learn the failure and
        # stop with the serial run's exit code, said once, with no checkpoint left.
        model = os.path.join(self.dir, "block.yaml")
        with open(model, "w") as f:
            f.write(BLOCK)
        output = os.path.join(self.dir, "out")
        command = [MPIRUN, "--oversubscribe", "-np", "3", "bash", "-c",
                   "trap '' XFSZ; ulimit -f 1024; exec \"$@\"", "bash", BINARY, "run", model,
                   "-o", output, "--quiet", "--checkpoint-every", "1"]
        done = subprocess.run(command, capture_output=True, text=True, timeout=TIMEOUT,
                              env=dict(os.environ, OMP_NUM_THREADS="1"), cwd=self.dir)
        self.assertEqual(done.returncode, 3, done.stderr)
        self.assert_said_once(done, "run stopped: cannot write the checkpoint")
        self.assertIn("File too large", done.stderr)
        self.assertFalse(os.path.exists(os.path.join(output, "checkpoint.bin")))
        with open(os.path.join(output, "summary.json")) as f:
            self.assertEqual(json.load(f)["status"], "stopped")

    def test_fault_in_the_step_on_process_1(self):
        output = os.path.join(self.dir, "out")
        done = self.run_on(3, output, env={"GEOMPM_TEST_FAULT": "1:step"})
        self.assertEqual(done.returncode, 3, done.stderr)
        self.assert_said_once(done, "run stopped: a test fault (GEOMPM_TEST_FAULT=1:step) on "
                                    "process 1")
        # Every process stopped together: the run ended as a serial one ends, with its summary.
        with open(os.path.join(output, "summary.json")) as f:
            summary = json.load(f)
        self.assertEqual(summary["status"], "stopped")
        self.assertIn("test fault", summary["reason"])

    def test_fault_on_process_1_alone(self):
        done = self.run_on(2, os.path.join(self.dir, "out"),
                           env={"GEOMPM_TEST_FAULT": "1:between_steps"})
        self.assertEqual(done.returncode, 3, done.stderr)
        self.assert_said_once(done, "process 1 of 2: run stopped: a test fault")

    def test_model_error_said_once(self):
        bad = os.path.join(self.dir, "bad.yaml")
        with open(bad, "w") as f:
            f.write(COLUMN.replace("E: 1000,", "E: -1000,"))
        done = self.run_on(3, os.path.join(self.dir, "out"), model=bad)
        self.assertEqual(done.returncode, 2, done.stderr)
        self.assert_said_once(done, "error: ")
        self.assertIn("bad.yaml", done.stderr)


if __name__ == "__main__":
    unittest.main()
