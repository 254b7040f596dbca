"""Histories: how an adhesive equilibrium is reached is part of the model.

An adhesive contact can hold several equilibria at one speed and load; which one a point shows
depends on how it got there. A study states that history by name and stores it with every
point (the ``history`` column), so that a curve is a function of its scene and its history,
not of how densely it was sampled:

``approach`` (:class:`Approach`, the default)
    Quasi-static loading at the point's own constant speed, from first touch to the target load
    or penetration: the thesis's definition of a point (§4.4), and the state a contact reaches
    when it is pressed on at that speed. Every point is independent of every other point, so a
    curve recorded at 1 or 8 points per decade has the same values at the common ζ, and
    :func:`viscocontact.solve` of one point gives the point of the study.
``speed-ramp`` (:class:`SpeedRamp`)
    A slow change of speed at constant load from the chain's first point (itself reached by the
    approach), in either direction: the continuation in log ζ chooses its own steps from an
    error control (:mod:`~viscocontact.studies.ramp`) and records the requested ζ as side solves
    from its path, so the recorded values do not depend on the recorded ζ.
``cycle``
    The approach-retraction cycle in Δ̃ at constant speed (:class:`~viscocontact.studies.Cycle`).

Adhesionless equilibria are unique: their history is recorded, but does not change them.

The default is the approach because it is the thesis's definition, the state a single solve
gives, and the only one whose points are independent (a study of it runs its points in
parallel); the speed ramp is the history of a contact whose speed changes while it slides.
"""
from __future__ import annotations

from typing import Any, ClassVar, Mapping

import attrs

from ..errors import ValidationError

APPROACH, SPEED_RAMP, CYCLE = "approach", "speed-ramp", "cycle"

#: The histories a sweep offers (a cycle is its own study).
SWEEP_HISTORIES = (APPROACH, SPEED_RAMP)


@attrs.frozen(kw_only=True)
class Approach:
    """Quasi-static loading from first touch to the target at the point's own ζ."""

    name: ClassVar[str] = APPROACH

    def params(self) -> dict[str, Any]:
        return {"name": self.name}


def _positive(upper: float):
    def check(inst, attribute, value):
        if (isinstance(value, bool) or not isinstance(value, (int, float))
                or not 0 < float(value) <= upper):
            raise ValidationError(f"history.{attribute.name}", value, f"a number in (0, {upper}]")
    return check


@attrs.frozen(kw_only=True)
class SpeedRamp:
    """A slow change of ζ at constant load from the chain's first point.

    Parameters
    ----------
    tolerance : float
        The step control's bound, in ``(0, 0.5]``: a step of log ζ is accepted when its secant
        prediction of every edge lies within ``tolerance`` of that contact's half-width of the
        converged edge, and a change of the contact set (a birth, a merge, a detachment, a
        closure or an opening) is located in ζ to within ``tolerance`` decades. Its tenth
        certifies a result (:mod:`~viscocontact.studies.certify`).
    largest_step : float
        Largest step in decades of ζ, in ``(0, 2]``.
    """

    name: ClassVar[str] = SPEED_RAMP

    tolerance: float = attrs.field(default=0.02, converter=float, validator=_positive(0.5))
    largest_step: float = attrs.field(default=0.25, converter=float, validator=_positive(2.0))

    @property
    def smallest_step(self) -> float:
        """The step below which the branch is taken to end: a tenth of the event resolution."""
        return 0.1 * self.tolerance

    def params(self) -> dict[str, Any]:
        return {"name": self.name, "tolerance": self.tolerance,
                "largest_step": self.largest_step}

    def refined(self, factor: float = 10.0) -> "SpeedRamp":
        """The same ramp with a ``factor`` times tighter tolerance (and steps)."""
        return SpeedRamp(tolerance=self.tolerance / factor,
                         largest_step=self.largest_step / factor ** 0.5)


History = Approach | SpeedRamp


def history(value: Any) -> History:
    """A history from its name, its :meth:`params` mapping or itself.

    >>> history("approach")
    Approach()
    >>> history({"name": "speed-ramp", "tolerance": 0.01})
    SpeedRamp(tolerance=0.01, largest_step=0.25)
    """
    if isinstance(value, (Approach, SpeedRamp)):
        return value
    if isinstance(value, str):
        value = {"name": value}
    if isinstance(value, Mapping):
        options = dict(value)
        name = options.pop("name", None)
        if name == APPROACH and not options:
            return Approach()
        if name == SPEED_RAMP:
            unknown = set(options) - {"tolerance", "largest_step"}
            if unknown:
                raise ValidationError("history", dict(value),
                                      f"speed-ramp options tolerance, largest_step (not "
                                      f"{sorted(unknown)})")
            return SpeedRamp(**options)
    raise ValidationError("history", value, f"one of {list(SWEEP_HISTORIES)} (a name, a "
                                            f"mapping with 'name', or a history object)")
