#!/usr/bin/python3
"""Runs validation cases (cases/*.json: a model of examples/ with text overrides, a metric, its
reference with the source, and a tolerance) with the geompm binary, and prints the rows of the
summary table of docs/validation.md: case, reference, result, tolerance, verdict.

Usage: /usr/bin/python3 scripts/validation/run_cases.py [--binary build/geompm] [--jobs 2]
                                                        [--work DIR] [CASE ...]
"""
import argparse
import concurrent.futures
import glob
import json
import os
import subprocess
import tempfile

import metrics

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def load_cases(names=()):
    cases = []
    for path in sorted(glob.glob(os.path.join(HERE, "cases", "*.json"))):
        name = os.path.splitext(os.path.basename(path))[0]
        if names and name not in names:
            continue
        with open(path) as f:
            case = json.load(f)
        case["name"] = name
        cases.append(case)
    return cases


def model_text(case):
    """The example's text with the case's overrides, each replacing exactly one occurrence."""
    with open(os.path.join(ROOT, "examples", case["model"])) as f:
        text = f.read()
    for old, new in case.get("overrides", []):
        if text.count(old) != 1:
            raise ValueError(f"{case['name']}: override {old!r} found {text.count(old)} times")
        text = text.replace(old, new)
    return text


def run(case, binary, work):
    directory = os.path.join(work, case["name"])
    os.makedirs(directory, exist_ok=True)
    model = os.path.join(work, case["name"] + ".yaml")  # (a generated mesh: no relative paths)
    with open(model, "w") as f:
        f.write(model_text(case))
    subprocess.run([binary, "run", "-q", "-t", "1", "-o", directory, model],
                   env=dict(os.environ, OMP_WAIT_POLICY="passive"), check=False,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    history = metrics.read_history(os.path.join(directory, "history.csv"))
    value = metrics.evaluate(case["metric"], history)
    return value, metrics.verdict(value, case["tolerance"], case["reference"]["value"])


def row(case, value, verdict):
    ref = case["reference"]
    shown = "—" if value is None else f"{value:.4g}"
    if value is not None and ref["value"] != 0:
        shown += f" ({100 * (value / ref['value'] - 1):+.2f} %)"
    return (f"| {case['title']} | {ref['value']:g} ({ref['source']}) | {shown} | "
            f"{case['tolerance_text']} | {verdict} |")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "geompm"))
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--work", default=None)
    parser.add_argument("cases", nargs="*")
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="geompm_cases_")
    cases = load_cases(args.cases)
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda c: run(c, args.binary, work), cases))
    print("| case | reference (source) | geompm | tolerance | verdict |")
    print("|---|---|---|---|---|")
    for case, (value, verdict) in zip(cases, results):
        print(row(case, value, verdict))


if __name__ == "__main__":
    main()
