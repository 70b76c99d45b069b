#!/usr/bin/python3
"""Turns the JSON output of bench_step into docs/performance.md.

Everything in the doc is computed from the JSON and the machine it ran on, so the doc can be
regenerated at any time and never states a number that was not measured. Findings from profiling
(which a table cannot show) live in bench/performance_notes.md and are copied in verbatim.

Usage: make_performance_doc.py RESULTS.json OUTPUT.md [--build-dir DIR] [--load-after "a b c"]
                                [--notes bench/performance_notes.md] [--wall-seconds S]
"""

import argparse
import datetime
import json
import math
import os
import re
import subprocess

# The targets (docs/performance.md restates them).
TARGET_RATE = 1.0e6  # points per second per core, non-solve work of one Newton iteration
TARGET_BYTES = 1024.0  # bytes per 2D material point
TARGET_EXPONENT = 1.3  # time per step ~ n^exponent

PHASES = [
    # (key, label, what it times)
    ("map", "map", "phase 1: `GridSystem::initialise` + `external_force`"),
    ("constraints", "constraints", "fixities to constrained dofs + `set_constraints` (pattern, scatter maps)"),
    ("internal_force@1", "internal force, 1 thread", "stress update + f_int + tangent assembly"),
    ("internal_force@all", "internal force, all threads", "the same on every core"),
    ("analyze", "analyze", "UMFPACK symbolic analysis (once per step)"),
    ("factorize_solve", "factorize + solve", "UMFPACK numeric factorisation + one solve (per Newton iteration)"),
    ("convect", "convect", "phase 3: `GridSystem::convect` + relocation (PointLocator)"),
    ("step", "**whole step**", "`StepSolver::advance`"),
]


def run(command):
    try:
        return subprocess.run(command, capture_output=True, text=True, check=False).stdout
    except OSError:
        return ""


def machine_facts(build_dir, context):
    facts = {}
    lscpu = run(["lscpu"])
    model = re.search(r"Model name:\s*(.+)", lscpu)
    facts["cpu"] = model.group(1).strip() if model else "unknown"
    facts["cores"] = str(os.cpu_count())
    try:
        with open("/proc/meminfo") as meminfo:
            kb = int(re.search(r"MemTotal:\s*(\d+)", meminfo.read()).group(1))
        facts["memory"] = f"{kb / 1024 ** 2:.1f} GiB"
    except (OSError, AttributeError):
        facts["memory"] = "unknown"
    facts["mhz"] = str(context.get("mhz_per_cpu", "?"))
    caches = context.get("caches", [])
    facts["caches"] = ", ".join(
        f"L{c['level']} {c['type'].lower()} {c['size'] // 1024} KiB" for c in caches)
    compiler, build_type = "unknown", "unknown"
    cache = os.path.join(build_dir, "CMakeCache.txt")
    if os.path.exists(cache):
        with open(cache) as f:
            text = f.read()
        cxx = re.search(r"^CMAKE_CXX_COMPILER:\w+=(.+)$", text, re.M)
        if cxx:
            compiler = run([cxx.group(1).strip(), "--version"]).splitlines()[0:1]
            compiler = compiler[0] if compiler else cxx.group(1)
        bt = re.search(r"^CMAKE_BUILD_TYPE:\w+=(.*)$", text, re.M)
        build_type = bt.group(1) if bt else build_type
    facts["compiler"] = compiler
    facts["build_type"] = build_type
    # Which BLAS UMFPACK's dense frontal kernels run on matters more than anything in geompm
    # for the solve: reference BLAS is several times slower than an optimised one.
    if context.get("blas"):  # recorded by bench_step itself: what the run really used
        facts["blas"] = context["blas"]
        return finish_facts(facts)
    binary = os.path.join(build_dir, "bench", "bench_step")
    blas = [line.split("=>")[1].split("(")[0].strip()
            for line in run(["ldd", binary]).splitlines() if "blas" in line]
    resolved = [os.path.realpath(b) for b in blas]
    facts["blas"] = ", ".join(resolved) if resolved else "unknown"
    return finish_facts(facts)


