"""Whole `geompm run` timings for the benchmark scripts that run complete models
(bench/newton_predictor.py, bench/energy_search.py, bench/ghost_penalty.py,
bench/strip_refinement.py): one run, its repetitions with the median wall time, and the Markdown
table they write."""
import argparse
import os
import re
import statistics
import subprocess
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

SUMMARY = re.compile(r"finished: (\d+) steps, (\d+) Newton iterations \(at most (\d+) in a step\), "
                     r"(\d+) cut-backs, wall time ([\d.]+) s")


def arguments(doc, only_help):
    """The scripts' shared options: --build-dir, --repetitions, --only."""
    parser = argparse.ArgumentParser(description=doc.split("\n")[0])
    parser.add_argument("--build-dir", default="build")
    parser.add_argument("--repetitions", type=int, default=3)
    parser.add_argument("--only", action="append", default=[], help=only_help)
    return parser.parse_args()


def short_failure(message):
    """Where a run stopped and why, from geompm's 'run stopped: phase ..., the step at time T did
    not converge with the smallest allowed time step (...): REASON; more' message."""
    m = re.search(r"phase '([^']+)': the step at time ([\d.e+-]+) did not converge with the "
                  r"smallest allowed time step \([^)]*\): ([^;]*)", message)
    if not m:
        return message[:160]
    phase, time, reason = m.groups()
    return f"at t = {float(time):g} of phase '{phase}': {reason.strip()}"


def run(binary, text, work, name):
    """One run on one thread: ((steps, iterations, most in a step, cut-backs, wall), history,
    failure), the summary None and the failure said where the run stopped."""
    model = os.path.join(work, name + ".yaml")
    with open(model, "w") as f:
        f.write(text)
    out = os.path.join(work, name)
    res = subprocess.run([binary, "run", model, "-q", "-t", "1", "-o", out], capture_output=True,
                         text=True)
    m = SUMMARY.search(res.stderr)
    history = np.genfromtxt(os.path.join(out, "history.csv"), delimiter=",", names=True)
    if not m:
        said = (res.stderr + res.stdout).strip().splitlines() or ["(no message)"]
        stopped = [line for line in said if line.startswith("run stopped")]
        return None, history, short_failure((stopped or said)[-1])
    steps, iterations, most, cutbacks, wall = m.groups()
    return (int(steps), int(iterations), int(most), int(cutbacks), float(wall)), history, ""


def repeated(binary, text, work, name, repetitions, measure=None):
    """The model run `repetitions` times (stopping at the first that fails): ((summary, history,
    failure, measure(output directory) of the first run or None), median wall time)."""
    walls, first = [], None
    for k in range(repetitions):
        out = f"{name}_{k}"
        summary, history, failure = run(binary, text, work, out)
        if summary is None:
            first = (None, history, failure, None)
            break
        walls.append(summary[4])
        first = first or (summary, history, "",
                          measure(os.path.join(work, out)) if measure else None)
    return first, statistics.median(walls) if walls else float("nan")


def compared_runs(args, models, variants_of, measure=None):
    """For each (label, key) of `models` that --only selects: (label, key, {name: repeated run})
    for the variants {name: model text} of variants_of(key), each run args.repetitions times on
    one thread in a temporary directory."""
    binary = os.path.join(ROOT, args.build_dir, "geompm")
    with tempfile.TemporaryDirectory() as work:
        for label, key in models:
            if args.only and not any(part in key for part in args.only):
                continue
            yield label, key, {
                name: repeated(binary, text, work, f"{key.replace(':', '_')}_{name}",
                               args.repetitions, measure)
                for name, text in variants_of(key).items()}


def history_difference(a, b, column):
    """The largest difference of a load column between two runs' histories, relative to the
    first's largest value; NaN where either stopped or they took other steps."""
    (s0, h0, _, _), _ = a
    (s1, h1, _, _), _ = b
    if not (s0 and s1 and len(h0) == len(h1)):
        return float("nan")
    return float(np.max(np.abs(h0[column] - h1[column])) / np.max(np.abs(h0[column])))


def history_cell(d):
    return "other steps" if d != d else "identical as printed" if d == 0 else f"{d:.1e}"


def machine(repetitions):
    """'N runs of each, ..., CPU, load average at the end': the tables' measuring conditions."""
    cpu = "unknown"
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    with open("/proc/loadavg") as f:
        load = f.read().split()[0]
    return (f"{repetitions} runs of each, the median wall time; `geompm run -t 1`, VTK off; {cpu}, "
            f"2 cores, load average {load} at the end")


def write_table(name, lines, rows, only):
    """bench/`name`: the header `lines` and the rows {key: row}; with `only`, the table as it was
    with just the rows of these keys (marked `(`key`)`) replaced."""
    path = os.path.join(ROOT, "bench", name)
    if only and os.path.exists(path):
        with open(path) as f:
            lines = f.read().rstrip("\n").split("\n")
        for k, line in enumerate(lines):
            for key, row in rows.items():
                if f"(`{key}`)" in line:
                    lines[k] = row
    else:
        lines = lines + list(rows.values())
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote bench/{name}")
