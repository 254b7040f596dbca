"""A plain-text progress bar with an estimate of the time left (stderr, no dependency).

On a terminal the bar is redrawn in place; in a log file (anything that is not a tty) one line is
written per finished point, so that a batch job's log shows the progress too::

    sweep   12/30 [########............]  40%  0:12 elapsed  ~0:18 left  adhesive ζ=0.01 converged

The estimate divides the time spent in this run by the points finished in this run (points taken
over from an interrupted run do not count), times the points still to do. The total can change
while the study runs (a cycle's retraction ends when the profile detaches).
"""
from __future__ import annotations

import sys
import time
from typing import TextIO


def _clock(seconds: float) -> str:
    seconds = int(round(seconds))
    h, rest = divmod(seconds, 3600)
    m, s = divmod(rest, 60)
    return f"{h}:{m:02d}:{s:02d}" if h else f"{m}:{s:02d}"


class Progress:
    """Progress of ``total`` points, ``done`` of which were finished before this run.

    Parameters
    ----------
    label : str
        First word of the line (``"sweep"``, ``"cycle"``).
    total : int
        Points expected (may be updated with :meth:`update`).
    done : int
        Points already finished (resumed study).
    stream : file, optional
        Default :data:`sys.stderr`; ``None`` disables the output.
    width : int
        Characters of the bar.
    """

    def __init__(self, label: str, total: int, done: int = 0, stream: TextIO | None = sys.stderr,
                 width: int = 20, clock=time.monotonic):
        self.label, self.total, self.done = label, max(int(total), 0), int(done)
        self.stream, self.width, self.clock = stream, width, clock
        self.resumed = self.done
        self.start = clock()
        self.tty = bool(stream is not None and getattr(stream, "isatty", lambda: False)())
        self._drawn = False

    def line(self, note: str = "") -> str:
        """The progress text (without line ending)."""
        total = max(self.total, self.done, 1)
        frac = self.done / total
        filled = int(round(self.width * frac))
        elapsed = self.clock() - self.start
        fresh = self.done - self.resumed
        if fresh > 0:
            left = f"~{_clock(elapsed / fresh * (total - self.done))} left"
        else:
            left = "? left"
        digits = len(str(total))
        text = (f"{self.label} {self.done:>{digits}}/{total} [{'#' * filled}"
                f"{'.' * (self.width - filled)}] {100 * frac:3.0f}%  {_clock(elapsed)} elapsed  "
                f"{left}")
        return f"{text}  {note}" if note else text

    def update(self, done: int | None = None, total: int | None = None, note: str = "") -> None:
        """Record progress (``done`` defaults to one more point) and redraw."""
        self.done = self.done + 1 if done is None else int(done)
        if total is not None:
            self.total = int(total)
        if self.stream is None:
            return
        text = self.line(note)
        if self.tty:
            self.stream.write("\r" + text + "\x1b[K")
            self._drawn = True
        else:
            self.stream.write(text + "\n")
        self.stream.flush()

    def close(self, message: str = "") -> None:
        """End the bar (a newline on a terminal) and write ``message`` on its own line."""
        if self.stream is None:
            return
        if self.tty and self._drawn:
            self.stream.write("\n")
        if message:
            self.stream.write(message + "\n")
        self.stream.flush()
