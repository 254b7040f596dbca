"""The cohesive law in the units of the grid solve (:class:`GridLaw`), which the cohesive solve
(:mod:`.cohesive`) and the tips' geometry (:mod:`.tips`) share."""
from __future__ import annotations

import attrs

__all__ = ["GridLaw"]


@attrs.frozen(kw_only=True)
class GridLaw:
    """The cohesive law on the grid, in the units of the grid solve.

    Attributes
    ----------
    strength : float
        ``σ̃0``, the cohesive tension (> 0).
    opening : float
        ``η = h̃0/Λ̃``, the gap up to which it acts (> 0).
    zone : float
        The quasi-static Dugdale zone ``q0 a0 = h̃0²/(4γ̃)`` (``x̃`` units), which sets the grid.
    """

    strength: float
    opening: float
    zone: float
