#!/usr/bin/python3
"""Reconstruction of a rendered hidden letter (tools/nlos/hidden_letter.xml):
femto renders a small confocal capture and a single-lit-point capture of a T
0.6 units in front of the wall; every method of reconstruct.py must show the
T and agree on its depth within a voxel (f-k migration: the confocal capture
only; precision 0.98, recall 0.97, and 0.67 / 0.40 with the wall mirrored).

Detection: a pixel of the max-projection (over z, normalised to its peak) is
"object" at half the peak or more (the half-maximum criterion of a point
spread function's width). Precision: the detected pixels must lie within the
method's resolution of the letter, the lateral resolution of confocal NLOS
(O'Toole et al., Nature 2018, eq. 9: dx = c dt sqrt(w^2 + z^2) / (2 w), w the
wall's half width, z the depth, dt the FWHM of the method's temporal kernel)
plus a voxel's half diagonal: at least 90% of them. Recall: at least 70% of
the letter's own pixels are detected. Both methods reach 79-92% on these
captures; reconstructing with the wall mirrored (a planted bug) gives at most
43%, and a wrong time axis loses the depth check.

Usage: test_reconstruct.py FEMTO_EXECUTABLE PLUGIN_DIR
"""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import reconstruct  # noqa: E402

BOX = np.array([-0.4, -0.4, 0.3, 0.4, 0.4, 0.9])
VOXELS = np.array([32, 32, 24])
DEPTH = 0.6
WALL_HALF = 1.0
RES = 24  # wall points a side


def letter_distance(x, y):
    """Distance from (x, y) to the T: bar |x| <= 0.2, |y - 0.2| <= 0.05; stem |x| <= 0.05, |y| <= 0.15."""
    def rect(cx, cy, hx, hy):
        return np.hypot(np.maximum(np.abs(x - cx) - hx, 0.0), np.maximum(np.abs(y - cy) - hy, 0.0))
    return np.minimum(rect(0.0, 0.2, 0.2, 0.05), rect(0.0, 0.0, 0.05, 0.15))


