"""render(time_limit=...): whole passes until the budget, then the same bits as
render(passes=N) for the N reached, and as the CLI's --passes N. No time is
asserted: the count reached is read back and rendered again."""
import json

import numpy as np
import pytest

import femto
from conftest import FOG_BOX, TINY_FOG_BOX, cli_render, same_bits

BEAMS = {"integrator": "transient_beams", "photon_count": 2000, "beam_photon_count": 300}


@pytest.mark.parametrize("extra, spp", [({"integrator": "transient_path"}, 1), (BEAMS, 2)])
def test_time_limited_equals_passes_reached(femto_bin, tmp_path, extra, spp):
    defines = dict(TINY_FOG_BOX, **extra)
    defines.pop("spp")
    scene = femto.load_file(FOG_BOX, **defines)
    limited = scene.render(spp=spp, seed=3, threads=2, time_limit="0.3s", time_clock="cpu",
                           output=tmp_path / "limited.exr")
    assert limited.completed and limited.passes >= 1 and limited.spp_per_pass == spp
    assert limited.samples == limited.passes * spp * 16 * 16
    sidecar = json.loads((tmp_path / "limited.json").read_text())
    assert (sidecar["passes"], sidecar["spp_per_pass"], sidecar["time_clock"]) == (limited.passes, spp, "cpu")
    counted = scene.render(spp=spp, seed=3, threads=1, passes=limited.passes)
    assert counted.passes == limited.passes and not counted.time_limit_reached
    assert same_bits(limited.transient, counted.transient)
    assert same_bits(limited.steady, counted.steady)
    cli_render(femto_bin, FOG_BOX, tmp_path / "cli.exr", defines,
               ["--spp", str(spp), "--passes", str(limited.passes), "--seed", "3"])
    assert same_bits(limited.transient, np.load(tmp_path / "cli.npy"))


def test_cap_and_seconds_as_a_number():
    scene = femto.load_file(FOG_BOX, **TINY_FOG_BOX)
    result = scene.render(spp=1, time_limit=3600, passes=3)  # an hour: the cap of 3 passes ends it
    assert result.passes == 3 and not result.time_limit_reached and result.cpu_seconds > 0


@pytest.mark.parametrize("bad", ["5x", "0", -1, "inf"])
def test_bad_time_limit_is_a_value_error(bad):
    scene = femto.load_file(FOG_BOX, **TINY_FOG_BOX)
    with pytest.raises(ValueError, match="time_limit"):
        scene.render(time_limit=bad)


def test_bad_clock_and_passes_are_value_errors():
    scene = femto.load_file(FOG_BOX, **TINY_FOG_BOX)
    with pytest.raises(ValueError, match="time_clock"):
        scene.render(time_limit=1, time_clock="gpu")
    with pytest.raises(ValueError, match="passes"):
        scene.render(passes=0)
