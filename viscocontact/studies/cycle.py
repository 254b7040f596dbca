r"""Quasi-static approach-retraction cycles in penetration control (thesis §4.6.1, figures 4.8-4.9).

The rigid profile, sliding at a fixed ζ, is pressed in and pulled out in steps of the penetration
Δ̃: approach from ``start`` up to ``max_penetration``, then retraction down to detachment (or to
``min_penetration``). Every point starts from the contact set of the previous one, so the path
(and with roughness its hysteresis: spots held by adhesive necks on the way out) is carried along.

**Detachment (pull-off in penetration control).** On the way out the last contact vanishes at
Δ̃_out, where the solved branch ends: the solve returns no contact, or fails to find a contacting
equilibrium at Δ̃ <= 0 (where no contact is an admissible state; a failure at Δ̃ > 0 is stored as
a failure and the retraction goes on from the last equilibrium). The first such point brackets
Δ̃_out; ``refine`` bisection steps, each continued from the last contacting state, shrink the
bracket to ``step / 2**refine``. ``detachment_penetration`` is the smallest Δ̃ with contact found.

**Pull-off force.** The most tensile mean pressure on the retraction branch, min p̃∞ — the force
at which a load-controlled test would snap off (point A of the thesis's Fig. 1.6; point B, the end
of the displacement-controlled branch, is Δ̃_out). Zero, at no penetration (NaN), when the branch
never carries tension (adhesionless contact).

**Contact toughness (eq. 4.57).** The external work per period needed to pull the profile off,
quasi-statically, while it slides:

.. math:: \tilde T = \frac{2(1-\nu^2)\,T}{\Lambda^2 E_0}
          = 2\pi \int_{\tilde\Delta_0}^{\tilde\Delta_{out}} \tilde p_\infty(\tilde\Delta)\,
          d\tilde\Delta \;\ge 0,

with Δ̃_0 the penetration where p̃∞ changes sign on the retraction branch and Δ̃_out the
detachment penetration; since Δ̃_out < Δ̃_0 and p̃∞ < 0 in between, T̃ is positive. T is the
work per unit out-of-plane length over one period λ0 (J/m), ``T = λ0 ∫ p∞ dΔ``. It is computed
with the trapezoidal rule over the contacting retraction points, from (Δ̃_0, 0) (linear
interpolation of the sign change) to the last contacting point; the pressure jumps to zero at
detachment without any change of Δ̃, so the jump does no work. The truncation error is at most
``|p̃∞(Δ̃_out)| × 2π × bracket``. When p̃∞ never becomes negative (adhesionless contact) T̃ = 0 and
Δ̃_0 is NaN; when the retraction starts in tension (``max_penetration`` < Δ̃_0) Δ̃_0 is NaN and
T̃ is integrated from ``max_penetration`` (a lower bound).

**Cycle work.** ``cycle_work = 2π(∫_approach p̃∞ dΔ̃ - ∫_retraction p̃∞ dΔ̃)``, the normal work
lost over the cycle (adhesion hysteresis, on T̃'s scale), and ``area_loop``, the area between the
loading and unloading Ã-Δ̃ curves of Fig. 4.8 (pressure and area counted as zero out of contact).
Both are trapezoidal estimates on the computed points: for a reversible path (adhesionless
contact) they vanish only as the step goes to zero.
"""
from __future__ import annotations

import math
from typing import Any, ClassVar, Mapping, Sequence

import attrs
import numpy as np

from ..errors import ValidationError
from ..problem import Discretization
from ..scene import Scene
from ..methods.bem.approach import ContinueFrom
from .base import (Chain, Study, adhesion_gamma, check_scene, int_list, real_list, scene_variant,
                   starting_point)
from .point import ERROR, PointSpec, has_contact
from .sweep import ADHESIONLESS, ADHESIVE, _discretization

__all__ = ["Cycle", "CycleMetrics", "cycle_metrics"]

APPROACH, RETRACT = "approach", "retract"


def _refine(inst, attribute, value):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not 0 <= value <= 30:
        raise ValidationError("cycle.refine", value, "an integer in [0, 30]")


def _max_failures(inst, attribute, value):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
        raise ValidationError("cycle.max_failures", value, "an integer >= 1")


