#!/usr/bin/python3
"""Tests of figure 1's helpers: the equal-time spp guess (equal_time.py), the
handling of a render's files, and side_by_side_volume.py. Run by ctest."""
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import equal_time  # noqa: E402
import side_by_side_volume as sbs  # noqa: E402


class NextSpp(unittest.TestCase):
    def test_one_point_scales_through_the_origin(self):
        self.assertEqual(equal_time.next_spp([(16, 2.0)], 10.0), 80)

    def test_two_points_find_a_linear_cost_exactly(self):
        # time = 3 + 0.05 spp: 10 s at 140 spp, whatever the two points measured.
        cost = lambda spp: 3 + 0.05 * spp  # noqa: E731
        self.assertEqual(equal_time.next_spp([(16, cost(16)), (400, cost(400))], 10.0), 140)
        self.assertEqual(equal_time.next_spp([(500, cost(500)), (16, cost(16))], 10.0), 140)

    def test_never_below_one_and_no_division_by_a_flat_line(self):
        self.assertEqual(equal_time.next_spp([(16, 5.0)], 0.01), 1)
        # Same time at two budgets (load noise): scale the last point instead.
        self.assertEqual(equal_time.next_spp([(16, 2.0), (32, 2.0)], 4.0), 64)


class Outputs(unittest.TestCase):
    def test_rename_and_remove_take_every_file_of_a_render_and_no_other(self):
        with tempfile.TemporaryDirectory() as d:
            names = ["a.npy", "a.json", "a.exr", "a_before.exr", "a_after.exr", "ab.npy", "b.npy"]
            for n in names:
                open(os.path.join(d, n), "w").close()
            new = equal_time.rename_outputs(os.path.join(d, "a.npy"), os.path.join(d, "c"))
            self.assertEqual(new, os.path.join(d, "c.npy"))
            self.assertEqual(sorted(os.listdir(d)),
                             ["ab.npy", "b.npy", "c.exr", "c.json", "c.npy", "c_after.exr", "c_before.exr"])
            equal_time.remove_outputs(os.path.join(d, "c.npy"))
            self.assertEqual(sorted(os.listdir(d)), ["ab.npy", "b.npy"])


class SideBySide(unittest.TestCase):
    def test_layout_and_merged_bins(self):
        rng = np.random.default_rng(1)
        a = rng.random((3, 4, 8, 3), dtype=np.float32)
        b = rng.random((3, 2, 8, 3), dtype=np.float32)
        row = sbs.side_by_side([a, b], merge=4, gutter=1)
        self.assertEqual(row.shape, (3, 4 + 1 + 2, 2, 3))
        np.testing.assert_allclose(row[:, :4, 1], a[:, :, 4:8].mean(axis=2), rtol=1e-6)
        np.testing.assert_allclose(row[:, 5:, 0], b[:, :, 0:4].mean(axis=2), rtol=1e-6)
        self.assertFalse(row[:, 4].any())

    def test_refuses_mismatched_volumes(self):
        with self.assertRaises(ValueError):
            sbs.side_by_side([np.zeros((3, 4, 8, 3)), np.zeros((3, 4, 6, 3))])
        with self.assertRaises(ValueError):
            sbs.side_by_side([np.zeros((3, 4, 6, 3))], merge=4)

    def test_unit_exposure_puts_the_percentile_at_one(self):
        rng = np.random.default_rng(3)
        v = np.zeros((4, 5, 10, 3), dtype=np.float32)
        v[:2] = rng.random((2, 5, 10, 3), dtype=np.float32) * 50.0  # half the volume black
        scaled = sbs.unit_exposure(v)
        lum = scaled @ np.array([0.2126, 0.7152, 0.0722], dtype=np.float32)
        self.assertAlmostEqual(float(np.percentile(lum[lum > 0], 99.5)), 1.0, places=5)
        np.testing.assert_array_equal(sbs.unit_exposure(np.zeros((2, 2, 2, 3), np.float32)), 0.0)

    def test_sidecar_only_for_one_shared_window(self):
        import json
        with tempfile.TemporaryDirectory() as d:
            paths = [os.path.join(d, f"v{i}.npy") for i in range(2)]
            for i, p in enumerate(paths):
                with open(p[:-4] + ".json", "w") as f:
                    json.dump({"start_opl": 3.0, "bin_width_opl": 0.25}, f)
            row = np.zeros((4, 11, 6, 3), np.float32)
            info = sbs.sidecar(paths, row, 2)
            self.assertEqual((info["width"], info["height"], info["bins"]), (11, 4, 6))
            self.assertEqual((info["start_opl"], info["bin_width_opl"], info["end_opl"]), (3.0, 0.5, 6.0))
            with open(paths[1][:-4] + ".json", "w") as f:
                json.dump({"start_opl": 0.0, "bin_width_opl": 0.25}, f)
            self.assertIsNone(sbs.sidecar(paths, row, 2))  # different windows: no time stamps


if __name__ == "__main__":
    unittest.main()
