"""Running femto from the speed-vs-error harness: renders at a budget, the
cached reference render, and `femto compare --json -`."""
import collections
import hashlib
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import time

SUMMARY = re.compile(r"^rendered (.+) in ([0-9.]+) s \(", re.M)


class RunError(RuntimeError):
    """femto failed: the command and what it printed."""


def _cpu_of_children():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _run(cmd):
    """Run `cmd`; returns (stdout, wall seconds, CPU seconds). The CPU time is
    user + system of the process and its threads (the growth of this
    process's reaped-children usage: one child runs at a time): unlike wall
    time it barely changes when other processes share the cores."""
    cpu0, start = _cpu_of_children(), time.monotonic()
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wall, cpu = time.monotonic() - start, _cpu_of_children() - cpu0
    if proc.returncode != 0:
        raise RunError(f"`{' '.join(cmd)}` exited {proc.returncode}:\n{proc.stdout}{proc.stderr}")
    return proc.stdout, wall, cpu


def result_file(output):
    """What a render to `output` (.exr) produced to compare: the .npy volume of
    a transient film, else the image itself."""
    stem, _ = os.path.splitext(output)
    return stem + ".npy" if os.path.exists(stem + ".npy") else output


# A render's times and the file to compare. seconds: the render as femto
# reports it (RenderStats::seconds: no scene loading or output writing);
# wall_seconds and cpu_seconds (user + system): the whole femto process.
# stdout: what femto printed (the summary lines).
RenderResult = collections.namedtuple("RenderResult", "seconds wall_seconds cpu_seconds file stdout", defaults=("",))


def render(femto, scene, output, defines, seed, threads, extra=()):
    """Render; returns a RenderResult (`extra`: more femto render arguments). The EXR frames are deleted: the
    harness compares the volume, and they would fill the disk (the fog
    benchmark passes -D frames=false, so that writing them is not timed)."""
    cmd = [femto, "render", scene, "-o", output, "--seed", str(seed), "--no-progress"]
    if threads:
        cmd += ["-t", str(threads)]
    for name, value in defines:
        cmd += ["-D", f"{name}={value}"]
    cmd += list(extra)
    out, wall, cpu = _run(cmd)
    m = SUMMARY.search(out)
    if not m:
        raise RunError(f"`{' '.join(cmd)}` printed no 'rendered ... in N s' line:\n{out}")
    stem, _ = os.path.splitext(output)
    shutil.rmtree(stem + "_frames", ignore_errors=True)
    return RenderResult(float(m.group(2)), wall, cpu, result_file(output), out)


def compare(femto, reference, test):
    """`femto compare REF TEST --json -` as a dict (fields: docs/compare.md)."""
    out, _, _ = _run([femto, "compare", reference, test, "--json", "-"])
    return json.loads(out)


def reference_key(scene, defines, integrator, param, budget, seed):
    """Cache key of a reference render: the scene file's content (not the
    commit: a reference stays valid while the scene and its overrides do),
    the overrides, integrator, budget and seed."""
    with open(scene, "rb") as f:
        scene_hash = hashlib.sha256(f.read()).hexdigest()
    spec = {"scene": scene_hash, "defines": sorted(defines), "integrator": integrator,
            "param": param, "budget": budget, "seed": seed}
    return hashlib.sha256(json.dumps(spec, sort_keys=True).encode()).hexdigest()[:16], spec


def cached_reference(femto, scene, defines, integrator, param, budget, seed, threads, cache_dir, log=print):
    """The reference render's file, rendered once and then taken from
    `cache_dir`/<key>/ (with meta.json saying what it is)."""
    key, spec = reference_key(scene, defines, integrator, param, budget, seed)
    folder = os.path.join(cache_dir, key)
    meta_path = os.path.join(folder, "meta.json")
    if os.path.exists(meta_path):
        with open(meta_path) as f:
            meta = json.load(f)
        path = os.path.join(folder, meta["file"])
        if os.path.exists(path):
            log(f"reference: cached {path} ({integrator} {param}={budget}, seed {seed})")
            return path
    os.makedirs(folder, exist_ok=True)
    log(f"reference: rendering {integrator} {param}={budget} (seed {seed}) into {folder} ...")
    r = render(femto, scene, os.path.join(folder, "reference.exr"),
               list(defines) + [("integrator", integrator), (param, str(budget))], seed, threads)
    path, seconds = r.file, r.seconds
    meta = dict(spec, scene_file=os.path.abspath(scene), file=os.path.basename(path), seconds=seconds,
                cpu_seconds=round(r.cpu_seconds, 3))
    with open(meta_path, "w") as f:
        json.dump(meta, f, indent=2)
    log(f"reference: done in {seconds:.1f} s")
    return path


def run_cli(main):
    """Exit with `main(sys.argv[1:])`'s status; a failed femto run ends the
    tool with its one-line error instead of a traceback."""
    try:
        sys.exit(main(sys.argv[1:]))
    except RunError as e:
        sys.exit(f"error: {e}")
