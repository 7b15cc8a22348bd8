"""femto.compare: the CLI's compareFiles on arrays and files, checked against
the metrics' formulas (docs/compare.md) computed here with NumPy, and
against `femto compare --json` itself."""
import json
import subprocess

import numpy as np
import pytest

import femto


def volumes():
    rng = np.random.default_rng(5)
    ref = rng.random((3, 4, 5, 3), dtype=np.float32)
    test = (ref + rng.normal(0, 0.1, ref.shape)).astype(np.float32)
    return ref, test


def test_volume_metrics_are_the_formulas():
    ref, test = volumes()
    d = femto.compare(ref, test)
    r, t = ref.astype(np.float64), test.astype(np.float64)
    assert d["kind"] == "volume" and d["bins"] == 5
    assert d["metrics"]["mse"] == pytest.approx(np.mean((t - r) ** 2), rel=1e-12)
    assert d["metrics"]["relmse"] == pytest.approx(np.mean((t - r) ** 2 / (r * r + 1e-2)), rel=1e-12)
    assert d["metrics"]["mae"] == pytest.approx(np.mean(np.abs(t - r)), rel=1e-12)
    assert d["metrics"]["max_error"] == pytest.approx(np.max(np.abs(t - r)), rel=1e-12)
    per_bin = np.mean((t - r) ** 2, axis=(0, 1, 3))
    np.testing.assert_allclose(d["per_bin"]["mse"], per_bin, rtol=1e-12)
    ri, ti = r.sum(axis=2), t.sum(axis=2)
    assert d["time_integral"]["mse"] == pytest.approx(np.mean((ti - ri) ** 2), rel=1e-12)


def test_image_metrics_and_psnr():
    ref, test = volumes()
    d = femto.compare(ref[:, :, 0], test[:, :, 0], epsilon=0.5)
    r, t = ref[:, :, 0].astype(np.float64), test[:, :, 0].astype(np.float64)
    assert d["kind"] == "image"
    assert d["metrics"]["relmse"] == pytest.approx(np.mean((t - r) ** 2 / (r * r + 0.5)), rel=1e-12)
    mse = np.mean((t - r) ** 2)
    assert d["metrics"]["psnr"] == pytest.approx(10 * np.log10(r.max() ** 2 / mse), rel=1e-9)


def test_files_give_what_the_cli_reports(femto_bin, tmp_path):
    ref, test = volumes()
    np.save(tmp_path / "ref.npy", ref)
    np.save(tmp_path / "test.npy", test)
    cli = subprocess.run([femto_bin, "compare", str(tmp_path / "ref.npy"), str(tmp_path / "test.npy"), "--json", "-",
                          "--bins", "1:4"], capture_output=True, text=True, check=True)
    expected = json.loads(cli.stdout)
    got = femto.compare(tmp_path / "ref.npy", np.load(tmp_path / "test.npy", mmap_mode="r"), bins=(1, 4))
    assert got["metrics"] == pytest.approx(expected["metrics"], rel=1e-5)
    assert got["per_bin"]["relmse"] == pytest.approx(expected["per_bin"]["relmse"], rel=1e-5)
    assert list(got["bin_range"]) == expected["bin_range"]


def test_mismatched_inputs_are_a_scene_error():
    ref, test = volumes()
    with pytest.raises(femto.SceneError, match="time bins"):
        femto.compare(ref, test[:, :, :4])
