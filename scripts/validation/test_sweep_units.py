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


class UnitsDoNotMatter(unittest.TestCase):
    def check(self, shape, base):
        case = {"shape": shape, "B": "2.5", "su": "25", "E_over_su": "300", "nu": "0.49",
                "base": base}
        with tempfile.TemporaryDirectory() as metres, tempfile.TemporaryDirectory() as mm:
            rc_m, in_metres = curve(case, False, metres)
            rc_mm, in_mm = curve(case, True, mm)
        self.assertEqual(rc_m, rc_mm)
        self.assertEqual(len(in_metres), len(in_mm), "a different number of steps")
        self.assertGreater(len(in_metres), 5)
        largest = max(abs(q) for _, q in in_metres)
        self.assertGreater(largest, 1.0)  # the footing carries load
        for (s1, q1), (s2, q2) in zip(in_metres, in_mm):
            self.assertAlmostEqual(s1, s2, delta=1e-9)
            # Newton's tolerances are relative: the same iterates to round-off, well inside 1e-6.
            self.assertAlmostEqual(q1, q2, delta=1e-6 * largest)

    def test_rough_strip(self):
        self.check("strip", "rough")

    def test_smooth_circle(self):
        self.check("circle", "smooth")


if __name__ == "__main__":
    unittest.main()
