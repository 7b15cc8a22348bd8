"""Ctrl-C during scene.render(): a real SIGINT to this process stops the
render after the tiles in flight and raises KeyboardInterrupt carrying the
partial result (finished tiles rendered, the rest black)."""
import os
import signal
import threading
import time

import numpy as np

import femto
from conftest import FOG_BOX, TINY_FOG_BOX


def test_ctrl_c_raises_keyboard_interrupt_with_the_partial_result():
    # 256x256: 64 tiles of about a second each on one thread; a minute in all.
    scene = femto.load_file(FOG_BOX, **dict(TINY_FOG_BOX, resolution=256, bins=8, bin_width=1.28, medium="none"))
    sent = []

    def ctrl_c():
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(1.0, ctrl_c)
    timer.start()
    try:
        scene.render(spp=512, threads=1)
    except KeyboardInterrupt as e:
        stopped = time.monotonic()
        result = e.result
    else:
        raise AssertionError("the render finished before Ctrl-C: make it longer")
    finally:
        timer.cancel()
    assert sent, "interrupted before the timer fired"
    assert stopped - sent[0] < 20, "the render did not stop promptly"
    assert not result.completed
    assert result.transient.shape == (256, 256, 8, 3)
    assert result.steady[:32, :32].sum() > 0, "the first tile was finished"
    assert not result.transient[-32:, -32:].any(), "the last tile was never started"
    assert np.isfinite(result.steady).all()