@attrs.frozen(kw_only=True)
class Cycle(Study):
    """Approach-retraction cycles of a base scene in penetration control.

    Parameters
    ----------
    scene : Scene
        The base scene (its load is replaced by the penetration path).
    max_penetration : float
        Δ̃ at the turning point.
    step : float
        Penetration step Δ̃ of both branches (> 0).
    start : float
        Δ̃ of the first approach point (default 0, first touch).
    min_penetration : float
        Lowest Δ̃ of the retraction if the profile has not detached before (default
        ``start - 2``).
    refine : int
        Bisection steps that locate detachment (bracket ``step / 2**refine``).
    max_failures : int
        A cycle ends after this many consecutive failed points that do not mark detachment (the
        path is lost); they stay in the file with their reasons.
    zetas : sequence of float, optional
        One cycle per ζ (default the scene's).
    gammas : sequence of float, optional
        One cycle per γ̃ (``0``: adhesionless, ``adhesion.kind = "none"``); default the scene's
        adhesion.
    seeds : sequence of int, optional
        Profile seeds (realizations); default the scene's profile only.
    fields : bool
    discretization : Discretization or dict, optional

    Notes
    -----
    Full contact has no edges to carry: a point after full contact restarts from first touch,
    which on the retraction branch loses the path's memory (``started_from`` says so). Keep
    ``max_penetration`` below closure to follow a genuine unloading path.
    """

    kind: ClassVar[str] = "cycle"

    scene: Scene = attrs.field(validator=attrs.validators.instance_of(Scene))
    max_penetration: float = attrs.field(
        converter=lambda v: real_list("cycle.max_penetration", [v])[0])
    step: float = attrs.field(
        converter=lambda v: real_list("cycle.step", [v], lo=0.0, lo_open=True)[0])
    start: float = attrs.field(default=0.0, converter=lambda v: real_list("cycle.start", [v])[0])
    min_penetration: float = attrs.field(
        converter=lambda v: real_list("cycle.min_penetration", [v])[0],
        default=attrs.Factory(lambda self: self.start - 2.0, takes_self=True))
    refine: int = attrs.field(default=4, validator=_refine)
    max_failures: int = attrs.field(default=3, validator=_max_failures)
    zetas: tuple = attrs.field(
        converter=lambda v: real_list("cycle.zetas", v, lo=0.0),
        default=attrs.Factory(lambda self: (self.scene.zeta,), takes_self=True))
    gammas: tuple | None = attrs.field(
        default=None, converter=lambda v: None if v is None else real_list("cycle.gammas", v,
                                                                           lo=0.0))
    seeds: tuple | None = attrs.field(
        default=None, converter=lambda v: None if v is None else int_list("cycle.seeds", list(v)))
    fields: bool = attrs.field(default=False, converter=bool)
    discretization: Discretization | None = attrs.field(default=None, converter=_discretization)

    def __attrs_post_init__(self):
        if self.max_penetration <= self.start:
            raise ValidationError("cycle.max_penetration", self.max_penetration,
                                  f"a value > cycle.start = {self.start}")
        if self.min_penetration >= self.max_penetration:
            raise ValidationError("cycle.min_penetration", self.min_penetration,
                                  f"a value < cycle.max_penetration = {self.max_penetration}")
        seen = set()
        for chain in self.chains():
            key = (chain.labels["gamma"], chain.labels["seed"])
            if key not in seen:
                seen.add(key)
                check_scene(chain.scene, f"the cycle's {dict(chain.labels)}")

    # ---- the path -----------------------------------------------------------------------------
    def approach_targets(self) -> tuple[float, ...]:
        """Δ̃ of the approach: ``start, start + step, ...``, ending exactly at the maximum."""
        n = math.ceil((self.max_penetration - self.start) / self.step - 1e-9)
        return tuple(self.start + i * self.step for i in range(n)) + (self.max_penetration,)

    def retract_targets(self) -> tuple[float, ...]:
        """Δ̃ of the regular retraction steps, ``max - step, max - 2 step, ...`` down to the min."""
        n = math.floor((self.max_penetration - self.min_penetration) / self.step + 1e-9)
        return tuple(self.max_penetration - j * self.step for j in range(1, n + 1))

    # ---- the study contract -------------------------------------------------------------------
    def params(self) -> dict[str, Any]:
        return {"max_penetration": self.max_penetration, "step": self.step, "start": self.start,
                "min_penetration": self.min_penetration, "refine": self.refine,
                "max_failures": self.max_failures,
                "zetas": list(self.zetas),
                "gammas": None if self.gammas is None else list(self.gammas),
                "seeds": None if self.seeds is None else list(self.seeds),
                "fields": self.fields,
                "discretization": (None if self.discretization is None
                                   else attrs.asdict(self.discretization))}

    @classmethod
    def from_params(cls, scene, params: Mapping[str, Any]) -> "Cycle":
        return cls(scene=scene, **params)

    def _adhesion(self, gamma: float | None, base: Mapping[str, Any]):
        if gamma is None:
            return None
        if gamma == 0.0:
            return {"kind": "none"}
        if "gamma" in base:
            return {**base, "gamma": gamma}
        return {"kind": "energy-balance", "gamma": gamma}

    def chains(self) -> list[Chain]:
        base = self.scene.to_dict()
        out: list[Chain] = []
        for zeta in self.zetas:
            for gamma in self.gammas if self.gammas is not None else (None,):
                for seed in self.seeds or (None,):
                    scene = scene_variant(base, zeta=zeta, control="penetration",
                                          value=self.start, seed=seed,
                                          adhesion=self._adhesion(gamma, base["adhesion"]))
                    g = adhesion_gamma(scene["adhesion"])
                    labels = {"variant": ADHESIONLESS if scene["adhesion"]["kind"] == "none"
                              else ADHESIVE, "seed": -1 if seed is None else seed, "gamma": g,
                              "load": math.nan}
                    out.append(Chain(index=len(out), scene=scene, labels=labels, zetas=(zeta,)))
        return out

    def grid(self) -> list[tuple[int, int, int]]:
        """Where each cycle sits on the grid ``(zeta, gamma, seed)``: ``(iz, ig, iseed)`` per
        chain, in :meth:`chains` order."""
        gammas = range(len(self.gammas) if self.gammas is not None else 1)
        seeds = range(len(self.seeds or (None,)))
        return [(iz, ig, iseed) for iz in range(len(self.zetas)) for ig in gammas for iseed in seeds]

    def _state(self, records: Sequence[Mapping[str, Any]]):
        """(approach records, retract records, anchor, detached records, probes done)."""
        n_app = len(self.approach_targets())
        approach, retract = list(records[:n_app]), list(records[n_app:])
        anchor = next((r for r in reversed(records) if has_contact(r)), None)
        detached = [i for i, r in enumerate(retract) if is_detached(r)]
        probes = len(retract) - detached[0] - 1 if detached else 0
        return approach, retract, anchor, [retract[i] for i in detached], probes

    def next_point(self, chain: Chain, records: Sequence[Mapping[str, Any]]):
        app = self.approach_targets()
        k = len(records)
        if _failures_in_a_row(records) >= self.max_failures:
            return None
        if k < len(app):
            target, phase = app[k], APPROACH
        else:
            _, retract, anchor, detached, probes = self._state(records)
            if anchor is None:
                return None                      # never in contact: nothing to retract
            if detached:
                if probes >= self.refine:
                    return None
                target = 0.5 * (anchor["target"] + max(r["target"] for r in detached))
            else:
                regular = self.retract_targets()
                if len(retract) >= len(regular):
                    return None
                target = regular[len(retract)]
            phase = RETRACT
        anchor = next((r for r in reversed(records) if has_contact(r)), None)
        started_from, initial = starting_point(anchor, target)
        if anchor is not None and initial is not None and initial.size:
            # the branch through the neighbour's equilibrium, followed to this penetration with
            # its events located (the approach's continuation): the values recorded do not
            # depend on the cycle's step
            initial = ContinueFrom(initial, anchor["target"])
        spec = PointSpec(chain=chain.index, step=k, phase=phase, started_from=started_from,
                         history={"name": "cycle"},
                         fields=self.fields, labels=dict(chain.labels),
                         discretization=(None if self.discretization is None
                                         else attrs.asdict(self.discretization)))
        return scene_variant(chain.scene, control="penetration", value=target), spec, initial

    def expected_points(self, chain: Chain, records) -> int:
        n_app = len(self.approach_targets())
        if len(records) < n_app:
            return n_app + len(self.retract_targets()) + self.refine
        if self.next_point(chain, records) is None:
            return len(records)
        _, retract, _, detached, probes = self._state(records)
        if detached:
            return len(records) + self.refine - probes
        return n_app + len(self.retract_targets()) + self.refine


