"""Mitsuba 3's dictionary scene format: femto.load_dict({"type": "scene", ...}).

The dictionary is written out as the Mitsuba 3 XML it stands for and loaded
by femto's own loader (load_string), so a dict scene and its XML twin render
the same bits and errors name the dict's path. Rules (Mitsuba 3's
`mi.load_dict`):

- a dict with "type" is an object; its tag (bsdf, shape, emitter, ...) is
  the kind of the plugin of that name. At the scene's top level its key is
  its id; nested, its key is its name (a shape's "bsdf", a film's "rfilter").
- {"type": "ref", "id": X}: a reference to the object with id X.
- {"type": "rgb", "value": v} and {"type": "spectrum", "value": v}: colours.
- bool, int, float and str: <boolean>, <integer>, <float>, <string>; a
  sequence of three numbers: <point> (positions, origins, directions alike).
- ScalarTransform4f (femto's, or any object with a 4x4 `matrix`), or a 4x4
  array: <transform> with that matrix.
"""
import math
import os

import numpy as np

from . import _femto
from ._scene import load_string

_COLOURS = ("rgb", "spectrum")


class _FromIdentity:
    """A method that, called on the class, starts from the identity:
    ScalarTransform4f.translate(v) as ScalarTransform4f().translate(v)."""

    def __init__(self, f):
        self.f = f

    def __get__(self, obj, cls):
        target = obj if obj is not None else cls()
        return lambda *args, **kwargs: self.f(target, *args, **kwargs)


