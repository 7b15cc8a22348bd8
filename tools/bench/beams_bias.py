#!/usr/bin/python3
"""transient_beams' bias at default settings on bounded media, against the
closed form of single scattering (issue 14: below 0.5 % of the window sum,
falling with the passes); prints the Markdown of docs/BENCHMARKS.md's
"Beams' bias against closed forms" section.

  tools/bench/beams_bias.py [--passes 4,16,64] [--pass-runs 192] \
      | tools/bench/benchmarks.py set beams-bias

Runs the CI tests TransientBeamsClosedForm.* (tests/unit/integrators/
transient_beams/test_transient_beams_closed_form.cpp: 8x8 pixels, the
derived radius, max_depth 2) with more runs than CI does
(FEMTO_CLOSED_FORM_RUNS, FEMTO_CLOSED_FORM_PASSES): each run is a render
with its own seed, so the runs' mean has a standard error from their spread,
and runs x passes = --pass-runs at every budget (equal cost). The closed form
integrates each pixel over 16x16 sub-rays (the test's reference). A bias is
shown below 0.5 % when |mean - 1| + 2 s.e. is. CI's tests use 4 runs of 3 passes.
"""
import argparse
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from provenance import ROOT, header, load_line  # noqa: E402

# Test name -> (label printed by the test, what it is).
# (Without observer time the window holds the same light from the same
# beams: its sums equal these, so those tests are not repeated.)
CASES = [
    ("BoundedMediumWithObserverTime", "sphere", "sphere of medium seen from outside"),
    ("CameraAndLightInsideASphereWithObserverTime", "sphere-inside", "camera and light inside a sphere"),
    ("SphereLitBesideTheCameraObliquePairs", "oblique", "sphere lit from beside the camera (oblique pairs)"),
]
WINDOW = re.compile(r"^(\S+) window: beams (\S+) \+- (\S+), closed form (\S+)")


def run_case(build, test, passes, runs, alpha):
    env = dict(os.environ, FEMTO_CLOSED_FORM_PASSES=str(passes), FEMTO_CLOSED_FORM_RUNS=str(runs),
               FEMTO_PLUGIN_PATH=os.path.join(build, "bin", "plugins"))
    if alpha is not None:
        env["FEMTO_CLOSED_FORM_ALPHA"] = str(alpha)
    out = subprocess.run([os.path.join(build, "bin", "femto_unit_tests"),
                          f"--gtest_filter=TransientBeamsClosedForm.{test}"],
                         env=env, capture_output=True, text=True).stdout
    for line in out.splitlines():
        m = WINDOW.match(line)
        if m:
            return float(m.group(2)), float(m.group(3)), float(m.group(4)), "[  PASSED  ]" in out
    raise RuntimeError(f"no window line from {test}:\n{out[-2000:]}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--passes", default="4,16,64")
    parser.add_argument("--pass-runs", type=int, default=192, help="runs x passes per row")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--alpha", type=float, default=None, help="the radius reduction (default: the integrator's)")
    args = parser.parse_args()
    budgets = [int(p) for p in args.passes.split(",")]
    load_start = os.getloadavg()
    header("Beams' bias against closed forms", "tools/bench/beams_bias.py",
           f"tools/bench/beams_bias.py --passes {args.passes} --pass-runs {args.pass_runs}"
           f"{'' if args.alpha is None else f' --alpha {args.alpha}'}",
           [f"transient_beams at its defaults (derived radius, alpha {args.alpha or 'as the integrator reads it'}), max_depth 2, "
            "8×8 pixels; runs × passes "
            f"= {args.pass_runs} per row; window sum over the closed form of single scattering"])
    print("| scene | passes | runs | window / closed form − 1 | standard error | bias shown below 0.5 % | "
          "CI test's verdict |")
    print("|---|---|---|---|---|---|---|")
    for test, label, what in CASES:
        for passes in budgets:
            runs = max(2, args.pass_runs // passes)
            est, se, ref, passed = run_case(args.build, test, passes, runs, args.alpha)
            rel, rel_se = est / ref - 1.0, se / ref
            shown = "yes" if abs(rel) + 2.0 * rel_se < 0.005 else "no"
            print(f"| {what} | {passes} | {runs} | {100 * rel:+.2f} % | {100 * rel_se:.2f} % | {shown} | "
                  f"{'passed' if passed else 'failed'} |")
            sys.stdout.flush()
    print()
    print(load_line(load_start, os.getloadavg()))


if __name__ == "__main__":
    main()
