#!/usr/bin/python3
"""Assemble docs/BENCHMARKS.md from one section per benchmark, so that
re-running a benchmark replaces its own section and nothing is ever appended
twice.

  tools/bench/benchmarks.py                       rebuild docs/BENCHMARKS.md from the sections
  some_benchmark | tools/bench/benchmarks.py set NAME
                                                  replace section NAME with standard input, rebuild
  tools/bench/benchmarks.py check                 exit 1 unless docs/BENCHMARKS.md is the assembly of
                                                  the sections and every section says its script,
                                                  machine and commit, with no heading repeated
  tools/bench/benchmarks.py list                  the sections, their scripts and commands

A section is docs/benchmarks/sections/<name>.md: what its script printed, from
its `## Title` on, with the provenance list every script writes
(tools/bench/provenance.py, provenance.sh: `- machine: ...`, `- commit: ...`).
An optional <name>.notes.md beside it is the hand-written reading of the
numbers (`###` headings at most); it follows the section and survives a
rerun (`set` reminds you to check it). Only the names in SECTIONS exist: a
new benchmark adds its line there, in the order the document should read.
"""
import os
import re
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
DOC = os.path.join(ROOT, "docs", "BENCHMARKS.md")
SECTIONS_DIR = os.path.join(ROOT, "docs", "benchmarks", "sections")

# (name, the command that regenerates it). The order is the document's.
SECTIONS = [
    ("ray-casting", "tools/bench/run_ray_bench.sh"),
    ("mpi-scaling", "tools/bench/run_mpi_bench.sh"),
    ("tile-heap", "tools/bench/tile_heap.sh"),
    ("many-scenes", "tools/bench/many_scenes.py"),
    ("transient-path", "tools/bench/run_transient_bench.sh"),
    ("path-sampling", "tools/bench/path_sampling_bench.py --seeds 3"),
    ("path-sampling-heterogeneous", "tools/bench/path_sampling_bench.py --seeds 3 --only c"),
    ("path-peer", "tools/compare/tof_peer_path.py --only 1"),
    ("path-peer-protocols", "tools/compare/tof_peer_path.py --only 2"),
    ("fog-box-speed-vs-error", "tools/bench/fog_box_benchmark.sh"),
    ("media-suite", "tools/bench/run_media_suite.sh"),
    ("fog-box-beams", "tools/bench/fog_box_beams.py --resolution 64 --seeds 2 --repeats 3"),
    ("mitransient-peer", "tools/bench/mitransient_peer.py"),
    ("time-splitting", "tools/bench/time_splitting.py"),
    ("beams-time-splitting", "tools/bench/beams_option.py --option time_splitting --seeds 3"),
    ("beams-stratified-photons", "tools/bench/beams_option.py --option stratified_photons --seeds 6"),
    ("time-gating", "tools/bench/time_gating.py"),
    ("beams-pass-split", "tools/bench/beams_pass_split.py --resolution 64 --seeds 2"),
    ("beams-peer", "tools/compare/tof_peer.py --passes 4,16,64 --seeds 2"),
    ("beams-port-window-sum-4", "tools/compare/tof_port_window_sum.py --seeds 8 --passes 4 --spp 2"),
    ("beams-port-window-sum-16", "tools/compare/tof_port_window_sum.py --seeds 8 --passes 16 --spp 2"),
    ("beams-alpha", "tools/bench/beams_alpha.py --passes 8 --seeds 2"),
    ("beams-alpha-64", "tools/bench/beams_alpha.py --alphas 0.7,0.9 --passes 64 --seeds 1"),
    ("beams-bias", "tools/bench/beams_bias.py --passes 4,32 --pass-runs 768"),
    ("gather-roulette", "tools/bench/gather_roulette.py --seeds 3"),
    ("surface-radius", "tools/bench/surface_radius_sweep.py --medium fog"),
    ("surface-radius-no-medium", "tools/bench/surface_radius_sweep.py --medium none"),
    ("beam-map", "tools/bench/run_beam_bench.sh"),
    ("transient-beams-cost", "tools/bench/run_beams_scaling.sh"),
]

INTRO = """\
# Benchmarks

Every number here comes from a script in the repository, run on the machine
and at the commit its section names (CPU time of the femto process unless a
section says otherwise; the machines were shared, so wall times carry their
load). This file is assembled by `tools/bench/benchmarks.py` from one file per
section in `docs/benchmarks/sections/`: rerunning a benchmark replaces its own
section (`SCRIPT | tools/bench/benchmarks.py set NAME`); edit the sections'
`*.notes.md` (the readings), never this file. Derivations and the history of
how the defaults were chosen are in [design/](design/README.md).

| section | script | machine | commit |
|---|---|---|---|
"""

FENCE = re.compile(r"^(```|~~~)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*$")


def section_path(name, notes=False):
    return os.path.join(SECTIONS_DIR, name + (".notes.md" if notes else ".md"))


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def headings(text):
    """(level, title) of the Markdown headings outside code fences."""
    inside = False
    for line in text.splitlines():
        if FENCE.match(line.strip()):
            inside = not inside
        elif not inside:
            m = HEADING.match(line)
            if m:
                yield len(m.group(1)), m.group(2)


