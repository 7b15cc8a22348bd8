"""The log-log plot of error against render time, one line per integrator,
with the machine and commit in the caption (Debian's matplotlib)."""
import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402


def _monte_carlo_guide(ax, rows, metric, time_key):
    """A dotted line of slope -1 (error ~ 1/time, the Monte Carlo rate of
    relMSE and MSE) through the first integrator's cheapest point."""
    first = [r for r in rows if r["integrator"] == rows[0]["integrator"]]
    pts = sorted((float(r[time_key]), float(r[metric])) for r in first)
    pts = [p for p in pts if p[0] > 0 and p[1] > 0]
    if len(pts) < 2:
        return
    (t0, e0), t1 = pts[0], pts[-1][0]
    ax.loglog([t0, t1], [e0, e0 * t0 / t1], ":", color="0.5", linewidth=1, label="slope -1 (Monte Carlo)")


def plot_error_vs_time(rows, path, title, caption, metric="relmse", time_key="seconds", corrected_metric=None):
    """rows: dicts with integrator, budget_param, budget, `time_key`, `metric`
    (and `corrected_metric`, if given: the error with the reference's own
    subtracted, drawn dashed in the integrator's colour; values <= 0 are left
    out). Writes `path` (.png or .svg, by extension)."""
    fig, ax = plt.subplots(figsize=(6.4, 4.4), dpi=100)
    integrators = list(dict.fromkeys(r["integrator"] for r in rows))
    for name in integrators:
        pts = sorted((float(r[time_key]), float(r[metric]), r) for r in rows if r["integrator"] == name)
        pts = [p for p in pts if p[0] > 0 and p[1] > 0]
        if not pts:
            continue
        line, = ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=name)
        for t, e, r in (pts[0], pts[-1]):
            ax.annotate(f"{r['budget_param']}={r['budget']}", (t, e), textcoords="offset points",
                        xytext=(4, 4), fontsize=7, color=line.get_color())
        if corrected_metric:
            fixed = sorted((float(r[time_key]), float(r[corrected_metric])) for r in rows if r["integrator"] == name)
            fixed = [p for p in fixed if p[0] > 0 and p[1] > 0]
            ax.loglog([p[0] for p in fixed], [p[1] for p in fixed], "x--", color=line.get_color(), linewidth=1,
                      label=f"{name}, reference's error subtracted")
    _monte_carlo_guide(ax, rows, metric, time_key)
    ax.set_xlabel({"cpu_seconds": "CPU time of the femto process, user + system (s)",
                   "wall_seconds": "wall time of the femto process (s)"}.get(time_key, "render time (s)"))
    ax.set_ylabel({"relmse": "relMSE", "mse": "MSE", "mae": "MAE"}.get(metric, metric))
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.text(0.01, 0.01, caption, fontsize=6.5, va="bottom", ha="left", wrap=True)
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    fig.savefig(path)
    plt.close(fig)
