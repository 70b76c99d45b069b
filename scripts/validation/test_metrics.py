"""Tests of the validation metrics and of the case files (run by ctest as validation.metrics)."""
import json
import math
import os
import re
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
        # A driven steel block ends at 0.09999999987 B, not 0.1 B: that is 0.1 B.
        self.assertAlmostEqual(metrics.value_at([0.0, 0.09999999987], [0.0, 5.0], 0.1), 5.0, 6)
        self.assertIsNone(metrics.value_at([0.0, 0.0999], [0.0, 5.0], 0.1))

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

    def test_period_from_zero_crossings(self):
        ts = [0.01 * k for k in range(1001)]
        vs = [math.sin(2 * math.pi * t / 2.5 + 0.3) for t in ts]
        self.assertAlmostEqual(metrics.period(ts, vs), 2.5, places=4)
        self.assertIsNone(metrics.period([0, 1, 2], [1.0, 2.0, 3.0]))

    def test_relative_rise_over_a_window(self):
        xs, ys = [0.0, 1.0, 2.0], [10.0, 10.0, 10.5]
        self.assertAlmostEqual(metrics.relative_rise(xs, ys, 1.0, 2.0), 0.05)
        self.assertIsNone(metrics.relative_rise(xs, ys, 1.0, 3.0))

    def test_largest_change_between_pairs_and_none_if_a_run_is_missing(self):
        values = {"a 0.49": 5.0, "a 0.4999": 5.1, "b 0.49": 5.2, "b 0.4999": 5.2}
        pairs = [["a 0.4999", "a 0.49"], ["b 0.4999", "b 0.49"]]
        self.assertAlmostEqual(metrics.largest_change(values, pairs), 0.02)
        self.assertIsNone(metrics.largest_change(dict(values, **{"a 0.49": None}), pairs))

    def test_combine_extrapolates_three_meshes(self):
        case = {"combine": "extrapolate", "order": ["h1", "h2", "h3"]}
        combined = metrics.combine(case, {"h1": 5.8, "h2": 5.4, "h3": 5.2})
        self.assertAlmostEqual(combined["extrapolated"], 5.0)
        self.assertIsNone(metrics.combine(case, {"h1": 5.8, "h2": None, "h3": 5.2})["extrapolated"])

    def test_verdicts(self):
        self.assertEqual(metrics.verdict(6.3, {"above": 0.05}, 6.05), "pass")
        self.assertEqual(metrics.verdict(6.4, {"above": 0.05}, 6.05), "not reached")
        self.assertEqual(metrics.verdict(6.0, {"above": 0.05}, 6.05), "not reached")
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


class Runner(unittest.TestCase):
    def test_overrides_set_yaml_keys_and_lists_by_index(self):
        model = {"materials": {"clay": {"nu": 0.49}}, "phases": [{"newton": {}}]}
        run_cases.set_key(model, "materials.clay.nu", 0.4999)
        run_cases.set_key(model, "phases.0.newton.max_iterations", 20)
        run_cases.set_key(model, "numerics.mixed_volume", "per_point")  # a block not there
        self.assertEqual(model["materials"]["clay"]["nu"], 0.4999)
        self.assertEqual(model["phases"][0]["newton"]["max_iterations"], 20)
        self.assertEqual(model["numerics"], {"mixed_volume": "per_point"})

    def test_verdict_and_result_of_a_case_with_two_references(self):
        case = {"reference": {"value": {"smooth": 5.69, "rough": 6.05}}, "tolerance": {"above": 0.05},
                "format": "{:.2f}"}
        values = {"smooth": 6.01, "rough": 6.25}
        self.assertEqual(run_cases.case_verdict(case, values), "smooth not reached, rough pass")
        self.assertEqual(run_cases.shown(case, values), "smooth 6.01 (+5.6 %); rough 6.25 (+3.3 %)")
        self.assertEqual(run_cases.case_verdict(case, {"smooth": 5.8, "rough": 6.1}), "pass")
        self.assertEqual(run_cases.shown(case, {"smooth": None, "rough": 6.1}), "stopped early: smooth")


class Cases(unittest.TestCase):
    KEYS = ("section", "title", "reference", "tolerance_text", "tests", "last_result")

    def test_every_case_is_complete_and_its_overrides_apply(self):
        cases = run_cases.load_cases()
        self.assertGreater(len(cases), 30)
        for case in cases:
            for key in self.KEYS:
                self.assertIn(key, case, case["name"])
            self.assertIn("source", case["reference"], case["name"])
            last = case["last_result"]
            self.assertIn("date", last, case["name"])
            # A number is judged by the runner; only a text result carries its own verdict.
            self.assertEqual("text" in last, "verdict" in last, case["name"])
            if "values" in last:
                self.assertIn("tolerance", case, case["name"])
                run_cases.case_verdict(case, last["values"])
            for run in case.get("runs", {}).values():
                run_cases.model_text(run)  # raises if the model or an override does not apply

    def test_every_verdict_names_tests_that_exist(self):
        root = run_cases.ROOT
        for case in run_cases.load_cases():
            self.assertTrue(case["tests"], case["name"])
            for test in case["tests"]:
                path, name = test.split(": ")
                suite, test_name = name.split(".")
                with open(os.path.join(root, path)) as f:
                    text = f.read()
                if path.endswith(".py"):  # a unittest class and its method
                    pattern = r"class " + suite + r"\b[\s\S]*def " + test_name + r"\b"
                else:
                    pattern = r"TEST(_P|_F)?\(\s*" + suite + r",\s*" + test_name + r"\)"
                self.assertRegex(text, pattern, f"{case['name']}: {test}")

    def test_the_summary_table_is_the_cases(self):
        with open(run_cases.DOC) as f:
            doc = f.read()
        self.assertTrue(run_cases.table(run_cases.load_cases()) in doc,
                        "docs/validation.md's summary table is not the case files': regenerate it "
                        "with scripts/validation/run_cases.py --table-only")


if __name__ == "__main__":
    unittest.main()
