"""Shared set-up of the femto Python module's tests (run by ctest: FEMTO_BIN,
FEMTO_SOURCE_DIR and PYTHONPATH=<build>/python come from tests/unit/python/CMakeLists.txt)."""
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

SOURCE_DIR = Path(os.environ.get("FEMTO_SOURCE_DIR", Path(__file__).resolve().parents[3]))
FOG_BOX = SOURCE_DIR / "scenes" / "cornell-box-fog" / "scene.xml"

# The fog Cornell box made tiny: 16x16 pixels, 32 bins over its OPL window 3 to 13.24, no frames.
TINY_FOG_BOX = {"resolution": 16, "bins": 32, "bin_width": 0.32, "frames": False, "spp": 4}


@pytest.fixture(scope="session")
def femto_bin():
    path = os.environ.get("FEMTO_BIN")
    if not path or not Path(path).exists():
        pytest.skip("FEMTO_BIN (the femto command-line program) is not set")
    return path


def cli_render(femto_bin, scene, output, defines=(), args=()):
    """`femto render` with -D name=value for each define; returns the completed process."""
    command = [femto_bin, "render", str(scene), "-o", str(output), "--no-progress", *args]
    for name, value in dict(defines).items():
        command += ["-D", f"{name}={str(value).lower() if isinstance(value, bool) else value}"]
    return subprocess.run(command, capture_output=True, text=True, check=True)


def same_bits(a, b):
    """Bitwise equality of two float arrays (NaN payloads and signed zeros included)."""
    a, b = np.ascontiguousarray(a), np.ascontiguousarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and a.tobytes() == b.tobytes()
