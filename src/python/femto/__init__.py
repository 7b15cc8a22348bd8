"""femto from Python: scenes in, NumPy arrays out (docs/python.md).

    import femto
    scene = femto.load_file("scenes/cornell-box-fog/scene.xml", spp=64)
    result = scene.render(seed=0)
    result.steady      # height x width x 3 float32
    result.transient   # height x width x bins x 3 float32 (a memmap when large)
    result.time_axis   # bin edges in optical path length and in seconds
"""
from . import _femto
from ._femto import SceneError
from ._scene import Scene, load_file, load_string
from ._dict import ScalarTransform4f, dict_to_xml, load_dict
from ._result import Progress, RenderResult, TimeAxis
from ._compare import compare
from . import view

__all__ = ["SceneError", "Scene", "load_file", "load_string", "load_dict", "dict_to_xml", "ScalarTransform4f", "plugins", "add_plugin_dir", "compare", "view",
           "Progress", "RenderResult", "TimeAxis"]

SceneError.__doc__ = ("A femto error: a scene file (with .file and .line, as the CLI names them), a bad parameter, "
                      "an output that cannot be written. str(e) and e.message are what `femto render` prints after "
                      "'error: '.")


def plugins():
    """Every plugin on the search path as (name, kind, description), as `femto plugins` lists them."""
    return list(_femto.plugins())


def add_plugin_dir(path):
    """Search `path` for plugins before the other directories (the CLI's -p)."""
    _femto.add_plugin_dir(str(path))
