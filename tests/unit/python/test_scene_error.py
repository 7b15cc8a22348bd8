"""Scene errors reach Python as femto.SceneError with the file, the line and
the text `femto render` prints after "error: "."""
import subprocess

import pytest

import femto
from conftest import FOG_BOX

BAD_SCENE = """<scene version="3.0.0">
  <integrator type="path"/>
  <sensor type="perspective">
    <film type="hdrfilm">
      <integer name="width" value="ten"/>
    </film>
  </sensor>
</scene>
"""


def test_error_names_file_and_line_as_the_cli(femto_bin, tmp_path):
    scene = tmp_path / "bad.xml"
    scene.write_text(BAD_SCENE)
    with pytest.raises(femto.SceneError) as caught:
        femto.load_file(scene)
    error = caught.value
    assert error.file == str(scene)
    assert error.line == 5
    cli = subprocess.run([femto_bin, "render", str(scene), "-o", str(tmp_path / "x.exr")], capture_output=True, text=True)
    assert cli.returncode == 1
    assert cli.stderr == f"error: {error.message}\n"
    assert str(error) == error.message
    assert error.message.startswith(f"{scene}:5: ")


def test_load_string_names_the_given_name():
    with pytest.raises(femto.SceneError) as caught:
        femto.load_string(BAD_SCENE, base_dir=".", name="inline.xml")
    assert (caught.value.file, caught.value.line) == ("inline.xml", 5)
    assert "width" in caught.value.message


def test_strict_refuses_unused_parameters():
    xml = BAD_SCENE.replace('value="ten"', 'value="10"').replace("<integer", '<float name="nobody_reads_me" value="1"/>\n      <integer', 1)
    femto.load_string(xml)  # a warning only
    with pytest.raises(femto.SceneError) as caught:
        femto.load_string(xml, strict=True, name="strict.xml")
    assert caught.value.line == 5 and "nobody_reads_me" in caught.value.message


def test_defines_reach_the_scene():
    scene = femto.load_file(FOG_BOX, resolution=8, bins=5, frames=False)
    info = scene.info
    assert info["crop_size"] == (8, 8) and info["bins"] == 5 and info["writes_frames"] is False
    # Unknown $name: the loader's error, not a crash.
    with pytest.raises(femto.SceneError):
        femto.load_file(FOG_BOX, integrator="no_such_integrator")


def test_plugins_lists_the_builtin_plugins():
    listed = {(name, kind) for name, kind, _ in femto.plugins()}
    assert ("transient_path", "integrator") in listed and ("diffuse", "bsdf") in listed
