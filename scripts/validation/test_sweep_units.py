"""Units must not matter (issue 45): the robustness sweep's strip and circular footings written
in kN and m and in N and mm give the same q/s_u against s/B at every step. Run by ctest as
validation.sweep_units (label validation_long) with GEOMPM_BINARY set to the geompm executable."""
import os
import tempfile
import unittest

import sweep


def curve(case, millimetres, work):
    args = type("Args", (), {"newton": "", "numerics": "", "binary": os.environ["GEOMPM_BINARY"],
                             "units": "N-mm" if millimetres else "kN-m"})
    _, returncode, rows = sweep.run(case, args, work)
    B, _ = sweep.width_and_strength(case, millimetres)
    return returncode, [(-float(r["settlement"]) / B,
                         sweep.q_over_su(case, float(r["force"]), millimetres)) for r in rows]


def mean_load(curve, s0, s1):
    """The load averaged over the settlement from s0 to s1 (trapezoids of the piecewise linear
    curve)."""
    area = 0.0
    for (sa, qa), (sb, qb) in zip(curve, curve[1:]):
        lo, hi = max(sa, s0), min(sb, s1)
        if hi > lo and sb > sa:
            q_lo = qa + (qb - qa) * (lo - sa) / (sb - sa)
            q_hi = qa + (qb - qa) * (hi - sa) / (sb - sa)
            area += 0.5 * (q_lo + q_hi) * (hi - lo)
    return area / (s1 - s0)


class UnitsDoNotMatter(unittest.TestCase):
    def check(self, shape, base):
        case = {"shape": shape, "B": "2.5", "su": "25", "E_over_su": "300", "nu": "0.49",
                "base": base}
        with tempfile.TemporaryDirectory() as metres, tempfile.TemporaryDirectory() as mm:
            _, in_metres = curve(case, False, metres)
            _, in_mm = curve(case, True, mm)
        self.assertGreater(min(len(in_metres), len(in_mm)), 5)
        largest = max(abs(q) for _, q in in_metres)
        self.assertGreater(largest, 1.0)  # the footing carries load
        # The same steps give the same iterates to round-off (Newton's tolerances are relative),
        # well inside 1e-6, until the two runs take different steps: the adaptive step follows
        # Newton's iteration count, and round-off, which differs between the unit systems, can
        # tip a step's count by one at its tolerance (measured: the rough strip's 33rd step, at
        # 0.067 B, took 5 iterations in kN-m, 4 in N-mm). The steps must agree to 0.05 B at least.
        same = 0
        for (s1, q1), (s2, q2) in zip(in_metres, in_mm):
            if abs(s1 - s2) > 1e-9:
                break
            self.assertAlmostEqual(q1, q2, delta=1e-6 * largest)
            same = s1
        self.assertGreater(same, 0.05, "the unit systems part before 0.05 B")
        # Beyond, the two paths are the same curve to the path sensitivity of a plastic run whose
        # points cross cells: single steps there differ by up to 3.5 % (measured: the kN-m rough
        # strip fails at the smallest step at 0.082 B, and the step that backtracking then carries
        # dips 6 % for 0.001 B, a cell crossing the N-mm run passes at 0.0845 B with a 2 % dip),
        # so the curves are compared as the load averaged over the settlement in windows of
        # 0.02 B, over the windows both runs reach: measured within 0.7 %.
        reached = min(in_metres[-1][0], in_mm[-1][0])
        start = 0.02 * int(same / 0.02)
        windows = [(start + 0.02 * k, start + 0.02 * (k + 1)) for k in range(5)]
        for s0, s1 in [w for w in windows if w[1] <= reached + 1e-9]:
            self.assertAlmostEqual(mean_load(in_mm, s0, s1), mean_load(in_metres, s0, s1),
                                   delta=0.02 * largest, msg=f"over s/B = {s0:.2f}-{s1:.2f}")

    def test_rough_strip(self):
        self.check("strip", "rough")

    def test_smooth_circle(self):
        self.check("circle", "smooth")


if __name__ == "__main__":
    unittest.main()
