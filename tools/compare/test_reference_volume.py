#!/usr/bin/python3
"""Tests of reference_volume.py: the mean of K volumes and the variance of
that mean on synthetic arrays (against numpy computed directly, and against
the known noise the arrays were drawn with), and multi_seed_reference's
caching with a stand-in femto that writes seeded random volumes. Run by ctest."""
import json
import os
import stat
import sys
import tempfile
import textwrap
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import reference_volume as rv  # noqa: E402

EPS = rv.EPSILON


def relmse(test, ref, eps=EPS):
    """femto compare's relMSE (docs/compare.md), in numpy."""
    return float(np.mean((test - ref) ** 2 / (ref * ref + eps)))


class Synthetic(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.rng = np.random.default_rng(12345)

    def tearDown(self):
        self.dir.cleanup()

    def write(self, volumes):
        paths = []
        for i, v in enumerate(volumes):
            paths.append(os.path.join(self.dir.name, f"r{i}.npy"))
            np.save(paths[-1], v.astype(np.float32))
        return paths

    def test_rebin_sums_runs_of_bins(self):
        v = np.arange(2 * 1 * 6 * 3, dtype=np.float64).reshape(2, 1, 6, 3)
        r = rv.rebin(v, 3)
        self.assertEqual(r.shape, (2, 1, 2, 3))
        np.testing.assert_array_equal(r[1, 0, 1], v[1, 0, 3] + v[1, 0, 4] + v[1, 0, 5])
        np.testing.assert_array_equal(rv.rebin(v, 6)[:, :, 0], v.sum(axis=2))
        with self.assertRaises(ValueError):
            rv.rebin(v, 4)

    def test_mean_and_variance_of_mean_equal_numpy_in_chunks(self):
        k, shape = 5, (7, 4, 8, 3)
        vols = [self.rng.gamma(2.0, 0.05, shape).astype(np.float32) for _ in range(k)]
        paths = self.write(vols)
        out = os.path.join(self.dir.name, "mean.npy")
        # A chunk smaller than one row of the K volumes: one row per block, 7 blocks.
        est = rv.mean_and_error(paths, out, factors=(1, 2, 8), chunk_bytes=1)
        stack = np.stack(vols).astype(np.float64)
        mean = stack.mean(axis=0)
        np.testing.assert_allclose(np.load(out), mean, rtol=1e-6)
        self.assertEqual(np.load(out).dtype, np.float32)
        for f in (1, 2, 8):
            s = np.stack([rv.rebin(v, f) for v in stack])
            m = s.mean(axis=0)
            expected = np.mean(s.var(axis=0, ddof=1) / k / (m * m + EPS))
            self.assertAlmostEqual(est[f] / expected, 1.0, places=10, msg=f"factor {f}")
        # The time integral's (factor = bins) is the same sum as femto compare's time_integral.
        integ = stack.sum(axis=3)
        self.assertAlmostEqual(est[8] / np.mean(integ.var(axis=0, ddof=1) / k / (integ.mean(0) ** 2 + EPS)), 1.0,
                               places=10)

    def test_rebin_factor_gives_the_coarse_mean(self):
        vols = [self.rng.random((3, 2, 8, 3)) for _ in range(3)]
        paths = self.write(vols)
        out = os.path.join(self.dir.name, "mean.npy")
        est = rv.mean_and_error(paths, out, factors=(1,), rebin_factor=4)
        coarse = np.stack([rv.rebin(v.astype(np.float32).astype(np.float64), 4) for v in vols])
        np.testing.assert_allclose(np.load(out), coarse.mean(axis=0), rtol=1e-6)
        m = coarse.mean(axis=0)
        self.assertAlmostEqual(est[1] / np.mean(coarse.var(axis=0, ddof=1) / 3 / (m * m + EPS)), 1.0, places=10)

    def test_estimate_predicts_the_reference_share_of_a_measured_relmse(self):
        # Truth T; K renders T + N(0, sigma^2); a test render T + N(0, tau^2)
        # independent of them. The K renders' estimate of the reference's
        # contribution should match the one the known sigma gives and the
        # reference's actual error, and subtracting it from relMSE(test, mean)
        # should leave the test's own error (all with femto compare's
        # denominators ref^2 + eps: replacing them by T^2 + eps is a separate,
        # second-order effect of relMSE itself).
        k, shape = 8, (24, 24, 32, 3)
        truth = self.rng.uniform(0.05, 0.3, shape)
        sigma = 0.02 * self.rng.uniform(0.5, 1.5, shape)
        renders = [truth + sigma * self.rng.standard_normal(shape) for _ in range(k)]
        test = truth + 0.03 * self.rng.standard_normal(shape)
        out = os.path.join(self.dir.name, "mean.npy")
        est = rv.mean_and_error(self.write(renders), out)[1]
        ref = np.load(out).astype(np.float64)
        den = ref * ref + EPS
        known = np.mean(sigma ** 2 / k / den)
        # The estimate averages 55296 sample variances of K-1 = 7 degrees of
        # freedom (relative sd sqrt(2/7) each): its relative sd is ~0.25 %;
        # 2 % is 8 sd. Without the 1/K it would be 8x off, without ddof=1 12 % low.
        self.assertAlmostEqual(est / known, 1.0, delta=0.02)
        # The reference's actual error: relative sd ~sqrt(2/55296) = 0.6 %.
        self.assertAlmostEqual(est / np.mean((ref - truth) ** 2 / den), 1.0, delta=0.04)
        measured, own = relmse(test, ref), float(np.mean((test - truth) ** 2 / den))
        # measured - own = the reference's error (~6 % of measured here) plus a
        # zero-mean cross term 2 (t - T)(T - ref) / den of sd ~2.5 % of est.
        self.assertLess(abs(measured - est - own), 0.1 * est)
        self.assertGreater(measured - own, 0.5 * est)  # the correction is not negligible

    def test_refuses_one_render_and_mismatched_shapes(self):
        p = self.write([np.zeros((2, 2, 4, 3)), np.zeros((2, 2, 8, 3))])
        with self.assertRaises(ValueError):
            rv.mean_and_error(p[:1])
        with self.assertRaises(ValueError):
            rv.mean_and_error(p)
        with self.assertRaises(ValueError):
            rv.mean_and_error([p[0], p[0]], factors=(3,))


# A stand-in for `femto render`: writes a (4, 5, 8, 3) volume drawn from the
# seed, its sidecar, and a line per call to a log (to count renders).
FAKE_FEMTO = textwrap.dedent("""\
    #!/usr/bin/python3
    import json, os, sys
    import numpy as np
    a = sys.argv
    out, seed = a[a.index("-o") + 1], int(a[a.index("--seed") + 1])
    stem = os.path.splitext(out)[0]
    np.save(stem + ".npy", np.random.default_rng(seed).random((4, 5, 8, 3)).astype(np.float32))
    with open(stem + ".json", "w") as f:
        json.dump({"format": "femto transient volume", "version": 1, "width": 5, "height": 4, "bins": 8,
                   "start_opl": 3, "bin_width_opl": 0.5}, f)
    with open(os.environ["FAKE_FEMTO_LOG"], "a") as f:
        f.write(f"{seed}\\n")
    print(f"rendered {out} in 0.250 s (160 samples)")
""")


class MultiSeedReference(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        d = self.dir.name
        self.femto = os.path.join(d, "femto")
        with open(self.femto, "w") as f:
            f.write(FAKE_FEMTO)
        os.chmod(self.femto, os.stat(self.femto).st_mode | stat.S_IXUSR)
        self.scene = os.path.join(d, "scene.xml")
        with open(self.scene, "w") as f:
            f.write("<scene/>")
        self.log_file = os.path.join(d, "renders.log")
        os.environ["FAKE_FEMTO_LOG"] = self.log_file
        self.cache = os.path.join(d, "cache")

    def tearDown(self):
        self.dir.cleanup()

    def renders(self):
        with open(self.log_file) as f:
            return [int(line) for line in f]

    def reference(self, seeds, rebin_factor=1):
        return rv.multi_seed_reference(self.femto, self.scene, [("bins", "8")], "transient_path", "spp", 16,
                                       seeds, 0, self.cache, log=lambda s: None, rebin_factor=rebin_factor)

    def test_renders_each_seed_once_and_averages_them(self):
        path, est = self.reference([11, 12, 13])
        self.assertEqual(sorted(self.renders()), [11, 12, 13])
        vols = np.stack([np.random.default_rng(s).random((4, 5, 8, 3)).astype(np.float32) for s in (11, 12, 13)])
        np.testing.assert_allclose(np.load(path), vols.astype(np.float64).mean(axis=0), rtol=1e-6)
        m = vols.astype(np.float64).mean(axis=0)
        self.assertAlmostEqual(est / np.mean(vols.var(axis=0, ddof=1) / 3 / (m * m + EPS)), 1.0, places=5)
        meta = rv.reference_meta(path)
        self.assertEqual(meta["seeds"], [11, 12, 13])
        self.assertEqual(meta["relmse_estimate"], est)
        self.assertIn("integral_relmse_estimate", meta)
        with open(os.path.join(os.path.dirname(path), "reference.json")) as f:
            self.assertEqual(json.load(f)["bins"], 8)
        # Again: the mean comes from the cache, nothing is rendered.
        self.assertEqual(self.reference([11, 12, 13]), (path, est))
        self.assertEqual(len(self.renders()), 3)
        # One more seed: only that one is rendered, the others are reused.
        path4, _ = self.reference([11, 12, 13, 14])
        self.assertNotEqual(path4, path)
        self.assertEqual(sorted(self.renders()), [11, 12, 13, 14])

    def test_rebinned_reference_has_a_coarser_sidecar(self):
        path, _ = self.reference([21, 22], rebin_factor=4)
        self.assertEqual(np.load(path).shape, (4, 5, 2, 3))
        with open(os.path.join(os.path.dirname(path), "reference.json")) as f:
            info = json.load(f)
        self.assertEqual((info["bins"], info["bin_width_opl"], info["start_opl"]), (2, 2.0, 3))

    def test_needs_two_different_seeds(self):
        for seeds in ([5], [5, 5]):
            with self.assertRaises(ValueError):
                self.reference(seeds)
        self.assertFalse(os.path.exists(self.log_file))


if __name__ == "__main__":
    unittest.main()
