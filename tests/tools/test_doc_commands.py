#!/usr/bin/env python3
"""Every command a user page shows runs (docs/house-rules.md, "Docs").

Extracts each command of the ```sh blocks of the README and the user pages
(docs/*.md but the generated BENCHMARKS.md), in page order, and runs it with
bash from the page's own temporary folder, which holds links to the
repository's scenes/, tools/, examples/ and build/ (the femto being tested),
as a reader would run it from the repository's root. Commands run at small
size: the rewrites in REWRITES below (what and why, one line each) turn a
page's command into its small version; a page's later commands find the files
its earlier ones wrote, and the generic input files pages name (out.npy,
ref.npy, ...) are rendered first when a page names them (FIXTURES). A command
fails the test when it exits non-zero or times out; commands that cannot run
here are in SKIPPED, each with its reason.

Usage: test_doc_commands.py SOURCE_DIR FEMTO BUILD_DIR [PAGE.md ...]
(with pages: only those; exit 1 naming each failed command with its page and
line, 77 when femto cannot render here).
"""
import os
import pathlib
import re
import selectors
import shutil
import subprocess
import sys
import tempfile
import time

README_MAX_SECONDS = 120  # per command
FENCE = re.compile(r"^```(\w*)\s*$")
BUILD = pathlib.Path("build")  # the build folder, set in main()

# (pattern, reason): commands matching are reported as skipped, never run.
SKIPPED = [
    (r"^make (render|test)\b", "the README's quick start: `make test` is the suite this test runs in, and "
                               "tools/check-fresh-machine.sh runs both on a pristine root"),
    (r"^mpirun\b", "needs MPI ranks: tests/cli/mpi runs `mpirun -n 2 femto render` when femto is built with MPI"),
]

