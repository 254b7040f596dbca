r"""The BEM's error estimate: the converged equilibrium solved again on a coarser mesh.

Coarser meshes, each solved at the same control from the converged edges (a few Newton-type
iterations): half the elements per contact and half the interior resolution
(:func:`fewer_elements`; a sharp edge's zone follows the elements,
:data:`~viscocontact.methods.bem.meshing.SHARP_ELEMENTS`), and, when the mesh has edge zones,
zones twice as coarse (:func:`coarser_zones`: twice the grading's excess ``g - 1`` and twice
the edge element). Richardson's rule turns each change of Ã and μ into an error,
``|Ã_coarse - Ã| / (2^p - 1)`` at the order of its kind, and the estimate is their sum,
relative to Ã (``μ`` relative to ``max(|μ|, FRICTION_FLOOR·√m2)``, as the spectral method's).
"""
from __future__ import annotations

import math
import time

import attrs
import numpy as np

from ...contact.fields import friction
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


@attrs.frozen(kw_only=True)
class Coarse:
    """One coarse solve of an estimate: Ã and μ (NaN when it did not converge), its elements per
    contact, residual evaluations, time, and what was coarsened (``"elements"`` or
    ``"edge zones"``)."""

    kind: str
    area: float
    friction: float
    elements: int
    evaluations: int
    seconds: float
    message: str = ""


@attrs.frozen(kw_only=True)
class Estimate:
    """The estimate of one solve: relative errors of Ã and μ and the coarse solves they come
    from (NaN when a coarse solve did not converge)."""

    area: float
    friction: float
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
        return {"estimates": {"area": self.area, "friction": self.friction},
                "coarse": [attrs.asdict(c) for c in self.coarse]}


def measures(prep, state: State) -> tuple[float, float]:
    """Ã and μ of a converged partial-contact state."""
    fields = state.fields
    mesh = fields.mesh
    return (float(np.sum(mesh.width)),
            friction(mesh, fields.sigma, prep.shape, fields.mean_pressure, fields.loads))


def relative_changes(fine: tuple[float, float], coarse: tuple[float, float],
                     m2: float) -> tuple[float, float]:
    """``|Ã_c - Ã|/Ã`` and ``|μ_c - μ|/max(|μ|, FRICTION_FLOOR·√m2)`` (0 for μ when neither is
    defined, e.g. at zero load)."""
    d_area = abs(coarse[0] - fine[0]) / max(fine[0], 1e-300)
    scale = max(abs(fine[1]) if np.isfinite(fine[1]) else 0.0,
                FRICTION_FLOOR * math.sqrt(max(m2, 0.0)), 1e-300)
    d_mu = abs(coarse[1] - fine[1]) / scale
    if not np.isfinite(d_mu):
        d_mu = 0.0 if not (np.isfinite(fine[1]) or np.isfinite(coarse[1])) else np.inf
    return float(d_area), float(d_mu)


def coarse_solve(parts, prep, state: State, target, kind: str, disc) -> Coarse:
    """The equilibrium with discretisation ``disc`` at ``target`` from the edges of the converged
    ``state`` (its contact-set changes included, no polish); ``parts(disc)``: the solve's parts
    for that discretisation (their ``equilibrium`` and ``log``)."""
    t0 = time.perf_counter()
    solve = parts(disc)
    out = solve.equilibrium.solve(state.edges, target, polish=False)
    common = dict(kind=kind, elements=disc.elements, evaluations=solve.log.evaluations,
                  seconds=time.perf_counter() - t0)
    if out.outcome is not Outcome.CONVERGED or out.fields is None:
        return Coarse(area=float("nan"), friction=float("nan"), **common,
                      message=f"the coarse solve ({kind}) ended {out.outcome.value}: "
                              f"{out.message}")
    area, mu = measures(prep, out)
    message = "" if len(out.edges) == len(state.edges) else (
        f"the coarse mesh ({kind}) has another contact set ({len(out.edges) // 2} contacts "
        f"against {len(state.edges) // 2})")
    return Coarse(area=area, friction=mu, **common, message=message)


def estimate(parts, disc, prep, spec, state: State, target) -> Estimate:
    """The error estimate of the converged ``state`` at ``target`` (a :class:`~.sets.Control`)
    of a problem with discretisation ``disc`` (``spec`` its
    :class:`~viscocontact.contact.mesh.MeshSpec`; ``parts(disc)`` the parts of its solve with
    another discretisation, :class:`~viscocontact.methods.bem.method.Solve`).

    The change of Ã and μ under half the elements (:func:`fewer_elements`) at
    :data:`ELEMENT_ORDER`, plus, when the mesh has edge zones, the change under zones twice as
    coarse (:func:`coarser_zones`) at :data:`EDGE_ORDER`, each coarsened alone: they do not
    follow one power, and their changes have opposite signs on Johnson's contact with δX = 1e-4
    (64 elements: +1.1e-4 from the elements, -2.1e-4 from the zones), so that coarsened at once
    they would cancel.
    """
    runs = [(coarse_solve(parts, prep, state, target, "elements", fewer_elements(disc)),
             ELEMENT_ORDER)]
    if spec.smallest is not None:
        runs.append((coarse_solve(parts, prep, state, target, "edge zones",
                                  coarser_zones(disc)), EDGE_ORDER))
    fine = measures(prep, state)
    area = mu = 0.0
    for run, order in runs:
        d_area, d_mu = relative_changes(fine, (run.area, run.friction), prep.m2)
        area += d_area / (2.0**order - 1.0)
        mu += d_mu / (2.0**order - 1.0)
    return Estimate(area=area, friction=mu, coarse=tuple(run for run, _ in runs))
