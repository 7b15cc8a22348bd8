"""Scenes and their render: the CLI's loader and render driver, files to arrays."""
import os
import shutil
import tempfile
import weakref
from pathlib import Path

import numpy as np

from . import _femto
from ._result import Progress, RenderResult, TimeAxis

# Volumes larger than this (bytes) come back as a memory map over the streamed
# .npy instead of a copy in memory (render(memory_limit=...) overrides it).
DEFAULT_MEMORY_LIMIT = 1 << 30


def _define_text(value):
    """A Python value as the XML would write it (-D name=value)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


class Scene:
    """A loaded scene. set() changes a parameter without reloading (parameters()
    lists what can change). render(spp=N) renders exactly what `femto render
    --spp N` renders: in place where the sampler's sample_count can change,
    otherwise from the scene loaded again with that count (edits replayed)."""

    def __init__(self, loader, spp, native):
        self._loader = loader  # spp -> the native scene loaded with that sample count
        self._scenes = {spp: native}
        self._default_spp = spp
        self._edits = {}  # key -> value, replayed on scenes loaded later
        self._own_spp = native.describe()["spp"]

    def _native(self, spp):
        if spp not in self._scenes:
            native = self._loader(spp)
            for key, value in self._edits.items():
                native.set_parameter(key, value)
            self._scenes[spp] = native
        return self._scenes[spp]

    def parameters(self) -> dict:
        """The parameters set() can change and their values, as {"object.parameter":
        value}: "film.start_opl", "sampler.sample_count", and those of objects with
        an id ("fog.sigma_t", "light.intensity"); a colour is a tuple of 3.
        docs/python.md lists them."""
        return dict(self._native_for(None).parameters())

    def set(self, key, value):
        """Change parameter `key` (a name parameters() lists) to `value`: a number,
        or three for a colour. The next render uses it; nothing is reloaded.
        Raises SceneError for a name that cannot change or a bad value."""
        values = [float(v) for v in (value if hasattr(value, "__len__") else [value])]
        for native in self._scenes.values():
            native.set_parameter(key, values)
        self._edits[key] = values
        if key == "sampler.sample_count":
            self._own_spp = int(values[0])

    @property
    def info(self) -> dict:
        """Film size, crop, sample count, integrator and, for a transient film, its time axis."""
        return self._native_for(None).describe()

    @property
    def time_axis(self):
        info = self.info
        return TimeAxis(info["bins"], info["start_opl"], info["bin_width_opl"]) if info["transient"] else None

    def __repr__(self):
        return repr(self._native(self._default_spp))

    def render(self, spp=None, seed=0, threads=None, progress=None, output=None, memory_limit=None, tmp_dir=None,
               passes=None, time_limit=None, time_clock="wall"):
        """Render with the scene's integrator, as `femto render` does.

        spp: samples per pixel (None: the scene's), per pass. seed: the base
        seed (the arrays depend only on scene, spp, passes and seed, not on
        threads). passes: independent passes of spp samples averaged (None:
        the integrator's own, --passes). time_limit: seconds, or a duration
        text as --time-limit takes ("30s", "5m"): whole passes until the next
        would pass it, at most `passes`; result.passes says how many, and
        render(spp, passes=result.passes, seed) gives the same bits.
        time_clock: "wall" (default) or "cpu" (all threads' CPU time). threads:
        worker threads (None: all cores). progress: called with a Progress as
        the CLI's bar is redrawn. output: keep the files `femto render -o
        output` writes there (None: render into a temporary folder, removed
        once the arrays no longer need it). memory_limit: volumes of more
        bytes are returned as a read-only np.memmap of the .npy (default 1 GiB).
        tmp_dir: where the temporary folder goes (default: tempfile's).

        Ctrl-C stops the render after the tiles in flight and raises
        KeyboardInterrupt with the partial RenderResult as its `.result`; an
        exception raised by `progress` stops it the same way.
        """
        if threads is not None and int(threads) < 1:
            raise ValueError(f"threads must be a whole number >= 1, got {threads}")
        if spp is not None and int(spp) < 1:
            raise ValueError(f"spp must be a whole number >= 1, got {spp}")
        if seed < 0:
            raise ValueError(f"seed must be >= 0, got {seed}")
        if passes is not None and int(passes) < 1:
            raise ValueError(f"passes must be a whole number >= 1, got {passes}")
        if time_clock not in ("wall", "cpu"):
            raise ValueError(f"time_clock must be 'wall' or 'cpu', got {time_clock!r}")
        limit_seconds = _seconds(time_limit)
        native = self._native_for(None if spp is None else int(spp))
        limit = DEFAULT_MEMORY_LIMIT if memory_limit is None else int(memory_limit)
        temporary = None
        if output is None:
            temporary = tempfile.mkdtemp(prefix="femto-render-", dir=tmp_dir)
            output = Path(temporary) / ("render" + native.describe()["extension"])
        output = Path(output)
        callback = None if progress is None else (lambda state: progress(Progress(**state)))
        try:
            stats = _femto.render(native, output, int(seed), 0 if threads is None else int(threads), callback,
                                  0 if passes is None else int(passes), limit_seconds, time_clock)
            result = _collect(native, output, stats, limit, temporary)
        except BaseException:
            if temporary:
                shutil.rmtree(temporary, ignore_errors=True)
            raise
        stopped_by = stats["stopped_by"]
        if stopped_by is not None:
            stopped_by.result = result
            raise stopped_by
        return result


    def _native_for(self, spp):
        """The native scene rendering `spp` samples per pixel (None: the scene's own)."""
        default = self._native(self._default_spp)
        if "sampler.sample_count" not in default.parameters():
            return self._native(spp)
        default.set_parameter("sampler.sample_count", [float(self._own_spp if spp is None else spp)])
        return default


def _seconds(time_limit):
    """render(time_limit=...) in seconds: None -> 0 (no limit), a number, or "30s" / "5m" (--time-limit's parser)."""
    if time_limit is None:
        return 0.0
    if isinstance(time_limit, str):
        try:
            return _femto.parse_duration(time_limit)
        except Exception as e:  # femto's Error: a message, not a scene error
            raise ValueError(f"time_limit: {e}") from None
    seconds = float(time_limit)
    if not seconds > 0 or seconds == float("inf"):
        raise ValueError(f"time_limit must be a number of seconds > 0, got {time_limit}")
    return seconds


def _read_optional_image(path):
    return _femto.read_image(path) if path is not None and Path(path).exists() else None


def _collect(native, output, stats, limit, temporary):
    """The arrays of the files just written; a temporary folder is removed now,
    or when the memory-mapped volume is released."""
    info = native.describe()
    paths = native.output_paths(output)
    steady = _femto.read_image(paths["steady"])[:, :, :3]
    transient = before = after = time_axis = None
    if info["transient"]:
        time_axis = TimeAxis(info["bins"], info["start_opl"], info["bin_width_opl"])
        before, after = _read_optional_image(paths["before"]), _read_optional_image(paths["after"])
        volume = Path(paths["volume"])
        if volume.exists():
            mapped = np.load(volume, mmap_mode="r")
            if mapped.nbytes > limit:
                transient = mapped
            else:
                transient = np.array(mapped)  # a copy: the file can go
                del mapped
    if temporary:
        if isinstance(transient, np.memmap):
            # Everything but the volume and its sidecar (the time window
            # femto.compare checks) goes now; those go with the map's last view.
            keep = {volume.name, volume.with_suffix(".json").name}
            for entry in Path(temporary).iterdir():
                if entry.name not in keep:
                    shutil.rmtree(entry) if entry.is_dir() else entry.unlink()
            weakref.finalize(transient, shutil.rmtree, temporary, True)
        else:
            shutil.rmtree(temporary, ignore_errors=True)
        files = {}
    else:
        files = {k: Path(v) for k, v in paths.items() if Path(v).exists()}
    return RenderResult(steady=steady, transient=transient, before=before, after=after, time_axis=time_axis,
                        completed=stats["completed"], samples=stats["samples"],
                        invalid_samples=stats["invalid_samples"], seconds=stats["seconds"], files=files,
                        cpu_seconds=stats["cpu_seconds"], passes=stats["passes"], spp_per_pass=stats["spp_per_pass"],
                        time_limit_reached=stats["time_limit_reached"])


def _split_options(defines, given):
    merged = dict(defines or {})
    merged.update(given)
    return {str(k): _define_text(v) for k, v in merged.items()}


def load_file(path, *, strict=False, film_size=None, defines=None, **kwargs) -> Scene:
    """Load a Mitsuba 0.6 / Mitsuba 3 / mitransient XML scene file.

    Keyword arguments are the CLI's -D name=value: they set <default> values
    and $name (`defines=` takes a dict, for names that clash with the options).
    strict: parameters nobody read are errors (the CLI's --strict).
    film_size: (width, height) overriding the film's (the CLI's --resolution;
    not called resolution, which scenes use as a define, as the fog box does).
    Raises SceneError naming the file and line."""
    path = os.fspath(path)
    values = _split_options(defines, kwargs)

    def loader(spp):
        return _femto.load_file(path, values, strict, spp, film_size)

    return Scene(loader, None, loader(None))


def load_string(xml, base_dir=".", *, strict=False, film_size=None, name="<string>", defines=None, **kwargs) -> Scene:
    """Load a scene from XML text; meshes and includes resolve against base_dir.
    `name` is the file name errors give. Other arguments as load_file."""
    base = os.fspath(base_dir)
    values = _split_options(defines, kwargs)

    def loader(spp):
        return _femto.load_string(xml, base, values, strict, spp, film_size, name)

    return Scene(loader, None, loader(None))
