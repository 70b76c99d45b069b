#!/usr/bin/env python3
"""The table of performance note 12 (docs/performance.md): the time of one Mohr-Coulomb stress
update, the cone's exact return against the rounded surface's Newton return, from the medians of
bench_material_return's JSON output (bench/run_benchmarks.sh runs both).

    bench/material_return_table.py bench/results/bench_material_return.json \
        bench/material_return_timings.md
"""
import json
import sys

from make_performance_doc import to_ms
WHERE = {"along": "along the cone (p = −100 kPa, deviators up to 80 kPa)",
         "apex": "around the apex (p = +20 kPa, the apex at 17.3 kPa)"}


def medians(path):
    """{case name: (µs per update, coefficient of variation)} from the aggregates."""
    with open(path) as f:
        data = json.load(f)
    out, cv = {}, {}
    for b in data["benchmarks"]:
        name = b["run_name"].split("/")[-1]
        if b.get("aggregate_name") == "median" or (b["run_type"] == "iteration" and name not in out):
            out[name] = to_us(b) / b["states"]
        elif b.get("aggregate_name") == "cv":
            cv[name] = b["real_time"]
    return {k: (v, cv.get(k)) for k, v in out.items()}


def to_us(b):
    return 1e3 * to_ms(b["real_time"], b["time_unit"])


def main(source, target):
    m = medians(source)
    lines = ["# One Mohr–Coulomb stress update (bench_material_return)", "",
             "| trial states | cone (exact return) | rounded (Newton, a = 2 kPa) | rounded / cone |",
             "|---|---|---|---|"]
    for where, text in WHERE.items():
        cone, rounded = m.get(f"cone_{where}"), m.get(f"rounded_{where}")
        if not cone or not rounded:
            raise SystemExit(f"{source}: no median for cone_{where} or rounded_{where}")
        lines.append(f"| {text} | {cone[0]:.2f} µs | {rounded[0]:.2f} µs | × {rounded[0] / cone[0]:.1f} |")
    cvs = [v for _, v in m.values() if v is not None]
    spread = max(cvs) if cvs else None
    lines.append("")
    lines.append("Medians over the repetitions of 4096 updates each"
                 + (f"; largest coefficient of variation {100 * spread:.1f} %." if spread is not None
                    else "."))
    with open(target, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    main(sys.argv[1], sys.argv[2])
