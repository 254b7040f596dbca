"""The boundary-element method with energy-balance edges (thesis §4.4) as a
:class:`~viscocontact.methods.base.SolutionMethod`.

A solve wires the parts, each with one job: the mesh policy
(:mod:`~viscocontact.methods.bem.meshing`), the edge system of a fixed contact set
(:mod:`~viscocontact.methods.bem.system`), the equilibrium at one control value with its
contact-set changes (:mod:`~viscocontact.methods.bem.equilibrium`), the grid checks
(:mod:`~viscocontact.methods.bem.checks`), the approach from first touch with its events and
jumps (:mod:`~viscocontact.methods.bem.approach`, :mod:`~viscocontact.methods.bem.relax`),
the closed state (:mod:`~viscocontact.methods.bem.closed`)
and the result (:meth:`Solve.assemble`).
"""
from __future__ import annotations

import time
from typing import ClassVar

import attrs
import numpy as np

from ...contact.fields import dissipated_friction, edge_flux_friction, friction
from ...errors import OUTSIDE_MODEL, ModelValidityWarning, warn_user
from ...result import ContactResult, SolveStatus
from ..base import SolutionMethod
from .checks import Checks
from .closed import ClosedContact
from .equilibrium import Equilibrium
from .estimate import estimate
from .meshing import MeshPolicy, mesh_spec
from .approach import Approach, ApproachOptions, ContinueFrom
from .path import Path
from .relax import RelaxFrom, Relaxation
from .sets import Control
from .state import Outcome, SolveLog, State
from .system import residual_scale


@attrs.frozen(kw_only=True)
class BEM(SolutionMethod):
    """Boundary elements on edge-clustered meshes, one energy balance per contact edge.

    Its options (mesh, tolerances, solvers, restarts) are the problem's
    (:class:`~viscocontact.problem.ContactProblem`): ``discretization``, ``tolerances``,
    ``solver``, ``fallback`` and ``max_restarts``. It solves every scene, adhesive or not.

    Parameters
    ----------
    estimate_error : bool
        Solve a converged equilibrium again from its edges on coarser meshes (half the elements;
        with edge zones, zones twice as coarse) for ``extras["error_estimate"]``
        (:mod:`~viscocontact.methods.bem.estimate`): 7-17 % of the solve's time on the thesis
        scenes, plus about 0.6 s once per process and coarse mesh for its stress-intensity
        calibration. ``False``: NaN, and no second solve.
    """

    name: ClassVar[str] = "bem"
    estimate_error: bool = attrs.field(default=True, validator=attrs.validators.instance_of(bool))

    def plan_steps(self, problem, prepared) -> tuple:
        from .planning import bem_steps, estimate_step

        steps = bem_steps(problem, prepared)
        return (*steps, estimate_step(problem, prepared)) if self.estimate_error else steps

    def solve(self, problem, initial=None, *, fields: bool = False, prepared=None):
        prep = prepared if prepared is not None else problem.prepare()
        return Solve(problem, prep).run(initial, fields, self.estimate_error)


