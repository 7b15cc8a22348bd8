"""What a render hands back: arrays, the time axis, the render's statistics."""
import dataclasses
from typing import Optional

import numpy as np

# Speed of light in vacuum (m/s): OPL in metres / c = seconds (femto/time/time_grid.h).
SPEED_OF_LIGHT = 299792458.0


@dataclasses.dataclass(frozen=True)
class TimeAxis:
    """The transient film's bins: bin i covers OPL [edges_opl[i], edges_opl[i+1])."""
    bins: int
    start_opl: float
    bin_width_opl: float

    @property
    def edges_opl(self) -> np.ndarray:
        """bins + 1 edges, optical path length in scene units."""
        return self.start_opl + self.bin_width_opl * np.arange(self.bins + 1, dtype=np.float64)

    @property
    def edges_seconds(self) -> np.ndarray:
        """The edges in seconds, for a scene in metres (OPL / c)."""
        return self.edges_opl / SPEED_OF_LIGHT

    @property
    def centers_opl(self) -> np.ndarray:
        return self.start_opl + self.bin_width_opl * (np.arange(self.bins, dtype=np.float64) + 0.5)


@dataclasses.dataclass(frozen=True)
class Progress:
    """What the CLI's progress bar shows, handed to render(progress=...)."""
    label: str
    fraction: float          # of the whole job done, 0..1 (every pass, then the frames), as the CLI's bar
    elapsed: float           # seconds
    eta: Optional[float]     # seconds left, linear extrapolation; None while unknown and when finished
    finished: bool

    def __str__(self):
        eta = "" if self.eta is None else f", ETA {self.eta:.0f}s"
        return f"{self.label} {100 * self.fraction:5.1f}% ({self.elapsed:.0f}s{eta})"


@dataclasses.dataclass
class RenderResult:
    """One render. After a Ctrl-C (completed False) the arrays hold the tiles
    finished before the stop and black elsewhere, as `femto render` writes them."""
    steady: np.ndarray                   # height x width x 3 float32 (the crop window)
    transient: Optional[np.ndarray]      # height x width x bins x 3 float32, or None for a steady film
    before: Optional[np.ndarray]         # light arriving before the time window (height x width x 3)
    after: Optional[np.ndarray]          # light arriving at or after its end
    time_axis: Optional[TimeAxis]
    completed: bool
    samples: int
    invalid_samples: int
    seconds: float
    files: dict                          # the files written, when render(output=...) kept them; else {}
    cpu_seconds: float = 0.0             # the process's CPU time (all threads) while the passes rendered
    passes: int = 0                      # passes rendered (of spp_per_pass samples per pixel each)
    spp_per_pass: int = 0
    time_limit_reached: bool = False     # render(time_limit=...) ended the passes

    @property
    def memory_mapped(self) -> bool:
        """Is .transient a read-only map of the streamed .npy rather than a copy in memory?"""
        return isinstance(self.transient, np.memmap)
