"""mitransient's phasor film (phasor_hdr_film): each pixel's Fourier
coefficients sum(v exp(-2 pi i f (opl - start_opl))) at mitransient's
frequencies, OPL from each camera ray's near-clip point.

- Closed form: a wall at depth D lit from the camera, seen through a narrow
  field of view: every pixel's phasor is its steady value times
  exp(-2 pi i f (2D - near_clip)) to within the pixel's spread of path
  lengths (derived below).
- Independent estimator: the same scene and samples into mitransient's
  transient film, whose volume's DFT at the film's frequencies (bin centres)
  must agree with the phasors to within the binning's phase error, at most
  pi f bin_width per unit of light (derived, not fitted).
- The frequencies are numpy's fftfreq selection as mitransient writes it.
"""
import json
import os
import subprocess

import numpy as np

from femto import _femto

FEMTO = os.environ.get("FEMTO_BIN", "femto")

SCENE = """<scene version="3.0.0">
  <default name="film" value="phasor_hdr_film"/>
  <default name="fov" value="2"/>
  <default name="depth" value="2"/>
  <integrator type="transient_path"><integer name="max_depth" value="$depth"/>
    <boolean name="time_gating" value="false"/></integrator>
  <sensor type="perspective"><float name="fov" value="$fov"/><float name="near_clip" value="0.5"/>
    <transform name="to_world"><lookat origin="0, 0, 0" target="0, 0, 1" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="16"/></sampler>
    <film type="$film"><integer name="width" value="6"/><integer name="height" value="5"/>
      <integer name="temporal_bins" value="3000"/><float name="bin_width_opl" value="0.01"/>
      <float name="start_opl" value="0.25"/>
      <float name="wl_mean" value="2"/><float name="wl_sigma" value="20"/>
      <rfilter type="box"/></film></sensor>
  <emitter type="point"><point name="position" x="0" y="0" z="0"/><float name="intensity" value="1"/></emitter>
  <shape type="rectangle"><transform name="to_world"><scale value="10"/><rotate y="1" angle="180"/>
    <translate z="3"/></transform><bsdf type="diffuse"/></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="10"/><rotate x="1" angle="-90"/>
    <translate y="-1"/></transform><bsdf type="diffuse"/></shape>
</scene>
"""
D, NEAR, START = 3.0, 0.5, 0.25


def render(tmp_path, name, *defines, strict=True):
    scene = tmp_path / "scene.xml"
    scene.write_text(SCENE)
    out = tmp_path / f"{name}.exr"
    cmd = [FEMTO, "render", str(scene), "-o", str(out), "--seed", "5", "-t", "2", "--no-progress"]
    cmd += ["--strict"] if strict else []
    for d in defines:
        cmd += ["-D", d]
    subprocess.run(cmd, check=True, capture_output=True, text=True)
    return out


def phasors(out):
    x = np.load(out.with_suffix(".npy")).astype(np.float64)
    info = json.loads(out.with_suffix(".json").read_text())
    return x[..., 0, :] + 1j * x[..., 1, :], np.array(info["frequencies"])


def test_frequencies_are_mitransients(tmp_path):
    out = render(tmp_path, "wall")
    _, f = phasors(out)
    nt, bw, mean, sigma = 3000, 0.01, 2.0, 20.0
    lo = max(0, int(np.floor(nt * bw / mean - 3 * nt * bw / (sigma * 6))))
    hi = min(nt // 2, int(np.ceil(nt * bw / mean + 3 * nt * bw / (sigma * 6))))
    expected = np.fft.fftfreq(nt, d=bw)[lo:hi + 1].astype(np.float32)
    np.testing.assert_array_equal(f.astype(np.float32), expected)


def test_wall_phase_is_the_closed_form(tmp_path):
    out = render(tmp_path, "wall")
    z, f = phasors(out)
    x = np.load(out.with_suffix(".npy"))
    assert x.shape == (5, 6, len(f), 2, 3)
    # Direct light only (max_depth 2): from the near-clip point the path is
    # (2 D - near) / cos(theta), minus start_opl. Over a 2 degree field of view
    # cos(theta) >= cos(sqrt(2) deg): the path lengths spread by at most
    # (2 D - near) (1 / cos - 1), a phase of 2 pi f times that.
    tau = 2 * D - NEAR - START
    spread = (2 * D - NEAR) * (1 / np.cos(np.radians(np.sqrt(2.0))) - 1)
    expected = np.exp(-2j * np.pi * f * tau)
    for k in range(len(f)):
        unit = z[:, :, k, :] / np.abs(z[:, :, k, :])
        assert np.all(np.abs(unit - expected[k]) <= 2 * np.pi * f[k] * spread + 1e-5), f[k]


def test_agrees_with_the_transient_films_dft(tmp_path):
    # Two bounces (floor and wall): light arrives over a range of times. The
    # transient film's window [0.25, 30.25) holds all of it (checked), and
    # with time gating off both films see the same samples.
    phasor = render(tmp_path, "phasor", "depth=3", "fov=30")
    # (not strict: the transient film leaves the phasor film's wl_mean and wl_sigma unread)
    volume = render(tmp_path, "volume", "depth=3", "fov=30", "film=transient_hdr_film", strict=False)
    z, f = phasors(phasor)
    v = np.load(volume.with_suffix(".npy")).astype(np.float64)  # (h, w, bins, 3)
    bw = 0.01
    centres = (np.arange(v.shape[2]) + 0.5) * bw  # OPL - start_opl at each bin's centre
    total = v.sum(axis=2)
    assert total.sum() > 0
    after = _femto.read_image(str(volume.with_name("volume_after.exr")))
    assert after.max() == 0, "the transient film's window holds all the light"
    for k, freq in enumerate(f):
        dft = np.einsum("hwbc,b->hwc", v, np.exp(-2j * np.pi * freq * centres))
        # A contribution at tau is binned at a centre within bw / 2 of it: its
        # phase is off by at most pi f bw, so |dft - phasor| <= pi f bw sum |v|.
        bound = np.pi * freq * bw * total + 1e-6 * total.max()
        assert np.all(np.abs(dft - z[:, :, k, :]) <= bound), freq