class HiddenLetter(unittest.TestCase):
    femto = plugins = None

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.captures = {}
        for confocal in ("True", "False"):
            out = os.path.join(cls.tmp.name, f"letter_{confocal}.exr")
            subprocess.run([cls.femto, "render", os.path.join(HERE, "hidden_letter.xml"), "--strict", "--no-progress",
                            "-t", "2", "-p", cls.plugins, "-D", f"res={RES}", "-D", "spp=32", "-D",
                            f"confocal={confocal}", "-o", out], check=True, capture_output=True)
            cls.captures[confocal] = reconstruct.load_capture(out[:-4] + ".npy")

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def reconstruct(self, confocal, method):
        capture, start, width = self.captures[confocal]
        points = reconstruct.wall_points(capture.shape[0], capture.shape[1], np.zeros(3), np.full(2, WALL_HALF))
        lit = None if confocal == "True" else np.zeros(3)
        return reconstruct.reconstruct(capture, start, width, points, BOX, VOXELS, lit, method), width, points

    def check_letter(self, confocal):
        depths = {}
        for method in ("fbp", "phasor") + (("fk",) if confocal == "True" else ()):
            with self.subTest(method=method):
                volume, width, points = self.reconstruct(confocal, method)
                voxel = (BOX[3:] - BOX[:3]) / VOXELS
                if method == "fbp":
                    kernel_fwhm = 2.355 * max(voxel)  # the time blur reconstruct.py applies
                elif method == "fk":
                    kernel_fwhm = 2.0 * max(2.0 * WALL_HALF / RES, width)  # the wall's and the bins' sampling
                else:
                    spacing = 2.0 * WALL_HALF / RES
                    kernel_fwhm = 2.0 * max(spacing, 2.0 * width)  # its default wavelength
                resolution = kernel_fwhm * np.hypot(WALL_HALF, DEPTH) / (2.0 * WALL_HALF)
                reach = resolution + 0.5 * np.linalg.norm(voxel[:2])
                xs = BOX[0] + (np.arange(VOXELS[0]) + 0.5) * voxel[0]
                ys = BOX[1] + (np.arange(VOXELS[1]) + 0.5) * voxel[1]
                x, y = np.meshgrid(xs, ys)
                distance = letter_distance(x, y)
                image = volume.max(axis=0)
                detected = image >= 0.5 * image.max()
                precision = (detected & (distance <= reach)).sum() / detected.sum()
                recall = (detected & (distance == 0)).sum() / (distance == 0).sum()
                self.assertGreaterEqual(precision, 0.9, f"{method}: detections off the letter (reach {reach:.3f})")
                self.assertGreaterEqual(recall, 0.7, f"{method}: the letter is not found")
                # The letter's depth: the z of the brightest voxel.
                z = np.unravel_index(volume.argmax(), volume.shape)[0]
                depths[method] = BOX[2] + (z + 0.5) * voxel[2]
                self.assertLessEqual(abs(depths[method] - DEPTH), voxel[2], f"{method}: depth {depths[method]}")
        self.assertLessEqual(abs(depths["fbp"] - depths["phasor"]), (BOX[5] - BOX[2]) / VOXELS[2] + 1e-9)

    def test_command_line_says_what_it_wrote(self):
        prefix = os.path.join(self.tmp.name, "rec")
        capture = os.path.join(self.tmp.name, "letter_True.npy")
        run = subprocess.run([sys.executable, os.path.join(HERE, "reconstruct.py"), capture, "--box=" + ",".join(map(str, BOX)),
                              "--voxels", "8,6,4", "-o", prefix], check=True, capture_output=True, text=True)
        for path in (prefix + ".npy", prefix + ".png"):
            self.assertTrue(os.path.isfile(path), path)
            self.assertIn(path, run.stdout)
        self.assertEqual(np.load(prefix + ".npy").shape, (4, 6, 8))
        self.assertIn("4x6x8", run.stdout)

    def test_the_capture_alone_is_enough(self):
        # The sidecar holds the wall's points, the lit point and whether the
        # legs were kept: no --box, wall or laser options. The default box is
        # the wall's extent, as deep as it is wide; the letter's depth and
        # centre come out within a voxel of the truth for both captures.
        for confocal in ("True", "False"):
            with self.subTest(confocal=confocal):
                prefix = os.path.join(self.tmp.name, f"alone_{confocal}")
                capture = os.path.join(self.tmp.name, f"letter_{confocal}.npy")
                subprocess.run([sys.executable, os.path.join(HERE, "reconstruct.py"), capture, "--method", "phasor",
                                "-o", prefix], check=True, capture_output=True, text=True)
                volume = np.load(prefix + ".npy")
                info = reconstruct.load_capture(capture, with_info=True)[3]
                points, lit, _ = reconstruct.capture_geometry(capture, info)
                self.assertEqual(lit is None, confocal == "True")
                box = reconstruct.default_box(points, np.array(info["nlos_sensor_origin"]))
                voxel = (box[3:] - box[:3]) / np.array(volume.shape[::-1])
                z, y, x = np.unravel_index(volume.argmax(), volume.shape)
                at = box[:3] + (np.array([x, y, z]) + 0.5) * voxel
                self.assertLessEqual(abs(at[2] - DEPTH), voxel[2], f"depth {at[2]}")
                self.assertLessEqual(letter_distance(at[0], at[1]), np.linalg.norm(voxel[:2]), f"at {at}")

    def test_phasor_film_capture_shows_the_letter(self):
        # The same confocal capture into mitransient's phasor film (a band of
        # frequencies around the phasor method's default wavelength, 2 / RES
        # x 2): reconstruct.py reads it directly and finds the T as the
        # time-domain methods do.
        scene = os.path.join(self.tmp.name, "letter_phasor.xml")
        with open(os.path.join(HERE, "hidden_letter.xml")) as f:
            text = f.read()
        start = text.index('<film type="transient_hdr_film">')
        end = text.index("</film>", start) + len("</film>")
        wavelength = 2.0 * 2.0 * WALL_HALF / RES
        film = ('<film type="phasor_hdr_film"><integer name="width" value="$res"/><integer name="height" value="$res"/>'
                '<integer name="temporal_bins" value="$bins"/><float name="bin_width_opl" value="0.005"/>'
                f'<float name="start_opl" value="1.0"/><float name="wl_mean" value="{wavelength}"/>'
                f'<float name="wl_sigma" value="{2 * wavelength}"/><rfilter type="box"/></film>')
        with open(scene, "w") as f:
            f.write(text[:start] + film + text[end:])
        out = os.path.join(self.tmp.name, "phasor.exr")
        subprocess.run([self.femto, "render", scene, "--strict", "--no-progress", "-t", "2", "-p", self.plugins,
                        "-D", f"res={RES}", "-D", "spp=32", "-o", out], check=True, capture_output=True)
        z, frequencies, start_opl, info = reconstruct.load_phasor_capture(out[:-4] + ".npy")
        self.assertGreater(len(frequencies), 2)
        points = reconstruct.wall_points(RES, RES, np.zeros(3), np.full(2, WALL_HALF))
        volume = reconstruct.phasor_from_film(z, frequencies, start_opl, points,
                                              reconstruct.voxel_centers(BOX, VOXELS), None)
        voxel = (BOX[3:] - BOX[:3]) / VOXELS
        xs = BOX[0] + (np.arange(VOXELS[0]) + 0.5) * voxel[0]
        ys = BOX[1] + (np.arange(VOXELS[1]) + 0.5) * voxel[1]
        x, y = np.meshgrid(xs, ys)
        distance = letter_distance(x, y)
        image = volume.max(axis=0)
        detected = image >= 0.5 * image.max()
        reach = wavelength * np.hypot(WALL_HALF, DEPTH) / (2.0 * WALL_HALF) + 0.5 * np.linalg.norm(voxel[:2])
        precision = (detected & (distance <= reach)).sum() / detected.sum()
        recall = (detected & (distance == 0)).sum() / (distance == 0).sum()
        self.assertGreaterEqual(precision, 0.9, f"detections off the letter (reach {reach:.3f})")
        self.assertGreaterEqual(recall, 0.7, "the letter is not found")
        z_index = np.unravel_index(volume.argmax(), volume.shape)[0]
        self.assertLessEqual(abs(BOX[2] + (z_index + 0.5) * voxel[2] - DEPTH), voxel[2])
        # The command line reads it too (geometry from its sidecar).
        prefix = os.path.join(self.tmp.name, "rec_phasor")
        subprocess.run([sys.executable, os.path.join(HERE, "reconstruct.py"), out[:-4] + ".npy", "--method", "phasor",
                        "--box=" + ",".join(map(str, BOX)), "--voxels", "8,6,4", "-o", prefix], check=True,
                       capture_output=True, text=True)
        self.assertEqual(np.load(prefix + ".npy").shape, (4, 6, 8))

    def test_confocal_capture_shows_the_letter(self):
        self.check_letter("True")

    def test_single_lit_point_capture_shows_the_letter(self):
        self.check_letter("False")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    HiddenLetter.femto, HiddenLetter.plugins = sys.argv[1], sys.argv[2]
    unittest.main(argv=sys.argv[:1])
