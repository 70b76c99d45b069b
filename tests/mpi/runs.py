"""geompm runs on one process (the serial code, no mpirun) and under mpirun, for the mpi tests.

Environment: GEOMPM_BINARY (the geompm executable), GEOMPM_MPIRUN (mpirun).
"""
import csv
import os
import subprocess

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("GEOMPM_BINARY", os.path.join(ROOT, "build", "geompm"))
MPIRUN = os.environ.get("GEOMPM_MPIRUN", "mpirun")


def run(model, output, processes, *extra, env=None):
    """Runs `model` (a path, or relative to examples/) into `output` on `processes` processes."""
    command = [BINARY, "run", os.path.join(ROOT, "examples", model), "-o", output, "--quiet"]
    if processes > 1:
        command = [MPIRUN, "--oversubscribe", "-np", str(processes)] + command
    environment = dict(os.environ, OMP_NUM_THREADS="1")
    environment.update(env or {})
    return subprocess.run(command + list(extra), capture_output=True, text=True, env=environment,
                          timeout=900)


def history(output):
    """history.csv's columns and rows (as floats)."""
    with open(os.path.join(output, "history.csv")) as f:
        rows = list(csv.reader(f))
    columns = rows[0]
    values = [[float(v) for v in row] for row in rows[1:]]
    return columns, values