class Solve:
    """One BEM solve: the parts wired for a problem and its prepared tables."""

    def __init__(self, problem, prep):
        self.problem = problem
        self.prep = prep
        disc = problem.discretization
        adhesion = problem.adhesion
        self.spec = mesh_spec(disc, prep.kernel, adhesion)
        self.log = SolveLog()
        self.policy = MeshPolicy(self.spec, disc, prep.shape.wavelength)
        self.checks = Checks(prep, disc.check_points)
        self.closed = ClosedContact(prep, disc.check_points, self.checks.origin,
                                    adhesive=adhesion.work_of_adhesion > 0,
                                    strength=adhesion.closed_strength(prep.shape.amplitude))
        tol = problem.tolerances
        self.equilibrium = Equilibrium(
            prep=prep, spec=self.spec, policy=self.policy, adhesion=adhesion,
            solver=problem.solver, fallback=problem.fallback,
            tolerances=attrs.evolve(tol, residual=tol.residual * residual_scale(prep.kernel)),
            max_restarts=problem.max_restarts, checks=self.checks, log=self.log)
        self.path = Path(self.equilibrium, self.closed, disc.path_step)
        self.approach = Approach(self.path, ApproachOptions(path_step=disc.path_step))

    def run(self, initial, want_fields: bool, estimate_error: bool = False) -> ContactResult:
        t0 = time.perf_counter()
        p = self.problem
        target = (Control.penetration_of(p.penetration) if p.penetration is not None
                  else Control.load_of(p.mean_pressure))
        adhesive = self.equilibrium.adhesive
        if not adhesive and self.closed.closes(target):
            # the adhesionless answer does not depend on the path: the closed contact, exactly
            # (at the one penetration of an incompressible solid's closed contact no partial
            # contact exists: its mean gap would be zero; the approach ended there on contacts
            # with slivers of gap at the solver's tolerance)
            self.log.event("the closed contact carries the load without tension")
            out = State.full_contact()
        elif isinstance(initial, ContinueFrom):
            out = self.approach.continued(initial, target)
        elif isinstance(initial, RelaxFrom):
            out = Relaxation(self.equilibrium, self.closed, initial.tolerance).run(
                initial.edges, target)
        elif initial is not None and getattr(initial, "full_contact", False):
            out = self.approach.from_full_contact(target)
        elif initial is not None:
            edges = np.asarray(getattr(initial, "edges", initial), dtype=float).ravel()
            out = self.equilibrium.solve(edges, target)
            if out.outcome is Outcome.NOT_CONVERGED and adhesive and not target.is_load:
                # retracted past the fold of its branch, the contact pulls off
                out = Relaxation(self.equilibrium, self.closed).run(edges, target)
            if out.outcome is Outcome.NOT_CONVERGED and not adhesive:
                # an adhesionless equilibrium does not depend on the path: start afresh
                self.log.event(f"no equilibrium from the given contact set ({out.message}); "
                               "solved from first touch")
                self.policy.forget()       # the same answer as a solve from first touch
                out = self.approach.run(target)
        else:
            out = self.approach.run(target)
        found = (estimate(self.coarser, p.discretization, self.prep, self.spec, out, target,
                          p.adhesion)
                 if estimate_error and out.outcome is Outcome.CONVERGED else None)
        if found is not None:
            self.log.event(f"error estimate {found.error:.2g} (Ã {found.area:.2g}, μ "
                           f"{found.friction:.2g}) from coarser meshes"
                           + (f"; {found.message}" if found.message else ""))
        result = self.assemble(out, target, want_fields, time.perf_counter() - t0)
        if found is not None:
            result.extras.update(error_estimate=found.error, **found.extras())
        return result

    def coarser(self, disc) -> "Solve":
        """The parts of this problem's solve with the coarser discretisation ``disc``, the
        contacts this solve refined refined by the same factor (:meth:`MeshPolicy.inherit`)."""
        solve = Solve(attrs.evolve(self.problem, discretization=disc), self.prep)
        solve.policy.inherit(self.policy, disc.elements / self.problem.discretization.elements)
        return solve

    def assemble(self, out: State, target: Control, want_fields: bool,
                 elapsed: float) -> ContactResult:
        """The :class:`ContactResult` of the final state."""
        p, log = self.problem, self.log
        sqrt_m2 = np.sqrt(self.prep.m2) if self.prep.m2 > 0 else np.nan
        adh = p.adhesion
        dx = float(adh.edge_advance())
        extras = {"events": list(log.events), "path_events": list(log.records),
                  "residual_history": list(log.history),
                  "seconds": elapsed, "method": BEM.name, "error_estimate": float("nan"),
                  "friction_dissipation": float("nan"), "friction_edges": float("nan"),
                  "outside_model": ""}
        common = dict(iterations=log.iterations, function_evaluations=log.evaluations,
                      zeta=p.zeta, edge_perturbation=dx, extras=extras)
        kind = out.outcome
        if kind in (Outcome.CONVERGED, Outcome.NOT_CONVERGED) and out.fields is not None:
            fields = out.fields
            mesh = fields.mesh
            area = float(np.sum(mesh.width))
            pm = fields.mean_pressure
            mu = friction(mesh, fields.sigma, self.prep.shape, pm, fields.loads)
            extras["friction_dissipation"] = dissipated_friction(
                self.prep.kernel, mesh, fields.sigma, self.prep.shape.amplitude, pm, fields.loads)
            converged = kind is Outcome.CONVERGED
            terms = adh.edge_terms(out.ctx) if converged else None
            message = out.message
            if out.ctx is not None:
                k = terms.stress_intensity if terms is not None else out.ctx.stress_intensity()
                extras["friction_edges"] = edge_flux_friction(
                    k, out.ctx.edge_compliance, self.prep.shape.amplitude, pm)
                why = (adh.outside_model(out.ctx, mu, extras["friction_dissipation"],
                                         extras["friction_edges"]) if converged else None)
                if why:
                    extras["outside_model"] = why
                    message = f"{message}; {OUTSIDE_MODEL}: {why}"
                    warn_user(f"{OUTSIDE_MODEL}: {why}", ModelValidityWarning)
            _, gap = self.checks.gap_outside(fields)
            fld = self.checks.fields_on_grid(fields) if want_fields else None
            extras["conformity"] = self.checks.conformity(
                fields, None if fld is None else fld["displacement"])
            return ContactResult(
                area=area, mean_pressure=pm, penetration=fields.penetration, friction=mu,
                reduced_friction=mu / sqrt_m2, n_contacts=mesh.n_contacts,
                edges=mesh.edges.reshape(-1, 2).copy(), full_contact=False,
                converged=converged,
                status=SolveStatus.CONVERGED if converged else SolveStatus.NOT_CONVERGED,
                message=message, residual=out.residual,
                min_gap=float(gap.min()) if gap.size else np.inf,
                edge_terms=terms, fields=fld, **common)
        if kind is Outcome.FULL_CONTACT:
            extras["friction_edges"] = 0.0          # no edges
            result = self.closed.result(target, out.message, want_fields, common)
            why = self.equilibrium.limitation
            if not result.converged and why is not None:
                # the contact sets on the way that the model could not evaluate are the likelier
                # cause than the closed interface reached past them
                result = attrs.evolve(result, message=f"{result.message}; on the way the "
                                      f"adhesion model rejected contact sets: {why}")
            return result
        if kind is Outcome.NO_CONTACT:
            pen = np.nan if target.is_load else target.value
            return ContactResult(area=0.0, mean_pressure=0.0, penetration=pen, friction=np.nan,
                                 reduced_friction=np.nan, n_contacts=0, edges=np.zeros((0, 2)),
                                 full_contact=False, converged=True, status=SolveStatus.NO_CONTACT,
                                 message=out.message, residual=0.0, min_gap=np.inf, **common)
        return ContactResult(area=np.nan, mean_pressure=np.nan, penetration=np.nan, friction=np.nan,
                             reduced_friction=np.nan, n_contacts=0, edges=np.zeros((0, 2)),
                             full_contact=False, converged=False, status=SolveStatus.FAILED,
                             message=out.message, residual=np.inf, min_gap=np.nan, **common)