def finish_facts(facts):
    facts["kernel"] = run(["uname", "-sr"]).strip()
    facts["commit"] = run(["git", "-C", os.path.dirname(os.path.abspath(__file__)), "rev-parse",
                           "--short", "HEAD"]).strip() or "unknown"
    dirty = run(["git", "-C", os.path.dirname(os.path.abspath(__file__)), "status",
                 "--porcelain", "--untracked-files=no", "--", "../src"]).strip()
    facts["dirty"] = bool(dirty)
    return facts


def parse_name(run_name):
    """(phase, cells, threads, formulation): formulation None for the displacement one."""
    parts = run_name.split("/")
    cells = threads = formulation = None
    for p in parts[1:]:
        if p.startswith("cells:"):
            cells = int(p.split(":")[1])
        elif p.startswith("threads:"):
            threads = int(p.split(":")[1])
        elif p.startswith("formulation:"):
            formulation = p.split(":")[1]
    return parts[0], cells, threads, formulation


def to_ms(value, unit):
    return value * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[unit]


def load_results(path):
    with open(path) as f:
        data = json.load(f)
    cores = int(data["context"].get("omp_max_threads", data["context"].get("num_cpus", 1)))
    medians, cvs = {}, {}
    for b in data["benchmarks"]:
        phase, cells, threads, formulation = parse_name(b["run_name"])
        key = phase
        if phase == "internal_force":
            key = "internal_force@1" if threads == 1 else "internal_force@all"
        if formulation:  # the mixed variants: keys of their own, read by the mixed section only
            key += "#" + formulation
        if b.get("aggregate_name") == "median":
            medians[(key, cells)] = dict(b, time_ms=to_ms(b["real_time"], b["time_unit"]),
                                         cpu_ms=to_ms(b["cpu_time"], b["time_unit"]))
        elif b.get("aggregate_name") == "cv":
            cvs[(key, cells)] = b["real_time"]
        elif b["run_type"] == "iteration" and (key, cells) not in medians:
            # A single repetition reports no aggregates: its one run is its median.
            medians[(key, cells)] = dict(b, time_ms=to_ms(b["real_time"], b["time_unit"]),
                                         cpu_ms=to_ms(b["cpu_time"], b["time_unit"]))
    # The step benchmark carries the memory counters (bytes per point).
    memory = {cells: entry for (key, cells), entry in medians.items()
              if key == "step" and "step_peak_B_per_point" in entry}
    sizes = sorted({cells for (_, cells) in medians})
    repetitions = max((b.get("repetitions", 1) for b in data["benchmarks"]), default=1)
    return data["context"], cores, sizes, medians, cvs, memory, repetitions


def slope(xs, ys):
    """Least-squares slope of log y against log x."""
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    den = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / den if den > 0 else float("nan")


def fmt_ms(ms):
    if ms is None:
        return "–"
    if ms >= 10000:
        return f"{ms / 1000:.1f} s"
    if ms >= 1000:
        return f"{ms / 1000:.2f} s"
    if ms >= 10:
        return f"{ms:.0f} ms"
    return f"{ms:.2f} ms"


def fmt_count(x):
    if x >= 1e6:
        return f"{x / 1e6:.2f} M"
    if x >= 1e3:
        return f"{x / 1e3:.0f} k"
    return f"{x:.0f}"


