"""What every study is: a base scene, parameters, and independent chains of points.

A study implements the contract of :class:`Study`:

1. ``kind`` — the tag written into the study file (``"sweep"``, ``"cycle"``); never renamed.
2. ``params()`` — its parameters as JSON-ready data, and ``from_params(scene, params)`` — the
   inverse, so that a study file rebuilds the study that wrote it.
3. ``chains()`` — the independent sequences of points (:class:`Chain`): one ζ-continuation, one
   approach-retraction path. Chains are the unit of parallelism.
4. ``next_point(chain, records)`` — the scene, :class:`~viscocontact.studies.point.PointSpec` and
   initial contact set of the chain's next point, or ``None`` when the chain is finished; a *pure
   function* of the chain's finished records, so that a resumed study takes exactly the same path.
5. ``expected_points(chain, records)`` — an estimate of the chain's length (progress bar).
"""
from __future__ import annotations

import abc
import math
from typing import Any, ClassVar, Mapping, Sequence

import attrs
import numpy as np

from ..errors import ValidationError
from .point import FIRST_TOUCH, NEIGHBOUR, NO_CONTACT, carried_edges


@attrs.frozen(kw_only=True)
class Chain:
    """An independent sequence of points.

    Parameters
    ----------
    index : int
        Position in :meth:`Study.chains` (written with every record).
    scene : dict
        The chain's scene (``Scene.to_dict()`` form) before the per-point ζ and load are set.
    labels : dict
        ``variant``, ``seed``, ``gamma``, ``load`` of the chain, copied into every record.
    zetas : tuple of float
        The ζ values of the chain's points (one value for a cycle).
    """

    index: int
    scene: Mapping[str, Any] = attrs.field(eq=False)
    labels: Mapping[str, Any]
    zetas: tuple


class Study(abc.ABC):
    """Base class of the studies (see the module docstring for the contract)."""

    kind: ClassVar[str]

    @abc.abstractmethod
    def params(self) -> dict[str, Any]:
        """The study parameters as JSON-ready data (written to the study file)."""

    @classmethod
    @abc.abstractmethod
    def from_params(cls, scene, params: Mapping[str, Any]) -> "Study":
        """The study of a base scene and :meth:`params` output."""

    @abc.abstractmethod
    def chains(self) -> list[Chain]:
        """The independent chains of points."""

    @abc.abstractmethod
    def next_point(self, chain: Chain, records: Sequence[Mapping[str, Any]]):
        """``(scene dict, PointSpec, initial edges)`` of the next point, or ``None``."""

    @abc.abstractmethod
    def expected_points(self, chain: Chain, records: Sequence[Mapping[str, Any]]) -> int:
        """Estimated number of points of the chain."""


# ---- building the scenes of a study -------------------------------------------------------------
def scene_variant(base: Mapping[str, Any], *, zeta: float | None = None,
                  control: str | None = None, value: float | None = None,
                  seed: int | None = None, adhesion: Mapping[str, Any] | None = None) -> dict:
    """A copy of a scene dict with ζ, the load, the profile's (or surface's) seed or the
    adhesion replaced.

    Keys of the ``[physical]`` table that would contradict a replaced value (``velocity`` and
    ``tau`` for ζ,
    ``mean_pressure``/``penetration`` for the load, ``work_of_adhesion`` for the adhesion, and
    ``cohesive_range``/``cohesive_strength`` for an adhesion that is not a Maugis–Dugdale law
    without its own ``range``) are dropped from the copy; the others stay.
    """
    from ..units import COHESIVE_KEYS, COHESIVE_KIND

    out = {k: (dict(v) if isinstance(v, Mapping) else v) for k, v in base.items()}
    physical = dict(out.get("physical") or {})
    if zeta is not None:
        out["sliding"] = {**dict(out.get("sliding") or {}), "zeta": float(zeta)}
        physical.pop("velocity", None)
        physical.pop("tau", None)
    if control is not None:
        if value is None:
            raise TypeError("scene_variant: a control needs its value")
        out["load"] = {control: float(value)}
        physical.pop("mean_pressure", None)
        physical.pop("penetration", None)
    if seed is not None:
        out["surface" if "surface" in out else "profile"]["seed"] = int(seed)
    if adhesion is not None:
        out["adhesion"] = dict(adhesion)
        physical.pop("work_of_adhesion", None)
        if adhesion.get("kind") != COHESIVE_KIND or "range" in adhesion:
            for key in COHESIVE_KEYS:           # the Dugdale law's range: only for its kind
                physical.pop(key, None)
    if "physical" in out:
        out["physical"] = physical
    return out


def check_scene(scene: Mapping[str, Any], what: str):
    """Build a scene dict (raising the scene's own ValidationError, with ``what`` appended)."""
    from ..read import scene_from_dict

    try:
        return scene_from_dict(scene)
    except ValidationError as exc:
        raise ValidationError(exc.field, exc.value, f"{exc.allowed} (in {what})") from exc


def adhesion_gamma(adhesion: Mapping[str, Any]) -> float:
    """γ̃ of an adhesion table (0 for ``"none"``, NaN when the kind has no ``gamma``)."""
    if adhesion.get("kind") == "none":
        return 0.0
    value = adhesion.get("gamma")
    return float(value) if isinstance(value, (int, float)) else math.nan


def starting_point(anchor: Mapping[str, Any] | None, target_penetration: float | None):
    """``(started_from, initial)`` for a point continued from ``anchor`` (a record or None).

    The anchor's contact set when it has one; else the approach path from first touch, except
    that a penetration ``<= 0`` reached from no contact starts from no contact (an empty contact
    set), which is where a quasi-static approach stands before first touch. A full-contact anchor
    cannot be carried (it has no edges): the point starts from first touch.
    """
    if anchor is not None:
        edges = carried_edges(anchor)
        if edges is not None:
            return NEIGHBOUR, edges
        if anchor["full_contact"]:
            return FIRST_TOUCH, None
    if target_penetration is not None and target_penetration <= 0:
        return NO_CONTACT, np.zeros(0)
    return FIRST_TOUCH, None


