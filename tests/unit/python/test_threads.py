"""The arrays depend on scene, spp and seed only, not on the thread count;
the progress callback gets the fraction and ETA the CLI's bar shows."""
import femto
from conftest import FOG_BOX, TINY_FOG_BOX, same_bits


def test_thread_count_does_not_change_the_arrays():
    # 48x48 pixels: four tiles of 32, so two threads really render in parallel.
    scene = femto.load_file(FOG_BOX, **dict(TINY_FOG_BOX, resolution=48))
    one = scene.render(seed=3, threads=1)
    two = scene.render(seed=3, threads=2)
    default = scene.render(seed=3)
    assert same_bits(one.transient, two.transient) and same_bits(one.transient, default.transient)
    assert same_bits(one.steady, two.steady)


def test_progress_reports_fraction_and_eta():
    scene = femto.load_file(FOG_BOX, **dict(TINY_FOG_BOX, resolution=96))
    reports = []
    scene.render(spp=16, threads=1, progress=reports.append)
    assert reports, "no progress report"
    assert all(isinstance(r, femto.Progress) for r in reports)
    last = reports[-1]
    assert last.finished and last.fraction == 1.0 and last.eta is None
    fractions = [r.fraction for r in reports]
    assert fractions == sorted(fractions)
    for r in reports[:-1]:
        # The bar's ETA: time so far extrapolated over what is left.
        if r.eta is not None:
            assert abs(r.eta - r.elapsed * (1 - r.fraction) / r.fraction) < 1e-6
    assert "%" in str(last)


def test_exception_in_progress_stops_the_render():
    # Seconds of work on one thread, far more than the bar's first redraw (100 ms).
    scene = femto.load_file(FOG_BOX, **dict(TINY_FOG_BOX, resolution=128, medium="none"))

    class Stop(Exception):
        pass

    def stop(report):
        raise Stop()

    try:
        scene.render(spp=256, threads=1, progress=stop)
    except Stop as e:
        assert not e.result.completed
    else:
        raise AssertionError("the callback's exception was swallowed")
