"""ζ-sweeps: contact area and friction against the dimensionless speed (thesis figures 4.7, 4.10).

A sweep solves its base scene at every ζ of a list (log-spaced by :func:`log_zetas`), for every
load of a list (all in load control, p̃∞, or all in penetration control, Δ̃), adhesive and
adhesionless side by side, and for every profile seed (realizations, averaged by
:mod:`~viscocontact.studies.realizations`).

Which equilibrium an adhesive point shows depends on how it is reached, so a sweep states its
history (:mod:`~viscocontact.studies.history`), stored with every point: ``"approach"`` (the
default: every point by quasi-static loading at its own speed from first touch, independent of
the others, so its chains are single points that run in parallel) or a ``SpeedRamp`` (a slow change
of ζ at constant load from the chain's first point, :mod:`~viscocontact.studies.ramp`; one chain
per load and seed). Either way the recorded values do not depend on which ζ are recorded.
Adhesionless equilibria are unique: their chains run along ζ, each point started from its
neighbour's contact set (a warm start; a point that does not converge from it is solved from
first touch). Different chains are independent and run in parallel (``workers``, ``scheduler``
of :func:`~viscocontact.studies.run`).
"""
from __future__ import annotations

from typing import Any, ClassVar, Mapping, Sequence

import attrs
import numpy as np

from ..errors import ValidationError
from ..problem import Discretization
from ..scene import Scene
from .base import (Chain, Study, adhesion_gamma, check_scene, int_list, log_zetas, real_list,
                   scene_variant, secant_start, starting_point)
from .certify import REFINEMENT
from .history import Approach, SpeedRamp, history
from .point import RAMP, PointSpec, has_contact

__all__ = ["Sweep", "log_zetas"]

CONTROLS = ("mean_pressure", "penetration")
ADHESIVE, ADHESIONLESS = "adhesive", "adhesionless"


def _history(value):
    return history(value)


def _zetas(value) -> tuple:
    return real_list("sweep.zetas", value, lo=0.0)


def _loads(value) -> tuple:
    return real_list("sweep.loads", value)


def _seeds(value):
    return None if value is None else int_list("sweep.seeds", list(value))


def _scene_kind(inst, attribute, value):
    from ..areal.scene import ArealScene

    if not isinstance(value, (Scene, ArealScene)):
        raise ValidationError("sweep.scene", value, "a Scene or an ArealScene")