def secant_start(records: Sequence[Mapping[str, Any]], key: str, value: float, *,
                 log: bool = False, phase: str | None = None) -> np.ndarray | None:
    """The contact set of the next point of a chain predicted from its last two points, or None.

    Along a continuation (ζ, or the penetration of a cycle) the edges move smoothly between
    jumps, so the secant through the last two converged contact sets, extrapolated to the next
    parameter ``value`` (in ``log`` scale for ζ), starts the solver closer than the last set does.
    Only when the last two records both carry a contact set with the same number of contacts
    (and the same ``phase`` when given), the next value continues in the same direction at most
    twice as far, and the prediction is a valid contact set; each edge moves by at most half of
    its contact's half-width (the whole move scaled by one factor). A pure function of the
    records, so a resumed study makes the same prediction.
    """
    from ..contact.topology import repair

    if len(records) < 2:
        return None
    older, last = records[-2], records[-1]
    x0, x1 = carried_edges(older), carried_edges(last)
    if x0 is None or x1 is None or x0.shape != x1.shape or x1.size == 0:
        return None
    if phase is not None and not (older.get("phase") == last.get("phase") == phase):
        return None
    v0, v1, v = float(older[key]), float(last[key]), float(value)
    if log:
        if min(v0, v1, v) <= 0:
            return None
        v0, v1, v = math.log(v0), math.log(v1), math.log(v)
    if not (math.isfinite(v0) and math.isfinite(v1) and math.isfinite(v)) or v1 == v0:
        return None
    ratio = (v - v1) / (v1 - v0)
    if not 0 < ratio <= 2:
        return None
    move = ratio * (x1 - x0)
    half = np.repeat(0.5 * (x1[1::2] - x1[0::2]), 2)
    big = np.max(np.abs(move) / (0.5 * half))
    if not np.isfinite(big):
        return None
    out = x1 + move / max(big, 1.0)
    _, changed, _, _ = repair(out, 1e-8, 1e-8)
    return None if changed else out


# ---- checking and parsing parameters ------------------------------------------------------------
def real_list(name: str, values, *, lo: float | None = None, lo_open: bool = False,
              min_size: int = 1) -> tuple[float, ...]:
    """A tuple of finite reals ``>= lo`` (``> lo`` if ``lo_open``), else ValidationError."""
    bound = "" if lo is None else f" {'>' if lo_open else '>='} {lo}"
    desc = f"a list of at least {min_size} finite real number(s){bound}"
    try:
        out = tuple(float(v) for v in np.atleast_1d(np.asarray(values, dtype=float)))
    except (TypeError, ValueError):
        raise ValidationError(name, values, desc) from None
    if len(out) < min_size:
        raise ValidationError(name, list(out), desc)
    for v in out:
        if not math.isfinite(v) or (lo is not None and (v < lo or (lo_open and v == lo))):
            raise ValidationError(name, v, desc)
    return out


def int_list(name: str, values, *, lo: int = 0) -> tuple[int, ...]:
    """A tuple of distinct integers ``>= lo``."""
    desc = f"a list of distinct integers >= {lo}"
    out = []
    for v in values:
        if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or v < lo:
            raise ValidationError(name, v, desc)
        out.append(int(v))
    if len(set(out)) != len(out):
        raise ValidationError(name, out, desc)
    return tuple(out)


def log_zetas(start: float, stop: float, count: int) -> tuple[float, ...]:
    """``count`` log-spaced ζ from ``start`` to ``stop`` (both > 0), rounded to 12 digits."""
    real_list("zetas", [start, stop], lo=0.0, lo_open=True)
    if isinstance(count, bool) or not isinstance(count, (int, np.integer)) or count < 1:
        raise ValidationError("zetas", count, "a number of points >= 1")
    if count == 1:
        return (float(start),)
    values = np.logspace(math.log10(start), math.log10(stop), int(count))
    return tuple(float(f"{v:.12g}") for v in values)


def parse_numbers(name: str, text: str, *, log: bool = False) -> tuple[float, ...]:
    """``"a,b,c"`` or ``"START:STOP:N"`` (log-spaced when ``log``, else linear) as floats."""
    text = text.strip()
    desc = ("START:STOP:N (log-spaced) or a comma-separated list" if log
            else "START:STOP:N (evenly spaced) or a comma-separated list")
    try:
        if ":" in text:
            start, stop, count = text.split(":")
            n = int(count)
            if log:
                return log_zetas(float(start), float(stop), n)
            if n < 1:
                raise ValueError
            return tuple(float(f"{v:.12g}") for v in np.linspace(float(start), float(stop), n))
        return tuple(float(v) for v in text.split(",") if v.strip())
    except ValidationError as exc:
        raise ValidationError(name, text, f"{desc}; {exc.allowed}") from None
    except ValueError:
        raise ValidationError(name, text, desc) from None


def parse_seeds(text: str) -> tuple[int, ...]:
    """``"0,3,7"`` or ``"START:STOP"`` (``range(START, STOP)``) as seeds."""
    desc = "START:STOP (range) or a comma-separated list of integers >= 0"
    try:
        if ":" in text:
            start, stop = text.split(":")
            values = tuple(range(int(start), int(stop)))
        else:
            values = tuple(int(v) for v in text.split(",") if v.strip())
    except ValueError:
        raise ValidationError("--seeds", text, desc) from None
    if not values:
        raise ValidationError("--seeds", text, desc)
    return int_list("--seeds", values)
