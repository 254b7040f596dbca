r"""The BEM's error estimate: the converged equilibrium solved again on a coarser mesh.

Coarser meshes, each solved at the same control from the converged edges (a few Newton-type
iterations): half the elements per contact and half the interior resolution
(:func:`fewer_elements`; a sharp edge's zone follows the elements,
:data:`~viscocontact.methods.bem.meshing.SHARP_ELEMENTS`), and, when the mesh has edge zones,
zones twice as coarse (:func:`coarser_zones`: twice the grading's excess ``g - 1`` and twice
the edge element). Richardson's rule turns each change of Ã and μ into an error,
``|Ã_coarse - Ã| / (2^p - 1)`` at the order of its kind, and the estimate is their sum,
relative to Ã (``μ`` relative to ``max(|μ|, FRICTION_FLOOR·√m2)``, as the spectral method's).
The dissipated power's friction (the power balance's side: the bulk dissipation and the flux
into the edges) gets its estimate the same way, reported beside them. Without a flux into the
edges the two frictions discretise one quantity, and their estimates are raised to add up to
their misfit at least (:func:`~viscocontact.methods.power.bounded_by_power`).
"""
from __future__ import annotations

import math
import time

import attrs
import numpy as np

from ...contact.fields import dissipated_friction, edge_flux_friction, friction
from ..power import bounded_by_power
from .state import Outcome, State

#: Order assumed for the change under half the elements: the clustered mesh converges at second
#: order (Westergaard: 2.0; Johnson with δX = 0: 2.1 over N = 16-256, ``docs/verification.md``),
#: but not yet in its asymptotic range on coarse meshes and next to edge zones, where the change
#: under-states the error (Johnson with δX = 0: 0.66 of it at N = 128 taken at order 2); at order
#: 1 the estimate is the whole change, about three times a second-order error.
ELEMENT_ORDER = 1.0
#: Order assumed for the change under edge zones twice as coarse: the grading's error grows as
#: about ``(g - 1)^2.4`` (Johnson, δX = 1e-4, 64 elements: -1.6e-5, -5.0e-5, -1.0e-4 and
#: -2.6e-4 at g = 1.1, 1.15, 1.2 and 1.3 against g = 1.05); the edge element's is small once
#: zones are resolved (below 6e-6 from edge_resolution 0.1 to 0.2).
EDGE_ORDER = 2.0
#: ``μ`` is resolved relative to ``max(|μ|, FRICTION_FLOOR·√m2)`` (it vanishes on an elastic
#: solid), as in :class:`~viscocontact.methods.spectral.Spectral`.
FRICTION_FLOOR = 1e-2