def _is_areal(scene) -> bool:
    return not isinstance(scene, Scene)


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
    scene : Scene or ArealScene
        The base scene; its ζ is replaced by each of ``zetas`` and its load by each of ``loads``.
        The points of an areal scene (:class:`~viscocontact.areal.scene.ArealScene`) are
        independent (one chain each, solved in parallel), reached by the approach; its
        ``discretization`` is its grid.
    zetas : sequence of float
        ζ = q0 V τ >= 0, in the order of continuation (ascending is usual; see :func:`log_zetas`).
    loads : sequence of float, optional
        Values of the controlled quantity (default: the scene's own).
    control : {"mean_pressure", "penetration"}, optional
        Load control (p̃∞) or penetration control (Δ̃); default that of the scene.
    seeds : sequence of int, optional
        Profile (or surface) seeds, one realization each (the kind must take a ``seed``, e.g.
        ``self-affine``); default the scene's profile only.
    pair : bool
        With an adhesive scene, also sweep its adhesionless twin (``adhesion.kind = "none"``, same
        solver and mesh), side by side as in the thesis's figures.
    history : str, dict or history object
        How each point is reached (:func:`~viscocontact.studies.history.history`):
        ``"approach"`` (default) or ``"speed-ramp"`` / ``SpeedRamp(tolerance=...)``. A speed
        ramp needs ζ > 0 in a strictly monotonic order (the ramp's direction).
    fields : bool
        Store pressure, displacement and gap of every point.
    discretization : Discretization or dict, optional
        Mesh of every solve (default :class:`~viscocontact.problem.Discretization()`).
    certify : bool
        Also solve every adhesive point under the same history with a tenth of its tolerance
        (the approach's ``path_step``, the speed ramp's ``tolerance``) and record whether the
        two agree (:mod:`~viscocontact.studies.certify`): the columns ``certified``,
        ``certified_area``, ``certified_friction``. Costs 2-3 times the adhesive points; off by
        default.

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
    (('adhesive', 'adhesionless'), 14)
    """

    kind: ClassVar[str] = "sweep"

    scene: Any = attrs.field(validator=_scene_kind)
    zetas: tuple = attrs.field(converter=_zetas)
    loads: tuple = attrs.field(converter=_loads, default=attrs.Factory(
        lambda self: (self.scene.load.value,), takes_self=True))
    control: str = attrs.field(validator=_control, default=attrs.Factory(
        lambda self: self.scene.load.controlled, takes_self=True))
    seeds: tuple | None = attrs.field(default=None, converter=_seeds)
    pair: bool = attrs.field(default=True, converter=bool)
    history: Approach | SpeedRamp = attrs.field(factory=Approach, converter=_history)
    fields: bool = attrs.field(default=False, converter=bool)
    discretization: Discretization | None = attrs.field(default=None, converter=_discretization)
    certify: bool = attrs.field(default=False, converter=bool)

    def __attrs_post_init__(self):
        if _is_areal(self.scene) and self.certify:
            raise ValidationError("sweep.certify", True, "False for an areal scene (its points "
                                  "are not reached by a continuation with a step)")
        if self.certify:                # the certifying step must be a step the mesh allows
            disc = self.discretization or Discretization()
            try:
                attrs.evolve(disc, path_step=disc.path_step / REFINEMENT)
            except ValidationError as exc:
                raise ValidationError("sweep.discretization.path_step", disc.path_step,
                                      f"a step whose tenth is {exc.allowed} (certify=True "
                                      "certifies the points with a tenth of it)") from None
        if _is_areal(self.scene):
            if isinstance(self.history, SpeedRamp):
                raise ValidationError("sweep.history", self.history.params(),
                                      "the approach for an areal scene (each point is solved "
                                      "on its own)")
            if self.discretization is not None:
                raise ValidationError("sweep.discretization", attrs.asdict(self.discretization),
                                      "None for an areal scene (its grid is surface.grid)")
        if isinstance(self.history, SpeedRamp):
            logs = np.log10(np.maximum(self.zetas, 1e-300))
            steps = np.diff(logs)
            if min(self.zetas) <= 0 or not (np.all(steps > 0) or np.all(steps < 0)):
                raise ValidationError("sweep.zetas", list(self.zetas),
                                      "ζ > 0 in a strictly increasing or decreasing order "
                                      "(the direction of a speed ramp)")
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
                "history": self.history.params(), "fields": self.fields,
                "discretization": (None if self.discretization is None
                                   else attrs.asdict(self.discretization)),
                # only when on: a file written before certification is the same study
                **({"certify": True} if self.certify else {})}

    @classmethod
    def from_params(cls, scene, params: Mapping[str, Any]) -> "Sweep":
        params = dict(params)
        # files written before histories: continuation False was the approach; a continuation
        # from the neighbour (one jump per gap, or steps of zeta_step) reads as a speed ramp
        continued = params.pop("continuation", None)
        params.pop("zeta_step", None)
        if "history" not in params and continued is not None:
            params["history"] = "speed-ramp" if continued else "approach"
        return cls(scene=scene, **params)

    def _layout(self):
        """``(variant, load, seed, zetas, (iv, il, iseed, iz0))`` of every chain, in order."""
        along = [(0, self.zetas)]
        apart = [(iz, (z,)) for iz, z in enumerate(self.zetas)]
        for iv, variant in enumerate(self.variants):
            # adhesionless points are unique: one chain of warm starts; approached adhesive
            # points are independent
            # an areal point is solved on its own (its ladder of grids starts afresh)
            groups = (apart if _is_areal(self.scene) or (
                variant == ADHESIVE and isinstance(self.history, Approach)) else along)
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
        target = chain.labels["load"] if self.control == "penetration" else None
        ramped = chain.labels["variant"] == ADHESIVE and isinstance(self.history, SpeedRamp)
        ramp, anchor, fine_ramp = "", None, ""
        if ramped:
            ramp = next((str(r["ramp"]) for r in reversed(records) if r.get("ramp")), "")
            fine_ramp = next((str(r["certified_ramp"]) for r in reversed(records)
                              if r.get("certified_ramp")), "")
        elif chain.labels["variant"] == ADHESIONLESS:
            anchor = next((r for r in reversed(records) if has_contact(r)), None)
        started_from, initial = starting_point(anchor, target)
        if ramp:
            started_from = RAMP
        if anchor is not None and initial is not None and initial.size:
            predicted = secant_start(records, "zeta", chain.zetas[k], log=True)
            initial = initial if predicted is None else predicted
        spec = PointSpec(chain=chain.index, step=k, phase="sweep", started_from=started_from,
                         history=self.history.params(), ramp=ramp,
                         certify=self.certify and chain.labels["variant"] == ADHESIVE,
                         certified_ramp=fine_ramp,
                         fields=self.fields, labels=dict(chain.labels),
                         discretization=(None if self.discretization is None
                                         else attrs.asdict(self.discretization)))
        return scene, spec, initial

    def expected_points(self, chain: Chain, records) -> int:
        return len(chain.zetas)
