"""Same scene, spp and seed: the module's arrays are the CLI's files, bit for bit."""
import numpy as np
import pytest

import femto
from conftest import FOG_BOX, TINY_FOG_BOX, cli_render, same_bits


@pytest.mark.parametrize("integrator, extra", [
    ("transient_path", {}),
    # Two progressive passes: the passes' running mean and seeds match too.
    ("transient_beams", {"passes": 2, "photon_count": 2000, "beam_photon_count": 200}),
])
def test_render_matches_cli_bitwise(femto_bin, tmp_path, integrator, extra):
    defines = dict(TINY_FOG_BOX, integrator=integrator, **extra)
    defines.pop("spp")
    cli_render(femto_bin, FOG_BOX, tmp_path / "cli.exr", defines, ["--spp", "4", "--seed", "7", "-t", "2"])
    scene = femto.load_file(FOG_BOX, **defines)
    result = scene.render(spp=4, seed=7, threads=2)
    assert result.completed
    cli_volume = np.load(tmp_path / "cli.npy")
    assert result.transient.shape == (16, 16, 32, 3)
    assert same_bits(result.transient, cli_volume)
    assert same_bits(result.steady, femto._femto.read_image(tmp_path / "cli.exr")[:, :, :3])
    assert same_bits(result.before, femto._femto.read_image(tmp_path / "cli_before.exr")[:, :, :3])
    assert same_bits(result.after, femto._femto.read_image(tmp_path / "cli_after.exr")[:, :, :3])
    # A real render, not two empty files: light reached the film.
    assert cli_volume.sum() > 0


def test_time_axis_is_the_films(tmp_path):
    scene = femto.load_file(FOG_BOX, **TINY_FOG_BOX)
    axis = scene.render(spp=1).time_axis
    assert axis.bins == 32
    np.testing.assert_allclose(axis.edges_opl[[0, -1]], [3.0, 3.0 + 32 * 0.32])
    np.testing.assert_allclose(axis.edges_seconds, axis.edges_opl / 299792458.0)
    assert scene.time_axis == axis


def test_other_seed_other_noise():
    # The seed reaches the render (a test that would pass with the seed ignored proves nothing above).
    scene = femto.load_file(FOG_BOX, **TINY_FOG_BOX)
    assert not same_bits(scene.render(seed=1).transient, scene.render(seed=2).transient)
