"""Metric functions of the validation cases: numbers read from a run's history.csv (and
summary.json), in plain Python (no numpy), each tested in test_metrics.py."""
import csv
import json
import math


def read_history(path):
    """history.csv as {column: [values]}."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, values = rows[0], [[float(v) for v in row] for row in rows[1:] if row]
    return {name: [row[i] for row in values] for i, name in enumerate(header)}


def read_summary(path):
    with open(path) as f:
        return json.load(f)


def value_at(xs, ys, x):
    """y at x, linear between the rows; None if the run did not get to x (xs ascending)."""
    for k in range(1, len(xs)):
        if xs[k] >= x - 1e-12:
            if xs[k] == xs[k - 1]:
                return ys[k]
            a = (x - xs[k - 1]) / (xs[k] - xs[k - 1])
            return ys[k - 1] + a * (ys[k] - ys[k - 1])
    return None


def mean_over(xs, ys, lo, hi):
    """Mean of the rows with lo <= x <= hi (smooths the cell-crossing noise); None if none."""
    picked = [y for x, y in zip(xs, ys) if lo - 1e-12 <= x <= hi + 1e-12]
    return sum(picked) / len(picked) if picked else None


def largest_drift(series):
    """Largest |s_k - s_0| / |s_0| of a series that should stay constant (an energy)."""
    return max(abs(s - series[0]) for s in series) / abs(series[0])


def richardson(values, ratio=2.0):
    """Observed order and extrapolated value h -> 0 of three values on meshes refined by `ratio`
    each time; None, None when the differences do not shrink monotonically."""
    f1, f2, f3 = values
    d1, d2 = f1 - f2, f2 - f3
    if d1 == 0 or d2 == 0 or d1 * d2 < 0 or abs(d2) >= abs(d1):
        return None, None
    order = math.log(d1 / d2) / math.log(ratio)
    return order, f3 - d2 / (ratio ** order - 1)


def verdict(value, tolerance, reference):
    """'pass' when value lies within the tolerance: {"band": [lo, hi]} absolute, or
    {"relative": r} about the reference, or {"max": m}; 'not reached' otherwise or without a value."""
    if value is None:
        return "not reached"
    if "band" in tolerance:
        lo, hi = tolerance["band"]
        ok = lo <= value <= hi
    elif "relative" in tolerance:
        ok = abs(value - reference) <= tolerance["relative"] * abs(reference)
    else:
        ok = value <= tolerance["max"]
    return "pass" if ok else "not reached"


def evaluate(metric, history):
    """The number a case's `metric` asks for, from a history (the columns scaled as asked)."""
    kind = metric["kind"]
    x = [metric.get("x_scale", 1.0) * v for v in history.get(metric.get("x", "time"), [])]
    if kind == "drift":
        total = [sum(vals) for vals in zip(*(history[c] for c in metric["columns"]))]
        return largest_drift(total)
    y = [metric.get("y_scale", 1.0) * v for v in history[metric["y"]]]
    if kind == "value_at":
        return value_at(x, y, metric["at"])
    if kind == "mean_over":
        return mean_over(x, y, *metric["over"])
    raise ValueError(f"unknown metric kind {kind!r}")
