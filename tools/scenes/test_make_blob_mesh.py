#!/usr/bin/python3
"""Tests of make_blob_mesh.py, the fallback mesh of scenes/seed-glass-armadillo:
the mesh must be a closed, consistently oriented, outward-facing surface (glass
refracts correctly only through such a mesh) in the Armadillo's frame, with
unit vertex normals. Run by ctest."""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))


def read_obj(path):
    v, vn, f = [], [], []
    with open(path) as obj:
        for line in obj:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                v.append([float(x) for x in parts[1:4]])
            elif parts[0] == "vn":
                vn.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                f.append([int(p.split("/")[0]) - 1 for p in parts[1:]])
    return np.array(v), np.array(vn), np.array(f)


class BlobMesh(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.TemporaryDirectory()
        cls.path = os.path.join(cls.dir.name, "blob.obj")
        subprocess.run([sys.executable, os.path.join(HERE, "make_blob_mesh.py"), cls.path, "--level", "3"],
                       check=True, capture_output=True)
        cls.v, cls.vn, cls.f = read_obj(cls.path)

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    def test_triangle_count(self):
        self.assertEqual(self.f.shape, (20 * 4 ** 3, 3))

    def test_closed_and_consistently_oriented(self):
        # Each directed edge appears once and its reverse once: every edge is
        # shared by exactly two triangles that traverse it in opposite senses.
        directed = {}
        for a, b, c in self.f:
            for e in ((a, b), (b, c), (c, a)):
                directed[e] = directed.get(e, 0) + 1
        self.assertTrue(all(n == 1 for n in directed.values()), "an edge is traversed twice the same way")
        self.assertTrue(all((b, a) in directed for a, b in directed), "an edge borders only one triangle")

    def test_outward_and_star_shaped(self):
        p = self.v[self.f]
        n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
        volume = np.einsum("ij,ij->i", p[:, 0], n).sum() / 6.0
        self.assertGreater(volume, 0.0, "faces wind clockwise seen from outside")
        # Star-shaped (seen from the vertex mean, near the centre the radial
        # construction used, every face faces away), so it does not fold over.
        centre = self.v.mean(axis=0)
        self.assertTrue(np.all(np.einsum("ij,ij->i", p.mean(axis=1) - centre, n) > 0.0))

    def test_armadillo_frame_and_normals(self):
        self.assertAlmostEqual(self.v[:, 1].min(), -54.2, places=3)
        self.assertAlmostEqual(np.ptp(self.v[:, 1]), 151.3, places=3)
        self.assertEqual(len(self.vn), len(self.v))
        np.testing.assert_allclose(np.linalg.norm(self.vn, axis=1), 1.0, atol=1e-4)


if __name__ == "__main__":
    unittest.main()
