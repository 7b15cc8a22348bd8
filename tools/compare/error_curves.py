"""Pure functions of speed-vs-error curves (no rendering, no plotting).

A curve is a list of (seconds, error) points of one integrator at increasing
budgets. Between measured points, error is interpolated linearly in log-log
space (Monte Carlo error falls as a power of time, a straight line there).
Tested by test_error_curves.py.
"""
import math
import re


class SpecError(ValueError):
    """A command-line value the harness cannot use (one sentence)."""


def parse_integrator_spec(text):
    """'transient_path:spp=1,2,4' -> ('transient_path', 'spp', [1, 2, 4])."""
    m = re.fullmatch(r"([A-Za-z_][A-Za-z0-9_]*):([A-Za-z_][A-Za-z0-9_]*)=([0-9,]+)", text)
    if not m:
        raise SpecError(f"--integrator expects NAME:PARAM=B1,B2,... (e.g. transient_path:spp=1,2,4), got {text!r}")
    budgets = [int(b) for b in m.group(3).split(",") if b]
    if not budgets or min(budgets) < 1:
        raise SpecError(f"--integrator {text!r}: budgets must be whole numbers >= 1")
    return m.group(1), m.group(2), sorted(set(budgets))


def parse_define(text):
    """'name=value' -> ('name', 'value')."""
    name, sep, value = text.partition("=")
    if not sep or not name:
        raise SpecError(f"-D expects name=value, got {text!r}")
    return name, value


def _log_interp(x, x0, y0, x1, y1):
    """y at x on the straight line through (x0, y0), (x1, y1) in log-log space."""
    if x1 == x0:
        return y0
    t = (math.log(x) - math.log(x0)) / (math.log(x1) - math.log(x0))
    return math.exp(math.log(y0) + t * (math.log(y1) - math.log(y0)))


def _positive(points):
    return sorted((t, e) for t, e in points if t > 0 and e > 0)


def error_at_time(points, seconds):
    """Error of the curve at `seconds` (log-log interpolation), or None
    outside the measured time range."""
    pts = _positive(points)
    if not pts or seconds < pts[0][0] or seconds > pts[-1][0]:
        return None
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if t0 <= seconds <= t1:
            return _log_interp(seconds, t0, e0, t1, e1)
    return pts[0][1]  # a single point, at exactly its time


def time_to_reach(points, target):
    """First time at which the curve's error falls to `target` (log-log
    interpolation between the two budgets around the crossing), or None if
    it never does."""
    pts = _positive(points)
    if not pts:
        return None
    if pts[0][1] <= target:
        return pts[0][0]
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if e1 <= target < e0:
            # Invert the log-log line: time as a function of error.
            return _log_interp(target, e0, t0, e1, t1)
    return None


def common_target(curves):
    """An error every curve reaches: the largest of their smallest errors."""
    lows = [min(e for _, e in _positive(pts)) for pts in curves.values() if _positive(pts)]
    return max(lows) if lows else None


def common_time_range(curves):
    """(earliest, latest) time inside every curve's measured range, or None."""
    ranges = [(_positive(p)[0][0], _positive(p)[-1][0]) for p in curves.values() if _positive(p)]
    if not ranges:
        return None
    start, end = max(r[0] for r in ranges), min(r[1] for r in ranges)
    return (start, end) if start <= end else None


def common_time(curves):
    """A time inside every curve's measured range (the latest such time), or None."""
    span = common_time_range(curves)
    return span[1] if span else None


def equal_time_ratios(curves, baseline, seconds):
    """error(integrator) / error(baseline) at `seconds`, for every integrator
    (None where a curve does not cover that time)."""
    base = error_at_time(curves[baseline], seconds)
    ratios = {}
    for name, pts in curves.items():
        e = error_at_time(pts, seconds)
        ratios[name] = e / base if e is not None and base else None
    return ratios


def convergence_slope(points):
    """Least-squares slope of log(error) against log(time): -1 is the Monte
    Carlo rate (relMSE ~ 1/time)."""
    pts = _positive(points)
    if len(pts) < 2:
        return None
    xs = [math.log(t) for t, _ in pts]
    ys = [math.log(e) for _, e in pts]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    if sxx == 0:
        return None
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx


def error_at(points, seconds, slack=1.0):
    """(error, extrapolated) of the curve at `seconds`: log-log interpolation
    inside its measured time range; outside it, the Monte Carlo rate from the
    nearest end (error ~ 1/time: e_end * t_end / seconds), flagged
    extrapolated when `seconds` lies more than a factor `slack` outside the
    range (a render that stopped at 0.399 s of a 0.4 s budget is not worth a
    flag). (None, False) for a curve with no positive point."""
    pts = _positive(points)
    if not pts:
        return None, False
    if seconds < pts[0][0]:
        return pts[0][1] * pts[0][0] / seconds, seconds * slack < pts[0][0]
    if seconds > pts[-1][0]:
        return pts[-1][1] * pts[-1][0] / seconds, seconds > pts[-1][0] * slack
    return error_at_time(pts, seconds), False


def efficiency_ratio(baseline, other, seconds, slack=1.0):
    """(ratio, extrapolated): error(baseline) / error(other) at equal time
    `seconds`, i.e. how many times more efficient `other` is (relMSE x time is
    constant along a slope -1 curve, so this is also the ratio of relMSE x
    time). Either curve may be extrapolated (error_at): then the flag is set.
    (None, False) when a curve has no positive point."""
    b, bx = error_at(baseline, seconds, slack)
    o, ox = error_at(other, seconds, slack)
    if b is None or o is None:
        return None, False
    return b / o, bx or ox


def shared_error_target(curves):
    """An error inside every curve's measured error range (the geometric mean
    of the overlap [largest of the smallest errors, smallest of the largest]),
    so that every time to reach it is interpolated, never a bound; None when
    the ranges do not overlap."""
    ranges = [(min(e for _, e in _positive(p)), max(e for _, e in _positive(p))) for p in curves.values()
              if _positive(p)]
    if len(ranges) < len(curves) or not ranges:
        return None
    low, high = max(r[0] for r in ranges), min(r[1] for r in ranges)
    return math.sqrt(low * high) if low <= high else None


def split_bins_by_share(energy, k):
    """K consecutive bands of bins [(first, end), ...] where band j holds the
    bins whose light arrives once j/K and before (j+1)/K of the total has
    (cumulative share at the bin's end). Every band holds at least one bin."""
    total = sum(energy)
    n = len(energy)
    if k < 1 or n < k:
        raise SpecError(f"cannot split {n} time bins into {k} bands")
    ends, acc = [], 0.0
    for b, e in enumerate(energy):
        acc += e
        # Bin b closes band len(ends) once the light up to it reaches the band's share.
        while len(ends) < k - 1 and total > 0 and acc >= total * (len(ends) + 1) / k:
            ends.append(b + 1)
    while len(ends) < k - 1:
        ends.append(n)
    edges = [0] + ends + [n]
    # At least one bin per band, in order.
    for j in range(1, k + 1):
        edges[j] = max(edges[j], edges[j - 1] + 1)
    for j in range(k - 1, 0, -1):
        edges[j] = min(edges[j], edges[j + 1] - 1)
    return [(edges[j], edges[j + 1]) for j in range(k)]
