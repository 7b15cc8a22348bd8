#!/usr/bin/env python3
"""The fog Cornell box rendered from Python at two budgets with both transient
integrators: a pixel's time profile and each render's relMSE against a longer
reference (docs/python.md).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/fog_box_budgets.py [--resolution 32] [-o out/fog-budgets.png]
"""
import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # a file, no window
import matplotlib.pyplot as plt  # noqa: E402

import femto  # noqa: E402

SCENE = Path(__file__).resolve().parents[2] / "scenes" / "cornell-box-fog" / "scene.xml"
# Each integrator's budget: camera samples per pixel for transient_path,
# progressive passes (32 camera samples each) for transient_beams.
BUDGETS = {
    "transient_path": [{"spp": 8}, {"spp": 64}],
    "transient_beams": [{"passes": 1}, {"passes": 4}],
}
REFERENCE = {"integrator": "transient_path", "spp": 1024}


def render(resolution, integrator, spp=None, passes=None, seed=0):
    # 128 bins of 0.08 cover the scene's window (OPL 3 to 13.24); no per-bin EXRs.
    defines = dict(resolution=resolution, bins=128, bin_width=0.08, frames=False, integrator=integrator)
    if passes is not None:
        defines["passes"] = passes
    scene = femto.load_file(SCENE, **defines)
    return scene.render(spp=spp, seed=seed, progress=lambda p: print(f"\r{integrator}: {p}", end="", flush=True))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--resolution", type=int, default=32)
    parser.add_argument("-o", "--output", default="out/fog-budgets.png")
    args = parser.parse_args()

    reference = render(args.resolution, REFERENCE["integrator"], spp=REFERENCE["spp"], seed=1000)
    print()
    renders = []
    for integrator, budgets in BUDGETS.items():
        for budget in budgets:
            result = render(args.resolution, integrator, **budget)
            relmse = femto.compare(reference, result)["metrics"]["relmse"]  # results: time windows checked
            label = f"{integrator} {', '.join(f'{k}={v}' for k, v in budget.items())}"
            print(f"\n{label}: {result.seconds:.2f} s, relMSE {relmse:.4g}")
            renders.append((label, result, relmse))

    # A pixel on the back wall, below the light: the direct pulse, then the fog's and the walls' echoes.
    y, x = args.resolution // 2, args.resolution // 2
    opl = reference.time_axis.centers_opl
    figure, (profile, errors) = plt.subplots(1, 2, figsize=(11, 4))
    profile.plot(opl, reference.transient[y, x, :, 1], "k", lw=2, label="reference")
    for label, result, _ in renders:
        profile.plot(opl, result.transient[y, x, :, 1], lw=1, label=label)
    profile.set(xlabel="optical path length", ylabel="radiance (green)", title=f"pixel ({x}, {y})")
    profile.legend(fontsize=7)
    errors.barh([label for label, _, _ in renders], [relmse for _, _, relmse in renders])
    errors.set(xscale="log", xlabel="relMSE of the volume", title="error against the reference")
    figure.tight_layout()
    Path(args.output).parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
