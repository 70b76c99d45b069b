"""Tests of the validation metrics and of the case files (run by ctest as validation.metrics)."""
import json
import os
import tempfile
import unittest

import metrics
import run_cases


class Metrics(unittest.TestCase):
    def test_value_at_interpolates_and_says_when_the_run_fell_short(self):
        xs, ys = [0.0, 0.1, 0.2], [0.0, 1.0, 3.0]
        self.assertAlmostEqual(metrics.value_at(xs, ys, 0.15), 2.0)
        self.assertAlmostEqual(metrics.value_at(xs, ys, 0.2), 3.0)
        self.assertIsNone(metrics.value_at(xs, ys, 0.25))

    def test_mean_over_a_window(self):
        xs, ys = [0.0, 0.08, 0.09, 0.1], [9.0, 5.0, 5.2, 5.4]
        self.assertAlmostEqual(metrics.mean_over(xs, ys, 0.08, 0.1), 5.2)
        self.assertIsNone(metrics.mean_over(xs, ys, 0.2, 0.3))

    def test_largest_drift(self):
        self.assertAlmostEqual(metrics.largest_drift([2.0, 2.01, 1.98, 2.0]), 0.01)

    def test_richardson_recovers_a_first_order_sequence(self):
        # f(h) = 5 + 8 h on h = 1/10, 1/20, 1/40.
        order, limit = metrics.richardson([5.8, 5.4, 5.2])
        self.assertAlmostEqual(order, 1.0)
        self.assertAlmostEqual(limit, 5.0)
        self.assertEqual(metrics.richardson([5.0, 5.4, 5.2]), (None, None))

    def test_verdicts(self):
        self.assertEqual(metrics.verdict(5.35, {"band": [5.14, 5.40]}, 5.14), "pass")
        self.assertEqual(metrics.verdict(5.13, {"band": [5.14, 5.40]}, 5.14), "not reached")
        self.assertEqual(metrics.verdict(502.4, {"relative": 0.005}, 501.28), "pass")
        self.assertEqual(metrics.verdict(0.0069, {"max": 0.01}, 0), "pass")
        self.assertEqual(metrics.verdict(None, {"max": 0.01}, 0), "not reached")

    def test_evaluate_reads_a_history(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "history.csv")
            with open(path, "w") as f:
                f.write("time,step,settlement,force\n0,0,0,0\n1,1,-0.05,-2.5\n2,2,-0.1,-2.7\n")
            history = metrics.read_history(path)
        metric = {"kind": "value_at", "x": "settlement", "x_scale": -1, "y": "force",
                  "y_scale": -2, "at": 0.1}
        self.assertAlmostEqual(metrics.evaluate(metric, history), 5.4)


class Cases(unittest.TestCase):
    def test_every_case_is_complete_and_its_overrides_apply(self):
        cases = run_cases.load_cases()
        self.assertGreater(len(cases), 0)
        for case in cases:
            for key in ("title", "model", "metric", "reference", "tolerance", "tolerance_text"):
                self.assertIn(key, case, case["name"])
            self.assertIn("source", case["reference"], case["name"])
            run_cases.model_text(case)  # raises if the model or an override does not apply


if __name__ == "__main__":
    unittest.main()
