"""Scene.set: parameters changed without reloading render exactly what a scene
loaded with those values renders (both transient integrators), and a loop of
edits loads nothing (loads counted at the loader)."""
import numpy as np
import pytest

import femto
from femto import _scene

XML = """<scene version="3.0.0">
  <integrator type="{integrator}"><integer name="max_depth" value="4"/></integrator>
  <sensor type="perspective">
    <float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0.3, 0.2, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="{spp}"/></sampler>
    <film type="transient">
      <integer name="width" value="16"/><integer name="height" value="12"/>
      <integer name="temporal_bins" value="{bins}"/><float name="start_opl" value="{start}"/>
      <float name="bin_width_opl" value="{width}"/><rfilter type="box"/>
    </film>
  </sensor>
  <shape type="rectangle">
    <transform name="to_world"><scale value="2"/><rotate x="1" angle="-90"/><translate y="-1"/></transform>
    <bsdf type="diffuse"/>
  </shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value="0.3"/><rotate x="1" angle="90"/><translate y="1.2"/></transform>
    <emitter type="area" id="lamp"><rgb name="radiance" value="{radiance}"/></emitter>
  </shape>
  <medium type="homogeneous" id="fog"><rgb name="sigma_t" value="{sigma_t}"/><float name="albedo" value="{albedo}"/></medium>
  <shape type="cube">
    <transform name="to_world"><scale value="0.5"/></transform>
    <ref name="interior" id="fog"/>
  </shape>
  <emitter type="point" id="bulb"><point name="position" x="0" y="0.5" z="0.8"/><rgb name="intensity" value="{intensity}"/></emitter>
</scene>
"""

BASE = dict(spp=4, bins=24, start=3.0, width=0.25, radiance="1", sigma_t="0.5", albedo=0.8, intensity="2")
EDITS = [  # (key, value given to set, the XML's spelling of it)
    ("fog.sigma_t", [1.5, 0.7, 0.2], dict(sigma_t="1.5, 0.7, 0.2")),
    ("fog.albedo", 0.4, dict(albedo=0.4)),
    ("bulb.intensity", 5.0, dict(intensity="5")),
    ("lamp.radiance", [2, 1, 0.5], dict(radiance="2, 1, 0.5")),
    ("film.start_opl", 4.5, dict(start=4.5)),
    ("film.bin_width_opl", 0.125, dict(width=0.125)),
    ("film.temporal_bins", 40, dict(bins=40)),
    ("sampler.sample_count", 7, dict(spp=7)),
]


def xml(integrator, **changes):
    return XML.format(integrator=integrator, **{**BASE, **changes})


def render(scene):
    r = scene.render(seed=5, threads=2)
    return r.steady, np.asarray(r.transient)


@pytest.fixture
def loads(monkeypatch):
    """How many times a scene was loaded (every load goes through _femto.load_string here)."""
    count = {"n": 0}
    load = _scene._femto.load_string

    def counted(*args):
        count["n"] += 1
        return load(*args)

    monkeypatch.setattr(_scene._femto, "load_string", counted)
    return count


def test_parameters_lists_what_can_change_and_its_value():
    scene = femto.load_string(xml("transient_path"))
    values = scene.parameters()
    for key, _, _ in EDITS:
        assert key in values
    assert values["fog.sigma_t"] == (0.5, 0.5, 0.5) and values["film.temporal_bins"] == 24
    assert values["sampler.sample_count"] == BASE["spp"]
    scene.set("bulb.intensity", [1, 2, 3])
    assert scene.parameters()["bulb.intensity"] == (1.0, 2.0, 3.0)


@pytest.mark.parametrize("integrator", ["transient_path", "transient_beams"])
def test_each_edit_renders_what_a_fresh_load_renders(integrator, loads):
    scene = femto.load_string(xml(integrator))
    render(scene)  # an edit after a render, as in a user's loop
    changes = {}
    for key, value, spelled in EDITS:
        scene.set(key, value)
        changes.update(spelled)
        edited = render(scene)
        fresh = render(femto.load_string(xml(integrator, **changes)))
        assert edited[1].shape == fresh[1].shape, key
        assert np.array_equal(edited[0], fresh[0]) and np.array_equal(edited[1], fresh[1]), key
    assert loads["n"] == 1 + len(EDITS)  # the scene once, each fresh scene once


