"""femto.view on a tiny synthetic volume: one hot voxel shows up in the right
frame, at the right pixel, and nowhere else."""
import numpy as np
import pytest

import femto

HEIGHT, WIDTH, BINS = 4, 5, 6
Y, X, B = 2, 3, 4


@pytest.fixture
def volume():
    vol = np.zeros((HEIGHT, WIDTH, BINS, 3), dtype=np.float32)
    vol[Y, X, B] = 0.25
    return vol


def test_frames_put_the_hot_voxel_in_its_frame(volume):
    frames = femto.view.frames(volume)
    assert frames.shape == (BINS, HEIGHT, WIDTH, 3) and frames.dtype == np.uint8
    # The automatic exposure maps the (only) non-black voxel to white, to the
    # histogram's bucket width, 2^(1/32): within 2 %, so its sRGB byte is >= 252.
    assert frames[B, Y, X].min() >= 252
    frames[B, Y, X] = 0
    assert not frames.any(), "light outside the hot voxel"


def test_fixed_exposure_is_the_cli_encoding(volume):
    # 0.25 * 2^1 = 0.5 linear; sRGB(0.5) = 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354 -> byte 188.
    frames = femto.view.frames(volume, exposure=1.0)
    assert frames[B, Y, X].tolist() == [188, 188, 188]
    assert femto.view.exposure_of(volume) == pytest.approx(2.0, abs=np.log2(2 ** (1 / 32)))


def test_frames_of_a_bin_range(volume):
    frames = femto.view.frames(volume, exposure=2.0, bins=(B, None))
    assert frames.shape[0] == BINS - B and frames[0, Y, X].min() == 255


def test_streak_row_and_column(volume):
    row = femto.view.streak(volume, row=Y)
    assert row.shape == (BINS, WIDTH, 3)
    assert row[B, X, 0] == 0.25 and np.count_nonzero(row) == 3
    column = femto.view.streak(volume, column=X)
    assert column.shape == (HEIGHT, BINS, 3)
    assert column[Y, B, 0] == 0.25 and np.count_nonzero(column) == 3
    assert not femto.view.streak(volume, row=Y - 1).any()
    with pytest.raises(ValueError):
        femto.view.streak(volume, row=HEIGHT)


def test_animate_plays_every_frame(volume):
    import matplotlib
    matplotlib.use("Agg")
    animation = femto.view.animate(volume)
    shown = []
    for b in range(BINS):
        artists = animation._func(b)  # the frame callback matplotlib calls
        shown.append(np.array(artists[0].get_array()))
    hot = [b for b, image in enumerate(shown) if image.any()]
    assert hot == [B]
