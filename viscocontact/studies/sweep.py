"""ζ-sweeps: contact area and friction against the dimensionless speed (thesis figures 4.7, 4.10).

A sweep solves its base scene at every ζ of a list (log-spaced by :func:`log_zetas`), for every
load of a list (all in load control, p̃∞, or all in penetration control, Δ̃), adhesive and
adhesionless side by side, and for every profile seed (realizations, averaged by
:mod:`~viscocontact.studies.realizations`).

Along ζ each point is continued from its neighbour (``continuation=True``): the contact set of the
previous converged point is the initial guess of the next, which is several times cheaper than
starting from first touch. An adhesionless equilibrium is unique, so its value does not depend on
the start. An adhesive rough contact has many equilibria at one ζ and load, and which one a
continued point lands on depends on the history: a slow change of speed (``zeta_step``: the gap
to the next ζ crossed through unrecorded intermediate equilibria), an approach at that speed
(``continuation=False``) and a single jump over decades of ζ (the default) can give different
ones (``docs/figures.md``, "Which equilibrium"). A point that does not converge from its
neighbour's contact set is approached again from the neighbour in steps of ζ that halve on
failure (:func:`~viscocontact.studies.point.refined`; its message says so).
The first point of a chain, a point after a full-contact neighbour (full contact has no edges to
carry) and every point of a sweep with ``continuation=False`` follow the approach path from first
touch instead. A chain (one variant, load and seed) is sequential; different chains are
independent and run in parallel (``workers``, ``scheduler`` of :func:`~viscocontact.studies.run`).
"""
from __future__ import annotations

import math
from typing import Any, ClassVar, Mapping, Sequence

import attrs
import numpy as np

from ..errors import ValidationError
from ..problem import Discretization
from ..scene import Scene
from .base import (Chain, Study, adhesion_gamma, check_scene, int_list, log_zetas, real_list,
                   scene_variant, secant_start, starting_point)
from .point import NEIGHBOUR, PointSpec, carried_edges, has_contact

__all__ = ["Sweep", "log_zetas", "zeta_path"]

CONTROLS = ("mean_pressure", "penetration")
ADHESIVE, ADHESIONLESS = "adhesive", "adhesionless"


def _zeta_step(value) -> float | None:
    if value is None:
        return None
    if (isinstance(value, bool) or not isinstance(value, (int, float))
            or not 0 < float(value) <= 10):
        raise ValidationError("sweep.zeta_step", value,
                              "decades of ζ in (0, 10], or None for one step")
    return float(value)


def zeta_path(start: float, end: float, step: float | None) -> tuple[float, ...]:
    """The intermediate ζ of a continuation from ``start`` to ``end`` (both excluded), log-spaced,
    so that no step exceeds ``step`` decades; empty for ``step=None``, a ζ of 0 or a short gap.

    >>> [round(z, 6) for z in zeta_path(1.0, 1e-2, 0.5)]
    [0.316228, 0.1, 0.031623]
    >>> zeta_path(1.0, 0.0, 0.25), zeta_path(1.0, 0.6, 0.25)
    ((), ())
    """
    if step is None or start <= 0 or end <= 0:
        return ()
    decades = abs(math.log10(end) - math.log10(start))
    n = math.ceil(decades / step - 1e-9)
    if n <= 1:
        return ()
    return tuple(float(z) for z in np.logspace(math.log10(start), math.log10(end), n + 1)[1:-1])


def _zetas(value) -> tuple:
    return real_list("sweep.zetas", value, lo=0.0)


def _loads(value) -> tuple:
    return real_list("sweep.loads", value)


def _seeds(value):
    return None if value is None else int_list("sweep.seeds", list(value))


def _control(inst, attribute, value):
    if value not in CONTROLS:
        raise ValidationError("sweep.control", value, f"one of {list(CONTROLS)}")


def _discretization(value):
    if value is None or isinstance(value, Discretization):
        return value
    if isinstance(value, Mapping):
        return Discretization(**value)
    raise ValidationError("sweep.discretization", value, "a Discretization, a dict or None")