def test_ten_edits_in_a_loop_reload_nothing(loads):
    scene = femto.load_string(xml("transient_path"))
    totals = []
    for i in range(10):
        scene.set("bulb.intensity", 1.0 + i)
        scene.set("film.start_opl", 3.0 + 0.1 * i)
        totals.append(scene.render(spp=2 + i % 3, seed=1, threads=2).steady.sum())
    assert loads["n"] == 1
    assert len(set(totals)) == 10


def test_render_spp_in_place_equals_a_load_with_that_spp(loads):
    scene = femto.load_string(xml("transient_path"))
    a = scene.render(spp=9, seed=2, threads=1)
    assert scene.info["spp"] == BASE["spp"]  # the scene's own count is back
    b = femto.load_string(xml("transient_path", spp=9)).render(seed=2, threads=1)
    assert np.array_equal(a.steady, b.steady) and np.array_equal(np.asarray(a.transient), np.asarray(b.transient))
    assert loads["n"] == 2


def test_bad_edits_name_the_object_and_what_can_change():
    scene = femto.load_string(xml("transient_path"))
    with pytest.raises(femto.SceneError, match="cannot change after loading.*sigma_t"):
        scene.set("fog.sigma_s", 1.0)
    with pytest.raises(femto.SceneError, match="no object \"smoke\""):
        scene.set("smoke.sigma_t", 1.0)
    with pytest.raises(femto.SceneError, match="non-negative"):
        scene.set("fog.sigma_t", -1.0)
    with pytest.raises(femto.SceneError, match="temporal_bins"):
        scene.set("film.temporal_bins", 2.5)
    with pytest.raises(femto.SceneError, match="OBJECT.PARAMETER"):
        scene.set("intensity", 1.0)


LIGHTS = """<scene version="3.0.0">
  <integrator type="transient_path"><integer name="max_depth" value="3"/></integrator>
  <sensor type="perspective">
    <transform name="to_world"><lookat origin="0, 1, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="4"/></sampler>
    <film type="transient"><integer name="width" value="12"/><integer name="height" value="10"/>
      <integer name="temporal_bins" value="16"/><float name="start_opl" value="3"/>
      <float name="bin_width_opl" value="0.5"/><rfilter type="box"/></film>
  </sensor>
  <shape type="rectangle">
    <transform name="to_world"><scale value="2"/><rotate x="1" angle="-90"/><translate y="-1"/></transform>
    <bsdf type="diffuse"/>
  </shape>
  <emitter type="spot" id="spot"><rgb name="intensity" value="{spot}"/><float name="cutoff_angle" value="30"/>
    <transform name="to_world"><lookat origin="0, 1, 0" target="0, -1, 0" up="0, 0, 1"/></transform></emitter>
  <emitter type="projector" id="laser"><float name="scale" value="{scale}"/><float name="fov" value="5"/>
    <transform name="to_world"><lookat origin="1, 1, 1" target="0, -1, 0" up="0, 1, 0"/></transform></emitter>
  <emitter type="constant" id="sky"><rgb name="radiance" value="{sky}"/></emitter>
</scene>
"""


def test_lights_edits_render_what_a_fresh_load_renders(loads):
    base = dict(spot="2", scale=1.0, sky="0.1")
    scene = femto.load_string(LIGHTS.format(**base))
    changes = dict(base)
    before = render(scene)
    for key, value, spelled in [("spot.intensity", [3, 2, 1], dict(spot="3, 2, 1")), ("laser.scale", 4.0, dict(scale=4.0)),
                                ("sky.radiance", 0.25, dict(sky="0.25"))]:
        scene.set(key, value)
        changes.update(spelled)
        edited, fresh = render(scene), render(femto.load_string(LIGHTS.format(**changes)))
        assert not np.array_equal(edited[0], before[0]), f"{key}: the edit changed nothing the camera sees"
        assert np.array_equal(edited[0], fresh[0]) and np.array_equal(edited[1], fresh[1]), key
        before = edited
    assert loads["n"] == 4  # the scene and one fresh scene per edit