def verdict(ok):
    return "**met**" if ok else "**not met**"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("results")
    parser.add_argument("output")
    parser.add_argument("--build-dir", default="build")
    parser.add_argument("--load-after", default="")
    parser.add_argument("--wall-seconds", type=float, default=None)
    parser.add_argument("--notes", default=None)
    parser.add_argument("--commit", default=None,
                        help="the commit benchmarked, as recorded before the build")
    parser.add_argument("--omp-wait-policy", default=os.environ.get("OMP_WAIT_POLICY", "(default)"))
    args = parser.parse_args()

    context, cores, sizes, med, cvs, memory, repetitions = load_results(args.results)
    wait_policy = context.get("omp_wait_policy", args.omp_wait_policy)
    facts = machine_facts(args.build_dir, context)

    def t(key, cells):
        entry = med.get((key, cells))
        return entry["time_ms"] if entry else None

    def cpu(key, cells):
        entry = med.get((key, cells))
        return entry["cpu_ms"] if entry else None

    def counter(key, cells, name):
        entry = med.get((key, cells))
        return entry.get(name) if entry else None

    points = {c: (counter("step", c, "points") or memory.get(c, {}).get("points")) for c in sizes}
    out = []
    w = out.append
    date = context.get("date", datetime.datetime.now().isoformat())[:16].replace("T", " ")
    w("# Performance\n")
    w("<!-- Generated by bench/run_benchmarks.sh (bench/make_performance_doc.py) from "
      "bench/results/bench_step.json (not committed: results/ is ignored); edit the generator "
      "or bench/performance_notes.md, not this file. -->\n")
    w("What one implicit step of geompm costs, phase by phase, at sizes from 10^4 to 10^6 "
      "material points in 2D, measured by `bench/bench_step` and written here by "
      "`bench/run_benchmarks.sh`. Timings are **medians of "
      f"{repetitions} repetitions**, wall clock. Performance is measured here, never asserted "
      "in tests.\n")

    w("## Machine and run\n")
    w("| | |\n|---|---|")
    w(f"| date | {date} UTC |")
    w(f"| CPU | {facts['cpu']}, {facts['cores']} cores, {facts['mhz']} MHz |")
    w(f"| caches | {facts['caches']} |")
    w(f"| memory | {facts['memory']} |")
    w(f"| kernel | {facts['kernel']} |")
    w(f"| compiler | {facts['compiler']}, CMAKE_BUILD_TYPE={facts['build_type']} |")
    w(f"| BLAS under UMFPACK | {facts['blas']} |")
    commit = args.commit or (facts["commit"] + (" (src/ modified)" if facts["dirty"] else ""))
    w(f"| geompm commit | {commit} |")
    w(f"| OpenMP threads | {cores} (`OMP_WAIT_POLICY={wait_policy}`) |")
    load_before = ", ".join(f"{x:.2f}" for x in context.get("load_avg", []))
    w(f"| load average (1, 5, 15 min) | at start {load_before or '?'}; at end "
      f"{args.load_after or '?'} |")
    if args.wall_seconds:
        w(f"| benchmark run time | {args.wall_seconds / 60:.1f} min |")
    w("")

    w("## What is timed\n")
    w("The model (bench/step_case.cpp) is an elastic block (E = 1e5 kPa, nu = 0.3, density 2 t/m3) "
      "under its own weight in plane strain: a 10 m square of `cells` x `cells` Quad4 cells, "
      "the body filling all but the top row (the empty buffer row above a free surface), 4 "
      "points per cell, rollers on the sides and a fixed base, one quasi-static step of dt = 1 "
      "solved by Newton with UMFPACK. Each phase is timed on its own with everything before it "
      "in place; `step` times `StepSolver::advance` whole, from the same state every time.\n")
    w("| benchmark | what it times |\n|---|---|")
    for key, label, what in PHASES:
        w(f"| {label} | {what} |")
    w("")

    # --- the table ---------------------------------------------------------------------------
    w("## Time per phase (medians)\n")
    header = "| | " + " | ".join(f"{c}x{c} cells" for c in sizes) + " |"
    w(header)
    w("|---" * (len(sizes) + 1) + "|")
    w("| material points | " + " | ".join(fmt_count(points[c] or 0) for c in sizes) + " |")
    w("| free dofs | " + " | ".join(fmt_count(counter("analyze", c, "free_dofs") or 0)
                                  for c in sizes) + " |")
    w("| tangent non-zeros | " + " | ".join(fmt_count(counter("analyze", c, "nnz") or 0)
                                          for c in sizes) + " |")
    for key, label, _ in PHASES:
        w(f"| {label} | " + " | ".join(fmt_ms(t(key, c)) for c in sizes) + " |")
    w("| Newton iterations (solves) per step | " + " | ".join(
        f"{counter('step', c, 'newton_iterations') or 0:.0f}" for c in sizes) + " |")
    w("")
    fewer = sorted(((k, c), v.get("repetitions", 1)) for (k, c), v in med.items()
                   if v.get("repetitions", 1) < repetitions)
    if fewer:
        w("Each benchmark repeats " + f"{repetitions} times, except " + ", ".join(
            f"{k.split('@')[0]} at {c}x{c} ({n})" for (k, c), n in fewer)
          + ", whose single runs take the longest.\n")
    w("CPU time of the whole process (all threads), medians. Where it is well below the wall "
      "time times the threads, the process was waiting for a core that other work held.\n")
    w("| CPU time | " + " | ".join(f"{c}x{c}" for c in sizes) + " |")
    w("|---" * (len(sizes) + 1) + "|")
    for key, label, _ in PHASES:
        w(f"| {label} | " + " | ".join(fmt_ms(cpu(key, c)) for c in sizes) + " |")
    w("")

    # --- composition of a step -----------------------------------------------------------------
    w("## Where a step's time goes\n")
    w("A step with k Newton solves does map + constraints + (k+1) internal-force evaluations "
      "(the last one checks convergence) + analyze + k (factorize + solve) + convect. The "
      "phases' medians put together that way, against the measured step:\n")
    w("| | " + " | ".join(f"{c}x{c}" for c in sizes) + " |")
    w("|---" * (len(sizes) + 1) + "|")
    shares = {}
    for c in sizes:
        k = counter("step", c, "newton_iterations") or 0
        parts = {
            "map + constraints + convect": sum(t(x, c) or 0 for x in ("map", "constraints", "convect")),
            "internal force (all threads)": (k + 1) * (t("internal_force@all", c) or 0),
            "analyze + factorize + solve": (t("analyze", c) or 0) + k * (t("factorize_solve", c) or 0),
        }
        total = sum(parts.values())
        shares[c] = (parts, total, t("step", c))
    for name in ("map + constraints + convect", "internal force (all threads)",
                 "analyze + factorize + solve"):
        cells_text = []
        for c in sizes:
            parts, total, _ = shares[c]
            cells_text.append(f"{fmt_ms(parts[name])} ({100 * parts[name] / total:.0f} %)"
                              if total else "–")
        w(f"| {name} | " + " | ".join(cells_text) + " |")
    w("| sum of phases | " + " | ".join(fmt_ms(shares[c][1]) for c in sizes) + " |")
    w("| measured step | " + " | ".join(fmt_ms(shares[c][2]) for c in sizes) + " |")
    w("")
    largest = sizes[-1]
    parts, total, _ = shares[largest]
    dominant = max(parts, key=parts.get)
    w(f"At {largest}x{largest} cells the step is dominated by **{dominant}** "
      f"({100 * parts[dominant] / total:.0f} % of the phases' sum).\n")

    # --- non-solve rate ----------------------------------------------------------------------
    w("## Non-solve work of one Newton iteration\n")
    w("Stress update + internal force + tangent assembly (the step system's evaluation with the "
      "tangent), in material points per second.\n")
    w("| | " + " | ".join(f"{c}x{c}" for c in sizes) + " |")
    w("|---" * (len(sizes) + 1) + "|")
    rate1 = {c: counter("internal_force@1", c, "points_per_s_per_core") for c in sizes}
    rate_all = {c: counter("internal_force@all", c, "points_per_s") for c in sizes}
    rate_all_core = {c: counter("internal_force@all", c, "points_per_s_per_core") for c in sizes}
    rate_cpu = {c: (points[c] / (cpu("internal_force@1", c) / 1e3)
                    if cpu("internal_force@1", c) else None) for c in sizes}
    w("| 1 thread, per wall second | " + " | ".join(fmt_count(rate1[c] or 0) + "/s"
                                                  for c in sizes) + " |")
    w("| 1 thread, per CPU second | " + " | ".join(
        fmt_count(rate_cpu[c] or 0) + "/s" for c in sizes) + " |")
    w(f"| {cores} threads, total | " + " | ".join(fmt_count(rate_all[c] or 0) + "/s"
                                               for c in sizes) + " |")
    w(f"| {cores} threads, per core | " + " | ".join(fmt_count(rate_all_core[c] or 0) + "/s"
                                                  for c in sizes) + " |")
    w(f"| parallel speed-up on {cores} cores | " + " | ".join(
        f"{(rate_all[c] or 0) / rate1[c]:.2f}" if rate1[c] else "–" for c in sizes) + " |")
    busy = {c: cpu("internal_force@all", c) / t("internal_force@all", c)
            for c in sizes if cpu("internal_force@all", c) and t("internal_force@all", c)}
    w(f"| cores the {cores}-thread run actually had (CPU time / wall time) | " + " | ".join(
        f"{busy[c]:.2f}" if c in busy else "–" for c in sizes) + " |")
    w("")
    if busy and max(busy.values()) < 0.75 * cores:
        w(f"The {cores}-thread runs never had much more than one core's worth of CPU time (last "
          "row), because other work held the machine: the parallel speed-up cannot be judged "
          "from this run. The CPU time of the 1- and the "
          f"{cores}-thread runs is what shows whether threading adds work.\n")

    # --- memory --------------------------------------------------------------------------------
    w("## Memory per material point\n")
    w("Heap held after each stage (glibc `mallinfo2`, all arenas), and the peak resident set "
      "of a whole step above the process's resident set before the model was built (held "
      "plus transient memory: sorting copies, the factorisation's work space), all divided by "
      "the number of points. The point store is `MaterialPoints::bytes_per_point()` (capacity "
      "included).\n")
    w("| bytes per point | " + " | ".join(f"{c}x{c}" for c in sizes) + " |")
    w("|---" * (len(sizes) + 1) + "|")
    rows = [("point store (`MaterialPoints`)", "point_store_B_per_point"),
            ("model: mesh, topology, locator, points", "model_B_per_point"),
            ("grid: `GridSystem` state, pattern, tangent, f_ext, f_int", "grid_B_per_point"),
            ("solver: UMFPACK factorisation", "solver_B_per_point"),
            ("**peak of a whole step**", "step_peak_B_per_point")]
    for label, name in rows:
        w(f"| {label} | " + " | ".join(
            f"{memory[c][name]:.0f}" if c in memory and memory[c].get(name, -1) >= 0 else "–"
            for c in sizes) + " |")
    held = {c: memory[c]["model_B_per_point"] + memory[c]["grid_B_per_point"]
            for c in sizes if c in memory}
    w("| model + grid (without the factorisation) | " + " | ".join(
        f"{held[c]:.0f}" if c in held else "–" for c in sizes) + " |")
    w("")

    # --- mixed p-u formulation -----------------------------------------------------------------
    mixed_sizes = [c for c in sizes if med.get(("step#mixed_cell_average", c))]
    if mixed_sizes:
        w("## The mixed p–u formulation, and crossed triangles\n")
        w("The same block with the soil in the mixed p–u formulation (docs/theory.md §11, "
          "ν = 0.49): one pressure unknown more per node, the kernel's pressure blocks and "
          "the cell's pressure stabilisation; with the cell-averaged volume change (F-bar, §12, "
          "the default) every mixed point's dF and B are also computed once more, for its "
          "cell's average, and the tangent gains the average's coupling terms. At the field's "
          "pressure (`mixed_material_pressure: field`, §14, with the cell average) each point's "
          "material is updated once per iteration of its volume solve (eq. 14.1). With the "
          "incremental pressure equation and the fitted start (`mixed_pressure_equation: "
          "incremental`, `mixed_pressure_start: fitted`, eqs. 11.8 and 11.11), each step also "
          "fits the last nodal pressure around every node (a small least-squares solve a node). "
          "Last, the displacement formulation on the same grid with every square split into four "
          "triangles by its crossed diagonals (`diagonals: crossed`, docs/theory.md §15), which "
          "does not lock: four cells and about twice the nodes a square, and with 3 points a "
          "triangle three times the points. "
          "Medians, ms; × = against the displacement formulation at the same size.\n")
        variants = [("displacement", ""), ("mixed, per point", "#mixed_per_point"),
                    ("mixed, cell average", "#mixed_cell_average"),
                    ("mixed, at the field's pressure", "#mixed_field_pressure"),
                    ("mixed, cell average, incremental, fitted start",
                     "#mixed_incremental_fitted"),
                    ("displacement, crossed triangles (3× the points)",
                     "#displacement_crossed_tri3")]
        w("| size | formulation | free unknowns | tangent non-zeros | internal force (1 thread) "
          "| factorise + solve | whole step | Newton iterations |")
        w("|---|---|---|---|---|---|---|---|")
        for c in mixed_sizes:
            for label, tag in variants:
                def cell(key):
                    value, base = t(key + tag, c), t(key, c)
                    if value is None:
                        return "–"
                    return fmt_ms(value) + ("" if not tag or not base else f" (×{value / base:.2f})")
                free = counter("factorize_solve" + tag, c, "free_dofs")
                nnz = counter("factorize_solve" + tag, c, "nnz")
                its = counter("step" + tag, c, "newton_iterations")
                its_text = f"{its:.0f}" if its is not None else "–"
                w(f"| {c}x{c} ({fmt_count(points[c])} points) | {label} | "
                  f"{fmt_count(free) if free else '–'} | {fmt_count(nnz) if nnz else '–'} | "
                  f"{cell('internal_force@1')} | {cell('factorize_solve')} | {cell('step')} | "
                  f"{its_text} |")
        w("")

    # --- growth --------------------------------------------------------------------------------
    w("## Growth with size\n")
    w("Exponent p of time ~ n^p (n = material points): least-squares slope of log time against "
      "log n over all sizes, and between neighbouring sizes.\n")
    w("| | all sizes | " + " | ".join(f"{a} → {b}" for a, b in zip(sizes, sizes[1:])) + " |")
    w("|---" * (len(sizes) + 1) + "|")
    exponents, last_pair = {}, {}
    # The step's non-solve work put together from its phases (a difference of the measured step
    # and the solve would be swamped by the solve's noise at the largest size).
    non_solve = {}
    for c in sizes:
        k = counter("step", c, "newton_iterations") or 0
        if all(t(x, c) is not None for x in ("map", "constraints", "internal_force@all", "convect")):
            non_solve[c] = (t("map", c) + t("constraints", c) + (k + 1) * t("internal_force@all", c)
                            + t("convect", c))
    NON_SOLVE = "non-solve part of a step (map + constraints + (k+1) internal force + convect)"
    series = [(label, {c: t(key, c) for c in sizes}) for key, label, _ in PHASES]
    series.append((NON_SOLVE, non_solve))
    series.append(("whole step, process CPU time", {c: cpu("step", c) for c in sizes}))
    for label, values in series:
        cs = [c for c in sizes if values.get(c) and values[c] > 0 and points[c]]
        if len(cs) < 2:
            continue
        p_all = slope([points[c] for c in cs], [values[c] for c in cs])
        exponents[label] = p_all
        pairs = []
        last_pair[label] = None
        for a, b in zip(sizes, sizes[1:]):
            if a in cs and b in cs:
                last_pair[label] = slope([points[a], points[b]], [values[a], values[b]])
                pairs.append(f"{last_pair[label]:.2f}")
            else:
                pairs.append("–")
        w(f"| {label} | {p_all:.2f} | " + " | ".join(pairs) + " |")
    w("")

    # --- targets -------------------------------------------------------------------------------
    w("## Targets (from the issue)\n")
    w("| target | measured | |\n|---|---|---|")
    # Judged on the CPU-time rate: what a core does when it is not shared, the more favourable
    # reading on a loaded machine; the wall-clock rate is shown beside it.
    best_cpu = max((r for r in rate_cpu.values() if r), default=0)
    at_large = rate_cpu.get(largest) or 0
    w(f"| non-solve work of a Newton iteration ≥ 1 M points/s per core | "
      f"{fmt_count(at_large)}/s per CPU second on 1 thread at {largest}x{largest} (best "
      f"{fmt_count(best_cpu)}/s; per wall second {fmt_count(rate1.get(largest) or 0)}/s) | "
      f"{verdict(at_large >= TARGET_RATE)} |")
    if largest in memory:
        m = memory[largest]
        store_ok = m["point_store_B_per_point"] <= TARGET_BYTES
        held_ok = held[largest] <= TARGET_BYTES
        peak_ok = 0 <= m["step_peak_B_per_point"] <= TARGET_BYTES
        w(f"| ≤ 1 KB of memory per 2D material point | at {largest}x{largest}: point store "
          f"{m['point_store_B_per_point']:.0f} B, model + grid {held[largest]:.0f} B, peak of a "
          f"step with the factorisation {m['step_peak_B_per_point']:.0f} B | point store "
          f"{verdict(store_ok)}; model + grid {verdict(held_ok)}; whole step {verdict(peak_ok)} |")
    p_step = exponents.get("**whole step**")
    p_cpu = exponents.get("whole step, process CPU time")
    p_ns = exponents.get(NON_SOLVE)
    if p_step is not None:
        # "No faster than about n^1.3": the fit over all sizes and the growth between the two
        # largest sizes must both stay within about 1.3 (a fit can hide a steepening top end).
        top = last_pair.get("**whole step**")
        ok = p_step <= TARGET_EXPONENT + 0.05 and (top is None or top <= TARGET_EXPONENT + 0.05)
        fastest = max(((last_pair[l] or 0, l) for l in last_pair if l.startswith(
            ("analyze", "factorize", "map", "constraints", "internal", "convect"))),
            default=(0, ""))
        w(f"| time per step ≤ ~n^1.3 (while the direct solver is used) | whole step n^{p_step:.2f} "
          f"over all sizes, n^{top:.2f} between the two largest"
          + (f" (CPU time n^{p_cpu:.2f} over all)" if p_cpu is not None else "")
          + (f"; its non-solve part n^{p_ns:.2f}" if p_ns is not None else "")
          + (f"; fastest-growing phase at the top: {fastest[1]} (n^{fastest[0]:.2f})"
             if fastest[1] else "")
          + f" | {verdict(ok)} |")
    w("")

    # --- noise ---------------------------------------------------------------------------------
    w("## Noise\n")
    noisy = sorted(((v, k) for k, v in cvs.items() if v > 0.10), reverse=True)
    if cvs:
        worst = max(cvs.values())
        w(f"Coefficient of variation of the repetitions: median "
          f"{100 * sorted(cvs.values())[len(cvs) // 2]:.1f} %, worst {100 * worst:.1f} %.")
    if noisy:
        w(" Above 10 %: " + ", ".join(f"{k[0]} at {k[1]}x{k[1]} ({100 * v:.0f} %)"
                                      for v, k in noisy[:8]) + ".")
    loads = context.get("load_avg", [])
    if loads and loads[0] > 0.5 * cores:
        w(f" The machine was shared while this ran (1-minute load {loads[0]:.1f} on {cores} "
          "cores at the start): other processes took CPU time, so absolute times are "
          "pessimistic and the medians are the figures to read.")
    w("")

    if args.notes and os.path.exists(args.notes):
        with open(args.notes) as f:
            notes = f.read().rstrip()
        # Tables kept in their own files (bench/footing_timings.md, bench/predictor_timings.md,
        # ...: measured by whole-run scripts, bench/README.md); the notes mark where they go, so the doc always carries the last ones (without their
        # title).
        for name in re.findall(r"<!-- bench/([\w.]+\.md) -->", notes):
            timings = os.path.join(os.path.dirname(os.path.abspath(__file__)), name)
            if os.path.exists(timings):
                with open(timings) as f:
                    body = f.read().strip().split("\n", 1)[-1].strip()
                notes = notes.replace(f"<!-- bench/{name} -->", body)
        w(notes + "\n")

    w("## Reproducing\n")
    w("```sh\nBUILD_DIR=build bench/run_benchmarks.sh            # all sizes, 3 to 10 min on 2 cores\n"
      "GEOMPM_BENCH_CELLS=50,160 bench/run_benchmarks.sh  # quicker, fewer sizes\n```\n")
    with open(args.output, "w") as f:
        f.write("\n".join(out))


if __name__ == "__main__":
    main()
