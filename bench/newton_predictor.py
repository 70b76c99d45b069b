#!/usr/bin/env python3
"""Newton's first iterate: zero, zero with the plastic side's tangent at points on the yield
surface (`surface_tangent: plastic`, docs/materials.md §1.7), and extrapolated (`newton:
{predictor: extrapolated}`, docs/theory.md §4.5), on example models run to their end with
`geompm run -t 1`.

    /usr/bin/python3 bench/newton_predictor.py [--build-dir build] [--repetitions 3] [--only TEXT]

Each model is run from a zero start with the elastic side's tangent (the code's defaults; an
example's own `predictor` or `surface_tangent` setting is removed), with the plastic side's, and
extrapolated. Writes bench/predictor_timings.md (steps, Newton iterations, the most in a step, the median wall
time over the repetitions, and the largest difference of the model's load history between the two
starts); docs/performance.md carries it (bench/performance_notes.md marks where). With --only,
just the models whose example path contains TEXT are run, and their rows replaced in the table.
"""
import os
import re
import sys
import tempfile

from whole_runs import ROOT, arguments, history_cell, history_difference, machine, repeated, write_table

# Models derived from the examples as docs/validation.md derives them: `stiff_strip:n` is the c-phi
# strip's rigid-plastic limit of §8 (E = 5e4 c, pushed 0.002 B) on n cells under the half-width.
STIFF = "stiff_strip:"
# `tresca_stiff:kind:n`: the Tresca strip footing `kind` (rough: steel block, smooth, rigid: rough
# rigid footing) in the rigid-plastic limit of §5 (E = 1e4 s_u, pushed 0.005 B), from a zero start.
TRESCA_STIFF = "tresca_stiff:"

# (label, example, load column): plastic runs with a mechanism that carries over from step to step.
MODELS = [
    ("N_q strip, Mohr–Coulomb, displacement formulation", "frictional_footing/frictional_footing_nq.yaml", "force"),
    ("N_γ rough strip, Mohr–Coulomb, displacement formulation", "frictional_footing/frictional_footing_ngamma.yaml", "force"),
    ("N_γ smooth strip, Mohr–Coulomb, displacement formulation", "frictional_footing/frictional_footing_ngamma_smooth.yaml", "force"),
    ("c–φ strip, Mohr–Coulomb, displacement formulation", "mohr_coulomb_footing/mohr_coulomb_footing.yaml", "force"),
    ("c–φ strip, rigid-plastic limit of validation §8, h = B/20", STIFF + "10", "force"),
    ("c–φ strip, rigid-plastic limit of validation §8, h = B/40", STIFF + "20", "force"),
    ("thick cylinder, Tresca, mixed p–u", "thick_cylinder/thick_cylinder.yaml", "force"),
    ("strip, steel block, Tresca, mixed p–u, rigid-plastic limit of validation §5, h = B/40", TRESCA_STIFF + "rough:20", "force"),
    ("strip, smooth rigid footing, Tresca, mixed p–u, rigid-plastic limit of validation §5, h = B/40", TRESCA_STIFF + "smooth:20", "force"),
    ("strip, rough rigid footing, Tresca, mixed p–u, rigid-plastic limit of validation §5, h = B/40", TRESCA_STIFF + "rigid:20", "force"),
    ("strip, steel block, Tresca, mixed p–u", "strip_footing/strip_footing.yaml", "force"),
    ("strip, smooth rigid footing, Tresca, mixed p–u", "strip_footing/strip_footing_smooth.yaml", "force"),
    ("strip, rough rigid footing, Tresca, mixed p–u", "strip_footing/strip_footing_rigid_rough.yaml", "force"),
    ("circular, rough rigid footing, Tresca, mixed p–u", "circular_footing/circular_footing_rigid_rough.yaml", "force"),
]

# The soil models whose update `surface_tangent` steers.
PLASTIC_SIDE = re.compile(r"(model: (?:mohr_coulomb|tresca),)")


def model_text(example):
    if example.startswith((STIFF, TRESCA_STIFF)):
        if os.path.join(ROOT, "scripts") not in sys.path:
            sys.path.insert(0, os.path.join(ROOT, "scripts"))
        import validation_report as report
    if example.startswith(TRESCA_STIFF):
        kind, n = example[len(TRESCA_STIFF):].split(":")
        text = report.tresca_limit_text(report.STRIP_FILE[kind], int(n), start="zero")
    elif example.startswith(STIFF):
        text = report.mc_limit_text(report.example("mohr_coulomb_footing/mohr_coulomb_footing.yaml"),
                                    int(example[len(STIFF):]))
    else:
        with open(os.path.join(ROOT, "examples", example)) as f:
            text = f.read()
    return re.sub(r"vtk: \{every: \d+\}", "vtk: {every: 0}", text)


def main():
    args = arguments(__doc__, "run only the models whose example path contains this (repeatable)")
    binary = os.path.join(ROOT, args.build_dir, "geompm")
    rows = {}
    with tempfile.TemporaryDirectory() as work:
        for label, example, column in MODELS:
            if args.only and not any(part in example for part in args.only):
                continue
            text = model_text(example)
            # The zero start with the elastic side's tangent on the surface (the code's defaults):
            # an example that sets either of the other two has it removed here.
            zero = re.sub(r",\s*surface_tangent: plastic", "", text.replace("predictor: extrapolated, ", ""))
            variants = {"zero": zero,
                        "plastic": PLASTIC_SIDE.sub(r"\1 surface_tangent: plastic,", zero),
                        "extrapolated": zero.replace("newton: {", "newton: {predictor: extrapolated, ")}
            result = {name: repeated(binary, model, work, name, args.repetitions)
                      for name, model in variants.items()}
            differences = {name: history_difference(result["zero"], r, column)
                           for name, r in result.items()}
            print(label, {k: (v[0][0], v[1]) for k, v in result.items()}, differences, flush=True)
            rows[example] = (f"| {label} (`{example}`) | {cells(result['zero'])} | "
                             f"{cells(result['plastic'])} | {history_cell(differences['plastic'])} | "
                             f"{cells(result['extrapolated'])} | "
                             f"{history_cell(differences['extrapolated'])} |")
    lines = ["# Newton's first iterate: zero, zero with the plastic side's tangent on the surface, "
             "and extrapolated", "",
             f"Generated by `bench/newton_predictor.py` ({machine(args.repetitions)}). Each model "
             "as it is (a zero start), with `surface_tangent: plastic` added to "
             "its soil (docs/materials.md §1.7), and with `predictor: extrapolated` added to every "
             "phase's `newton` instead. 'Load history' is the largest difference of the load column "
             "from the zero start's over the run, relative to its largest value, where both runs "
             "took the same steps. Each cell: steps / Newton iterations / the most in a step / "
             "cut-backs / median wall time.", "",
             "| model | zero start | plastic side on the surface | load history | extrapolated | "
             "load history |",
             "|---|---|---|---|---|---|"]
    write_table("predictor_timings.md", lines, rows, args.only)


def cells(entry):
    (s, _, failure, _), w = entry
    if s is None:
        return f"stopped {failure}"
    return f"{s[0]} / {s[1]} / **{s[2]}** / {s[3]} / {w:.1f} s"


if __name__ == "__main__":
    main()