def _failures_in_a_row(records: Sequence[Mapping[str, Any]]) -> int:
    n = 0
    for r in reversed(records):
        if has_contact(r) or r["status"] == "no_contact" or (r["phase"] == RETRACT
                                                               and is_detached(r)):
            break
        n += 1
    return n


def is_detached(record: Mapping[str, Any]) -> bool:
    """Whether a retraction record marks detachment (see the module docstring)."""
    if record["status"] == "no_contact":
        return True
    # a solve that did not converge is no evidence of detachment
    return (bool(record["converged"]) and not has_contact(record)
            and record["target"] <= 0.0)


# ---- what a cycle measures ----------------------------------------------------------------------
@attrs.frozen(kw_only=True)
class CycleMetrics:
    """Pull-off, toughness and hysteresis of one cycle (see the module docstring).

    Attributes
    ----------
    toughness : float
        T̃ of eq. 4.57 (>= 0).
    zero_load_penetration : float
        Δ̃_0, where p̃∞ changes sign on the retraction branch (NaN if it does not).
    detached : bool
        Whether detachment was reached before ``min_penetration``.
    detachment_penetration : float
        Δ̃_out, the smallest penetration with contact on the retraction branch.
    detachment_bracket : float
        Width of the bracket on Δ̃_out (NaN when not detached).
    pull_off_pressure, pull_off_penetration : float
        min p̃∞ on the retraction branch and the Δ̃ where it is reached (0 and NaN when the
        branch never carries tension).
    cycle_work, area_loop : float
        ``2π ∮ p̃∞ dΔ̃`` and the area between the Ã-Δ̃ branches.
    """

    toughness: float
    zero_load_penetration: float
    detached: bool
    detachment_penetration: float
    detachment_bracket: float
    pull_off_pressure: float
    pull_off_penetration: float
    cycle_work: float
    area_loop: float