class ScalarTransform4f:
    """A 4x4 affine transform as Mitsuba 3's mi.ScalarTransform4f builds them:
    ScalarTransform4f().translate([0, 1, 0]).scale(2) is translate @ scale
    (the scale applies first). The class methods start from the identity
    (the older spelling, ScalarTransform4f.look_at(...))."""

    def __init__(self, matrix=None):
        self.matrix = np.eye(4) if matrix is None else np.array(matrix, dtype=np.float64).reshape(4, 4)

    def __matmul__(self, other):
        return ScalarTransform4f(self.matrix @ _matrix(other))

    def _then(self, m):
        return ScalarTransform4f(self.matrix @ m)

    @_FromIdentity
    def translate(self, v):
        m = np.eye(4)
        m[:3, 3] = _vector(v)
        return self._then(m)

    @_FromIdentity
    def scale(self, v):
        s = np.broadcast_to(np.asarray(v, dtype=np.float64), (3,))
        return self._then(np.diag([s[0], s[1], s[2], 1.0]))

    @_FromIdentity
    def rotate(self, axis, angle):
        """Rotation by `angle` degrees about `axis` (right-handed)."""
        a = _vector(axis)
        a = a / np.linalg.norm(a)
        c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
        x, y, z = a
        m = np.eye(4)
        m[:3, :3] = [[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
                     [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
                     [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]]
        return self._then(m)

    @_FromIdentity
    def look_at(self, origin, target, up):
        """Camera to world: +z toward target, +y near up, at origin (Mitsuba's look_at)."""
        o, t, u = _vector(origin), _vector(target), _vector(up)
        d = t - o
        d = d / np.linalg.norm(d)
        left = np.cross(u, d)
        left = left / np.linalg.norm(left)
        new_up = np.cross(d, left)
        m = np.eye(4)
        m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = left, new_up, d, o
        return self._then(m)

    def __repr__(self):
        return f"ScalarTransform4f({self.matrix.tolist()})"


def _vector(v):
    a = np.asarray(v, dtype=np.float64).reshape(-1)
    if a.size == 1:
        a = np.repeat(a, 3)
    if a.size != 3:
        raise ValueError(f"expected 3 numbers, got {v!r}")
    return a


def _matrix(value):
    m = getattr(value, "matrix", value)
    m = np.asarray(m, dtype=np.float64)
    if m.shape != (4, 4):
        raise ValueError(f"a transform needs a 4x4 matrix, got shape {m.shape}")
    return m


def _number(x):
    return repr(float(x))


def _attr(text):
    return (str(text).replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;").replace(">", "&gt;"))


class _Writer:
    def __init__(self):
        self.kinds = {name: kind for name, kind, _ in _femto.plugins()}
        self.lines = []

    def fail(self, path, message):
        raise _femto.SceneError(f"load_dict: {'.'.join(path) or '<scene>'}: {message}")

    def value(self, key, value, path, indent):
        pad = "  " * indent
        k = _attr(key)
        if isinstance(value, bool):
            self.lines.append(f'{pad}<boolean name="{k}" value="{"true" if value else "false"}"/>')
        elif isinstance(value, (int, np.integer)):
            self.lines.append(f'{pad}<integer name="{k}" value="{int(value)}"/>')
        elif isinstance(value, (float, np.floating)):
            self.lines.append(f'{pad}<float name="{k}" value="{_number(value)}"/>')
        elif isinstance(value, str):
            self.lines.append(f'{pad}<string name="{k}" value="{_attr(value)}"/>')
        elif isinstance(value, ScalarTransform4f) or hasattr(value, "matrix") or (
                isinstance(value, np.ndarray) and value.shape == (4, 4)):
            m = _matrix(value)
            self.lines.append(f'{pad}<transform name="{k}"><matrix value="{" ".join(_number(x) for x in m.reshape(-1))}"/></transform>')
        elif isinstance(value, dict):
            self.object(key, value, path, indent, top=False)
        elif isinstance(value, (list, tuple, np.ndarray)) and np.asarray(value).size == 3:
            x, y, z = (float(c) for c in np.asarray(value, dtype=np.float64).reshape(-1))
            self.lines.append(f'{pad}<point name="{k}" x="{_number(x)}" y="{_number(y)}" z="{_number(z)}"/>')
        else:
            self.fail(path, f"cannot write {type(value).__name__} {value!r} as a scene parameter")

    def object(self, key, d, path, indent, top):
        pad = "  " * indent
        kind_name = d.get("type")
        if not isinstance(kind_name, str):
            self.fail(path, 'a nested dict needs a "type"')
        if kind_name == "ref":
            if "id" not in d:
                self.fail(path, 'a {"type": "ref"} needs an "id"')
            self.lines.append(f'{pad}<ref name="{_attr(key)}" id="{_attr(d["id"])}"/>')
            return
        if kind_name in _COLOURS:
            if "value" not in d:
                self.fail(path, f'a {{"type": "{kind_name}"}} needs a "value"')
            v = np.asarray(d["value"], dtype=np.float64).reshape(-1)
            self.lines.append(f'{pad}<{kind_name} name="{_attr(key)}" value="{", ".join(_number(x) for x in v)}"/>')
            return
        tag = self.kinds.get(kind_name)
        if tag is None:
            self.fail(path, f'unknown plugin "{kind_name}" (femto.plugins() lists the known ones)')
        label = f'id="{_attr(key)}"' if top else f'name="{_attr(key)}"'
        self.lines.append(f'{pad}<{tag} type="{_attr(kind_name)}" {label}>')
        for k, v in d.items():
            if k == "type":
                continue
            self.value(k, v, path + [k], indent + 1)
        self.lines.append(f"{pad}</{tag}>")


def dict_to_xml(scene):
    """The Mitsuba 3 XML text a load_dict() scene dictionary stands for."""
    if not isinstance(scene, dict) or scene.get("type") != "scene":
        raise _femto.SceneError('load_dict: <scene>: the top-level dict needs "type": "scene"')
    w = _Writer()
    w.lines.append('<scene version="3.0.0">')
    for key, value in scene.items():
        if key == "type":
            continue
        if isinstance(value, dict) and value.get("type") not in (None, "ref") + _COLOURS:
            w.object(key, value, [key], 1, top=True)
        else:
            w.value(key, value, [key], 1)
    w.lines.append("</scene>")
    return "\n".join(w.lines) + "\n"


def load_dict(scene, base_dir=".", *, strict=False, film_size=None, defines=None, **kwargs):
    """Load a scene given as Mitsuba 3's dictionary ({"type": "scene", ...}).
    Meshes resolve against base_dir; other arguments as load_string."""
    return load_string(dict_to_xml(scene), os.fspath(base_dir), strict=strict, film_size=film_size,
                       name="<dict>", defines=defines, **kwargs)
