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

    def test_efficiency_ratio_interpolates_where_curves_overlap(self):
        # FAST reaches MC's error in half the time: 2x as efficient at every shared time.
        for t in (1.0, 1.5, 3.0, 4.0):
            ratio, extrapolated = ec.efficiency_ratio(MC, FAST, t)
            self.assertAlmostEqual(ratio, 2.0)
            self.assertFalse(extrapolated)
        # Budgets that differ per curve: error = 3 / t^2 measured at 1 and 3, error = 1 / t at 2 and 4;
        # at t = 2 the first interpolates to 3/4 exactly on its log-log line, the second is measured: 0.75 / 0.5.
        steep, mc = [(1.0, 3.0), (3.0, 1.0 / 3.0)], [(2.0, 0.5), (4.0, 0.25)]
        ratio, extrapolated = ec.efficiency_ratio(steep, mc, 2.0)
        self.assertAlmostEqual(ratio, 1.5)
        self.assertFalse(extrapolated)

    def test_efficiency_ratio_extrapolates_with_slope_minus_one(self):
        # Disjoint CPU ranges (what printed "no shared range"): a = 1/t on [1, 2],
        # b = 0.25/t on [4, 8]; at t = 2, b extrapolates to 0.0625 * 4 / 2 = 0.125: ratio 4, flagged.
        a, b = [(1.0, 1.0), (2.0, 0.5)], [(4.0, 0.0625), (8.0, 0.03125)]
        ratio, extrapolated = ec.efficiency_ratio(a, b, 2.0)
        self.assertAlmostEqual(ratio, 4.0)
        self.assertTrue(extrapolated)
        # Beyond both: each from its own last point, still 4 for two slope -1 curves.
        ratio, extrapolated = ec.efficiency_ratio(a, b, 100.0)
        self.assertAlmostEqual(ratio, 4.0)
        self.assertTrue(extrapolated)
        # Below the first point: a curve of slope -2 extrapolated with -1 from its first point.
        value, extrapolated = ec.error_at([(2.0, 0.25), (4.0, 0.0625)], 1.0)
        self.assertAlmostEqual(value, 0.5)
        self.assertTrue(extrapolated)
        self.assertEqual(ec.efficiency_ratio([], b, 1.0), (None, False))
        # Within the slack (a render that stopped just short of its budget): the same value, not flagged.
        self.assertEqual(ec.error_at(a, 2.05, slack=1.05), (0.5 * 2.0 / 2.05, False))
        self.assertTrue(ec.error_at(a, 2.2, slack=1.05)[1])

    def test_shared_error_target(self):
        # Errors [0.125, 1] and [0.0625, 0.5] overlap on [0.125, 0.5]: the geometric middle 0.25,
        # which both curves reach inside their measured range (no "<=" bounds).
        curves = {"mc": MC, "b": [(4.0, 0.5), (8.0, 0.0625)]}
        self.assertAlmostEqual(ec.shared_error_target(curves), 0.25)
        self.assertAlmostEqual(ec.time_to_reach(MC, 0.25), 4.0)
        self.assertIsNone(ec.shared_error_target({"a": [(1.0, 1.0), (2.0, 0.5)], "b": [(1.0, 0.1), (2.0, 0.05)]}))

    def test_split_bins_by_share(self):
        # Half the light in the first two bins: early = bins 0:2, late = 2:6.
        self.assertEqual(ec.split_bins_by_share([1, 1, 0.5, 0.5, 0.5, 0.5], 2), [(0, 2), (2, 6)])
        self.assertEqual(ec.split_bins_by_share([1, 1, 1, 1], 4), [(0, 1), (1, 2), (2, 3), (3, 4)])
        # All the light in bin 0: the bands still hold one bin or more each, in order.
        self.assertEqual(ec.split_bins_by_share([1, 0, 0, 0], 3), [(0, 1), (1, 2), (2, 4)])
        with self.assertRaises(ec.SpecError):
            ec.split_bins_by_share([1], 2)

    def test_convergence_slope(self):
        self.assertAlmostEqual(ec.convergence_slope(MC), -1.0)
        self.assertAlmostEqual(ec.convergence_slope([(1.0, 1.0), (4.0, 0.5)]), -0.5)
        self.assertIsNone(ec.convergence_slope([(1.0, 1.0)]))
        self.assertTrue(math.isfinite(ec.convergence_slope(FAST)))


if __name__ == "__main__":
    unittest.main()
