#!/usr/bin/python3
"""The robustness sweep of issue 45 (docs/validation.md §20): rigid strip and circular footings
on weightless Tresca clay as a user writes them (tests/sweep/footing_template.yaml), over
B or D in {1, 2.5} m, s_u in {1, 25} kPa, E/s_u in {100, 300, 1000}, nu in {0.49, 0.4999},
smooth and rough, each pushed to 0.1 B; prints one markdown row per run and the count that pass
(finished at 0.1 B, at most 10 Newton iterations a step, q/s_u at 0.1 B within 5 % of 2 + pi for
the strip, Cox, Eason & Hopkins' 5.69 smooth / 6.05 rough for the circle).

Usage: /usr/bin/python3 scripts/validation/sweep.py [--design fractional|full|distinct|CASES.csv] [--jobs 2]
           [--binary build/geompm] [--work DIR] [--newton "{line_search: 6}"]
           [--numerics "{mixed_volume: per_point}"] [--units N-mm]
--design fractional runs the 16 cases of tests/sweep/fractional_design.csv (the default), full
all 96, distinct the 24 distinct problems among them (B and s_u only scale a problem), or the cases of a CSV file with the same columns. --newton and --numerics try other settings than the defaults; --units N-mm writes the same
models in N and mm (E and s_u in N/mm^2, lengths in mm): the normalised results must not change.
"""
import argparse
import concurrent.futures
import csv
import itertools
import math
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TEMPLATE = os.path.join(ROOT, "tests", "sweep", "footing_template.yaml")
DESIGN = os.path.join(ROOT, "tests", "sweep", "fractional_design.csv")
REFERENCE = {("strip", "smooth"): 2 + math.pi, ("strip", "rough"): 2 + math.pi,
             ("circle", "smooth"): 5.69, ("circle", "rough"): 6.05}  # docs/references.md §3
TOLERANCE, MOST_ITERATIONS = 0.05, 10


def cases(design):
    if design not in ("full", "distinct"):
        with open(DESIGN if design == "fractional" else design) as f:
            return list(csv.DictReader(f))
    keys = ["shape", "B", "su", "E_over_su", "nu", "base"]
    # B and s_u only scale the problem (test_sweep_units.py): "distinct" runs each of the 24
    # distinct problems once, at B = 1 m and s_u = 1 kPa.
    widths, strengths = (["1", "2.5"], ["1", "25"]) if design == "full" else (["1"], ["1"])
    grid = itertools.product(["strip", "circle"], widths, strengths, ["100", "300", "1000"],
                             ["0.49", "0.4999"], ["smooth", "rough"])
    return [dict(zip(keys, values)) for values in grid]


def width_and_strength(case, millimetres):
    """B and s_u in the model's units: m and kPa, or mm and N/mm^2."""
    return (float(case["B"]) * (1000.0 if millimetres else 1.0),
            float(case["su"]) * (1e-3 if millimetres else 1.0))


def q_over_su(case, force, millimetres):
    """q/s_u from the contact force: a half strip's per unit length, a circle's per radian."""
    B, su = width_and_strength(case, millimetres)
    return (8 * force / B**2 if case["shape"] == "circle" else 2 * force / B) / su


def model_text(case, newton, numerics, millimetres):
    B, su = width_and_strength(case, millimetres)
    circle = case["shape"] == "circle"
    fields = {
        "TITLE": name(case), "KINEMATICS": "axisymmetric" if circle else "plane_strain",
        "B": B, "B4": 4 * B, "B02": 0.2 * B, "B5": 5 * B, "SU": su,
        "E": float(case["E_over_su"]) * su, "NU": case["nu"], "CONTACT": case["base"],
        "PUSH": 0.1 * B, "HELD": "" if circle else ", rotation: 0",
        "NEWTON": f"    newton: {newton}" if newton else "",
        "NUMERICS": f"numerics: {numerics}" if numerics else ""}
    with open(TEMPLATE) as f:
        text = f.read()
    for key, value in fields.items():
        text = text.replace(f"@{key}@", f"{value:g}" if isinstance(value, float) else str(value))
    return text


def name(case):
    return "{shape}_B{B}_su{su}_E{E_over_su}_nu{nu}_{base}".format(**case)


def run(case, args, work):
    text = model_text(case, args.newton, args.numerics, args.units == "N-mm")
    model = os.path.join(work, name(case) + ".yaml")
    with open(model, "w") as f:
        f.write(text)
    out = os.path.join(work, name(case))
    res = subprocess.run([args.binary, "run", model, "-q", "-t", "1", "-o", out],
                         capture_output=True, text=True)
    rows = []
    history = os.path.join(out, "history.csv")
    if os.path.exists(history):
        with open(history) as f:
            rows = list(csv.DictReader(f))
    return case, res.returncode, rows


def reading(case, returncode, rows, millimetres):
    """(settlement / B reached, q / s_u there, most Newton iterations, verdict)."""
    if not rows:
        return 0.0, float("nan"), 0, "no result"
    B, _ = width_and_strength(case, millimetres)
    last = rows[-1]
    s = -float(last["settlement"]) / B
    q = q_over_su(case, float(last["force"]), millimetres)
    most = max(int(float(r["newton_iterations"])) for r in rows)
    reference = REFERENCE[(case["shape"], case["base"])]
    finished = returncode == 0 and s > 0.1 - 1e-9
    ok = finished and most <= MOST_ITERATIONS and abs(q / reference - 1) <= TOLERANCE
    verdict = "pass" if ok else ("stopped" if not finished else
                                 "iterations" if most > MOST_ITERATIONS else "off")
    return s, q, most, verdict


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--design", default="fractional",
                        help="fractional, full, distinct or a CSV file of cases (the columns of "
                             "tests/sweep/fractional_design.csv)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "geompm"))
    parser.add_argument("--work", default=None)
    parser.add_argument("--newton", default="")
    parser.add_argument("--numerics", default="")
    parser.add_argument("--units", choices=["kN-m", "N-mm"], default="kN-m")
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="geompm_sweep_")
    os.makedirs(work, exist_ok=True)
    print("| footing | B (m) | s_u (kPa) | E/s_u | ν | base | reached s/B | q/s_u | "
          "vs reference | Newton max | verdict |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    passed = 0
    todo = cases(args.design)
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for case, rc, rows in pool.map(lambda c: run(c, args, work), todo):
            s, q, most, verdict = reading(case, rc, rows, args.units == "N-mm")
            reference = REFERENCE[(case["shape"], case["base"])]
            passed += verdict == "pass"
            print(f"| {case['shape']} | {case['B']} | {case['su']} | {case['E_over_su']} | "
                  f"{case['nu']} | {case['base']} | {s:.3f} | {q:.3f} | "
                  f"{100 * (q / reference - 1):+.1f} % | {most} | {verdict} |", flush=True)
    print(f"\n{passed} of {len(todo)} pass (runs in {work})")


if __name__ == "__main__":
    main()
