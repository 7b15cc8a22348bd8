#!/usr/bin/python3
"""Tests of the harness's pure functions (error_curves.py), on curves whose
answers follow from the log-log interpolation by hand. Run by ctest."""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import error_curves as ec  # noqa: E402

# relMSE = 1 / time exactly (the Monte Carlo rate): a straight line in log-log.
MC = [(1.0, 1.0), (2.0, 0.5), (4.0, 0.25), (8.0, 0.125)]
# Twice as efficient: the same error in half the time.
FAST = [(0.5, 1.0), (1.0, 0.5), (2.0, 0.25), (4.0, 0.125)]


class ErrorCurves(unittest.TestCase):
    def test_parse_integrator_spec(self):
        self.assertEqual(ec.parse_integrator_spec("transient_path:spp=4,1,2"), ("transient_path", "spp", [1, 2, 4]))
        self.assertEqual(ec.parse_integrator_spec("transient_beams:passes=1,2"), ("transient_beams", "passes", [1, 2]))
        for bad in ["transient_path", "transient_path:spp", "x:spp=0,1", "x:spp=a"]:
            with self.assertRaises(ec.SpecError):
                ec.parse_integrator_spec(bad)

    def test_parse_define(self):
        self.assertEqual(ec.parse_define("bins=256"), ("bins", "256"))
        with self.assertRaises(ec.SpecError):
            ec.parse_define("bins")

    def test_error_at_time_interpolates_in_log_log(self):
        self.assertAlmostEqual(ec.error_at_time(MC, 3.0), 1.0 / 3.0)  # on the 1/t line between 2 and 4
        self.assertAlmostEqual(ec.error_at_time(MC, 8.0), 0.125)
        self.assertIsNone(ec.error_at_time(MC, 0.5))
        self.assertIsNone(ec.error_at_time(MC, 9.0))

    def test_time_to_reach(self):
        self.assertAlmostEqual(ec.time_to_reach(MC, 0.2), 5.0)
        self.assertAlmostEqual(ec.time_to_reach(FAST, 0.2), 2.5)
        self.assertEqual(ec.time_to_reach(MC, 2.0), 1.0)  # reached at the first budget
        self.assertIsNone(ec.time_to_reach(MC, 0.01))
        # Points given out of order are sorted by time first.
        self.assertAlmostEqual(ec.time_to_reach([(4.0, 0.25), (1.0, 1.0), (2.0, 0.5)], 0.5), 2.0)

    def test_equal_time_ratio_and_common_range(self):
        curves = {"mc": MC, "fast": FAST}
        self.assertEqual(ec.common_time(curves), 4.0)
        self.assertAlmostEqual(ec.common_target(curves), 0.125)
        ratios = ec.equal_time_ratios(curves, "mc", 3.0)
        self.assertAlmostEqual(ratios["mc"], 1.0)
        self.assertAlmostEqual(ratios["fast"], 0.5)
        self.assertIsNone(ec.common_time({"a": [(1.0, 1.0), (2.0, 0.5)], "b": [(3.0, 1.0), (4.0, 0.5)]}))
        self.assertIsNone(ec.common_time_range({"a": [(1.0, 1.0), (2.0, 0.5)], "b": [(3.0, 1.0), (4.0, 0.5)]}))
        self.assertEqual(ec.common_time_range({"a": [(1.0, 1.0), (5.0, 0.5)], "b": [(2.0, 1.0), (4.0, 0.5)]}), (2.0, 4.0))

    def test_convergence_slope(self):
        self.assertAlmostEqual(ec.convergence_slope(MC), -1.0)
        self.assertAlmostEqual(ec.convergence_slope([(1.0, 1.0), (4.0, 0.5)]), -0.5)
        self.assertIsNone(ec.convergence_slope([(1.0, 1.0)]))
        self.assertTrue(math.isfinite(ec.convergence_slope(FAST)))


if __name__ == "__main__":
    unittest.main()
