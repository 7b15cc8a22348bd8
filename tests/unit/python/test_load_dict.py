"""femto.load_dict: Mitsuba 3's dictionary scenes. A dict and the XML a user
would write for it (look_at, translate, rotate, scale as XML transform
operations, not matrices) render the same image; ScalarTransform4f matches
the XML operations; errors name the dict's path."""
import numpy as np
import pytest

import femto

T = femto.ScalarTransform4f

XML = """<scene version="3.0.0">
  <integrator type="transient_path"><integer name="max_depth" value="4"/></integrator>
  <sensor type="perspective">
    <float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0.3, 0.2, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="8"/></sampler>
    <film type="transient">
      <integer name="width" value="24"/><integer name="height" value="20"/>
      <integer name="temporal_bins" value="32"/><float name="start_opl" value="3"/>
      <float name="bin_width_opl" value="0.25"/><rfilter type="box"/>
    </film>
  </sensor>
  <bsdf type="diffuse" id="white"><rgb name="reflectance" value="0.7, 0.6, 0.5"/></bsdf>
  <shape type="rectangle">
    <transform name="to_world"><scale value="2"/><rotate x="1" angle="-90"/><translate y="-1"/></transform>
    <ref id="white"/>
  </shape>
  <medium type="homogeneous" id="fog"><float name="sigma_t" value="0.5"/><float name="albedo" value="0.8"/></medium>
  <shape type="cube">
    <transform name="to_world"><scale value="0.5"/></transform>
    <ref name="interior" id="fog"/>
  </shape>
  <emitter type="point"><point name="position" x="0" y="0.5" z="0.5"/><rgb name="intensity" value="2"/></emitter>
</scene>
"""

DICT = {
    "type": "scene",
    "integrator": {"type": "transient_path", "max_depth": 4},
    "sensor": {
        "type": "perspective",
        "fov": 40.0,
        "to_world": T.look_at(origin=[0.3, 0.2, 4], target=[0, 0, 0], up=[0, 1, 0]),
        "sampler": {"type": "independent", "sample_count": 8},
        "film": {"type": "transient", "width": 24, "height": 20, "temporal_bins": 32, "start_opl": 3.0,
                 "bin_width_opl": 0.25, "rfilter": {"type": "box"}},
    },
    "white": {"type": "diffuse", "reflectance": {"type": "rgb", "value": [0.7, 0.6, 0.5]}},
    # Mitsuba 3: T().translate(a).rotate(...).scale(s) applies the scale first (XML lists it first).
    "floor": {"type": "rectangle", "to_world": T().translate([0, -1, 0]).rotate([1, 0, 0], -90).scale(2),
              "bsdf": {"type": "ref", "id": "white"}},
    "fog": {"type": "homogeneous", "sigma_t": 0.5, "albedo": 0.8},
    "box": {"type": "cube", "to_world": T.scale(0.5), "interior": {"type": "ref", "id": "fog"}},
    "light": {"type": "point", "position": [0, 0.5, 0.5], "intensity": {"type": "rgb", "value": 2}},
}


def test_dict_renders_what_its_xml_renders():
    from_dict = femto.load_dict(DICT, strict=True).render(seed=3, threads=1)
    from_xml = femto.load_string(XML, strict=True).render(seed=3, threads=1)
    assert from_xml.steady.sum() > 0
    # The matrices are built in double here and from the XML operations in the
    # loader: equal to float rounding, so the images to a few ulps.
    np.testing.assert_allclose(from_dict.transient, from_xml.transient, rtol=1e-4, atol=1e-6)
    np.testing.assert_allclose(from_dict.steady, from_xml.steady, rtol=1e-4, atol=1e-6)


def test_transform_methods_compose_as_mitsuba():
    # translate @ rotate @ scale: a point is scaled, then rotated, then moved.
    m = T().translate([1, 2, 3]).rotate([0, 0, 1], 90).scale(2).matrix
    np.testing.assert_allclose(m @ [1, 0, 0, 1], [1, 4, 3, 1], atol=1e-12)
    # The class-method spelling starts from the identity.
    np.testing.assert_allclose(T.translate([1, 0, 0]).matrix, T().translate([1, 0, 0]).matrix)
    # look_at: +z toward the target, the origin where the camera is.
    la = T.look_at(origin=[0, 0, 4], target=[0, 0, 0], up=[0, 1, 0]).matrix
    np.testing.assert_allclose(la @ [0, 0, 1, 0], [0, 0, -1, 0], atol=1e-12)
    np.testing.assert_allclose(la[:3, 3], [0, 0, 4])


def test_errors_name_the_dicts_path():
    bad = dict(DICT, floor={"type": "rectangle", "bsdf": {"type": "no_such_bsdf"}})
    with pytest.raises(femto.SceneError, match=r"floor\.bsdf: unknown plugin \"no_such_bsdf\""):
        femto.load_dict(bad)
    with pytest.raises(femto.SceneError, match=r"\"type\": \"scene\""):
        femto.load_dict({"type": "shape"})
    with pytest.raises(femto.SceneError, match=r"light\.intensity: a \{\"type\": \"rgb\"\} needs a \"value\""):
        femto.load_dict(dict(DICT, light={"type": "point", "intensity": {"type": "rgb"}}))
    # Parameters nobody reads are the loader's errors, in strict mode, as for XML.
    with pytest.raises(femto.SceneError, match="no_such_parameter"):
        femto.load_dict(dict(DICT, fog={"type": "homogeneous", "no_such_parameter": 1.0}), strict=True)
