"""What a benchmark table must say about where it was measured (the project's
rule: machine, load and commit), for the Python benchmark scripts; the shell
scripts use provenance.sh."""
import os
import subprocess

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def cpu_model():
    out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
    return next((l.split(":", 1)[1].strip() for l in out.splitlines() if l.startswith("Model name")), "unknown CPU")


def commit(paths=("src", "tools", "scenes")):
    """Short HEAD, marked when the sources that made the numbers differ from it."""
    head = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout
    dirty = subprocess.run(["git", "-C", ROOT, "diff", "--quiet", "HEAD", "--", *paths]).returncode
    return head.strip() + (" (with uncommitted changes)" if dirty else "")


def load_line(start, end):
    """The closing line of a table: os.getloadavg() before and after the runs."""
    return ("Load average (1, 5, 15 min) at the start: " + " ".join(f"{x:.2f}" for x in start) +
            "; at the end: " + " ".join(f"{x:.2f}" for x in end) + ".")
