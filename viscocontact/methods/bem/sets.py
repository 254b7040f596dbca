"""Contact sets as values: the control of a solve and where points lie relative to contacts."""
from __future__ import annotations

import attrs
import numpy as np

from ...contact.topology import TWO_PI

#: Contacts narrower than this detach; contacts closer than ``MIN_GAP`` merge (q0-scaled).
MIN_WIDTH = 1e-8
MIN_GAP = 1e-8


@attrs.frozen
class Control:
    """What is held fixed in an equilibrium: the penetration ``Δ̃`` or the mean pressure ``p̃∞``.

    ``Control.penetration(d)`` and ``Control.load(p)`` build one; :meth:`fields_kwargs` is what
    :func:`~viscocontact.contact.fields.solve_fields` takes.
    """

    kind: str = attrs.field(validator=attrs.validators.in_(("penetration", "mean_pressure")))
    value: float = attrs.field(converter=float)

    @classmethod
    def penetration_of(cls, value: float) -> "Control":
        return cls("penetration", value)

    @classmethod
    def load_of(cls, value: float) -> "Control":
        return cls("mean_pressure", value)

    @property
    def is_load(self) -> bool:
        return self.kind == "mean_pressure"

    def fields_kwargs(self) -> dict:
        return {self.kind: self.value}


def inside(x, edges, closed: bool) -> np.ndarray:
    """Which of the points ``x`` lie in a contact ``[edges[2j], edges[2j+1]]`` (periodic;
    ``closed``: the edges count as inside)."""
    inside = np.zeros(np.shape(x), bool)
    for a, b in zip(edges[0::2], edges[1::2]):
        for shift in (-TWO_PI, 0.0, TWO_PI):
            xs = x + shift
            inside |= ((xs >= a) & (xs <= b)) if closed else ((xs > a) & (xs < b))
    return inside


def necks(edges, move) -> tuple[np.ndarray, np.ndarray]:
    """``(width, closing)`` of every neck, right edge ``j`` to left edge ``j + 1`` (the last
    across the period): its width between ``edges``, and how much the move ``move`` of the
    edges narrows it (negative: it widens)."""
    x, move = np.asarray(edges, dtype=float), np.asarray(move, dtype=float)
    width = np.roll(x, -1)[1::2] - x[1::2]
    width[-1] += TWO_PI
    return width, move[1::2] - np.roll(move, -1)[1::2]


def first_touch(shape):
    """Penetration and edges of the first contact at the highest peak of a normalised profile:
    a contact of half-width ``√(2e-3/κ)`` (κ the peak's curvature, at most π/8) and the
    penetration at which the profile reaches it."""
    xp = shape.peak_position
    kappa = max(-float(shape.profile.curvatures(xp)) / shape.amplitude, 1e-6)
    a0 = min(np.sqrt(2e-3 / kappa), np.pi / 8)
    d0 = max(1.0 - float(shape.heights(xp + a0)), 1e-9)
    return d0, np.array([xp - a0, xp + a0])