def slug(title):
    """GitHub's anchor of a heading."""
    return re.sub(r"[^\w\- ]", "", title.lower().replace("`", "").replace("*", "")).replace(" ", "-")


def provenance(text):
    """(script, machine, commit) a section states, '' where it states none."""
    def field(pattern):
        m = re.search(pattern, text, re.M)
        return m.group(1).strip() if m else ""
    script = field(r"Generated by `([^`]+)`")
    machine = field(r"^- machine: ([^,;\n]+)")
    commit = field(r"^- commit: ([0-9a-f]{7,40}(?: \(with uncommitted changes\))?)")
    return script, machine, commit


def problems_of_section(name, text, notes):
    levels = list(headings(text))
    if not levels or levels[0][0] != 2 or not text.startswith("## "):
        yield f"{name}: a section starts with its '## Title' line"
    if any(level < 2 for level, _ in levels):
        yield f"{name}: a top-level '#' heading inside the section"
    script, machine, commit = provenance(text)
    for what, value in (("Generated by `SCRIPT`", script), ("- machine: ...", machine), ("- commit: HASH", commit)):
        if not value:
            yield f"{name}: the section does not state its {what}"
    if notes is not None and any(level < 3 for level, _ in headings(notes)):
        yield f"{name}.notes.md: a reading's headings are '###' or deeper (it sits inside its section)"


def assemble(texts):
    """The document from {name: (section, notes or None)}."""
    rows, body = [], []
    for name, _ in SECTIONS:
        section, notes = texts[name]
        title = next(t for level, t in headings(section) if level == 2)
        script, machine, commit = provenance(section)
        rows.append(f"| [{title}](#{slug(title)}) | `{script}` | {machine} | {commit} |")
        body.append(section.strip("\n") + "\n")
        if notes:
            body.append(notes.strip("\n") + "\n")
    return INTRO + "\n".join(rows) + "\n\n" + "\n".join(body)


def load(replace=None):
    """Every section's text (and notes), with `replace` = (name, text) in place
    of the stored one; and the problems found in them."""
    texts, problems = {}, []
    names = [name for name, _ in SECTIONS]
    for name in names:
        path, notes_path = section_path(name), section_path(name, notes=True)
        if replace and replace[0] == name:
            section = replace[1]
        elif os.path.exists(path):
            section = read(path)
        else:
            problems.append(f"{name}: {os.path.relpath(path, ROOT)} is missing")
            continue
        notes = read(notes_path) if os.path.exists(notes_path) else None
        problems += problems_of_section(name, section, notes)
        texts[name] = (section, notes)
    for file in sorted(os.listdir(SECTIONS_DIR)):
        stem = file[:-len(".notes.md")] if file.endswith(".notes.md") else file[:-3]
        if stem not in names:
            problems.append(f"docs/benchmarks/sections/{file}: no section of that name in tools/bench/benchmarks.py")
    if not problems:
        seen = {}
        for _, title in headings(assemble(texts)):
            key = title.lower()
            if key in seen:
                problems.append(f"heading \"{title}\" appears twice in docs/BENCHMARKS.md")
            seen[key] = True
    return texts, problems


def write(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


def main(argv):
    command = argv[1] if len(argv) > 1 else "build"
    if command == "list":
        for name, script in SECTIONS:
            print(f"{name:28} {script}")
        return 0
    if command == "set":
        if len(argv) != 3:
            sys.exit("usage: SCRIPT | benchmarks.py set NAME")
        name = argv[2]
        if name not in dict(SECTIONS):
            sys.exit(f"error: no benchmark section \"{name}\"; the sections are: {', '.join(n for n, _ in SECTIONS)}"
                     " (a new one adds its line to SECTIONS in tools/bench/benchmarks.py)")
        text = sys.stdin.read().strip("\n") + "\n"
        texts, problems = load(replace=(name, text))
        if problems:
            sys.exit("error: section not written:\n  " + "\n  ".join(problems))
        write(section_path(name), text)
        write(DOC, assemble(texts))
        print(f"wrote {os.path.relpath(section_path(name), ROOT)} and docs/BENCHMARKS.md")
        if texts[name][1]:
            print(f"note: {os.path.relpath(section_path(name, True), ROOT)} reads the previous numbers: check it",
                  file=sys.stderr)
        return 0
    if command in ("build", "check"):
        texts, problems = load()
        if not problems:
            doc = assemble(texts)
            if command == "build":
                write(DOC, doc)
                print("wrote docs/BENCHMARKS.md")
            elif not os.path.exists(DOC) or read(DOC) != doc:
                problems.append("docs/BENCHMARKS.md is not the assembly of docs/benchmarks/sections/ "
                                "(edit the sections, then run tools/bench/benchmarks.py)")
        for problem in problems:
            print(problem)
        if command == "check":
            print(f"{len(problems)} problem(s) in docs/BENCHMARKS.md")
        return 1 if problems else 0
    sys.exit(f"usage: benchmarks.py [build|set NAME|check|list] (got \"{command}\")")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
