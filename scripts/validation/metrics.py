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
    """y at x, linear between the rows; None if the run did not get to x (xs ascending). A run
    that ends a hair short of x (a driven body's own elastic shortening, 1e-9 of it) gets there."""
    for k in range(1, len(xs)):
        if xs[k] >= x - 1e-6 * max(1.0, abs(x)):
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


def period(ts, vs):
    """Period of an oscillation from the zero crossings of v(t) (linear between the rows): twice
    the mean time between crossings; None with fewer than three crossings."""
    crossings = [ts[k - 1] + (ts[k] - ts[k - 1]) * vs[k - 1] / (vs[k - 1] - vs[k])
                 for k in range(1, len(ts)) if vs[k - 1] * vs[k] < 0]
    if len(crossings) < 3:
        return None
    return 2 * (crossings[-1] - crossings[0]) / (len(crossings) - 1)


def relative_rise(xs, ys, lo, hi):
    """(y(hi) - y(lo)) / |y(lo)|: how much a load still rises over a window (a limit load: ~0)."""
    a, b = value_at(xs, ys, lo), value_at(xs, ys, hi)
    return None if a is None or b is None else (b - a) / abs(a)


def largest_change(values, pairs):
    """Largest |a - b| / |b| over pairs of named values (e.g. the same run at two nu)."""
    changes = [abs(values[a] - values[b]) / abs(values[b]) for a, b in pairs
               if values.get(a) is not None and values.get(b) is not None]
    return max(changes) if len(changes) == len(pairs) else None


def verdict(value, tolerance, reference):
    """'pass' when value lies within the tolerance: {"band": [lo, hi]} absolute, or
    {"relative": r} about the reference, {"above": r} from the reference to (1 + r) times it, or
    {"max": m}; 'not reached' otherwise or without a value."""
    if value is None:
        return "not reached"
    if "band" in tolerance:
        lo, hi = tolerance["band"]
        ok = lo <= value <= hi
    elif "relative" in tolerance:
        ok = abs(value - reference) <= tolerance["relative"] * abs(reference)
    elif "above" in tolerance:
        ok = reference <= value <= (1 + tolerance["above"]) * reference
    else:
        ok = value <= tolerance["max"]
    return "pass" if ok else "not reached"


def combine(case, values):
    """The case's numbers from its runs' values: {"run": value} each on its own (the default), or
    one number: the largest change over `pairs`, or the extrapolation of three runs (`order`)."""
    how = case.get("combine", "each")
    if how == "each":
        return values
    if how == "largest_change":
        return {"largest change": largest_change(values, case["pairs"])}
    if how == "extrapolate":
        ordered = [values.get(name) for name in case["order"]]
        if None in ordered:
            return {"extrapolated": None}
        return {"extrapolated": richardson(ordered, case.get("ratio", 2.0))[1]}
    raise ValueError(f"unknown combine {how!r}")


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
    if kind == "rise":
        return relative_rise(x, y, *metric["over"])
    if kind == "period":
        return period(x, y)
    if kind == "last":
        return y[-1] if y else None
    raise ValueError(f"unknown metric kind {kind!r}")