def _trapz(x, y) -> float:
    x, y = np.asarray(x, float), np.asarray(y, float)
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(x))) if len(x) > 1 else 0.0


def cycle_metrics(points: Mapping[str, np.ndarray]) -> CycleMetrics:
    """Metrics of one cycle from its records (column arrays in step order).

    ``points`` needs ``phase``, ``target``, ``status``, ``converged``, ``n_contacts``,
    ``full_contact``, ``mean_pressure`` and ``area``.
    """
    phase = np.asarray(points["phase"]).astype(str)
    target = np.asarray(points["target"], float)
    status = np.asarray(points["status"]).astype(str)
    pm = np.asarray(points["mean_pressure"], float)
    area = np.asarray(points["area"], float)
    touching = (np.asarray(points["n_contacts"]) > 0) | np.asarray(points["full_contact"], bool)
    contact = np.asarray(points["converged"], bool) & touching
    app = np.flatnonzero(phase == APPROACH)
    ret = np.flatnonzero(phase == RETRACT)
    nan = math.nan

    # the retraction branch: the turning point plus every contacting retraction point, Δ̃ falling
    turn = [i for i in app if contact[i]][-1:]
    branch = np.array(turn + [i for i in ret if contact[i]], dtype=int)
    branch = branch[np.argsort(-target[branch], kind="stable")]
    converged = np.asarray(points["converged"], bool)
    detached_at = [i for i in ret if status[i] == "no_contact"
                   or (converged[i] and not touching[i] and target[i] <= 0.0)]
    if branch.size == 0:
        return CycleMetrics(toughness=nan, zero_load_penetration=nan, detached=bool(detached_at),
                            detachment_penetration=nan, detachment_bracket=nan,
                            pull_off_pressure=nan, pull_off_penetration=nan, cycle_work=nan,
                            area_loop=nan)
    d, p, a = target[branch], pm[branch], area[branch]
    d_out = float(d[-1])
    detached = bool(detached_at)
    bracket = float(d_out - max(target[i] for i in detached_at)) if detached else nan

    # Δ̃_0 and T̃ (eq. 4.57)
    tensile = np.flatnonzero(p < 0)
    if tensile.size == 0:
        d0, tough = nan, 0.0
    else:
        j = int(tensile[0])
        if j == 0:
            d0, xs, ys = nan, d, p
        else:
            d0 = float(d[j - 1] + (d[j] - d[j - 1]) * p[j - 1] / (p[j - 1] - p[j]))
            xs, ys = np.r_[d0, d[j:]], np.r_[0.0, p[j:]]
        tough = 2.0 * math.pi * _trapz(xs, ys)
    k = int(np.argmin(p))
    pull_off, pull_off_at = (float(p[k]), float(d[k])) if p[k] < 0 else (0.0, nan)

    # hysteresis: work and area between the branches (zero out of contact)
    a_app = np.where(contact[app], area[app], 0.0)
    p_app = np.where(contact[app], pm[app], 0.0)
    ok = np.asarray([status[i] != ERROR and (contact[i] or status[i] == "no_contact")
                     for i in app], bool)
    order = np.argsort(target[app][ok], kind="stable")
    x_app = target[app][ok][order]
    work = 2.0 * math.pi * (_trapz(x_app, p_app[ok][order]) - _trapz(d[::-1], p[::-1]))
    loop = _trapz(d[::-1], a[::-1]) - _trapz(x_app, a_app[ok][order])
    return CycleMetrics(toughness=tough, zero_load_penetration=d0, detached=detached,
                        detachment_penetration=d_out, detachment_bracket=bracket,
                        pull_off_pressure=pull_off, pull_off_penetration=pull_off_at,
                        cycle_work=work, area_loop=loop)