def fewer_elements(disc):
    """``disc`` with half the elements and half the interior resolution (at least 8 and 1)."""
    return attrs.evolve(
        disc, elements=max(8, disc.elements // 2),
        interior_resolution=(None if disc.interior_resolution is None
                             else max(1.0, 0.5 * disc.interior_resolution)))


def coarser_zones(disc):
    """``disc`` with edge zones twice as coarse: twice the grading's excess ``g - 1`` and twice
    the edge element (``edge_resolution``), at most 2 and 1."""
    return attrs.evolve(
        disc, grading=min(2.0, 1.0 + 2.0 * (disc.grading - 1.0)),
        edge_resolution=(None if disc.edge_resolution is None
                         else min(1.0, 2.0 * disc.edge_resolution)))


def finer(disc):
    """``disc`` refined the other way round from :func:`fewer_elements` and
    :func:`coarser_zones` at once: twice the elements and the interior resolution, and, with
    edge zones, half the grading's excess ``g - 1`` and half the edge element (each within its
    allowed range; equal to ``disc`` when none can be refined further)."""
    return attrs.evolve(
        disc, elements=min(4096, 2 * disc.elements),
        interior_resolution=(None if disc.interior_resolution is None
                             else min(64.0, 2.0 * disc.interior_resolution)),
        grading=max(1.05, 1.0 + 0.5 * (disc.grading - 1.0)),
        edge_resolution=(None if disc.edge_resolution is None
                         else max(1e-3, 0.5 * disc.edge_resolution)))


@attrs.frozen(kw_only=True)
class Coarse:
    """One coarse solve of an estimate: Ã, μ and the dissipated power's μ (NaN when it did not
    converge), its elements per contact, residual evaluations, time, and what was coarsened
    (``"elements"`` or ``"edge zones"``)."""

    kind: str
    area: float
    friction: float
    dissipation: float
    elements: int
    evaluations: int
    seconds: float
    message: str = ""


@attrs.frozen(kw_only=True)
class Estimate:
    """The estimate of one solve: relative errors of Ã, μ and the dissipated power's μ (the
    latter two relative to ``scale``, :func:`friction_scale`) and the coarse solves they come
    from (NaN when a coarse solve did not converge)."""

    area: float
    friction: float
    dissipation: float
    scale: float
    coarse: tuple

    @property
    def error(self) -> float:
        """The larger of the two (NaN when either is)."""
        if not np.isfinite(self.area + self.friction):
            return float("nan")
        return max(self.area, self.friction)

    @property
    def message(self) -> str:
        return "; ".join(c.message for c in self.coarse if c.message)

    def extras(self) -> dict:
        """The result's entries: ``estimates`` (as the spectral method's) and ``coarse``."""
        return {"estimates": {"area": self.area, "friction": self.friction,
                              "dissipation": self.dissipation, "friction_scale": self.scale},
                "coarse": [attrs.asdict(c) for c in self.coarse]}


def measures(prep, state: State, adhesion) -> tuple[float, float, float]:
    """Ã, μ and the dissipated power's μ (bulk and the flux into the edges, whose stress
    intensities are the ``adhesion`` model's, as in the result) of a converged partial-contact
    state."""
    fields = state.fields
    mesh = fields.mesh
    pm = fields.mean_pressure
    dissipated = dissipated_friction(prep.kernel, mesh, fields.sigma, prep.shape.amplitude, pm,
                                     fields.loads) + edge_flux(prep, state, adhesion)
    return (float(np.sum(mesh.width)),
            friction(mesh, fields.sigma, prep.shape, pm, fields.loads), float(dissipated))


def edge_flux(prep, state: State, adhesion) -> float:
    """The flux into the edges' tips of a converged state, in friction units (round-off where
    its edges carry no stress singularity: no adhesion, or a cohesive zone)."""
    if state.ctx is None:
        return 0.0
    return float(edge_flux_friction(adhesion.edge_terms(state.ctx).stress_intensity,
                                    state.ctx.edge_compliance, prep.shape.amplitude,
                                    state.fields.mean_pressure))


def friction_scale(friction: float, m2: float) -> float:
    """``max(|μ|, FRICTION_FLOOR·√m2)``: what the friction's estimate is relative to."""
    mu = abs(friction) if np.isfinite(friction) else 0.0
    return float(max(mu, FRICTION_FLOOR * math.sqrt(max(m2, 0.0)), 1e-300))


def relative_changes(fine: tuple[float, ...], coarse: tuple[float, ...],
                     m2: float) -> tuple[float, ...]:
    """``|Ã_c - Ã|/Ã``, then the changes of μ and of the other frictions (the dissipated
    power's) relative to :func:`friction_scale` (0 for one that neither defines, e.g. at zero
    load)."""
    d_area = abs(coarse[0] - fine[0]) / max(fine[0], 1e-300)
    scale = friction_scale(fine[1], m2)
    out = [float(d_area)]
    for f, c in zip(fine[1:], coarse[1:]):
        d = abs(c - f) / scale
        if not np.isfinite(d):
            d = 0.0 if not (np.isfinite(f) or np.isfinite(c)) else np.inf
        out.append(float(d))
    return tuple(out)


def coarse_solve(parts, prep, state: State, target, kind: str, disc, adhesion) -> Coarse:
    """The equilibrium with discretisation ``disc`` at ``target`` from the edges of the converged
    ``state`` (its contact-set changes included, no polish); ``parts(disc)``: the solve's parts
    for that discretisation (their ``equilibrium`` and ``log``)."""
    t0 = time.perf_counter()
    solve = parts(disc)
    out = solve.equilibrium.solve(state.edges, target, polish=False)
    common = dict(kind=kind, elements=disc.elements, evaluations=solve.log.evaluations,
                  seconds=time.perf_counter() - t0)
    if out.outcome is not Outcome.CONVERGED or out.fields is None:
        return Coarse(area=float("nan"), friction=float("nan"), dissipation=float("nan"),
                      **common, message=f"the coarse solve ({kind}) ended "
                                        f"{out.outcome.value}: {out.message}")
    area, mu, dissipated = measures(prep, out, adhesion)
    message = "" if len(out.edges) == len(state.edges) else (
        f"the coarse mesh ({kind}) has another contact set ({len(out.edges) // 2} contacts "
        f"against {len(state.edges) // 2})")
    return Coarse(area=area, friction=mu, dissipation=dissipated, **common, message=message)


def estimate(parts, disc, prep, spec, state: State, target, adhesion) -> Estimate:
    """The error estimate of the converged ``state`` at ``target`` (a :class:`~.sets.Control`)
    of a problem with discretisation ``disc`` (``spec`` its
    :class:`~viscocontact.contact.mesh.MeshSpec`; ``parts(disc)`` the parts of its solve with
    another discretisation, :class:`~viscocontact.methods.bem.method.Solve`; ``adhesion`` its
    adhesion model).

    The change of Ã and μ under half the elements (:func:`fewer_elements`) at
    :data:`ELEMENT_ORDER`, plus, when the mesh has edge zones, the change under zones twice as
    coarse (:func:`coarser_zones`) at :data:`EDGE_ORDER`, each coarsened alone: they do not
    follow one power, and their changes have opposite signs on Johnson's contact with δX = 1e-4
    (64 elements: +1.1e-4 from the elements, -2.1e-4 from the zones), so that coarsened at once
    they would cancel.
    """
    runs = [(coarse_solve(parts, prep, state, target, "elements", fewer_elements(disc),
                          adhesion), ELEMENT_ORDER)]
    if spec.smallest is not None:
        runs.append((coarse_solve(parts, prep, state, target, "edge zones",
                                  coarser_zones(disc), adhesion), EDGE_ORDER))
    fine = measures(prep, state, adhesion)
    errors = np.zeros(3)
    for run, order in runs:
        errors += np.asarray(relative_changes(fine, (run.area, run.friction, run.dissipation),
                                              prep.m2)) / (2.0**order - 1.0)
    if not adhesion.singular_edges(prep.shape.amplitude):
        # no flux into the edges (whose finite-δX balance is a model of its own, not a
        # discretisation of the bulk's power): the two frictions are bounded by their misfit
        misfit = abs(fine[1] - fine[2]) / friction_scale(fine[1], prep.m2)
        errors[1], errors[2] = bounded_by_power(float(errors[1]), float(errors[2]), misfit)
    return Estimate(area=float(errors[0]), friction=float(errors[1]),
                    dissipation=float(errors[2]), scale=friction_scale(fine[1], prep.m2),
                    coarse=tuple(run for run, _ in runs))