# (pattern, replacement, why): applied in order to every command before it runs.
SMALL = "32"      # film side of every render, in pixels
SCALE = 128 // 32  # pages show pixel coordinates of the fog box's 128x128 renders
REWRITES = [
    (r"(-D\s*resolution=)\d+", rf"\g<1>{SMALL}", "renders at 32x32 instead of the page's size"),
    (r"(-D\s*res=)\d+", rf"\g<1>{SMALL}", "NLOS captures at 32x32 wall points"),
    (r"(--resolution\s+)\d+x\d+", rf"\g<1>{SMALL}x{SMALL}", "renders at 32x32"),
    (r"(-D\s*spp=)\d+", r"\g<1>2", "2 samples per pixel (and per pass)"),
    (r"(--spp\s+)\d+", r"\g<1>2", "2 samples per pixel"),
    (r"(-D\s*passes=)\d+", r"\g<1>1", "one progressive pass"),
    (r"(--voxels\s+)\d+,\d+,\d+", r"\g<1>16,16,8", "NLOS reconstructions on 16x16x8 voxels"),
    (r"(--time-limit\s+)\S+", r"\g<1>1s", "time-bounded renders stop after 1 s"),
    (r"(:spp=)\d+(,\d+)*", r"\g<1>1,2", "budget ladders of speed-vs-error runs: 1 and 2 samples per pixel"),
    (r"(:passes=)\d+(,\d+)*", r"\g<1>1,2", "budget ladders: 1 and 2 passes"),
    (r"(--reference-budget\s+spp=)\d+", r"\g<1>8", "references of 8 samples per pixel"),
    (r"(--(?:row|column)\s+)(\d+)", lambda m: f"{m.group(1)}{int(m.group(2)) // SCALE}",
     "pixel rows and columns scaled to the 32x32 film"),
    (r"(--pixel\s+)(\d+),(\d+)", lambda m: f"{m.group(1)}{int(m.group(2)) // SCALE},{int(m.group(3)) // SCALE}",
     "pixels scaled to the 32x32 film"),
    (r"(--crop\s+)(\d+),(\d+),(\d+),(\d+)",
     lambda m: m.group(1) + ",".join(str(int(v) // SCALE) for v in m.groups()[1:]), "crops scaled to the 32x32 film"),
    (r"^((?:build/bin/)?femto compare \S+\.xml\b(?!.*--budgets).*)$", r"\1 --budgets 0.5,1 --reference-time 4",
     "integrator comparisons at budgets of 0.5 and 1 CPU s against a 4 CPU s reference"),
    (r"\$HOME/femto\b", "$PWD/prefix", "femto installs to a prefix in the test's folder, not to $HOME"),
    (r"/tmp/tfb\b", "$PWD/tfb", "out-of-tree builds go to the test's folder, not to /tmp"),
    (r"^cmake --install build\b", lambda m: f"cmake --install {BUILD}", "`cmake --install build` installs the build tested"),
    (r"^((?:build/bin/)?femto view\b(?!.*--no-browser).*)$", r"\1 --no-browser",
     "`femto view` serves without opening a browser; it passes once it prints its address"),
]
# A `femto render` of a scene gets these unless the command sets them: the
# small film and few samples of the rewrites above, no per-bin EXR frames.
RENDER_DEFAULTS = [(r"--resolution\b|-D\s*res(olution)?=", f"--resolution {SMALL}x{SMALL}"),
                   (r"--spp\b|-D\s*spp=", "--spp 2")]

# Generic input files the pages name, rendered when a page mentions them.
FOG = "scenes/cornell-box-fog/scene.xml"
FIXTURE_RENDER = f"build/bin/femto render {FOG} --resolution {SMALL}x{SMALL} --spp 2 -D frames=false --no-progress"
# file a page names -> (the stem whose files the command writes, the command)
FIXTURES = {
    "out.npy": ("out", f"{FIXTURE_RENDER} --seed 1 -o out.exr"),
    "ref.npy": ("ref", f"{FIXTURE_RENDER} --seed 2 -o ref.exr"),
    "test.npy": ("test", f"{FIXTURE_RENDER} --seed 3 -o test.exr"),
    "ref.exr": ("ref", f"{FIXTURE_RENDER} --seed 2 -o ref.exr"),
    "test.exr": ("test", f"{FIXTURE_RENDER} --seed 3 -o test.exr"),
    "path.npy": ("path", f"{FIXTURE_RENDER} --seed 4 -o path.exr"),
    "reference.npy": ("reference", f"{FIXTURE_RENDER} --seed 5 -o reference.exr"),
    "beams.npy": ("beams", f"{FIXTURE_RENDER} --seed 6 -D integrator=transient_beams -D passes=1 -o beams.exr"),
    "mask.png": ("mask", f"{FIXTURE_RENDER} --seed 7 -o mask.exr"),
    "analytic.csv": ("analytic", "printf 'time,value\\n4,0.001\\n8,0.002\\n12,0.001\\n' > analytic.csv"),
}


def pages(root, only):
    if only:
        return [root / p for p in only]
    return [root / "README.md"] + [p for p in sorted((root / "docs").glob("*.md")) if p.name != "BENCHMARKS.md"]


def commands(path):
    """(line, command) of every logical command in the page's ```sh blocks:
    continuation lines joined, blank and comment-only lines dropped."""
    out, inside, language, pending, start = [], False, "", "", 0
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        fence = FENCE.match(line.strip())
        if fence or line.strip().startswith("```"):
            inside, language = (False, "") if inside else (True, fence.group(1) if fence else "")
            continue
        if not inside or language != "sh":
            continue
        if not pending:
            start = number
        if line.rstrip().endswith("\\"):
            pending += line.rstrip()[:-1] + " "
            continue
        text = (pending + line).strip()
        pending = ""
        if text and not text.startswith("#"):
            out.append((start, text))
    return out


def skip_reason(command):
    for pattern, reason in SKIPPED:
        if re.search(pattern, command):
            return reason
    if re.search(r"\|\s*jq\b", command) and not shutil.which("jq"):
        return "pipes into jq, which is not installed (not a femto dependency)"
    if "build/python" in command and not (BUILD / "python" / "femto").exists():
        return "the Python module is not built (pybind11 missing: docs/python.md)"
    return None


def without_comment(command):
    """The command without a trailing shell comment (a '#' after a blank, outside quotes)."""
    quote = None
    for i, c in enumerate(command):
        if quote:
            quote = None if c == quote else quote
        elif c in "\"'":
            quote = c
        elif c == "#" and (i == 0 or command[i - 1].isspace()):
            return command[:i].rstrip()
    return command


def rewrite(command):
    command = without_comment(command)
    for pattern, replacement, _ in REWRITES:
        command = re.sub(pattern, replacement, command, flags=re.M)
    if re.search(r"(^|\s)(build/bin/)?femto render\b", command):
        for present, added in RENDER_DEFAULTS:
            if not re.search(present, command):
                command = re.sub(r"((?:build/bin/)?femto render)\b", rf"\1 {added}", command, count=1)
        if "--no-progress" not in command:
            command = re.sub(r"((?:build/bin/)?femto render)\b", r"\1 --no-progress", command, count=1)
    return command


def workspace(root, femto, build, folder):
    """A folder that looks like the repository's root to the pages' commands."""
    for name in ("scenes", "tools", "examples"):
        if (root / name).exists():
            (folder / name).symlink_to(root / name)
    (folder / "build" / "bin").mkdir(parents=True)
    (folder / "build" / "bin" / "femto").symlink_to(femto)
    plugins = pathlib.Path(femto).resolve().parent / "plugins"
    if plugins.exists():
        (folder / "build" / "bin" / "plugins").symlink_to(plugins)
    if (build / "python").exists():
        (folder / "build" / "python").symlink_to(build / "python")
    (folder / "out").mkdir()
    (folder / "path").mkdir()
    (folder / "path" / "femto").symlink_to(femto)


def run(command, folder, assignments, timeout):
    """Runs one command with bash; returns (ok, seconds, output)."""
    env = dict(os.environ, PATH=f"{folder / 'path'}:{os.environ.get('PATH', '/usr/bin:/bin')}")
    env["XDG_CACHE_HOME"] = str(folder / "cache")  # femto compare's references: not in the user's cache
    env.pop("FEMTO_PLUGIN_PATH", None)  # femto finds its plugins beside itself, as for a reader
    env.pop("DISPLAY", None)
    env.pop("BROWSER", None)
    server = re.search(r"(^|\s)(build/bin/)?femto view\b", command)
    script = "set -eo pipefail\n" + "".join(a + "\n" for a in assignments) + ("exec " if server else "") + command
    start = time.time()
    if server:
        return run_server(script, folder, env, timeout, start)
    try:
        p = subprocess.run(["bash", "-c", script], cwd=folder, env=env, capture_output=True, text=True,
                           timeout=timeout)
    except subprocess.TimeoutExpired as e:
        return False, time.time() - start, f"timed out after {timeout} s\n{e.stdout or ''}{e.stderr or ''}"
    return p.returncode == 0, time.time() - start, f"exit {p.returncode}\n{p.stdout}{p.stderr}"


def run_server(script, folder, env, timeout, start):
    """`femto view`: passes once it prints its address; stopped then."""
    p = subprocess.Popen(["bash", "-c", script], cwd=folder, env=env, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    output = ""
    try:
        with selectors.DefaultSelector() as selector:
            selector.register(p.stdout, selectors.EVENT_READ)
            while time.time() - start < timeout:
                if not selector.select(timeout=1.0):
                    continue
                line = p.stdout.readline()
                if not line:
                    break
                output += line
                if re.search(r"http://127\.0\.0\.1:\d+/", line):
                    return True, time.time() - start, output
        return False, time.time() - start, f"no address printed (exit {p.poll()})\n{output}"
    finally:
        p.terminate()
        try:
            p.wait(timeout=10)
        except subprocess.TimeoutExpired:
            p.kill()
            p.wait()


class Fixtures:
    """The generic input files, each rendered once into a shared folder and
    linked into the pages' folders that name it."""

    def __init__(self, root, femto, build, folder):
        self.root, self.femto, self.build, self.folder = root, femto, build, folder
        self.made = {}

    def link(self, file, into):
        stem, command = FIXTURES[file]
        if stem not in self.made:
            if not (self.folder / "build").exists():
                workspace(self.root, self.femto, self.build, self.folder)
            ok, _, output = run(command, self.folder, [], README_MAX_SECONDS)
            self.made[stem] = None if ok else f"fixture {file}: {command}\n{output}"
        if self.made[stem]:
            return self.made[stem]
        for made in self.folder.iterdir():
            if (made.name.startswith(stem + ".") or made.name.startswith(stem + "_")) and \
                    not (into / made.name).exists():
                (into / made.name).symlink_to(made)
        return None


def check_page(root, femto, build, page, report, fixtures):
    """Runs a page's commands in its own folder; returns the failures."""
    found = commands(page)
    if not found:
        return []
    name = page.relative_to(root)
    failures = []
    with tempfile.TemporaryDirectory(prefix="femto-doc-") as tmp:
        folder = pathlib.Path(tmp)
        workspace(root, femto, build, folder)
        text = page.read_text(encoding="utf-8")
        for file in FIXTURES:
            if re.search(r"(?<![\w/.-])" + re.escape(file) + r"\b", text) and not (folder / file).exists():
                problem = fixtures.link(file, folder)
                if problem:
                    failures.append(f"{name}: {problem}")
        if failures:
            return failures
        assignments = []
        for line, command in found:
            reason = skip_reason(command)
            if reason:
                report.append(f"skipped  {name}:{line}: {command}\n         ({reason})")
                continue
            if re.fullmatch(r"[A-Za-z_]\w*=\S*", command):
                assignments.append(command)  # a variable later commands of the page use
                continue
            small = rewrite(command)
            ok, seconds, output = run(small, folder, assignments, README_MAX_SECONDS)
            shown = command if small == command else f"{command}\n         as: {small}"
            report.append(f"{'ran' if ok else 'FAILED'}{'' if ok else ' '}  {name}:{line}: {shown} ({seconds:.1f} s)")
            if not ok:
                failures.append(f"{name}:{line}: {command}\n  ran as: {small}\n  " +
                                "\n  ".join(output.strip().splitlines()[-15:]))
    return failures


def self_check(root, femto, build):
    """The runner must report a wrong command as failed: a page showing a
    command that exits non-zero (a missing scene) and one that is fine."""
    with tempfile.TemporaryDirectory(prefix="femto-doc-self-") as tmp:
        page = pathlib.Path(tmp) / "page.md"
        page.write_text("```sh\nbuild/bin/femto render scenes/no-such-scene/scene.xml -o out/x.exr\n"
                        "femto --version\n```\n", encoding="utf-8")
        report = []
        failures = check_page(pathlib.Path(tmp), femto, build, page, report, None)
        if len(failures) != 1 or "no-such-scene" not in failures[0]:
            sys.exit("self-check failed: the runner did not report exactly the wrong command:\n" + "\n".join(report))


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    global BUILD
    root, femto, build = (pathlib.Path(a).resolve() for a in argv[1:4])
    BUILD = build
    if not femto.exists():
        print(f"{femto} is not built: skipped")
        return 77
    self_check(root, femto, build)
    failures, report = [], []
    with tempfile.TemporaryDirectory(prefix="femto-doc-fixtures-") as shared:
        fixtures = Fixtures(root, femto, build, pathlib.Path(shared))
        for page in pages(root, argv[4:]):
            failures += check_page(root, femto, build, page, report, fixtures)
    print("\n".join(report))
    print("\nrewrites (page command -> small command):")
    for pattern, _, why in REWRITES:
        print(f"  {why}")
    ran = sum(1 for r in report if r.startswith("ran"))
    skipped = sum(1 for r in report if r.startswith("skipped"))
    print(f"\n{ran} command(s) ran, {skipped} skipped, {len(failures)} failed")
    for failure in failures:
        print("\nFAILED " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