@attrs.frozen(kw_only=True)
class Sweep(Study):
    """A ζ-sweep of a base scene.

    Parameters
    ----------
    scene : Scene
        The base scene; its ζ is replaced by each of ``zetas`` and its load by each of ``loads``.
    zetas : sequence of float
        ζ = q0 V τ >= 0, in the order of continuation (ascending is usual; see :func:`log_zetas`).
    loads : sequence of float, optional
        Values of the controlled quantity (default: the scene's own).
    control : {"mean_pressure", "penetration"}, optional
        Load control (p̃∞) or penetration control (Δ̃); default that of the scene.
    seeds : sequence of int, optional
        Profile seeds, one realization each (the profile kind must take a ``seed``, e.g.
        ``self-affine``); default the scene's profile only.
    pair : bool
        With an adhesive scene, also sweep its adhesionless twin (``adhesion.kind = "none"``, same
        solver and mesh), side by side as in the thesis's figures.
    continuation : bool
        Continue each point from its neighbour along ζ (else every point from first touch).
    zeta_step : float or None
        Largest step of an adhesive continuation in decades of ζ, in ``(0, 10]``: a larger gap
        between two ζ of the list (or to a ζ after a failed point) is crossed through
        log-spaced intermediate equilibria that are solved but not recorded, the way a slow
        change of speed crosses it. ``None`` (default): one step, whatever its size.
        Adhesionless points and ζ = 0 always take one step.
    fields : bool
        Store pressure, displacement and gap of every point.
    discretization : Discretization or dict, optional
        Mesh of every solve (default :class:`~viscocontact.problem.Discretization()`).

    Examples
    --------
    >>> from viscocontact.scene import Scene
    >>> scene = Scene.from_toml('''
    ... [profile]
    ... kind = "sinusoid"
    ... amplitude = 0.1
    ... [rheology]
    ... kind = "standard-linear-solid"
    ... beta = 10.0
    ... [adhesion]
    ... kind = "energy-balance"
    ... gamma = 1e-4
    ... [load]
    ... mean_pressure = 0.1
    ... [sliding]
    ... zeta = 1.0
    ... ''')
    >>> sweep = Sweep(scene=scene, zetas=log_zetas(1e-3, 1e2, 6), loads=[0.05, 0.1])
    >>> sweep.variants, len(sweep.chains())
    (('adhesive', 'adhesionless'), 4)
    """

    kind: ClassVar[str] = "sweep"

    scene: Scene = attrs.field(validator=attrs.validators.instance_of(Scene))
    zetas: tuple = attrs.field(converter=_zetas)
    loads: tuple = attrs.field(converter=_loads, default=attrs.Factory(
        lambda self: (self.scene.load.value,), takes_self=True))
    control: str = attrs.field(validator=_control, default=attrs.Factory(
        lambda self: self.scene.load.controlled, takes_self=True))
    seeds: tuple | None = attrs.field(default=None, converter=_seeds)
    pair: bool = attrs.field(default=True, converter=bool)
    continuation: bool = attrs.field(default=True, converter=bool)
    zeta_step: float | None = attrs.field(default=None, converter=_zeta_step)
    fields: bool = attrs.field(default=False, converter=bool)
    discretization: Discretization | None = attrs.field(default=None, converter=_discretization)

    def __attrs_post_init__(self):
        seen = set()
        for chain in self.chains():  # every variant, load and seed builds a valid scene
            key = tuple(chain.labels.items())
            if key not in seen:
                seen.add(key)
                check_scene(scene_variant(chain.scene, zeta=chain.zetas[0]),
                            f"the sweep's {dict(chain.labels)}")

    @property
    def variants(self) -> tuple[str, ...]:
        """``("adhesive", "adhesionless")``, ``("adhesive",)`` or ``("adhesionless",)``."""
        if not self.scene.adhesive:
            return (ADHESIONLESS,)
        return (ADHESIVE, ADHESIONLESS) if self.pair else (ADHESIVE,)

    # ---- the study contract -----------------------------------------------------------------
    def params(self) -> dict[str, Any]:
        return {"zetas": list(self.zetas), "loads": list(self.loads), "control": self.control,
                "seeds": None if self.seeds is None else list(self.seeds), "pair": self.pair,
                "continuation": self.continuation, "fields": self.fields,
                **({} if self.zeta_step is None else {"zeta_step": self.zeta_step}),
                "discretization": (None if self.discretization is None
                                   else attrs.asdict(self.discretization))}

    @classmethod
    def from_params(cls, scene, params: Mapping[str, Any]) -> "Sweep":
        return cls(scene=scene, **params)     # files written before zeta_step: one step

    def _layout(self):
        """``(variant, load, seed, zetas, (iv, il, iseed, iz0))`` of every chain, in order."""
        groups = ([(0, self.zetas)] if self.continuation
                  else [(iz, (z,)) for iz, z in enumerate(self.zetas)])
        for iv, variant in enumerate(self.variants):
            for il, load in enumerate(self.loads):
                for iseed, seed in enumerate(self.seeds or (None,)):
                    for iz0, zetas in groups:
                        yield variant, load, seed, tuple(zetas), (iv, il, iseed, iz0)

    def chains(self) -> list[Chain]:
        base = self.scene.to_dict()
        out: list[Chain] = []
        scenes: dict = {}
        for variant, load, seed, zetas, _ in self._layout():
            if (variant, load, seed) not in scenes:
                adhesion = ({"kind": "none"} if variant == ADHESIONLESS and self.scene.adhesive
                            else None)
                scene = scene_variant(base, control=self.control, value=load, seed=seed,
                                      adhesion=adhesion)
                labels = {"variant": variant, "seed": -1 if seed is None else seed,
                          "gamma": adhesion_gamma(scene["adhesion"]), "load": load}
                scenes[variant, load, seed] = scene, labels
            scene, labels = scenes[variant, load, seed]
            out.append(Chain(index=len(out), scene=scene, labels=labels, zetas=zetas))
        return out

    def grid(self) -> list[tuple[int, int, int, int]]:
        """Where each chain sits on the grid ``(variant, load, seed, zeta)`` of
        :meth:`StudyData.axes`: ``(iv, il, iseed, iz0)`` per chain (in :meth:`chains` order),
        its point ``step`` at ζ index ``iz0 + step``."""
        return [position for *_, position in self._layout()]

    def next_point(self, chain: Chain, records: Sequence[Mapping[str, Any]]):
        k = len(records)
        if k >= len(chain.zetas):
            return None
        scene = scene_variant(chain.scene, zeta=chain.zetas[k])
        anchor = None
        if self.continuation:
            anchor = next((r for r in reversed(records) if has_contact(r)), None)
        target = chain.labels["load"] if self.control == "penetration" else None
        started_from, initial = starting_point(anchor, target)
        path: tuple[float, ...] = ()
        if self.continuation and initial is not None and initial.size:
            if chain.labels["variant"] == ADHESIVE and anchor is not None:
                path = zeta_path(float(anchor["zeta"]), chain.zetas[k], self.zeta_step)
            predicted = secant_start(records, "zeta", path[0] if path else chain.zetas[k],
                                     log=True)
            initial = initial if predicted is None else predicted
        origin: dict[str, Any] = {}
        if anchor is not None and started_from == NEIGHBOUR:
            carried = carried_edges(anchor)
            if carried is not None:
                origin = dict(origin=float(anchor["zeta"]), origin_edges=carried.tolist())
        spec = PointSpec(chain=chain.index, step=k, phase="sweep", started_from=started_from,
                         path=path, **origin,
                         fields=self.fields, labels=dict(chain.labels),
                         discretization=(None if self.discretization is None
                                         else attrs.asdict(self.discretization)))
        return scene, spec, initial

    def expected_points(self, chain: Chain, records) -> int:
        return len(chain.zetas)
